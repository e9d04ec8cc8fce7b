// `svgmotion bench target VIDEO`: the target stage's speed as `fit` loads a video: decoding,
// temporal denoising (fit's default radius 2) and, with --stabilise, camera-shake removal,
// then the cleanup (colour, mask, distance field) of every keyframe. Reports the medians over
// the repetitions of the load's wall and CPU time and of the denoising's share (load_target
// times it), peak memory, and what the stabiliser found (its model, the largest shake
// removed), so the stabiliser's cost on a real clip can be read off without a fit.
#include "cli/bench_target.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "cli/bench_util.h"
#include "cli/cli_args.h"
#include "svgmotion/error.h"
#include "svgmotion/target_video.h"

namespace svgm::cli {

int bench_target(const std::vector<std::string>& argv) {
  const Args a = parse_args("bench target", argv, {"--size", "--keyframes", "--denoise", "--repeat"},
                            {"--stabilise", "--json"});
  if (a.positional.size() != 1) throw UsageError("bench target: expected one video (or folder of frames)");
  const std::string source = a.positional[0];
  const int width = a.get_int("--size", 256, 32, 4096);
  const int repeat = a.get_int("--repeat", 3, 1, 1000);
  TargetOptions to;
  to.keyframes = a.get_int("--keyframes", 15, 2, 1000);
  to.denoise_radius = a.get_int("--denoise", 2, 0, 4);
  to.stabilise = a.has("--stabilise");
  const TargetInfo info = probe_target(source);
  const int height = std::max(1, static_cast<int>(std::lround(static_cast<double>(width) * info.height / info.width)));
  std::vector<double> wall, cpu, denoise;
  TargetFrames t;
  for (int r = 0; r < repeat; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = cpu_seconds();
    t = load_target(source, width, height, to);
    wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    cpu.push_back(cpu_seconds() - c0);
    denoise.push_back(t.denoise_seconds);
  }
  const double wall_s = median(wall), cpu_s = median(cpu), denoise_s = median(denoise);
  if (a.has("--json")) {
    std::printf("{\"source\": \"%s\", \"frames\": %d, \"source_size\": [%d, %d], \"size\": [%d, %d], "
                "\"keyframes\": %d, \"denoise_radius\": %d, \"stabilise\": %s, \"wall_s\": %.3f, \"cpu_s\": %.3f, "
                "\"denoise_s\": %.3f, \"shake_model\": \"%s\", \"max_shake_px\": %.3f, \"peak_rss_mb\": %.1f}\n",
                source.c_str(), info.frames, info.width, info.height, width, height, to.keyframes, to.denoise_radius,
                to.stabilise ? "true" : "false", wall_s, cpu_s, denoise_s, t.shake_model.c_str(), t.max_shake_px,
                peak_rss_mb());
  } else {
    std::printf("%s: %d frames at %dx%d, %d keyframes at %dx%d\n", source.c_str(), info.frames, info.width,
                info.height, to.keyframes, width, height);
    std::printf("  load: wall %.2f s, CPU %.2f s (median of %d), of which denoising (radius %d) %.2f s\n", wall_s, cpu_s,
                repeat, to.denoise_radius, denoise_s);
    if (to.stabilise)
      std::printf("  camera shake: model %s, up to %.2f px removed (fitting width)\n", t.shake_model.c_str(),
                  t.max_shake_px);
    std::printf("  peak memory %.1f MB\n", peak_rss_mb());
  }
  return 0;
}

}  // namespace svgm::cli
