// The svgmotion command-line tool: dispatches subcommands and turns every error into one line.
//
// Errors (svgm::Error and anything else) print "svgmotion: <message>" on stderr and exit 1;
// usage mistakes exit 2. Nothing is written by a command that fails (outputs are atomic).
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "svgmotion/error.h"

namespace {

constexpr const char* kUsage = R"(svgmotion: an editable animated SVG from a static SVG and a motion

usage:
  svgmotion render IN.svg -o OUT.png [--size W] [--background white|transparent] [--time T]
                   [--device D] [--strict]
  svgmotion fit IN.svg --target VIDEO|FRAMES_DIR -o OUT_DIR [--iterations N] [--keyframes K]
                [--size N] [--palette P.json] [--resume] [--no-track] [--device D]
  svgmotion run [CONFIG.yaml] [--input X.svg] [--prompt "..."] [-o RUN_DIR] [--from STAGE] [key.path=value ...]
  svgmotion plugins
  svgmotion devices
  svgmotion palette N
  svgmotion bench render IN.svg [--frames K] [--size N] [--repeat R] [--json] [--device D]
  svgmotion bench raster IN.svg [--frames K] [--size N] [--repeat R] [--json] [--device D]
  svgmotion bench raster --scaling [--json]
  svgmotion help

--device picks the OpenCL device: auto (default), cpu, gpu, or part of its name.
)";

}  // namespace

int main(int argc, char** argv) {
  // Bad input must give our one error line, not FFmpeg's or OpenCV's chatter before it. These
  // are read when OpenCV first loads its video back end, i.e. after this point.
  setenv("OPENCV_LOG_LEVEL", "SILENT", 0);
  setenv("OPENCV_FFMPEG_LOGLEVEL", "-8", 0);  // AV_LOG_QUIET
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "help" || args[0] == "--help" || args[0] == "-h") {
    std::fputs(kUsage, args.empty() ? stderr : stdout);
    return args.empty() ? 2 : 0;
  }
  const std::string cmd = args[0];
  args.erase(args.begin());
  try {
    if (cmd == "render") return svgm::cli::cmd_render(args);
    if (cmd == "devices") return svgm::cli::cmd_devices(args);
    if (cmd == "bench") return svgm::cli::cmd_bench(args);
    if (cmd == "fit") return svgm::cli::cmd_fit(args);
    if (cmd == "palette") return svgm::cli::cmd_palette(args);
    if (cmd == "run") return svgm::cli::cmd_run(args);
    if (cmd == "plugins") return svgm::cli::cmd_plugins(args);
    std::fprintf(stderr, "svgmotion: unknown command '%s' (try svgmotion help)\n", cmd.c_str());
    return 2;
  } catch (const svgm::Error& e) {
    std::fprintf(stderr, "svgmotion: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "svgmotion: internal error: %s\n", e.what());
    return 1;
  }
}
