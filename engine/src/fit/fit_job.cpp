// One fit from files to files (see fit_job.h).
#include "fit/fit_job.h"
#include "svgmotion/atomic_file.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "fit/checkpoint.h"
#include "fit/palette.h"
#include "fit/preview_video.h"
#include "fit/smil_writer.h"
#include "svgmotion/error.h"
#include "svgmotion/svg_reader.h"
#include "svgmotion/target_video.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

constexpr int kCheckpointEvery = 250;  // iterations between checkpoints

// Premultiplied float renders over white, as 8-bit images.
RgbaImage render_panel(const std::vector<float>& renders, int k, int w, int h) {
  std::vector<float> rgb(static_cast<size_t>(w) * h * 4);
  const float* src = &renders[static_cast<size_t>(k) * w * h * 4];
  for (size_t p = 0; p < static_cast<size_t>(w) * h; ++p) {
    for (int c = 0; c < 3; ++c) rgb[4 * p + c] = src[4 * p + c] + (1 - src[4 * p + 3]);
    rgb[4 * p + 3] = 1;
  }
  return rgba8_image(rgb.data(), w, h);
}

}  // namespace

int run_fit_job(const FitJob& job, const std::function<bool()>& interrupted) {
  const fs::path& input = job.svg;
  const fs::path& out = job.out;
  const FitOptions& fo = job.options;
  const int keyframes = job.keyframes;
  const std::string target_str = job.target.string();
  const std::string* target_path = &target_str;
  const Scene scene = read_svg_file(input);
  for (const auto& w : scene.warnings) std::fprintf(stderr, "svgmotion: warning: %s\n", w.c_str());
  if (scene.paths.empty()) throw Error(input.string() + ": nothing to animate (no visible paths)");
  const Scene fit_scene =
      job.palette ? apply_palette(scene, read_palette(*job.palette), job.palette->string()) : scene;
  const RenderSize size = render_size(scene, job.width);
  TargetOptions to;
  to.keyframes = keyframes;
  to.white_threshold = job.mask_threshold;
  if (!(to.white_threshold > 0 && to.white_threshold <= 1))
    throw Error("the mask threshold must be in (0, 1]");
  const TargetFrames target = load_target(*target_path, size.width, size.height, to);

  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) throw Error(out.string() + ": cannot create: " + ec.message());
  ClRuntime rt(job.device);
  Fitter fitter(rt, fit_scene, target, fo);
  if (job.tracks) {
    auto flows = read_tracks(*job.tracks);
    if (flows.size() == static_cast<size_t>(target.keyframes)) fitter.set_flows(std::move(flows));
    else if (!flows.empty())
      std::fprintf(stderr, "svgmotion: warning: %s has flows for %zu keyframes, not %d; tracking the fit instead\n",
                   job.tracks->c_str(), flows.size(), target.keyframes);
  }
  const fs::path ckpt = out / "checkpoint.bin";
  const std::string key = input.string() + "|" + std::to_string(fs::file_size(input)) + "|" +
                          *target_path + "|" + std::to_string(keyframes) + "|" +
                          std::to_string(size.width) + "x" + std::to_string(size.height);
  if (job.resume) {
    if (!fs::exists(ckpt)) throw Error(ckpt.string() + ": no checkpoint to resume from");
    fitter.restore(load_checkpoint(ckpt, key));
    std::fprintf(stderr, "svgmotion: resuming at iteration %d\n", fitter.iteration());
  }

  const bool tty = ::isatty(2) && !job.quiet;
  const auto t0 = std::chrono::steady_clock::now();
  const int start = fitter.iteration();
  auto last_print = t0;
  LossTerms loss;
  bool stopped = false;
  while (!fitter.done() && !(stopped = interrupted())) {
    loss = fitter.step();
    const int it = fitter.iteration();
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - t0).count();
    const double eta = elapsed / std::max(1, it - start) * (fo.iterations - it);
    if (tty && (now - last_print > std::chrono::milliseconds(200) || fitter.done())) {
      std::fprintf(stderr, "\rfit: iteration %d/%d  loss %.5f  keyframes %d/%d  %.0fs, ETA %.0fs   ",
                   it, fo.iterations, loss.total(), fitter.active_keyframes(), fitter.keyframes(),
                   elapsed, eta);
      last_print = now;
    } else if (!tty && !job.quiet && (it % 100 == 0 || fitter.done())) {
      std::fprintf(stderr, "fit: iteration %d/%d loss %.5f keyframes %d/%d elapsed %.1fs eta %.0fs\n",
                   it, fo.iterations, loss.total(), fitter.active_keyframes(), fitter.keyframes(),
                   elapsed, eta);
    }
    if (it % kCheckpointEvery == 0) save_checkpoint(ckpt, key, fitter.state());
  }
  if (tty) std::fputc('\n', stderr);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  save_checkpoint(ckpt, key, fitter.state());

  // Outputs: the animation in the original colours, the preview, a small report.
  const auto points = fitter.keyframe_points_canvas();
  AnimationTiming timing;
  timing.keyframes = fitter.keyframes();
  timing.duration_s = target.source_frames / std::max(1e-6, target.fps);
  const fs::path into = job.export_into.value_or(input);
  const Scene export_scene = job.export_into ? read_svg_file(into) : scene;
  if (export_scene.paths.size() != scene.paths.size())
    throw Error(into.string() + ": does not hold the fitted SVG's paths");
  for (const auto& w : write_animation_svg(into, export_scene, fitter.raster_plan(), points, timing, out / "animation.svg"))
    std::fprintf(stderr, "svgmotion: warning: %s\n", w.c_str());
  const auto renders = fitter.render_keyframes();
  const int active = fitter.active_keyframes();
  const int W = size.width, H = size.height;
  write_preview_video(out / "preview.mp4", active, 2,
                      [&](int k, int panel) {
                        return panel == 0 ? rgba8_image(&target.raw[static_cast<size_t>(k) * W * H * 4], W, H)
                                          : render_panel(renders, k, W, H);
                      },
                      std::max(1.0, (timing.keyframes - 1) / timing.duration_s));
  nlohmann::json report = {{"svg", input.string()},
                           {"target", *target_path},
                           {"iterations", fitter.iteration()},
                           {"keyframes", fitter.keyframes()},
                           {"size", {W, H}},
                           {"seconds", seconds},
                           {"loss", {{"total", loss.total()}, {"image", loss.image}, {"smoothness", loss.smooth},
                                     {"g1", loss.g1}, {"containment", loss.contain}}},
                           {"keyframe_image_loss", fitter.keyframe_losses()},
                           {"device", rt.info().name}};
  write_file_atomic(out / "fit.json", report.dump(2) + "\n");
  if (stopped) {
    std::fprintf(stderr, "svgmotion: interrupted at iteration %d; wrote %s (continue with --resume)\n",
                 fitter.iteration(), (out / "animation.svg").c_str());
    return 130;
  }
  std::fprintf(stderr, "svgmotion: fitted %d keyframes in %.1fs; wrote %s, preview.mp4, fit.json\n",
               fitter.keyframes(), seconds, (out / "animation.svg").c_str());
  return 0;
}

}  // namespace svgm
