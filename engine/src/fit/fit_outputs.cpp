// The outputs of a fit job (fit_run.h): the result gate's verdict, the animation files in the
// original colours (animation_export.h), preview.mp4, fit.json, and the closing message.
#include "fit/fit_run.h"
#include "fit/target/heap_trim.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "fit/output/checkpoint.h"
#include "media/preview_video.h"
#include "media/video_encoder.h"
#include "svgmotion/atomic_file.h"
#include "svgmotion/error.h"
#include "svgmotion/log.h"
#include "svgmotion/utf8_text.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

// A premultiplied float render over white, as an 8-bit image.
RgbaImage render_panel(const std::vector<float>& render, int w, int h) {
  std::vector<float> rgb(static_cast<size_t>(w) * h * 4);
  const float* src = render.data();
  for (size_t p = 0; p < static_cast<size_t>(w) * h; ++p) {
    for (int c = 0; c < 3; ++c) rgb[4 * p + c] = src[4 * p + c] + (1 - src[4 * p + 3]);
    rgb[4 * p + 3] = 1;
  }
  return rgba8_image(rgb.data(), w, h);
}

}  // namespace

CleanedFrameReader FitRun::final_cleaned_reader() const {
  if (!fine || !fine_packed) return {};
  const size_t px = static_cast<size_t>(fine_target->width) * fine_target->height;
  return [this, px](int k, float* out) { unpack_white_runs_range(fine_rgba, static_cast<size_t>(k) * px, px, out); };
}

