// `svgmotion devices`: the OpenCL devices this machine offers, and which `auto` picks;
// `--warm` compiles and caches the kernel programs a default run uses, once, at set-up.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <set>
#include <string>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "cli/warm_kernels.h"
#include "opencl/compile_child.h"
#include "opencl/cpu_share.h"
#include "opencl/kernel_cache.h"
#include "opencl/runtime.h"
#include "opencl/tuning.h"
#include "fit/output/tolerance_choice.h"
#include "raster/loss_taps.h"
#include "svgmotion/device.h"

namespace svgm::cli {

namespace {

// Builds, and launches every kernel of, what a default run builds (warm_kernels.h), and says
// what it built. The raster program depends on the width through its tuning alone (the band
// height: 16 rows at 256 px, 8 at 512, 4 at 1024 on PoCL), so it is built once per tuning of
// the widths a default run renders at: the fit's 256 px, the video's and the refinement's
// 512 px, and the compact export's tolerance renders, whose larger side is 1024 px
// (fit/output/tolerance_choice.h; a narrower drawing's width falls in one of the classes
// below). Each in the builds a run uses there (raster/loss_blur.h): the paper's blur (renders,
// and fits of a video as sharp as the render) everywhere, and at the fitting widths the matched
// one, which serves every blur matching picks (any σ, chroma σ and chroma weight: its taps are
// a kernel argument). Then the fitter's program. A default run then compiles nothing.
void warm(const std::string& device) {
  const auto t0 = std::chrono::steady_clock::now();
  ClRuntime rt(device);
  int compiled = 0, cached = 0;
  // One program: how it was obtained and how long that took.
  auto one = [&](const std::string& what, const std::function<void()>& make) {
    const auto s0 = std::chrono::steady_clock::now();
    const int before = rt.programs_built_from_source() + rt.programs_compiled_in_child();
    make();
    const bool built = rt.programs_built_from_source() + rt.programs_compiled_in_child() > before;
    (built ? compiled : cached) += 1;
    std::printf("warm: %-56s %s, %.1f s\n", what.c_str(), built ? "compiled" : "cached",
                std::chrono::duration<double>(std::chrono::steady_clock::now() - s0).count());
    std::fflush(stdout);
  };
  // A matched blur with every part the build has (a radius above the paper's, reflect
  // padding, chroma taps of their own, a chroma weight): the program is the same for any.
  constexpr double kSigma = 1.2, kChromaSigma = 1.35, kChromaWeight = 0.5;
  std::set<std::string> tunings;
  for (int width : {256, 512, kToleranceRenderPx}) {
    if (!tunings.insert(kernel_build_options(raster_tuning(rt.info(), width))).second) continue;
    const bool fits = width <= 512;
    // The export's renders are a frame at a time: a few rows launch every kernel as a full
    // frame does (the same work-group sizes), without a 1024-px frame's loss buffers.
    const int height = fits ? width : 64;
    const std::string px = std::to_string(width) + " px (band " + std::to_string(raster_tuning(rt.info(), width).band_height) + ")";
    one("raster program, " + px + ", the paper's blur",
        [&] { warm_raster(rt, width, height, kLossSigma, kLossSigma, 1); });
    if (fits)
      one("raster program, " + px + ", blur-matched (any sigma)",
          [&] { warm_raster(rt, width, height, kSigma, kChromaSigma, kChromaWeight); });
  }
  one("fitter program", [&] { warm_fitter(rt); });
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("warm: %d kernel programs compiled, %d already cached, %.1f s (cache: %s)\n", compiled, cached, s,
              kernel_cache_dir().c_str());
}

}  // namespace

int cmd_devices(const std::vector<std::string>& argv) {
  const Args a = parse_args("devices", argv, {"--device", "--warm-for"}, {"--warm"});
  // The child that compiles one program for a fit (opencl/compile_child.h); not for users.
  if (const auto spec = a.get("--warm-for")) {
    setenv(kCompileChildVar, "", 1);  // this is the child: it compiles in itself
    ClRuntime rt(a.get("--device").value_or("auto"));
    warm_for(rt, *spec);
    return 0;
  }
  if (a.has("--warm")) {
    warm(a.get("--device").value_or("auto"));
    return 0;
  }
  const auto devs = list_devices();
  const size_t pick = select_device(devs, "auto");
  for (size_t i = 0; i < devs.size(); ++i) {
    const auto& d = devs[i];
    std::printf("%s%zu  %-4s  %s  [%s]  %u compute units, %.1f GB, %s\n", i == pick ? "*" : " ",
                i, d.type.c_str(), d.name.c_str(), d.platform.c_str(), d.compute_units,
                d.global_mem_bytes / 1e9, d.version.c_str());
  }
  std::printf("(* = what --device auto picks)\n");
  // What PoCL's CPU device was told (opencl/cpu_share.h), for checking a cluster job's manners.
  const CpuShare share = apply_cpu_share();
  const char* threads = std::getenv("POCL_MAX_PTHREAD_COUNT");
  const bool pinned = std::getenv("POCL_AFFINITY") && std::string(std::getenv("POCL_AFFINITY")) == "1";
  const bool ours = threads && std::to_string(share.threads) == threads && pinned == share.pin;
  std::printf("PoCL CPU threads: %s, %s (%s)\n", threads ? threads : "?", pinned ? "pinned to cores" : "not pinned",
              ours ? share.why.c_str() : "set in the environment");
  return 0;
}

}  // namespace svgm::cli
