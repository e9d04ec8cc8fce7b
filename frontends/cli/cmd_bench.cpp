// `svgmotion bench render`: median time per frame of the OpenCL renderer, peak memory, device.
//
// Times a whole batch of K frames (flatten through compositing, with the device finished) over
// several repetitions after a warm-up that includes kernel compilation, and reports the median
// divided by K. Kernel compilation is excluded; upload of the control points is excluded too,
// since in fitting they are produced on the device.
#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "opencl/runtime.h"
#include "raster/raster_cl.h"
#include "raster/raster_plan.h"
#include "svgmotion/error.h"
#include "svgmotion/render_size.h"
#include "svgmotion/svg_reader.h"

namespace svgm::cli {

namespace {

double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;  // Linux reports kilobytes
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

int bench_render(const std::vector<std::string>& argv) {
  const Args a = parse_args("bench render", argv, {"--frames", "--size", "--device", "--repeat"},
                            {"--json"});
  if (a.positional.size() != 1) throw Error("bench render: expected one input SVG");
  const int frames = a.get_int("--frames", 15, 1, 1000);
  const int width = a.get_int("--size", 256, 1, 16384);
  const int repeat = a.get_int("--repeat", 15, 1, 100000);
  const Scene scene = read_svg_file(a.positional[0]);
  const RenderSize size = render_size(scene, width);
  const RasterPlan plan = plan_raster(scene, size.view, size.width, size.height);
  ClRuntime rt(a.get("--device").value_or("auto"));
  ClRaster raster(rt, plan, frames);
  raster.set_rest_pose();
  // 8-bit output over white, as librsvg's benchmark produces: the same work a render does.
  const std::array<float, 4> white{1, 1, 1, 1};
  raster.forward(ClRaster::Output::Rgba8, white);  // warm-up: buffers touched, kernels built
  raster.finish();
  std::vector<double> ms;
  for (int r = 0; r < repeat; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    raster.forward(ClRaster::Output::Rgba8, white);
    raster.finish();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                     .count());
  }
  const double per_frame = median(ms) / frames;
  if (a.has("--json")) {
    std::printf(
        "{\"svg\": \"%s\", \"frames\": %d, \"width\": %d, \"height\": %d, \"lines\": %d, "
        "\"ms_per_frame\": %.4f, \"ms_per_batch\": %.4f, \"peak_rss_mb\": %.1f, "
        "\"device\": \"%s\", \"compile_s\": %.3f}\n",
        a.positional[0].c_str(), frames, size.width, size.height, plan.n_lines, per_frame,
        median(ms), peak_rss_mb(), rt.info().name.c_str(), rt.compile_seconds());
  } else {
    std::printf("%s: %dx%d, %d frames, %d lines\n", a.positional[0].c_str(), size.width,
                size.height, frames, plan.n_lines);
    std::printf("  median %.3f ms per frame (%.2f ms per batch of %d), peak memory %.1f MB\n",
                per_frame, median(ms), frames, peak_rss_mb());
    std::printf("  device: %s (kernel build/load %.2f s, not counted)\n", rt.info().name.c_str(),
                rt.compile_seconds());
  }
  return 0;
}

}  // namespace

int cmd_bench(const std::vector<std::string>& argv) {
  if (argv.empty()) throw Error("bench: which benchmark? (svgmotion bench render IN.svg ...)");
  const std::vector<std::string> rest(argv.begin() + 1, argv.end());
  if (argv[0] == "render") return bench_render(rest);
  throw Error("bench: unknown benchmark '" + argv[0] + "' (available: render)");
}

}  // namespace svgm::cli