void FitRun::write_animation() {
  activity("writing the animation");
  Fitter& final_fit = this->final_fit();
  const TargetFrames& ctarget = *coarse_target;
  const TargetFrames& final_target = this->final_target();
  iterations_done = fitter->iteration() + (keyed ? keyed->iteration() : 0) + (fine ? fine->iteration() : 0);
  final_size = fine ? render_size(scene, refine_w) : size;
  if (tty) std::fputc('\n', stderr);
  // The fit's seconds include the chroma weight's calibration before it.
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() +
            (chroma_cal ? chroma_cal->seconds : 0);

  // Outputs: the animation in the original colours, the preview, a small report.
  const auto points = final_fit.keyframe_points_canvas();
  // Only renders from here on (the last pass's losses stay readable for the report).
  coarse_fit().release_loss_memory();
  final_fit.release_loss_memory();
  timing.keyframes = final_fit.keyframes();
  const int N = std::max(2, ctarget.source_frames);
  timing.duration_s = (N - 1) / std::max(1e-6, ctarget.fps);
  for (int k = 0; k < timing.keyframes; ++k)
    timing.key_times.push_back(static_cast<double>(ctarget.source_index[static_cast<size_t>(k)]) / (N - 1));
  timing.key_times.front() = 0;
  timing.key_times.back() = 1;
  timing.loop = job.loop;
  timing.close_loop = job.loop == LoopMode::Loop && returns_to_start(ctarget);

  // The gate judges a finished fit; an interrupted one is written as it stands (resumable).
  // Each keyframe rendered as it is judged (and again for the preview below): the renders of
  // every keyframe at once were 16 bytes per pixel and keyframe, on the device and the host,
  // the fit's peak (126 MB for 30 keyframes at 512 px).
  verdict = judge_fit(final_target, &final_raw(), [&](int k) { return final_fit.render_keyframe(k); }, points,
                      final_fit.raster_plan(), fit_scene, final_size.view, gate_options, final_cleaned_reader());
  // Nothing after the gate reads the targets' cleaned frames (the preview shows the frames
  // before cleanup, compact; fit.json the targets' counts): 16 bytes per pixel and keyframe,
  // 88 MB for 21 keyframes at 512 px and 22 MB at 256, freed before the preview's encoder.
  for (TargetFrames* t : {fine_target ? &*fine_target : nullptr, &target, keyed_target ? &*keyed_target : nullptr})
    if (t) std::vector<float>().swap(t->rgba);
  rejected = !stopped && !verdict.passed;
  std::error_code ec;
  anim = out / (rejected && job.gate ? "animation.failed.svg" : "animation.svg");
  if (rejected && job.gate) fs::remove(out / "animation.svg", ec);  // never leave a stale success
  else fs::remove(out / "animation.failed.svg", ec);
  fs::remove(out / (rejected && job.gate ? "animation.json" : "animation.failed.json"), ec);
  fs::remove(out / (rejected && job.gate ? "animation.lottie" : "animation.failed.lottie"), ec);
  // The fit's result, kept in checkpoint.bin for `svgmotion export`, and written out per the
  // job's export settings (animation_export.h).
  FitResult result;
  // Paths inside the output folder are kept relative to it, so a moved run directory exports.
  auto stored_path = [&](const fs::path& p) {
    if (p.empty()) return std::string();
    const fs::path abs = fs::absolute(p).lexically_normal(), dir = fs::absolute(out).lexically_normal();
    const fs::path rel = abs.lexically_relative(dir);
    return !rel.empty() && *rel.begin() != ".." ? rel.string() : abs.string();
  };
  result.svg = stored_path(input);
  if (job.export_into) result.export_into = stored_path(*job.export_into);
  result.export_name = job.export_name;
  result.max_segment = job.max_segment;
  result.rejected = rejected && job.gate;
  result.timing = timing;
  result.fps = final_target.fps;
  result.source_frames = N;
  result.n_cp = final_fit.raster_plan().n_cp;
  result.points = points;
  if (!stopped) save_checkpoint(ckpt, key, coarse_state, &result);
  ExportSettings es;
  es.compact = job.compact;
  es.decimals = job.decimals;
  es.inbetweens = job.inbetweens;
  ExportDocument edoc;
  edoc.scene = export_scene ? *export_scene : scene;
  if (export_scene) edoc.map = map;
  edoc.into = into;
  const ExportOutcome exported = write_animation_files(
      result, es, edoc, final_fit.raster_plan(), anim,
      [&](const std::vector<double>& written_times, const std::vector<double>& frame_times) -> std::optional<PathMotion> {
        if (!job.group_transforms) return std::nullopt;
        group_motion = group_motion_export(final_fit.fit_plan(), final_fit.raster_plan(), final_fit.state().params,
                                           timing.keyframes, final_size.view, final_size.width, final_size.height,
                                           timing.key_times, frame_times, job.inbetweens, timing.close_loop, written_times);
        for (const std::string& b : group_motion->baked) log::warning("group %s", b.c_str());
        return group_motion->paths;
      });
  trim_heap();
  for (const std::string& w : exported.warnings) log::warning("%s", w.c_str());
  values_written = exported.values_written;
  if (job.compact)
    log::debug("fit: compact export: %d paths still, %d moved by a group transform (%d with a residual d); %zu keys of %zu values",
               exported.stats.still, exported.stats.transformed, exported.stats.residual, exported.stats.keys,
               exported.stats.values);
  const int active = final_fit.active_keyframes();
  const int W = final_size.width, H = final_size.height;
  // Target | fit side by side, over white, through the clips' encoder (faststart, BT.709-tagged:
  // it is for people, never read back; targets stay on write_preview_video, whose colours the
  // target reader decodes as it encodes them).
  write_video(out / "preview.mp4", active, std::max(1.0, (timing.keyframes - 1) / timing.duration_s),
              [&](int k) {
                const RgbaImage panels[2] = {raw_image(final_target, &final_raw(), k),
                                             render_panel(final_fit.render_keyframe(k), W, H)};
                RgbaImage frame{2 * W, H, std::vector<uint8_t>(static_cast<size_t>(2 * W) * H * 4, 255)};
                for (int p = 0; p < 2; ++p)
                  for (int y = 0; y < H; ++y)
                    for (int x = 0; x < W; ++x) {
                      const uint8_t* s = &panels[p].rgba[(static_cast<size_t>(y) * W + x) * 4];
                      uint8_t* d = &frame.rgba[(static_cast<size_t>(y) * 2 * W + p * W + x) * 4];
                      for (int c = 0; c < 3; ++c) d[c] = static_cast<uint8_t>((s[c] * s[3] + 255 * (255 - s[3]) + 127) / 255);
                    }
                return frame;
              },
              VideoOptions{});
}

