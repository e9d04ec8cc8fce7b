// One fit from files to files (see fit_job.h).
#include "fit/fit_job.h"
#include "fit/fit_progress.h"
#include "svgmotion/atomic_file.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "export/lottie_writer.h"
#include "fit/output/animation_export.h"
#include "fit/target/blur_match.h"
#include "fit/output/checkpoint.h"
#include "fit/target/chroma_calibration.h"
#include "fit/target/correction_palette.h"
#include "svg/document_order.h"
#include "export/group_transform.h"
#include "fit/optimise/inbetween.h"
#include "fit/optimise/keyframe_choice.h"
#include "fit/plan/motion_groups.h"
#include "fit/target/rest_start.h"
#include "fit/output/result_gate.h"
#include "color/palette_json.h"
#include "media/preview_video.h"
#include "fit/plan/segment_split.h"
#include "export/smil_writer.h"
#include "run/run_directory.h"
#include "raster/render_image.h"
#include "svgmotion/error.h"
#include "svgmotion/log.h"
#include "svgmotion/svg_reader.h"
#include "svgmotion/target_video.h"
#include "svgmotion/utf8_text.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

// The refinement's guard: a keyframe whose refined fit matches the video this many times worse
// at the coarse width than its coarse fit did keeps the coarse fit. Refined keyframes that are
// fine score 0.98-1.17 times the coarse loss there (the coarse loss does not reward detail
// finer than its pixels); a small shape the refinement lost scores 21-24 times (snail).
constexpr float kRefineGuard = 1.5f;
// The joint fit after keyframes were added from the target: at most this share of the
// iteration budget (it usually ends earlier, at the plateau test).
constexpr double kKeyedShare = 0.25;
constexpr int kCheckpointEvery = 250;  // iterations between checkpoints
// The loss is sampled for fit.json's loss_history every this many iterations: 200 samples for
// the default 2000 iterations, a few kB of JSON, enough for the report's chart.
constexpr int kLossHistoryEvery = 10;

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

// Does the target end where it began? The last keyframe against the first, compared with
// the typical change from one keyframe to the next: a quarter of it or less is "the same pose".
bool returns_to_start(const TargetFrames& t) {
  const int K = t.keyframes;
  if (K < 3 || t.source_index.front() != 0 || t.source_index.back() != t.source_frames - 1) return false;
  const size_t n = static_cast<size_t>(t.width) * t.height * 4;
  auto diff = [&](int a, int b) {
    double d = 0;
    for (size_t i = 0; i < n; ++i) d += std::fabs(t.rgba[a * n + i] - t.rgba[b * n + i]);
    return d / n;
  };
  double step = 0;
  for (int k = 1; k < K; ++k) step += diff(k - 1, k);
  step /= K - 1;
  return diff(0, K - 1) <= 0.25 * step;
}

std::string fmt(const char* f, double a, double b = 0, double c = 0, double d = 0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, f, a, b, c, d);
  return buf;
}

// What a user should hear about a target before minutes of fitting: frames stretched to
// another aspect, frames smaller than the fit, keyframes showing no figure or only figure.
std::vector<std::string> target_warnings(const TargetFrames& t, const std::string& name, const RenderSize& size) {
  std::vector<std::string> out;
  if (t.source_width > 0 && t.source_height > 0) {
    const double a = static_cast<double>(t.source_width) / t.source_height;
    const double b = static_cast<double>(size.width) / size.height;
    if (std::fabs(std::log(a / b)) > std::log(1.1))
      out.push_back(name + ": frames are " + std::to_string(t.source_width) + "x" + std::to_string(t.source_height) +
                    fmt(" (aspect %.2f), the SVG's aspect is %.2f: the frames are stretched to fit", a, b));
    if (t.source_width < size.width / 2 || t.source_height < size.height / 2)
      out.push_back(name + ": frames are " + std::to_string(t.source_width) + "x" + std::to_string(t.source_height) +
                    ", far smaller than the fitting size " + std::to_string(size.width) + "x" + std::to_string(size.height));
  }
  const size_t px = static_cast<size_t>(t.width) * t.height;
  int empty = 0, full = 0;
  for (int k = 0; k < t.keyframes; ++k) {
    size_t fg = 0;
    for (size_t i = 0; i < px; ++i) fg += t.mask[static_cast<size_t>(k) * px + i];
    empty += fg < px / 1000 + 1;
    full += fg > px * 98 / 100;
  }
  if (empty)
    out.push_back(name + ": " + std::to_string(empty) + " of " + std::to_string(t.keyframes) +
                  " keyframes show no figure (all background): the drawing has nothing to follow there");
  if (full)
    out.push_back(name + ": " + std::to_string(full) + " of " + std::to_string(t.keyframes) +
                  " keyframes are all figure (no background seen; try --mask-threshold)");
  return out;
}

// The fit's groups as the checkpoint's key names them: the fit group of every path (of its
// first control point), so a checkpoint made under another grouping (another version's rules)
// is not resumed into this one.
std::string group_membership(const FitPlan& f, const RasterPlan& plan) {
  std::string out;
  for (size_t p = 0; p < plan.path_cp_first.size(); ++p)
    out += std::to_string(plan.path_cp_count[p] > 0 ? f.cp_group[static_cast<size_t>(plan.path_cp_first[p])] : -1) + ",";
  return out;
}

}  // namespace

