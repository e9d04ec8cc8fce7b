// One fit from files to files (see fit_job.h): run_fit_job() lists the steps; this file holds
// the ones before fitting (reading the drawing, preparing the target, the output folder, the
// stages' plan, the chroma weight, the fitter). The fitting stages are in fit_stages.cpp, the
// outputs in fit_outputs.cpp; fit_run.h is what they share.
#include "fit/fit_job.h"
#include "fit/fit_run.h"
#include "opencl/compiler_pages.h"
#include "svgmotion/atomic_file.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "fit/target/heap_trim.h"
#include "fit/target/distance_field.h"
#include "fit/output/checkpoint.h"
#include "fit/target/correction_palette.h"
#include "raster/render_image.h"
#include "svg/document_order.h"
#include "color/palette_json.h"
#include "svgmotion/error.h"
#include "svgmotion/log.h"
#include "svgmotion/svg_reader.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

// What a user should hear about a target before minutes of fitting: frames stretched to
// another aspect, frames smaller than the fit, keyframes showing no figure or only figure.
std::vector<std::string> target_warnings(const TargetFrames& t, const std::string& name, const RenderSize& size) {
  std::vector<std::string> out;
  if (t.source_width > 0 && t.source_height > 0) {
    const double a = static_cast<double>(t.source_width) / t.source_height;
    const double b = static_cast<double>(size.width) / size.height;
    if (std::fabs(std::log(a / b)) > std::log(1.1))
      out.push_back(name + ": frames are " + std::to_string(t.source_width) + "x" + std::to_string(t.source_height) +
                    fit_fmt(" (aspect %.2f), the SVG's aspect is %.2f: the frames are stretched to fit", a, b));
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

std::string fit_fmt(const char* f, double a, double b, double c, double d) {
  char buf[256];
  std::snprintf(buf, sizeof buf, f, a, b, c, d);
  return buf;
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

int run_fit_job(const FitJob& job, const std::function<bool()>& interrupted) {
  FitRun run(job, interrupted);
  // Between steps the heap's free pages go back (heap_trim.h): what the run's earlier stages,
  // the loads and the stages' loss memory left behind.
  trim_heap();
  run.read_drawing();
  run.prepare_target();
  trim_heap();
  run.claim_output();
  run.plan_stages();
  run.choose_chroma_weight();
  trim_heap();
  run.start_fitter();
  run.fit_coarse();
  trim_heap();
  run.add_keyframes_from_target();
  trim_heap();
  run.refine();
  trim_heap();
  run.write_animation();
  run.write_report();
  return run.finish();
}

FitRun::FitRun(const FitJob& job, const std::function<bool()>& interrupted)
    : job(job),
      interrupted(interrupted),
      input(job.svg),
      out(job.out),
      fo(job.options),
      keyframes(job.keyframes),
      target_str(job.target.string()),
      target_path(&target_str) {}

void FitRun::read_drawing() {
  as_read = read_svg_file(input);
  for (const auto& w : as_read.warnings) log::warning("%s", w.c_str());
  if (as_read.paths.empty()) throw Error(input.string() + ": nothing to animate (no visible paths)");
  if (!(job.max_segment >= 0 && job.max_segment <= 1)) throw Error("the longest segment must be 0..1 of the canvas");
  // Long segments split (exactly) so the motion can bend them; the same split is applied to
  // the document written into, so the written paths have the fitted structure.
  split = plan_segment_split(as_read, job.max_segment * std::max(as_read.width, as_read.height));
  scene = split_scene(as_read, split);
  if (const int added = added_points(split))
    log::debug("fit: %d control points added by splitting long segments", added);
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
  fit_scene = std::move(palette_scene);
}

void FitRun::prepare_target() {
  size = render_size(scene, job.width);
  to.keyframes = keyframes;
  to.white_threshold = job.mask_threshold;
  // The clip at a glance (frame_scan.h): a lower frame rate's repeats are collapsed to the
  // poses they hold, and a shaking clip is stabilised unless told otherwise.
  activity("scanning the video's frames");
  scan = scan_frames(*target_path, size.width);
  to.stabilise = job.stabilise.value_or(scan.shaking);
  if (scan.collapse()) to.frames = spread_over_poses(scan.poses, keyframes);
  log::debug("fit: frame scan: %d frames, %zu distinct, cadence %d; whole-frame jitter %.3f px, step %.3f px (fitting width), "
             "rigid residual %.2f%s", scan.frames, scan.distinct.size(), scan.cadence, scan.jitter_fit_px, scan.step_fit_px,
             scan.rigid_residual, scan.shaking ? ": shaking" : "");
  to.denoise_radius = job.denoise_radius;
  // The refinement's load reuses these keyframes when it works at the same size (a 512-px video
  // fitted at 256 and refined at 512 denoises at 512 both times); released once it has.
  to.keep_denoised = job.denoise_radius > 0 && job.refine_width != 0;
  activity("starting OpenCL");
  rt.emplace(job.device);
  // The colours the target should show: the fitted scene's opaque flat fills and strokes; none
  // (no correction) when gradients cover much of the drawing (fit/target/correction_palette.h).
  if (job.colour_correction) {
    CorrectionPalette cp = correction_palette(*rt, fit_scene, size.width);
    gradient_share = cp.gradient_share;
    if (cp.gradient_share > 0)
      log::debug("fit: gradient paint covers %.1f%% of the canvas: %s", 100 * cp.gradient_share,
                 cp.usable ? "colours corrected" : "too much for colour correction, the video's colours are compared as they are");
    if (cp.usable) to.palette = std::move(cp.colours);
  }
  if (!(to.white_threshold > 0 && to.white_threshold <= 1))
    throw Error("the mask threshold must be in (0, 1]");
  // The document written into, and how the fitted paths map onto it, checked before fitting.
  into = job.export_into.value_or(input);
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
  RgbaImage rest_render = render_image(*rt, fit_scene, size.width, false);
  to.keep_part_share = 0.5 * smallest_part_share(rest_render.rgba, rest_render.width, rest_render.height, to.white_threshold);
  release_compiler_pages("the rest pose's render");
  activity("reading the video's keyframes at " + std::to_string(size.width) + " px");
  target = load_target(*target_path, size.width, size.height, to);
  // Blur matching at the fitting width first (see match_blur): the rest pose is judged as
  // soft as the video shows it (rest_start.h).
  first_blur = job.blur_matching ? match_render_blur(rest_render, target.rgba) : BlurMatch{};
  // Keyframe 0 is the drawing at rest when the video starts there (rest_start.h), or when told.
  rest_start = judge_rest_start(rest_render, target, to.white_threshold, to.dilate_px, kRestStartIou, first_blur.render_sigma);
  rest_render = RgbaImage{};
  pin_rest = job.start_at_rest.value_or(rest_start.at_rest);
  if (!job.quiet && !job.progress && !job.start_at_rest && !pin_rest)
    log::info("fit: the video's first frame is not the drawing at rest (foreground IoU %.3f < %.2f): keyframe 0 is fitted "
              "too, not pinned to the rest pose", rest_start.iou, kRestStartIou);
  else
    log::debug("fit: keyframe 0 %s (first frame against the rest pose: foreground IoU %.3f%s)",
               pin_rest ? "is the rest pose" : "is fitted", rest_start.iou, job.start_at_rest ? ", as told" : "");
  for (const std::string& w : target_warnings(target, *target_path, size))
    log::warning("%s", w.c_str());
  // From here on the preview and the gate alone read the frames before cleanup (compact_raw.h).
  target_raw = compact_raw(target);
  // Which prior told the shake from the motion matters to the user: a figure with nothing
  // still keeps the part of the shake inside its motion's band, about 0.45 of 1.6 px rms (fit/target/stabilise.h).
  if (scan.collapse() && !job.quiet && !job.progress)
    log::info("fit: the video shows each pose %d times (a lower frame rate): fitted at the %zu poses it shows, each at the "
              "frame it was first shown", scan.cadence, scan.poses.size());
  if (to.stabilise && !job.stabilise && !job.quiet && !job.progress)
    log::info("fit: the whole frame shakes (%.2f px from frame to frame at the fitting width): stabilised (--no-stabilise "
              "keeps it)", scan.jitter_fit_px);
  if (to.stabilise && !job.quiet && !job.progress) {
    if (target.shake_model == "smooth")
      log::info("fit: camera shake of up to %.2f px (fitting width) removed (nothing in the figure holds still: told from the motion by its "
                "smoothness alone, some of it stays)", target.max_shake_px);
    else
      log::info("fit: camera shake of up to %.2f px (fitting width) removed (read off the part that holds still, %.0f%% of the edges%s)",
                target.max_shake_px, 100 * target.still_share,
                target.shake_model == "still_smooth" ? "; its own slow course is kept" : "");
  }
}

void FitRun::release_denoised() {
  for (TargetFrames* t : {&target, keyed_target ? &*keyed_target : nullptr}) {
    if (!t) continue;
    decltype(t->denoised)().swap(t->denoised);
    t->denoised_frame.clear();
  }
}

void FitRun::release_compiler_pages(const char* after) {
  const size_t kb = svgm::release_compiler_pages();
  log::debug("fit: the OpenCL compiler's clean pages released after %s: %.1f MB", after, kb / 1000.0);
}

void FitRun::claim_output() {
  std::error_code ec;
  if (job.claim_out) lock.emplace(out, job.force, fit_output_names());
  fs::create_directories(out, ec);
  if (ec) throw Error(out.string() + ": cannot create: " + ec.message());
  // Refuse an unwritable folder or a non-file output now, not after minutes of fitting.
  if (::access(out.c_str(), W_OK | X_OK) != 0)
    throw Error(out.string() + ": cannot write (" + (errno == EROFS ? "read-only file system" : "permission denied") + ")");
  for (const char* f : {"animation.svg", "animation.failed.svg", "animation.json", "animation.failed.json",
                        "animation.lottie", "animation.failed.lottie", "preview.mp4", "fit.json", "checkpoint.bin"})
    output_target(out / f);
}

// Progress and ETA count work, not iterations: a refinement iteration costs about as many
// coarse ones as it has times the pixels.
double FitRun::work(int it) const { return std::min(it, coarse_iters) + std::max(0, it - coarse_iters) * fine_cost; }

double FitRun::seconds_in() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - begun).count();
}

void FitRun::activity(const std::string& note) {
  if (job.progress) job.progress(bar ? bar->fraction(seconds_in()) : 0, note);
}

// Blur matching at each width the fit runs at: the render σ of the loss that makes our
// rest pose look like the video's first frame (fit/target/blur_match.h).
BlurMatch FitRun::match_blur(const TargetFrames& t, const RenderSize& at, const BlurMatch* done) {
  if (!job.blur_matching) return BlurMatch{};
  const BlurMatch m = done ? *done : match_render_blur(render_image(*rt, fit_scene, at.width, false), t.rgba);
  log::debug("fit: blur matching at %dx%d: best render sigma %.2f (residual x%.3f, rest pose %.1f dB)%s; "
             "best chroma sigma %.2f with luma %.2f (residual x%.3f)%s; render sigma %.2f, chroma %.2f", at.width,
             at.height, m.best_sigma, m.residual_ratio, m.rest_psnr_db, m.best_sigma == m.render_sigma ? ", adopted" : "",
             m.best_chroma_sigma, m.chroma_luma_sigma, m.chroma_residual_ratio,
             m.chroma_sigma != m.render_sigma ? ", adopted" : ", not adopted", m.render_sigma, m.chroma_sigma);
  return m;
}

void FitRun::plan_stages() {
  // Coarse-to-fine: which width the refinement after the coarse fit runs at, if any.
  refine_w = job.refine_width;
  if (refine_w < 0)
    refine_w = target.source_width * 2 >= size.width * 3 ? std::min(2 * size.width, target.source_width) : 0;
  if (refine_w > 0 && refine_w <= size.width) refine_w = 0;
  refine_iters = refine_w > 0 ? std::max(0, static_cast<int>(std::lround(job.refine_share * fo.iterations))) : 0;
  if (refine_iters == 0) refine_w = 0;
  if (refine_w == 0) release_denoised();
  coarse_options = fo;
  coarse_options.pin_rest_keyframe = pin_rest;
  coarse_options.held_groups = held_groups;
  coarse_options.known_body = known.body;
  coarse_options.known_maps = known.maps;
  coarse_iters = fo.iterations;
  total_iters = coarse_iters + refine_iters;
  fine_cost = refine_w > 0 ? static_cast<double>(refine_w) * refine_w / (size.width * size.width) : 1;
  total_work = work(total_iters);
  coarse_blur = match_blur(target, size, &first_blur);
  coarse_options.render_blur_sigma = coarse_blur.render_sigma;
  coarse_options.chroma_blur_sigma = coarse_blur.chroma_sigma;
  coarse_target = &target;
}

void FitRun::prepare_fine() {
  if (fine_target) return;
  const RenderSize fine_size = render_size(scene, refine_w);
  TargetOptions fine_to = to;
  if (coarse_target != &target) fine_to.frames = coarse_target->source_index;
  if (to.stabilise) fine_to.shake_from = coarse_target;  // the camera path of the first load
  fine_to.keep_denoised = false;
  fine_to.denoised_from = coarse_target == &target ? &target : &*keyed_target;  // taken, freed as read
  // Its cleaned frames are packed as runs of white as the load cleans each (white_runs.h): their
  // floats (88 MB for 21 keyframes at 512 px) are never held whole for a stage that reads them
  // a keyframe at a time (the refinement's loss) or keyframe 0 alone (blur matching).
  fine_rgba = {};
  const size_t fine_px = static_cast<size_t>(fine_size.width) * fine_size.height;
  fine_to.rgba_sink = [this, fine_px](int, const float* rgba) { append_white_runs(fine_rgba, rgba, fine_px); };
  activity("reading the video's keyframes at " + std::to_string(fine_size.width) + " px for the refinement");
  TargetFrames t = load_target_compact(*target_path, fine_size.width, fine_size.height, fine_to, fine_raw);
  release_denoised();
  trim_heap();
  fine_options = fo.refined_at(static_cast<double>(fine_size.width) / size.width);
  fine_options.pin_rest_keyframe = pin_rest;
  fine_options.held_groups = held_groups;
  fine_options.known_body = known.body;
  fine_options.known_maps = known.maps;
  fine_options.iterations = refine_iters;
  fine_rgba.others.shrink_to_fit();
  fine_rgba.runs.shrink_to_fit();
  t.rgba.resize(fine_px * 4);  // keyframe 0 alone: what blur matching reads
  unpack_white_runs_range(fine_rgba, 0, fine_px, t.rgba.data());
  fine_blur = match_blur(t, fine_size);
  std::vector<float>().swap(t.rgba);
  fine_options.render_blur_sigma = fine_blur.render_sigma;
  fine_options.chroma_blur_sigma = fine_blur.chroma_sigma;
  // Its distance field is made again from its mask when a fitter needs it (distance_field.h):
  // it is not held through the coarse stage (22 MB for 21 keyframes at 512 px).
  std::vector<float>().swap(t.sdf);
  fine_target = std::move(t);
  fine_packed = true;
}

// The chroma weight: the job's, or the one under which a still fit of the first frame
// drifts least from rest (fit/target/chroma_calibration.h), when blur matching has seen the
// video's chroma damaged (chroma_calibration_gate; 1 otherwise, without the calibration's
// seconds).
void FitRun::choose_chroma_weight() {
  chroma_weight = job.chroma_weight;
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
    unpack_fine_rgba();  // the calibration's fine stage reads its target's frames whole
    if (fine_target) fill_distance_fields(*fine_target);
    const std::optional<ChromaStage> fine_stage =
        fine_target ? std::optional<ChromaStage>(ChromaStage{&*fine_target, fine_options}) : std::nullopt;
    chroma_cal = calibrate_chroma_weight(*rt, fit_scene, ChromaStage{&target, coarse_options},
                                         fine_stage ? &*fine_stage : nullptr, co);
    chroma_weight = chroma_cal->chosen;
    std::string drifts;
    for (const ChromaCandidate& c : chroma_cal->candidates)
      drifts += (drifts.empty() ? "" : ", ") + fit_fmt("%.3g at %g", 1e6 * c.drift, c.weight);
    if (!chroma_cal->note.empty()) log::warning("fit: chroma weight: %s", chroma_cal->note.c_str());
    else if (!job.quiet && !job.progress)
      log::info("fit: chroma weight %g, chosen on the first frame in %.1fs (its still fit's drift from rest, x1e-6: %s)",
                chroma_weight, chroma_cal->seconds, drifts.c_str());
  }
  coarse_options.chroma_weight = chroma_weight;
  // Nothing reads the finer target's frames again before its fitter is made (the refinement).
  pack_fine_rgba();
  if (fine_target) std::vector<float>().swap(fine_target->sdf);
}

