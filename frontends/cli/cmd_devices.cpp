// `svgmotion devices`: the OpenCL devices this machine offers, and which `auto` picks;
// `--warm` compiles and caches the kernel programs a default run uses, once, at set-up.
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "opencl/cpu_share.h"
#include "opencl/kernel_cache.h"
#include "opencl/runtime.h"
#include "raster/raster_cl.h"
#include "raster/raster_plan.h"
#include "scene/synthetic_scene.h"
#include "svgmotion/device.h"
#include "svgmotion/render_size.h"

namespace svgm::cli {

namespace {

// Builds, and launches once so that PoCL compiles each kernel for its work-group size too, what
// a default run builds: the raster program at the recolorer's and the fit's widths (256 px,
// band height 16; 512 px and up, 8) with the default blur, and the fitter's program. A fit whose
// blur is matched to a blurred target still builds its own taps then.
void warm(const std::string& device) {
  const auto t0 = std::chrono::steady_clock::now();
  ClRuntime rt(device);
  for (int width : {256, 512}) {
    const Scene scene = synthetic_blobs(3, width, 1);
    const RenderSize size = render_size(scene, width);
    const RasterPlan plan = plan_raster(scene, size.view, size.width, size.height);
    ClRaster r(rt, plan, 2);
    const std::array<float, 4> white{1, 1, 1, 1};
    r.set_rest_pose();
    r.forward(ClRaster::Output::Rgba8, white);
    r.forward(ClRaster::Output::Float, white);
    const std::vector<float> target = r.read_image();  // set_targets keeps no copy
    r.set_targets(target);
    r.loss_and_gradient(1000.0f, white);
  }
  rt.program({"field.cl", "motion.cl", "regularise.cl", "adam.cl"}, kFitterProgramOptions);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("warm: %d kernel programs compiled, %d already cached, %.1f s (cache: %s)\n",
              rt.programs_built_from_source(), rt.programs_loaded_from_cache(), s, kernel_cache_dir().c_str());
}

}  // namespace

int cmd_devices(const std::vector<std::string>& argv) {
  const Args a = parse_args("devices", argv, {"--device"}, {"--warm"});
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