int run_fit_job(const FitJob& job, const std::function<bool()>& interrupted) {
  const fs::path& input = job.svg;
  const fs::path& out = job.out;
  const FitOptions& fo = job.options;
  const int keyframes = job.keyframes;
  const std::string target_str = job.target.string();
  const std::string* target_path = &target_str;
  const Scene as_read = read_svg_file(input);
  for (const auto& w : as_read.warnings) log::warning("%s", w.c_str());
  if (as_read.paths.empty()) throw Error(input.string() + ": nothing to animate (no visible paths)");
  if (!(job.max_segment >= 0 && job.max_segment <= 1)) throw Error("the longest segment must be 0..1 of the canvas");
  // Long segments split (exactly) so the motion can bend them; the same split is applied to
  // the document written into, so the written paths have the fitted structure.
  const SplitPlan split =
      plan_segment_split(as_read, job.max_segment * std::max(as_read.width, as_read.height));
  const Scene scene = split_scene(as_read, split);
  if (const int added = added_points(split))
    log::debug("fit: %d control points added by splitting long segments", added);
  std::vector<std::string> held_groups;
  KnownMotion known;
  Scene palette_scene =
      job.palette ? apply_palette(scene, read_palette(*job.palette), job.palette->string()) : scene;
  // A procedural target's groups split where its motion moves them apart (motion_groups.h); not
  // when group transforms are exported (a document group has one transform).
  if (job.motion && !job.group_transforms) {
    std::ifstream in(*job.motion);
    const nlohmann::json motion = nlohmann::json::parse(in, nullptr, false);
    std::vector<std::string> notes;
    if (!motion.is_discarded()) {
      palette_scene = split_groups_by_motion(palette_scene, motion, &notes);
      palette_scene = merge_groups_by_body(palette_scene, motion, &notes);
      held_groups = still_groups(palette_scene, motion);
      known = known_motion(palette_scene, motion, job.motion_candidate);
    }
    if (!known.body.empty())
      log::debug("fit: the target's own motion: %zu rigid bodies warm-start the keyframes", known.maps.size());
    for (const std::string& n : notes) log::info("fit: group %s", n.c_str());
    if (!held_groups.empty()) log::info("fit: %zu groups the target holds still are held at rest", held_groups.size());
  }
  const Scene fit_scene = std::move(palette_scene);
  const RenderSize size = render_size(scene, job.width);
  TargetOptions to;
  to.keyframes = keyframes;
  to.white_threshold = job.mask_threshold;
  to.stabilise = job.stabilise;
  to.denoise_radius = job.denoise_radius;
  // The refinement's load reuses these keyframes when it works at the same size (a 512-px video
  // fitted at 256 and refined at 512 denoises at 512 both times); released once it has.
  to.keep_denoised = job.denoise_radius > 0 && job.refine_width != 0;
  ClRuntime rt(job.device);
  // The colours the target should show: the fitted scene's opaque flat fills and strokes; none
  // (no correction) when gradients cover much of the drawing (fit/target/correction_palette.h).
  double gradient_share = 0;
  if (job.colour_correction) {
    CorrectionPalette cp = correction_palette(rt, fit_scene, size.width);
    gradient_share = cp.gradient_share;
    if (cp.gradient_share > 0)
      log::debug("fit: gradient paint covers %.1f%% of the canvas: %s", 100 * cp.gradient_share,
                 cp.usable ? "colours corrected" : "too much for colour correction, the video's colours are compared as they are");
    if (cp.usable) to.palette = std::move(cp.colours);
  }
  if (!(to.white_threshold > 0 && to.white_threshold <= 1))
    throw Error("the mask threshold must be in (0, 1]");
  // The document written into, and how the fitted paths map onto it, checked before fitting.
  const fs::path into = job.export_into.value_or(input);
  std::optional<Scene> export_scene;
  ExportMap map;
  if (job.export_into) {
    export_scene = read_svg_file(into);
    const std::vector<int> match = match_paths(as_read, *export_scene, input.string());
    map.fitted_of.assign(export_scene->paths.size(), -1);
    bool reordered = false;
    for (size_t j = 0; j < match.size(); ++j) {
      map.fitted_of[static_cast<size_t>(match[j])] = static_cast<int>(j);
      reordered = reordered || match[j] != static_cast<int>(j);
    }
    if (reordered) map.order = match;
    for (size_t i = 0; i < export_scene->paths.size(); ++i)
      if (map.fitted_of[i] >= 0)
        export_scene->paths[i] = split_path(export_scene->paths[i], split[static_cast<size_t>(map.fitted_of[i])]);
  }
  // A detached part as large as half the drawing's smallest is never taken for a speck
  // (TargetOptions::keep_part_share): the share is the same at every width the fit loads.
  RgbaImage rest_render = render_image(rt, fit_scene, size.width, false);
  to.keep_part_share = 0.5 * smallest_part_share(rest_render.rgba, rest_render.width, rest_render.height, to.white_threshold);
  TargetFrames target = load_target(*target_path, size.width, size.height, to);
  // Keyframe 0 is the drawing at rest when the video starts there (rest_start.h), or when told.
  const RestStart rest_start = judge_rest_start(rest_render, target, to.white_threshold, to.dilate_px);
  rest_render = RgbaImage{};
  const bool pin_rest = job.start_at_rest.value_or(rest_start.at_rest);
  if (!job.quiet && !job.progress && !job.start_at_rest && !pin_rest)
    log::info("fit: the video's first frame is not the drawing at rest (foreground IoU %.3f < %.2f): keyframe 0 is fitted "
              "too, not pinned to the rest pose", rest_start.iou, kRestStartIou);
  else
    log::debug("fit: keyframe 0 %s (first frame against the rest pose: foreground IoU %.3f%s)",
               pin_rest ? "is the rest pose" : "is fitted", rest_start.iou, job.start_at_rest ? ", as told" : "");
  // The keyframes chosen from the target, when frames were added (keyframe_choice.h).
  std::optional<TargetFrames> keyed_target;
  auto release_denoised = [&target, &keyed_target] {
    for (TargetFrames* t : {&target, keyed_target ? &*keyed_target : nullptr}) {
      if (!t) continue;
      std::vector<float>().swap(t->denoised);
      t->denoised_frame.clear();
    }
  };
  for (const std::string& w : target_warnings(target, *target_path, size))
    log::warning("%s", w.c_str());
  // Which prior told the shake from the motion matters to the user: a figure with nothing
  // still keeps the part of the shake inside its motion's band, about 0.45 of 1.6 px rms (fit/target/stabilise.h).
  if (job.stabilise && !job.quiet && !job.progress) {
    if (target.shake_model == "smooth")
      log::info("fit: camera shake of up to %.2f px (fitting width) removed (nothing in the figure holds still: told from the motion by its "
                "smoothness alone, some of it stays)", target.max_shake_px);
    else
      log::info("fit: camera shake of up to %.2f px (fitting width) removed (read off the part that holds still, %.0f%% of the edges%s)",
                target.max_shake_px, 100 * target.still_share,
                target.shake_model == "still_smooth" ? "; its own slow course is kept" : "");
  }

  std::error_code ec;
  std::optional<RunLock> lock;
  if (job.claim_out) lock.emplace(out, job.force, fit_output_names());
  fs::create_directories(out, ec);
  if (ec) throw Error(out.string() + ": cannot create: " + ec.message());
  // Refuse an unwritable folder or a non-file output now, not after minutes of fitting.
  if (::access(out.c_str(), W_OK | X_OK) != 0)
    throw Error(out.string() + ": cannot write (" + (errno == EROFS ? "read-only file system" : "permission denied") + ")");
  for (const char* f : {"animation.svg", "animation.failed.svg", "animation.json", "animation.failed.json",
                        "animation.lottie", "animation.failed.lottie", "preview.mp4", "fit.json", "checkpoint.bin"})
    output_target(out / f);
  // Coarse-to-fine: which width the refinement after the coarse fit runs at, if any.
  int refine_w = job.refine_width;
  if (refine_w < 0)
    refine_w = target.source_width * 2 >= size.width * 3 ? std::min(2 * size.width, target.source_width) : 0;
  if (refine_w > 0 && refine_w <= size.width) refine_w = 0;
  const int refine_iters =
      refine_w > 0 ? std::max(0, static_cast<int>(std::lround(job.refine_share * fo.iterations))) : 0;
  if (refine_iters == 0) refine_w = 0;
  if (refine_w == 0) release_denoised();
  FitOptions coarse_options = fo;
  coarse_options.pin_rest_keyframe = pin_rest;
  coarse_options.held_groups = held_groups;
  coarse_options.known_body = known.body;
  coarse_options.known_maps = known.maps;
  // The coarse stage's iterations: the budget, or fewer when its loss stops falling
  // (FitOptions::plateau_window; set when the stage ends).
  int coarse_iters = fo.iterations;
  int total_iters = coarse_iters + refine_iters;
  // Progress and ETA count work, not iterations: a refinement iteration costs about as many
  // coarse ones as it has times the pixels.
  const double fine_cost = refine_w > 0 ? static_cast<double>(refine_w) * refine_w / (size.width * size.width) : 1;
  auto work = [&](int it) { return std::min(it, coarse_iters) + std::max(0, it - coarse_iters) * fine_cost; };
  double total_work = work(total_iters);
  // Blur matching at each width the fit runs at: the render σ of the loss that makes our
  // rest pose look like the video's first frame (fit/target/blur_match.h).
  auto match_blur = [&](const TargetFrames& t, const RenderSize& at) {
    if (!job.blur_matching) return BlurMatch{};
    const BlurMatch m = match_render_blur(render_image(rt, fit_scene, at.width, false), t.rgba);
    log::debug("fit: blur matching at %dx%d: best render sigma %.2f (residual x%.3f, rest pose %.1f dB)%s; "
               "best chroma sigma %.2f with luma %.2f (residual x%.3f)%s; render sigma %.2f, chroma %.2f", at.width,
               at.height, m.best_sigma, m.residual_ratio, m.rest_psnr_db, m.best_sigma == m.render_sigma ? ", adopted" : "",
               m.best_chroma_sigma, m.chroma_luma_sigma, m.chroma_residual_ratio,
               m.chroma_sigma != m.render_sigma ? ", adopted" : ", not adopted", m.render_sigma, m.chroma_sigma);
    return m;
  };
  const BlurMatch coarse_blur = match_blur(target, size);
  coarse_options.render_blur_sigma = coarse_blur.render_sigma;
  coarse_options.chroma_blur_sigma = coarse_blur.chroma_sigma;
  // The refinement's target and options (its chroma weight is set below), made on first use:
  // before the coarse fit when the chroma weight's calibration mirrors the refinement too.
  std::optional<TargetFrames> fine_target;
  BlurMatch fine_blur;
  FitOptions fine_options;
  // The coarse stage's target: the first load, or the keyframes chosen from the target.
  const TargetFrames* coarse_target = &target;
  auto prepare_fine = [&] {
    if (fine_target) return;
    const RenderSize fine_size = render_size(scene, refine_w);
    TargetOptions fine_to = to;
    if (coarse_target != &target) fine_to.frames = coarse_target->source_index;
    if (to.stabilise) fine_to.shake_from = coarse_target;  // the camera path of the first load
    fine_to.keep_denoised = false;
    fine_to.denoised_from = coarse_target;
    TargetFrames t = load_target(*target_path, fine_size.width, fine_size.height, fine_to);
    release_denoised();
    fine_options = fo.refined_at(static_cast<double>(fine_size.width) / size.width);
    fine_options.pin_rest_keyframe = pin_rest;
    fine_options.held_groups = held_groups;
    fine_options.known_body = known.body;
    fine_options.known_maps = known.maps;
    fine_options.iterations = refine_iters;
    fine_blur = match_blur(t, fine_size);
    fine_options.render_blur_sigma = fine_blur.render_sigma;
    fine_options.chroma_blur_sigma = fine_blur.chroma_sigma;
    fine_target = std::move(t);
  };
  // The chroma weight: the job's, or the one under which a still fit of the first frame
  // drifts least from rest (fit/target/chroma_calibration.h), when blur matching has seen the
  // video's chroma damaged (chroma_calibration_gate; 1 otherwise, without the calibration's
  // seconds).
  double chroma_weight = job.chroma_weight;
  std::optional<ChromaCalibration> chroma_cal;
  std::optional<ChromaGate> chroma_gate;
  if (job.chroma_weight_auto) {
    try {
      if (refine_w > 0) prepare_fine();
    } catch (const Error&) {
      // The refinement will say what is wrong with its target; measure and calibrate at the
      // fitting width.
    }
    // The blur matches above are the gate's measurement (none without blur matching: then
    // the calibration runs, as it cannot be told the chroma is clean).
    if (job.blur_matching) {
      const BlurMatch& m = fine_target ? fine_blur : coarse_blur;
      chroma_gate = chroma_calibration_gate(m, fine_target ? fine_target->width : target.width, target.source_width);
      if (!chroma_gate->calibrate) chroma_weight = 1;
      if (!chroma_gate->calibrate && !job.quiet && !job.progress)
        log::info("fit: chroma weight 1, not calibrated (%s)", chroma_gate->reason.c_str());
    }
  }
  if (job.chroma_weight_auto && (!chroma_gate || chroma_gate->calibrate)) {
    if (job.progress) job.progress(0, "choosing the chroma weight on the first frame");
    // Never a longer budget than the fit's own (a quick trial fit stays quick).
    ChromaCalibrationOptions co;
    co.iterations = std::min(co.iterations, coarse_options.iterations);
    co.fine_iterations = std::min(co.fine_iterations, std::max(1, refine_iters));
    const std::optional<ChromaStage> fine_stage =
        fine_target ? std::optional<ChromaStage>(ChromaStage{&*fine_target, fine_options}) : std::nullopt;
    chroma_cal = calibrate_chroma_weight(rt, fit_scene, ChromaStage{&target, coarse_options},
                                         fine_stage ? &*fine_stage : nullptr, co);
    chroma_weight = chroma_cal->chosen;
    std::string drifts;
    for (const ChromaCandidate& c : chroma_cal->candidates)
      drifts += (drifts.empty() ? "" : ", ") + fmt("%.3g at %g", 1e6 * c.drift, c.weight);
    if (!chroma_cal->note.empty()) log::warning("fit: chroma weight: %s", chroma_cal->note.c_str());
    else if (!job.quiet && !job.progress)
      log::info("fit: chroma weight %g, chosen on the first frame in %.1fs (its still fit's drift from rest, x1e-6: %s)",
                chroma_weight, chroma_cal->seconds, drifts.c_str());
  }
  coarse_options.chroma_weight = chroma_weight;
  Fitter fitter(rt, fit_scene, target, coarse_options);
  log::debug("fit: %s: %d keyframes of %d frames (%.3g fps) at %dx%d; %d paths in %d groups, %d control points; "
             "%d iterations on %s",
             target_path->c_str(), target.keyframes, target.source_frames, target.fps, size.width, size.height,
             static_cast<int>(fit_scene.paths.size()), fitter.fit_plan().n_groups, fitter.raster_plan().n_cp,
             coarse_options.iterations, rt.info().name.c_str());
  if (job.tracks) {
    auto flows = read_tracks(*job.tracks);
    if (flows.size() == static_cast<size_t>(target.keyframes)) fitter.set_flows(std::move(flows));
    else if (!flows.empty())
      log::warning("%s has flows for %zu keyframes, not %d; tracking the fit instead",
                   job.tracks->c_str(), flows.size(), target.keyframes);
  }
  const fs::path ckpt = out / "checkpoint.bin";
  // The checkpoint's key: everything that makes it this fit (files by size and time, so a
  // target replaced by hand under the same name is another fit); not the iteration budget, so
  // a resumed fit may be given more.
  auto stamp = [](const fs::path& p) {
    std::error_code e;
    const auto size = fs::is_regular_file(p, e) ? fs::file_size(p, e) : 0;
    return std::to_string(size) + "@" + std::to_string(fs::last_write_time(p, e).time_since_epoch().count());
  };
  const std::string key = input.string() + "|" + stamp(input) + "|" + *target_path + "|" + stamp(job.target) + "|" +
                          std::to_string(keyframes) + "|" + std::to_string(size.width) + "x" +
                          std::to_string(size.height) + "|" +
                          (fo.track ? "track" : "no-track") + "|" + fmt("%.6g", job.mask_threshold) + "|" +
                          (job.palette ? stamp(*job.palette) : "-") + "|" + (job.tracks ? stamp(*job.tracks) : "-") +
                          "|refine " + std::to_string(refine_w) + "/" + std::to_string(refine_iters) +
                          "|split " + fmt("%.6g", job.max_segment) + "|denoise " + std::to_string(job.denoise_radius) +
                          (job.stabilise ? "|stabilise" : "") + (pin_rest ? "" : "|free start") + "|chroma " + fmt("%.6g", chroma_weight) + "|groups " +
                          group_membership(fitter.fit_plan(), fitter.raster_plan());
  if (job.resume) {
    if (!fs::exists(ckpt)) throw Error(ckpt.string() + ": no checkpoint to resume from");
    fitter.resume(load_checkpoint(ckpt, key));
    log::info("svgmotion: resuming at iteration %d%s", fitter.iteration(),
              fitter.converged() ? " (the loss had stopped falling)" : "");
  } else if (job.resume_unfinished && fs::exists(ckpt)) {
    // An interrupted fit of exactly this problem goes on; anything else starts afresh.
    try {
      FitState st = load_checkpoint(ckpt, key);
      if (st.iteration < coarse_options.iterations) {
        fitter.resume(st);
        if (job.progress) job.progress(0, "resuming at iteration " + std::to_string(st.iteration));
        else if (!job.quiet) log::info("svgmotion: resuming at iteration %d", st.iteration);
      }
    } catch (const Error&) {
    }
  }

  const int resumed_from = fitter.iteration();
  const bool tty = ::isatty(2) && !job.quiet && !job.progress;
  const auto t0 = std::chrono::steady_clock::now();
  auto last_print = t0;
  LossTerms loss;
  bool stopped = false;
  // Divergence watch: the best per-keyframe loss since the last activation, a snapshot of the
  // last good state (taken every kSnapshotEvery iterations while the loss is sane).
  constexpr int kSnapshotEvery = 25, kMaxRollbacks = 4;
  constexpr float kDivergence = 10;
  constexpr int kDivergenceStreak = 50;  // iterations in a row above kDivergence * best
  int bad_streak = 0;
  float best = std::numeric_limits<float>::infinity();
  int best_active = 0, rollbacks = 0;
  FitState good;  // taken at the start of each stage
  std::vector<std::string> rollback_notes;
  // fit.json's loss_history (report.html charts it): iteration, total loss, image loss and
  // active keyframes, every kLossHistoryEvery iterations and at the end of each stage.
  struct LossSample {
    int iteration;
    float total, image;
    int active;
  };
  std::vector<LossSample> history;
  // The host's bar (job.progress): work done over work expected, never going back (fit_progress.h).
  FitProgress bar(fitter.keyframes(), coarse_options.iterations - fitter.iteration(), refine_iters, fine_cost,
                  coarse_options.plateau_window);
  // One stage of iterations on fitter `f` (the coarse fit, then the refinement), with the
  // divergence watch, progress over the whole budget and, for the coarse stage, checkpoints.
  auto run_stage = [&](Fitter& f, int done_before, bool checkpoints) {
    good = f.state();
    best = std::numeric_limits<float>::infinity();
    best_active = 0;
    bad_streak = 0;
    while (!f.done() && !(stopped = interrupted())) {
      loss = f.step();
      const int it = done_before + f.iteration();
      const float per = loss.total() / std::max(1, f.active_keyframes());
      if (f.active_keyframes() != best_active) {
        best_active = f.active_keyframes();
        best = std::numeric_limits<float>::infinity();
      }
      // Adam's first steps after an activation may overshoot for a few iterations and recover
      // (the paper's settings do); a divergence is a loss that stays high, or is not a number.
      bad_streak = std::isfinite(best) && per > kDivergence * best && per > 1e-3f ? bad_streak + 1 : 0;
      const bool diverged = !std::isfinite(per) || bad_streak >= kDivergenceStreak;
      if (diverged && rollbacks < kMaxRollbacks) {
        ++rollbacks;
        rollback_notes.push_back(fmt("iteration %.0f: loss %.4g per keyframe (best %.4g); rolled back to iteration %.0f at half the step size",
                                     it, per, best, done_before + good.iteration));
        log::warning("the fit diverged at %s", rollback_notes.back().c_str());
        f.restore(good);
        f.scale_learning_rates(0.5f);
        // The history follows the fit that goes on: samples past the restored state go.
        while (!history.empty() && history.back().iteration > done_before + good.iteration) history.pop_back();
        best_active = f.active_keyframes();
        best = std::numeric_limits<float>::infinity();
        bad_streak = 0;
        continue;
      }
      if (std::isfinite(per) && bad_streak == 0) best = std::min(best, per);
      if (it % kLossHistoryEvery == 0 || f.done()) history.push_back({it, loss.total(), loss.image, f.active_keyframes()});
      if (it % kSnapshotEvery == 0 && std::isfinite(per) && per <= 2 * best) good = f.state();
      const auto now = std::chrono::steady_clock::now();
      const double elapsed = std::chrono::duration<double>(now - t0).count();
      const double eta = elapsed / std::max(1e-9, work(it) - work(resumed_from)) * (total_work - work(it));
      const bool due = now - last_print > std::chrono::milliseconds(job.progress ? 500 : 200) || f.done();
      if (&f == &fitter) bar.coarse_step(f.iteration() - resumed_from, f.active_keyframes());
      else bar.refine_step(f.iteration());
      if (job.progress && due) {
        // No budget ("/2000") and no ETA here: the fit ends when its loss stops falling, and the
        // host draws the ETA from the bar's pace.
        job.progress(bar.fraction(), std::string(&f == &fitter ? "fit" : "refine") +
                                         fmt(" iteration %.0f, loss %.5f, keyframes %.0f", it, loss.total(),
                                             f.active_keyframes()) + "/" + std::to_string(f.keyframes()));
        last_print = now;
      } else if (tty && due) {
        std::fprintf(stderr, "\rfit: iteration %d/%d  loss %.5f  keyframes %d/%d  %.0fs, ETA %.0fs   ",
                     it, total_iters, loss.total(), f.active_keyframes(), f.keyframes(),
                     elapsed, eta);
        last_print = now;
      }
      // Every 100 iterations a line: the progress itself without a terminal or host display,
      // else a debug line (--verbose, run's log.txt).
      if (it % 100 == 0 || f.done())
        log::write(!tty && !job.quiet && !job.progress ? log::Level::Info : log::Level::Debug,
                   fmt("fit: iteration %.0f/%.0f loss %.5f", it, total_iters, loss.total()) +
                       fmt(" keyframes %.0f/%.0f elapsed %.1fs eta %.0fs", f.active_keyframes(), f.keyframes(), elapsed, eta));
      if (checkpoints && it % kCheckpointEvery == 0) save_checkpoint(ckpt, key, f.state());
    }
  };
  run_stage(fitter, 0, true);
  bar.coarse_done();
  // The coarse fit's state is what a resume starts from, also once the outputs are written
  // (below, with the result for `svgmotion export`): the refinement is not checkpointed.
  const FitState coarse_state = fitter.state();
  save_checkpoint(ckpt, key, coarse_state);
  const bool coarse_converged = fitter.converged();
  if (coarse_converged) {
    log::debug("fit: the loss stopped falling; the fit ends at iteration %d of %d", fitter.iteration(), fo.iterations);
    coarse_iters = fitter.iteration();
    total_iters = coarse_iters + refine_iters;
    total_work = work(total_iters);
  }
  // Keyframes from the target (keyframe_choice.h): every frame between keyframes drawn at the
  // spline's shape and judged by the loss; the frames it misses become keyframes, within the
  // budget, and the fit goes on with them (not checkpointed: a resumed fit makes the same choice
  // again from the coarse checkpoint above).
  const int key_budget = job.max_keyframes < 0 ? default_keyframe_budget(keyframes, target.source_frames) : job.max_keyframes;
  nlohmann::json key_report = {{"asked", target.keyframes}, {"budget", key_budget}};
  std::unique_ptr<Fitter> keyed;
  if (!stopped && key_budget > target.keyframes && target.source_frames > target.keyframes) {
    const auto t_choice = std::chrono::steady_clock::now();
    std::vector<int> between;
    for (int i = 0; i < target.source_frames; ++i)
      if (!std::binary_search(target.source_index.begin(), target.source_index.end(), i)) between.push_back(i);
    const int N = std::max(2, target.source_frames);
    std::vector<double> kt;
    for (int k : target.source_index) kt.push_back(static_cast<double>(k) / (N - 1));
    kt.front() = 0;
    kt.back() = 1;
    auto load_frames = [&](const std::vector<int>& frames) {
      TargetOptions o = to;
      o.frames = frames;
      o.keep_denoised = false;
      o.denoised_from = nullptr;
      if (to.stabilise) o.shake_from = &target;
      return load_target(*target_path, size.width, size.height, o);
    };
    SplineLoss sl;
    sl.render_sigma = coarse_options.render_blur_sigma;
    sl.chroma_sigma = coarse_options.chroma_blur_sigma;
    sl.chroma_weight = chroma_weight;
    sl.w_image = coarse_options.w_image;
    const std::vector<double> frame_db =
        measure_spline_frames(rt, fitter.raster_plan(), size, fitter.keyframe_points_canvas(), kt,
                              job.loop == LoopMode::Loop && returns_to_start(target), target.source_frames, between,
                              load_frames, sl);
    const std::vector<float> kl = fitter.evaluate_keyframe_losses();
    std::vector<double> key_db;
    for (float l : kl) key_db.push_back(loss_db(l, target.keyframes, coarse_options.w_image));
    const KeyframeChoice choice = choose_keyframes(target.source_index, key_db, between, frame_db, key_budget);
    nlohmann::json fdb = nlohmann::json::object();
    for (size_t j = 0; j < between.size(); ++j) fdb[std::to_string(between[j])] = std::round(frame_db[j] * 100) / 100;
    key_report["keyframe_db"] = key_db;
    key_report["spline_frame_db"] = std::move(fdb);
    key_report["missed"] = choice.missed;
    key_report["added"] = choice.added;
    key_report["worst_frame"] = choice.worst_frame;
    key_report["worst_db"] = choice.worst_db;
    if (!choice.added.empty()) {
      TargetOptions o = to;
      o.frames = choice.frames;
      o.keep_denoised = to.keep_denoised && refine_w > 0;
      o.denoised_from = nullptr;
      if (to.stabilise) o.shake_from = &target;
      keyed_target = load_target(*target_path, size.width, size.height, o);
      FitOptions ko = coarse_options;
      // The new keyframes start close (warm-started from the most alike fitted keyframe) and
      // every keyframe is refined jointly: a quarter of the budget, ended by the plateau test.
      ko.iterations = std::max(1, static_cast<int>(std::lround(kKeyedShare * fo.iterations)));
      keyed = std::make_unique<Fitter>(rt, fit_scene, *keyed_target, ko);
      std::vector<int> from = closest_sources(target.source_index, target, keyed_target->source_index, *keyed_target);
      std::vector<char> fresh(from.size(), 0);
      for (size_t k = 0; k < from.size(); ++k)
        fresh[k] = !std::binary_search(target.source_index.begin(), target.source_index.end(), keyed_target->source_index[k]);
      keyed->adopt_keyframes(fitter, from, fresh);
      // The first load's frames are not read again (the first fitter is only counted from
      // here on): their memory goes.
      for (auto* v : {&target.raw, &target.rgba, &target.sdf}) std::vector<float>().swap(*v);
      std::vector<uint8_t>().swap(target.mask);
      key_report["started_from"] = from;
      if (!job.quiet) log::info("fit: %s", choice.reason.c_str());
      coarse_target = &*keyed_target;
      const int before = coarse_iters;
      coarse_iters += ko.iterations;
      total_iters = coarse_iters + refine_iters;
      total_work = work(total_iters);
      run_stage(*keyed, before, false);
      coarse_iters = before + keyed->iteration();
      total_iters = coarse_iters + refine_iters;
      total_work = work(total_iters);
      key_report["iterations"] = keyed->iteration();
      key_report["reason"] = choice.reason;
    } else {
      char why[200];
      std::snprintf(why, sizeof why, "keyframes %d kept: the spline through them predicts every frame between them (worst: frame %d, %.1f dB)",
                    target.keyframes, choice.worst_frame, choice.worst_db);
      key_report["reason"] = choice.missed.empty() ? std::string(why) : choice.reason;
      log::debug("fit: %s", key_report["reason"].get<std::string>().c_str());
    }
    key_report["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_choice).count();
  }
  key_report["chosen"] = coarse_target->keyframes;
  Fitter& cfit = keyed ? *keyed : fitter;
  const TargetFrames& ctarget = *coarse_target;
  // The refinement: every keyframe at the finer width, from the coarse result (not
  // checkpointed: a resumed fit redoes it from the checkpoint above, which records that the
  // coarse stage had ended, so it is the same refinement).
  std::unique_ptr<Fitter> fine;
  std::vector<int> refine_kept_coarse;  // keyframes the refinement's guard put back
  std::vector<float> refine_loss_ratio;  // per keyframe: refined / coarse loss at the coarse width
  if (refine_w > 0 && !stopped) {
    const RenderSize fine_size = render_size(scene, refine_w);
    // Loaded before the keyframes were chosen (the chroma weight's calibration): again, at them.
    if (fine_target && fine_target->keyframes != ctarget.keyframes) fine_target.reset();
    prepare_fine();
    fine_options.chroma_weight = chroma_weight;
    fine = std::make_unique<Fitter>(rt, fit_scene, *fine_target, fine_options);
    const double scale = static_cast<double>(fine_size.width) / size.width;
    fine->adopt_coarse(cfit, scale);
    log::debug("fit: refining every keyframe at %dx%d for %d iterations", fine_size.width, fine_size.height,
               refine_iters);
    // The guard's baseline: how well each coarse keyframe matches the video at the coarse width.
    const std::vector<float> coarse_losses = cfit.evaluate_keyframe_losses();
    run_stage(*fine, coarse_iters, false);
    if (!stopped) {
      // The refinement's guard. A keyframe the refinement made worse at the coarse width (the
      // snail's pupil, off by more than the fine loss's reach, shrank to a hairline at 512 px:
      // 47.4 -> 36.5 dB at 256 px in keyframes 2-4) keeps its coarse fit. Both are judged by
      // the coarse fitter against the coarse target: the refined fit is brought down to it.
      const FitState coarse_state = cfit.state();
      cfit.adopt_coarse(*fine, 1 / scale);
      const std::vector<float> refined_losses = cfit.evaluate_keyframe_losses();
      cfit.restore(coarse_state);
      std::vector<char> worse(static_cast<size_t>(cfit.keyframes()), 0);
      for (size_t k = 0; k < worse.size(); ++k) {
        refine_loss_ratio.push_back(coarse_losses[k] > 0 ? refined_losses[k] / coarse_losses[k] : 1.f);
        worse[k] = refined_losses[k] > kRefineGuard * coarse_losses[k];
        if (worse[k]) refine_kept_coarse.push_back(static_cast<int>(k));
      }
      if (!refine_kept_coarse.empty()) {
        fine->take_keyframes(cfit, scale, worse);
        std::string ks;
        for (int k : refine_kept_coarse) ks += (ks.empty() ? "" : ", ") + std::to_string(k);
        log::info("fit: the refinement matched keyframe%s %s worse at %d px; kept from the coarse fit",
                  refine_kept_coarse.size() > 1 ? "s" : "", ks.c_str(), size.width);
      }
    }
  }
  Fitter& final_fit = fine ? *fine : cfit;
  const int iterations_done = fitter.iteration() + (keyed ? keyed->iteration() : 0) + (fine ? fine->iteration() : 0);
  const TargetFrames& final_target = fine ? *fine_target : ctarget;
  const RenderSize final_size = fine ? render_size(scene, refine_w) : size;
  if (tty) std::fputc('\n', stderr);
  // The fit's seconds include the chroma weight's calibration before it.
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() +
                         (chroma_cal ? chroma_cal->seconds : 0);

  // Outputs: the animation in the original colours, the preview, a small report.
  const auto points = final_fit.keyframe_points_canvas();
  const auto renders = final_fit.render_keyframes();
  AnimationTiming timing;
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
  const GateOptions gate_options;
  const GateVerdict verdict = judge_fit(final_target, renders, points, final_fit.raster_plan(), fit_scene,
                                        final_size.view, gate_options);
  const bool rejected = !stopped && !verdict.passed;
  const fs::path anim = out / (rejected && job.gate ? "animation.failed.svg" : "animation.svg");
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
  std::optional<GroupMotionExport> group_motion;
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
  for (const std::string& w : exported.warnings) log::warning("%s", w.c_str());
  AnimationTiming wt = timing;
  wt.keyframes = exported.values_written;
  if (job.compact)
    log::debug("fit: compact export: %d paths still, %d moved by a group transform (%d with a residual d); %zu keys of %zu values",
               exported.stats.still, exported.stats.transformed, exported.stats.residual, exported.stats.keys,
               exported.stats.values);
  const int active = final_fit.active_keyframes();
  const int W = final_size.width, H = final_size.height;
  write_preview_video(out / "preview.mp4", active, 2,
                      [&](int k, int panel) {
                        return panel == 0 ? rgba8_image(&final_target.raw[static_cast<size_t>(k) * W * H * 4], W, H)
                                          : render_panel(renders, k, W, H);
                      },
                      std::max(1.0, (timing.keyframes - 1) / timing.duration_s));
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
                           {"values_written", wt.keyframes},
                           {"size", {W, H}},
                           {"seconds", seconds},
                           {"loss", {{"total", loss.total()}, {"image", loss.image}, {"smoothness", loss.smooth},
                                     {"g1", loss.g1}, {"containment", loss.contain}}},
                           {"keyframe_image_loss", final_fit.keyframe_losses()},
                           {"keyframe_frames", ctarget.source_index},
                           {"resumed_from", resumed_from},
                           {"rollbacks", rollback_notes},
                           {"gate", gate_json(verdict, gate_options)},
                           {"device", rt.info().name}};
  if (!map.order.empty()) report["paint_order_applied"] = true;
  // Warm starts of newly activated keyframes (a resumed fit counts only those after resuming).
  // (The keyframes added from the target count with the first fit's.)
  const auto ws = [&](int Fitter::*n) { return fitter.*n + (keyed ? (*keyed).*n : 0); };
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
  if (job.stabilise) {
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
      drift[fmt("%g", c.weight)] = c.drift;
      drift_px[fmt("%g", c.weight)] = c.drift_px;
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
                 final_fit.keyframes(), seconds, anim.c_str());
  return 0;
}

}  // namespace svgm
