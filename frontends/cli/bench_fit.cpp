// `svgmotion bench fit IN.svg --target VIDEO`: the fitter's speed at the fit's defaults (or the
// given iterations, keyframes and size), without the outputs a fit writes. The drawing is
// fitted as `fit` fits it: long segments split (fit_job.h's max_segment), and the iterations
// end where the loss stops falling (FitOptions::plateau_window), as in `fit`. Times the setup
// (target loading, planning, kernel build) and the iterations apart, and reports the
// iterations' wall time and CPU time (user + sys of every thread: PoCL's workers included,
// the comparable figure on a shared machine), milliseconds per iteration and peak memory (the
// process's VmHWM, and what it was once the target was loaded and the fitter built: the rest is
// the iterations' device buffers, which PoCL keeps in host memory). Only the coarse stage runs:
// a fit's refinement at twice the width and its keyframes from the target come on top.
// Progressive activation makes early iterations cheaper than late ones, so only a whole
// schedule (--iterations N runs the fit's schedule for N) compares with another.
#include "cli/bench_fit.h"

#include <chrono>
#include <cstdio>

#include "cli/bench_util.h"
#include "cli/cli_args.h"
#include "fit/fit_job.h"
#include "fit/optimise/fitter.h"
#include "fit/plan/segment_split.h"
#include "fit/target/compact_raw.h"
#include "fit/target/heap_trim.h"
#include "fit/target/white_runs.h"
#include "opencl/compiler_pages.h"
#include "opencl/runtime.h"
#include "svgmotion/error.h"
#include "svgmotion/render_size.h"
#include "svgmotion/svg_reader.h"
#include "svgmotion/target_video.h"

namespace svgm::cli {

int bench_fit(const std::vector<std::string>& argv) {
  const Args a = parse_args("bench fit", argv, {"--target", "--iterations", "--keyframes", "--size", "--device"},
                            {"--json"});
  if (a.positional.size() != 1) throw UsageError("bench fit: expected one input SVG");
  const auto target_path = a.get("--target");
  if (!target_path) throw UsageError("bench fit: --target VIDEO is required (a video or a folder of frames)");
  FitOptions fo;
  fo.iterations = a.get_int("--iterations", fo.iterations, 1, 10000000);
  const int keyframes = a.get_int("--keyframes", 15, 2, 1000);
  const int width = a.get_int("--size", 256, 32, 4096);
  const auto t0 = std::chrono::steady_clock::now();
  const double c0 = cpu_seconds();
  const Scene as_read = read_svg_file(a.positional[0]);
  const Scene scene = split_scene(
      as_read, plan_segment_split(as_read, FitJob{}.max_segment * std::max(as_read.width, as_read.height)));
  if (scene.paths.empty()) throw Error(a.positional[0] + ": nothing to animate (no visible paths)");
  const RenderSize size = render_size(scene, width);
  TargetOptions to;
  to.keyframes = keyframes;
  // The target held as a fit's refinement holds it (fit_job.cpp's prepare_fine): `raw` compacted
  // and `rgba` packed as runs of white as the load cleans each keyframe (fit/target/white_runs.h),
  // the loss and the warm starts reading a keyframe at a time from the runs. Its floats (16 bytes
  // per pixel and keyframe: 88 MB for 21 keyframes at 512 px) are never whole; the same bits.
  WhiteRuns packed;
  const size_t frame_px = static_cast<size_t>(size.width) * size.height;
  to.rgba_sink = [&packed, frame_px](int, const float* rgba) { append_white_runs(packed, rgba, frame_px); };
  CompactRaw raw;
  TargetFrames target = load_target_compact(*target_path, size.width, size.height, to, raw);
  packed.runs.shrink_to_fit();
  packed.others.shrink_to_fit();
  trim_heap();  // the load's frames
  ClRuntime rt(a.get("--device").value_or("auto"));
  Fitter fitter(rt, scene, target, fo);
  fitter.read_targets_from([&packed, frame_px](int k, float* out) {
    unpack_white_runs_range(packed, static_cast<size_t>(k) * frame_px, frame_px, out);
  });
  // The fitter holds the distance field on the device and reads neither it nor the mask from
  // the target again, as the refinement's target drops them (5 bytes per pixel and keyframe).
  std::vector<float>().swap(target.sdf);
  std::vector<uint8_t>().swap(target.mask);
  // The OpenCL compiler's clean pages go after a first render, before any loss memory is made,
  // as a fit lets them go after its rest pose's render (opencl/compiler_pages.h): a process's
  // first kernels touch the compiler's pages again even when their binaries come from the
  // cache, and in the first step they were resident beside the loss's first buffers.
  (void)fitter.render_keyframe(0);
  release_compiler_pages();
  const auto t1 = std::chrono::steady_clock::now();
  const double c1 = cpu_seconds();
  const double setup_mb = peak_rss_mb();
  LossTerms loss;
  // The first step's kernels (the loss's and the gradient's) touch a few MB of them again.
  for (bool released = false; !fitter.done();) {
    loss = fitter.step();
    if (!released) released = true, release_compiler_pages();
  }
  const auto t2 = std::chrono::steady_clock::now();
  const double c2 = cpu_seconds();
  const double setup_s = std::chrono::duration<double>(t1 - t0).count();
  const double wall_s = std::chrono::duration<double>(t2 - t1).count();
  const double cpu_s = c2 - c1;
  const int n = fitter.iteration();
  const RasterPlan& plan = fitter.raster_plan();
  if (a.has("--json")) {
    std::printf("{\"svg\": \"%s\", \"paths\": %zu, \"lines\": %d, \"size\": [%d, %d], \"keyframes\": %d, "
                "\"iterations\": %d, \"converged\": %s, \"setup_s\": %.3f, \"wall_s\": %.3f, \"cpu_s\": %.3f, "
                "\"ms_per_iteration\": %.3f, \"cpu_ms_per_iteration\": %.3f, \"loss\": %.6g, "
                "\"peak_rss_mb\": %.1f, \"setup_peak_rss_mb\": %.1f, \"device\": \"%s\"}\n",
                a.positional[0].c_str(), scene.paths.size(), plan.n_lines, size.width, size.height, keyframes,
                n, fitter.converged() ? "true" : "false", setup_s, wall_s, cpu_s, 1e3 * wall_s / n, 1e3 * cpu_s / n, loss.total(), peak_rss_mb(),
                setup_mb, rt.info().name.c_str());
  } else {
    std::printf("%s: %zu paths, %d lines, %dx%d, %d keyframes, %d iterations%s\n", a.positional[0].c_str(),
                scene.paths.size(), plan.n_lines, size.width, size.height, keyframes, n,
                fitter.converged() ? " (the loss stopped falling)" : "");
    std::printf("  setup %.2f s (target, plan, kernels; CPU %.2f s)\n", setup_s, c1 - c0);
    std::printf("  iterations: wall %.2f s, CPU %.2f s (%.2f ms, CPU %.2f ms per iteration), final loss %.5g\n",
                wall_s, cpu_s, 1e3 * wall_s / n, 1e3 * cpu_s / n, loss.total());
    std::printf("  peak memory %.1f MB (%.1f MB after setup); device: %s\n", peak_rss_mb(), setup_mb, rt.info().name.c_str());
  }
  return 0;
}

}  // namespace svgm::cli