void FitRun::pack_fine_rgba() {
  if (!fine_target || fine_packed) return;
  fine_rgba = pack_white_runs(fine_target->rgba);
  fine_packed = true;
}

void FitRun::unpack_fine_rgba() {
  if (!fine_packed) return;
  fine_target->rgba = unpack_white_runs(fine_rgba);
  fine_packed = false;
}

void FitRun::drop_fine_target() {
  fine_target.reset();
  fine_raw = {};
  fine_rgba = {};
  fine_packed = false;
}

void FitRun::start_fitter() {
  activity("preparing the fitter");
  fitter.emplace(*rt, fit_scene, target, coarse_options);
  release_compiler_pages("the fitter's programs");
  log::debug("fit: %s: %d keyframes of %d frames (%.3g fps) at %dx%d; %d paths in %d groups, %d control points; "
             "%d iterations on %s",
             target_path->c_str(), target.keyframes, target.source_frames, target.fps, size.width, size.height,
             static_cast<int>(fit_scene.paths.size()), fitter->fit_plan().n_groups, fitter->raster_plan().n_cp,
             coarse_options.iterations, rt->info().name.c_str());
  if (job.tracks) {
    auto flows = read_tracks(*job.tracks);
    if (flows.size() == static_cast<size_t>(target.keyframes)) fitter->set_flows(std::move(flows));
    else if (!flows.empty())
      log::warning("%s has flows for %zu keyframes, not %d; tracking the fit instead",
                   job.tracks->c_str(), flows.size(), target.keyframes);
  }
  ckpt = out / "checkpoint.bin";
  // The checkpoint's key: everything that makes it this fit (files by size and time, so a
  // target replaced by hand under the same name is another fit); not the iteration budget, so
  // a resumed fit may be given more.
  auto stamp = [](const fs::path& p) {
    std::error_code e;
    const auto size = fs::is_regular_file(p, e) ? fs::file_size(p, e) : 0;
    return std::to_string(size) + "@" + std::to_string(fs::last_write_time(p, e).time_since_epoch().count());
  };
  key = input.string() + "|" + stamp(input) + "|" + *target_path + "|" + stamp(job.target) + "|" +
        std::to_string(keyframes) + "|" + std::to_string(size.width) + "x" +
        std::to_string(size.height) + "|" +
        (fo.track ? "track" : "no-track") + "|" + fit_fmt("%.6g", job.mask_threshold) + "|" +
        (job.palette ? stamp(*job.palette) : "-") + "|" + (job.tracks ? stamp(*job.tracks) : "-") +
        "|refine " + std::to_string(refine_w) + "/" + std::to_string(refine_iters) +
        "|split " + fit_fmt("%.6g", job.max_segment) + "|denoise " + std::to_string(job.denoise_radius) +
        (to.stabilise ? "|stabilise" : "") + (pin_rest ? "" : "|free start") + "|chroma " + fit_fmt("%.6g", chroma_weight) + "|groups " +
        group_membership(fitter->fit_plan(), fitter->raster_plan());
  if (job.resume) {
    if (!fs::exists(ckpt)) throw Error(ckpt.string() + ": no checkpoint to resume from");
    fitter->resume(load_checkpoint(ckpt, key));
    log::info("svgmotion: resuming at iteration %d%s", fitter->iteration(),
              fitter->converged() ? " (the loss had stopped falling)" : "");
  } else if (job.resume_unfinished && fs::exists(ckpt)) {
    // An interrupted fit of exactly this problem goes on; anything else starts afresh.
    try {
      FitState st = load_checkpoint(ckpt, key);
      if (st.iteration < coarse_options.iterations) {
        fitter->resume(st);
        if (job.progress) job.progress(0, "resuming at iteration " + std::to_string(st.iteration));
        else if (!job.quiet) log::info("svgmotion: resuming at iteration %d", st.iteration);
      }
    } catch (const Error&) {
    }
  }
}

}  // namespace svgm