void FitRun::write_report() {
  Fitter& final_fit = this->final_fit();
  const TargetFrames& ctarget = *coarse_target;
  const TargetFrames& final_target = this->final_target();
  const int W = final_size.width, H = final_size.height;
  const char* status = stopped ? "interrupted" : rejected ? "rejected" : "ok";
  nlohmann::json report = {{"status", status},
                           {"svg", input.string()},
                           {"target", *target_path},
                           {"animation", anim.filename().string()},
                           {"iterations", iterations_done},
                           {"converged_at", coarse_converged ? nlohmann::json(coarse_iters) : nlohmann::json()},
                           {"keyframes", final_fit.keyframes()},
                           {"key_times", timing.key_times},
                           {"duration_s", timing.duration_s},
                           {"loop", loop_mode_name(timing.loop)},
                           {"closed_loop", timing.close_loop},
                           {"values_written", values_written},
                           {"size", {W, H}},
                           {"seconds", seconds},
                           {"loss", {{"total", loss.total()}, {"image", loss.image}, {"smoothness", loss.smooth},
                                     {"g1", loss.g1}, {"containment", loss.contain}}},
                           {"keyframe_image_loss", final_fit.keyframe_losses()},
                           {"keyframe_frames", ctarget.source_index},
                           {"resumed_from", resumed_from},
                           {"rollbacks", rollback_notes},
                           {"gate", gate_json(verdict, gate_options)},
                           {"device", rt->info().name}};
  if (!map.order.empty()) report["paint_order_applied"] = true;
  // Warm starts of newly activated keyframes (a resumed fit counts only those after resuming).
  // (The keyframes added from the target count with the first fit's.)
  const auto ws = [&](int Fitter::*n) { return (*fitter).*n + (keyed ? (*keyed).*n : 0); };
  report["warm_starts"] = {{"similarity_tried", ws(&Fitter::warm_starts_tried)}, {"similarity_kept", ws(&Fitter::warm_starts_kept)},
                           {"field_tried", ws(&Fitter::field_warm_starts_tried)}, {"field_kept", ws(&Fitter::field_warm_starts_kept)},
                           {"known_motion_tried", ws(&Fitter::known_starts_tried)}, {"known_motion_kept", ws(&Fitter::known_starts_kept)}};
  report["keyframes_from_target"] = std::move(key_report);
  report["start"] = {{"pinned_to_rest", pin_rest}, {"decided", job.start_at_rest ? "option" : "target"},
                     {"first_frame_iou", rest_start.iou}, {"min_iou", kRestStartIou}};
  if (group_motion)
    report["group_transforms"] = {{"groups", final_fit.fit_plan().n_groups},
                                  {"as_transforms", group_motion->transform_groups},
                                  {"baked", group_motion->baked}};
  {
    nlohmann::json h = {{"every", kLossHistoryEvery}, {"iteration", nlohmann::json::array()},
                        {"total", nlohmann::json::array()}, {"image", nlohmann::json::array()},
                        {"active_keyframes", nlohmann::json::array()}};
    for (const LossSample& s : history) {
      h["iteration"].push_back(s.iteration);
      h["total"].push_back(std::isfinite(s.total) ? nlohmann::json(s.total) : nlohmann::json(nullptr));
      h["image"].push_back(std::isfinite(s.image) ? nlohmann::json(s.image) : nlohmann::json(nullptr));
      h["active_keyframes"].push_back(s.active);
    }
    report["loss_history"] = std::move(h);
  }
  report["target_frames"] = {{"held", ctarget.held_frames}, {"colour_corrected_keyframes", final_target.colour_corrected},
                             {"gradient_share", gradient_share}};
  // The loss's render σ (1: the paper's; more: the video was softer and its blur was matched).
  report["target_frames"]["render_blur_sigma"] = coarse_blur.render_sigma;
  if (fine) report["target_frames"]["refine_render_blur_sigma"] = fine_blur.render_sigma;
  // The chroma σ in YCbCr (= the render σ unless the video's chroma was found softer).
  report["target_frames"]["chroma_sigma"] = coarse_blur.chroma_sigma;
  if (fine) report["target_frames"]["refine_chroma_sigma"] = fine_blur.chroma_sigma;
  // Detached ink at least this share of the frame was kept as figure, not whitened as a speck.
  report["target_frames"]["kept_part_share"] = to.keep_part_share;
  // Codec noise: each keyframe averaged with this many flow-aligned neighbours either side.
  report["target_frames"]["denoise_radius"] = job.denoise_radius;
  report["target_frames"]["denoise_seconds"] = ctarget.denoise_seconds + (fine_target ? fine_target->denoise_seconds : 0.0);
  // The clip at a glance (frame_scan.h): its repeats, and the shake that decides stabilising.
  report["target_frames"]["distinct"] = scan.distinct.size();
  report["target_frames"]["cadence"] = scan.cadence;
  report["target_frames"]["poses"] = scan.poses.size();
  report["target_frames"]["frame_jitter_px"] = scan.jitter_fit_px;
  report["target_frames"]["frame_rigid_residual"] = scan.rigid_residual;
  report["target_frames"]["stabilise"] = {{"on", to.stabilise}, {"decided", job.stabilise ? "option" : "target"},
                                          {"shaking", scan.shaking}};
  if (to.stabilise) {
    report["target_frames"]["max_shake_removed_px"] = ctarget.max_shake_px;
    report["target_frames"]["shake_model"] = ctarget.shake_model;
    report["target_frames"]["still_share"] = ctarget.still_share;
    report["target_frames"]["shake_loop"] = ctarget.shake_loop;
  }
  // The chroma weight fitted with; with --chroma-weight auto, what chose it: each candidate's
  // drift from rest in the still fit of the first frame (mean squared RGB difference of the
  // render, and RMS control-point displacement in pixels of the last stage's width).
  report["chroma_weight"] = {{"chosen", chroma_weight}, {"auto", job.chroma_weight_auto}};
  // With auto: the gate's measurement (chroma σ over render σ, at the video's width), and why
  // the calibration was skipped when it was.
  if (chroma_gate) {
    report["chroma_weight"]["chroma_sigma_excess"] = chroma_gate->excess;
    report["chroma_weight"]["excess_threshold"] = chroma_gate->threshold;
    if (!chroma_gate->calibrate) report["chroma_weight"]["skipped"] = chroma_gate->reason;
  }
  if (chroma_cal) {
    nlohmann::json drift = nlohmann::json::object(), drift_px = nlohmann::json::object();
    for (const ChromaCandidate& c : chroma_cal->candidates) {
      drift[fit_fmt("%g", c.weight)] = c.drift;
      drift_px[fit_fmt("%g", c.weight)] = c.drift_px;
    }
    report["chroma_weight"]["drift"] = std::move(drift);
    report["chroma_weight"]["drift_px"] = std::move(drift_px);
    report["chroma_weight"]["calibration_seconds"] = chroma_cal->seconds;
    if (!chroma_cal->note.empty()) report["chroma_weight"]["note"] = chroma_cal->note;
  }
  if (fine)
    report["refined"] = {{"size", {W, H}},
                         {"iterations", final_fit.iteration()},
                         {"from_size", {size.width, size.height}},
                         {"kept_coarse_keyframes", refine_kept_coarse},
                         {"loss_ratio_at_coarse_width", refine_loss_ratio}};
  write_file_atomic(out / "fit.json", json_text(report, 2) + "\n");
}

int FitRun::finish() {
  if (stopped) {
    log::error("interrupted at iteration %d; wrote %s (continue with --resume)",
                 iterations_done, anim.c_str());
    return 130;
  }
  // A part that vanishes (a shape folded edge-on) is not a broken fit, but the user should
  // look at those keyframes: said even with --quiet, as every warning is.
  for (const std::string& w : verdict.warnings) log::warning("fit: %s", w.c_str());
  if (rejected) {
    std::string why = verdict.reasons.front();
    if (verdict.reasons.size() > 1) why += " (and " + std::to_string(verdict.reasons.size() - 1) + " more in fit.json)";
    if (job.gate)
      throw Rejected("the fit was rejected: " + why + "; wrote " + anim.string() + " for inspection, no animation.svg",
                     Rejected::kFitRejected);
    log::warning("the result gate would reject this fit: %s", why.c_str());
  }
  if (!job.quiet)
    log::info("svgmotion: fitted %d keyframes in %.1fs; wrote %s, animation.json, preview.mp4, fit.json",
                 final_fit().keyframes(), seconds, anim.c_str());
  return 0;
}

}  // namespace svgm
