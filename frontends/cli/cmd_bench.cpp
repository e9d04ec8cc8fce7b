// `svgmotion bench render|raster`: speed of the OpenCL renderer and of one differentiable
// iteration (forward + loss + backward) against librsvg's render of the same frames, peak
// memory, device; `bench raster --scaling` sweeps
// paths, size and frames on procedural scenes to show how the cost grows. `bench fit` and
// `bench target` (their own files) time a whole fit and the loading of a target.
//
// Each measurement times whole batches of K frames with the device finished, over several
// repetitions after a warm-up that includes kernel compilation (excluded), and reports medians.
// Uploads of control points and targets are excluded: in fitting they live on the device.
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>

#include "cli/bench_fit.h"
#include "cli/bench_librsvg.h"
#include "cli/bench_target.h"
#include "cli/bench_util.h"
#include "cli/cli_args.h"
#include "cli/commands.h"
#include "opencl/runtime.h"
#include "raster/raster_cl.h"
#include "raster/raster_plan.h"
#include "scene/synthetic_scene.h"
#include "svgmotion/error.h"
#include "svgmotion/log.h"
#include "svgmotion/render_size.h"
#include "svgmotion/svg_reader.h"

namespace svgm::cli {

namespace {

int bench_render(const std::vector<std::string>& argv) {
  const Args a = parse_args("bench render", argv, {"--frames", "--size", "--device", "--repeat"},
                            {"--json", "--profile"});
  if (a.positional.size() != 1) throw UsageError("bench render: expected one input SVG");
  const int frames = a.get_int("--frames", 15, 1, 1000);
  const int width = a.get_int("--size", 256, 1, 16384);
  const int repeat = a.get_int("--repeat", 15, 1, 100000);
  const Scene scene = read_svg_file(a.positional[0]);
  const RenderSize size = render_size(scene, width);
  const RasterPlan plan = plan_raster(scene, size.view, size.width, size.height);
  ClRuntime rt(a.get("--device").value_or("auto"), a.has("--profile"));
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
  if (a.has("--profile"))  // device time of each kernel in the last batch
    for (const auto& [name, t] : raster.kernel_times()) std::fprintf(stderr, "  %-14s %.3f ms\n", name.c_str(), t);
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

struct IterationTimes {
  double forward_ms = 0, total_ms = 0;  // medians per iteration (all K frames)
  // Median CPU time of the process (every thread: PoCL's workers and the host) over the
  // iteration's span. On a machine shared with other jobs the wall time swings with their load
  // (2-3x on the 2-core machine with five agents), the CPU time much less: it tells the
  // iteration's work from its waiting for cores.
  double cpu_ms = 0;
  int lines = 0;
};

// Median forward-only and forward+loss+backward times of one iteration over K frames. The
// frames are the rest pose moved by (1.3, -0.7) px and the target is the rest pose, so the loss
// and its gradient are not trivially zero.
IterationTimes time_iteration(ClRuntime& rt, const Scene& scene, int width, int frames,
                              int repeat) {
  const RenderSize size = render_size(scene, width);
  const RasterPlan plan = plan_raster(scene, size.view, size.width, size.height);
  ClRaster r(rt, plan, frames);
  const std::array<float, 4> white{1, 1, 1, 1};
  r.set_rest_pose();
  r.forward(ClRaster::Output::Float, white);
  const auto rest = r.read_image();
  std::vector<float> target(rest.size());
  for (size_t i = 0; i < rest.size(); i += 4) {
    for (int c = 0; c < 3; ++c) target[i + c] = rest[i + c] + (1.0f - rest[i + 3]);
    target[i + 3] = 1.0f;
  }
  r.set_targets(target);
  std::vector<float> cp;
  for (int k = 0; k < frames; ++k)
    for (size_t i = 0; i < plan.rest_cp.size(); i += 2) {
      cp.push_back(plan.rest_cp[i] + 1.3f);
      cp.push_back(plan.rest_cp[i + 1] - 0.7f);
    }
  r.set_control_points(cp);
  r.loss_and_gradient(1000.0f, white);  // warm-up
  std::vector<double> fwd, tot, cpu;
  for (int i = 0; i < repeat; ++i) {
    auto t0 = std::chrono::steady_clock::now();
    r.forward(ClRaster::Output::Float, white);
    r.finish();
    fwd.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    t0 = std::chrono::steady_clock::now();
    const double c0 = cpu_seconds();
    r.loss_and_gradient(1000.0f, white);  // returns after reading the loss: the device is done
    tot.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    cpu.push_back((cpu_seconds() - c0) * 1e3);
  }
  if (r.tape_overflow()) log::warning("backward tape overflowed");
  if (rt.profiling())  // device time of each kernel in the last iteration
    for (const auto& [name, t] : r.kernel_times()) std::fprintf(stderr, "  %-18s %.3f ms\n", name.c_str(), t);
  return {median(fwd), median(tot), median(cpu), plan.n_lines};
}

// One scene of `bench raster`: its iteration timed, librsvg's render of the same frames, the
// lines (or one JSON object on one line). Returns iteration / librsvg, in wall time and in CPU
// time, when librsvg is there.
struct Ratios {
  double wall = 0, cpu = 0;
};

std::optional<Ratios> bench_raster_scene(const Args& a, ClRuntime& rt, const std::string& svg,
                                         int width, int frames, int repeat) {
  const Scene scene = read_svg_file(svg);
  const IterationTimes t = time_iteration(rt, scene, width, frames, repeat);
  // The bar (issue 38): one iteration no longer than librsvg's plain render of the same frames.
  const std::optional<LibrsvgTimes> rsvg_t = librsvg_ms_per_frame(svg, width, frames, 5);
  if (a.has("--json")) {
    const std::string rsvg_ms = rsvg_t ? std::to_string(rsvg_t->ms_per_frame * frames) : "null";
    const std::string rsvg_cpu = rsvg_t ? std::to_string(rsvg_t->cpu_ms_per_frame * frames) : "null";
    std::printf("{\"svg\": \"%s\", \"frames\": %d, \"size\": %d, \"lines\": %d, "
                "\"forward_ms\": %.4f, \"backward_ms\": %.4f, \"total_ms\": %.4f, "
                "\"total_ms_per_frame\": %.4f, \"total_cpu_ms\": %.4f, \"librsvg_ms\": %s, "
                "\"librsvg_cpu_ms\": %s, \"peak_rss_mb\": %.1f, \"device\": \"%s\"}\n",
                svg.c_str(), frames, width, t.lines, t.forward_ms,
                t.total_ms - t.forward_ms, t.total_ms, t.total_ms / frames, t.cpu_ms, rsvg_ms.c_str(),
                rsvg_cpu.c_str(), peak_rss_mb(), rt.info().name.c_str());
  } else {
    std::printf("%s: %d frames at %d px, %d lines\n", svg.c_str(), frames, width, t.lines);
    std::printf("  per iteration: forward %.3f ms, backward (loss + gradients) %.3f ms, total %.3f ms\n",
                t.forward_ms, t.total_ms - t.forward_ms, t.total_ms);
    std::printf("  per frame: forward %.3f ms, total %.3f ms; peak memory %.1f MB\n",
                t.forward_ms / frames, t.total_ms / frames, peak_rss_mb());
    if (rsvg_t) {
      const double rsvg = rsvg_t->ms_per_frame;
      std::printf("  librsvg renders the same %d frames in %.3f ms (%.3f ms per frame): iteration / librsvg %.2fx\n",
                  frames, rsvg * frames, rsvg, t.total_ms / (rsvg * frames));
      std::printf("  CPU time (every thread): iteration %.3f ms, librsvg %.3f ms: %.2fx\n", t.cpu_ms,
                  rsvg_t->cpu_ms_per_frame * frames, t.cpu_ms / (rsvg_t->cpu_ms_per_frame * frames));
    } else
      std::printf("  librsvg: not available (librsvg2-2 and libcairo2 give the comparison)\n");
    std::printf("  device: %s\n", rt.info().name.c_str());
  }
  std::fflush(stdout);
  if (!rsvg_t) return std::nullopt;
  return Ratios{t.total_ms / (rsvg_t->ms_per_frame * frames), t.cpu_ms / (rsvg_t->cpu_ms_per_frame * frames)};
}

int bench_raster(const std::vector<std::string>& argv) {
  const Args a = parse_args("bench raster", argv, {"--frames", "--size", "--device", "--repeat"},
                            {"--json", "--scaling", "--profile"});
  const int frames = a.get_int("--frames", 15, 1, 1000);
  const int width = a.get_int("--size", 256, 1, 16384);
  const int repeat = a.get_int("--repeat", 9, 1, 100000);
  ClRuntime rt(a.get("--device").value_or("auto"), a.has("--profile"));
  if (a.has("--scaling")) {
    // One parameter varies at a time around (100 paths, 256 px, 15 frames).
    struct Row { const char* what; int paths, size, frames; };
    std::vector<Row> rows;
    for (int n : {10, 30, 100, 300, 1000}) rows.push_back({"paths", n, 256, 15});
    for (int sz : {128, 256, 512, 1024}) rows.push_back({"size", 100, sz, 15});
    for (int k : {1, 5, 15, 30}) rows.push_back({"frames", 100, 256, k});
    if (!a.has("--json"))
      std::printf("%-7s %6s %5s %6s %7s | %10s %11s %9s %12s %14s\n", "sweep", "paths", "size",
                  "frames", "lines", "forward_ms", "backward_ms", "total_ms", "ms_per_frame",
                  "ns_per_px_path");
    for (const Row& row : rows) {
      const Scene scene = synthetic_blobs(row.paths, row.size, 7);
      const IterationTimes t = time_iteration(rt, scene, row.size, row.frames, std::max(3, repeat / 3));
      const double per_unit = t.total_ms * 1e6 / (double(row.frames) * row.size * row.size * row.paths);
      if (a.has("--json"))
        std::printf("{\"sweep\": \"%s\", \"paths\": %d, \"size\": %d, \"frames\": %d, "
                    "\"lines\": %d, \"forward_ms\": %.3f, \"backward_ms\": %.3f, "
                    "\"total_ms\": %.3f}\n",
                    row.what, row.paths, row.size, row.frames, t.lines, t.forward_ms,
                    t.total_ms - t.forward_ms, t.total_ms);
      else
        std::printf("%-7s %6d %5d %6d %7d | %10.2f %11.2f %9.2f %12.3f %14.4f\n", row.what,
                    row.paths, row.size, row.frames, t.lines, t.forward_ms,
                    t.total_ms - t.forward_ms, t.total_ms, t.total_ms / row.frames, per_unit);
      std::fflush(stdout);
    }
    if (!a.has("--json"))
      std::printf("device: %s, peak memory %.1f MB\n", rt.info().name.c_str(), peak_rss_mb());
    return 0;
  }
  if (a.positional.empty()) throw UsageError("bench raster: expected one or more input SVGs (or --scaling)");
  // Several scenes are timed one after the other in the same run (issue 38's acceptance: two
  // scenes against librsvg, under the same machine load), each with its own lines or JSON
  // object; one input prints exactly what it always has.
  std::vector<double> ratios, cpu_ratios;
  for (const std::string& svg : a.positional) {
    const std::optional<Ratios> ratio = bench_raster_scene(a, rt, svg, width, frames, repeat);
    if (!ratio) continue;
    ratios.push_back(ratio->wall);
    cpu_ratios.push_back(ratio->cpu);
  }
  if (a.positional.size() > 1 && !a.has("--json") && !ratios.empty()) {
    std::printf("%zu scenes: iteration / librsvg", a.positional.size());
    for (size_t i = 0; i < ratios.size(); ++i) std::printf("%s %.2fx", i ? "," : "", ratios[i]);
    std::printf(" (max %.2fx); in CPU time", *std::max_element(ratios.begin(), ratios.end()));
    for (size_t i = 0; i < cpu_ratios.size(); ++i) std::printf("%s %.2fx", i ? "," : "", cpu_ratios[i]);
    std::printf(" (max %.2fx)\n", *std::max_element(cpu_ratios.begin(), cpu_ratios.end()));
  }
  return 0;
}

}  // namespace

int cmd_bench(const std::vector<std::string>& argv) {
  if (argv.empty()) throw Error("bench: which benchmark? (svgmotion bench render IN.svg ...)");
  const std::vector<std::string> rest(argv.begin() + 1, argv.end());
  if (argv[0] == "render") return bench_render(rest);
  if (argv[0] == "raster") return bench_raster(rest);
  if (argv[0] == "fit") return bench_fit(rest);
  if (argv[0] == "target") return bench_target(rest);
  throw Error("bench: unknown benchmark '" + argv[0] + "' (available: render, raster, fit, target)");
}

}  // namespace svgm::cli
