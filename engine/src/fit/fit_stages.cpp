// The fitting stages of a fit job (fit_run.h): the coarse fit, the keyframes added from the
// target and the refinement at the finer width, each a run of iterations under one watch
// (divergence, progress, checkpoints).
#include "fit/fit_run.h"
#include "fit/target/distance_field.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>

#include "fit/target/heap_trim.h"
#include "fit/optimise/keyframe_choice.h"
#include "fit/output/checkpoint.h"
#include "fit/target/white_runs.h"
#include "svgmotion/error.h"
#include "svgmotion/log.h"

namespace svgm {

// One stage of iterations on fitter `f` (the coarse fit, then the refinement), with the
// divergence watch, progress over the whole budget and, for the coarse stage, checkpoints.
void FitRun::run_stage(Fitter& f, int done_before, bool checkpoints) {
  constexpr int kSnapshotEvery = 25, kMaxRollbacks = 4;
  constexpr float kDivergence = 10;
  constexpr int kDivergenceStreak = 50;  // iterations in a row above kDivergence * best
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
      rollback_notes.push_back(fit_fmt("iteration %.0f: loss %.4g per keyframe (best %.4g); rolled back to iteration %.0f at half the step size",
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
    const double in = seconds_in();
    if (&f == &*fitter) bar->coarse_step(f.iteration() - resumed_from, f.active_keyframes(), in);
    else if (&f == keyed.get()) bar->keyed_step(f.iteration(), in);
    else bar->refine_step(f.iteration(), in);
    // The bar's estimate of the time left once it knows the pace, else the iterations' share.
    const double eta = bar->fraction(in) > 0 ? bar->seconds_left()
                                             : elapsed / std::max(1e-9, work(it) - work(resumed_from)) * (total_work - work(it));
    const bool due = now - last_print > std::chrono::milliseconds(job.progress ? 500 : 200) || f.done();
    if (job.progress && due) {
      // No budget ("/2000") and no ETA here: the fit ends when its loss stops falling, and the
      // host draws the ETA from the bar's pace.
      job.progress(bar->fraction(in), std::string(&f == fine.get() ? "refine" : "fit") +
                                        fit_fmt(" iteration %.0f, loss %.5f, keyframes %.0f", it, loss.total(),
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
                 fit_fmt("fit: iteration %.0f/%.0f loss %.5f", it, total_iters, loss.total()) +
                     fit_fmt(" keyframes %.0f/%.0f elapsed %.1fs eta %.0fs", f.active_keyframes(), f.keyframes(), elapsed, eta));
    if (checkpoints && it % kCheckpointEvery == 0) save_checkpoint(ckpt, key, f.state());
  }
}

void FitRun::fit_coarse() {
  resumed_from = fitter->iteration();
  tty = ::isatty(2) && !job.quiet && !job.progress;
  t0 = std::chrono::steady_clock::now();
  last_print = t0;
  best = std::numeric_limits<float>::infinity();
  // The host's bar (job.progress): time spent over time expected, never going back (fit_progress.h).
  std::vector<int> poses;
  int key_budget = 0;
  choice_plan(poses, key_budget);
  FitProgress::Plan plan;
  plan.keyframes = fitter->keyframes();
  plan.coarse_budget = coarse_options.iterations - fitter->iteration();
  plan.refine_budget = refine_iters;
  plan.fine_pixels = fine_cost;
  plan.plateau_window = coarse_options.plateau_window;
  plan.choice_frames = static_cast<int>(std::count_if(poses.begin(), poses.end(), [&](int i) {
    return !std::binary_search(target.source_index.begin(), target.source_index.end(), i);
  }));
  bar.emplace(plan);
  activity("starting the fit");
  run_stage(*fitter, 0, true);
  bar->coarse_done(seconds_in());
  // The coarse fit's state is what a resume starts from, also once the outputs are written
  // (below, with the result for `svgmotion export`): the refinement is not checkpointed.
  coarse_state = fitter->state();
  save_checkpoint(ckpt, key, coarse_state);
  coarse_converged = fitter->converged();
  if (coarse_converged) {
    log::debug("fit: the loss stopped falling; the fit ends at iteration %d of %d", fitter->iteration(), fo.iterations);
    coarse_iters = fitter->iteration();
    total_iters = coarse_iters + refine_iters;
    total_work = work(total_iters);
  }
}

void FitRun::choice_plan(std::vector<int>& poses, int& budget) const {
  // Only frames that show a pose of their own are judged: a repeat of a lower frame rate's
  // held frame is its run's pose, which the spline should pass through, not stop at
  // (frame_scan.h). Without a cadence, every frame.
  poses = scan.poses;
  if (!scan.collapse() || poses.empty() || poses.back() >= target.source_frames) {
    poses.resize(static_cast<size_t>(target.source_frames));
    std::iota(poses.begin(), poses.end(), 0);
  }
  const int n_poses = static_cast<int>(poses.size());
  budget = job.max_keyframes < 0 ? default_keyframe_budget(keyframes, n_poses) : job.max_keyframes;
  if (!(budget > target.keyframes && n_poses > target.keyframes)) poses.clear();
}

// Keyframes from the target (keyframe_choice.h): every frame between keyframes drawn at the
// spline's shape and judged by the loss; the frames it misses become keyframes, within the
// budget, and the fit goes on with them (not checkpointed: a resumed fit makes the same choice
// again from the coarse checkpoint above).
void FitRun::add_keyframes_from_target() {
  std::vector<int> poses;
  int key_budget = 0;
  choice_plan(poses, key_budget);
  key_report = {{"asked", target.keyframes}, {"budget", key_budget}};
  if (!stopped && !poses.empty()) {
    const auto t_choice = std::chrono::steady_clock::now();
    std::vector<int> between;
    for (int i : poses)
      if (!std::binary_search(target.source_index.begin(), target.source_index.end(), i)) between.push_back(i);
    const int N = std::max(2, target.source_frames);
    activity("judging the " + std::to_string(between.size()) + " frames between keyframes");
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
      TargetFrames t = load_target(*target_path, size.width, size.height, o);
      trim_heap();
      return t;
    };
    SplineLoss sl;
    sl.render_sigma = coarse_options.render_blur_sigma;
    sl.chroma_sigma = coarse_options.chroma_blur_sigma;
    sl.chroma_weight = chroma_weight;
    sl.w_image = coarse_options.w_image;
    // The fitted keyframes' own losses first: the coarse fitter's loss memory (Q and R, the
    // residual chunk, the tape pool: ~60 MB for 21 keyframes at 256 px) then goes while the
    // frames between them are judged, with a loss memory of their own (the refinement's guard
    // makes it again; evaluating reads the parameters only, so the losses are the same).
    const std::vector<float> kl = fitter->evaluate_keyframe_losses();
    fitter->release_loss_memory();
    trim_heap();
    const std::vector<double> frame_db =
        measure_spline_frames(*rt, fitter->raster_plan(), size, fitter->keyframe_points_canvas(), kt,
                              job.loop == LoopMode::Loop && returns_to_start(target), target.source_frames, between,
                              load_frames, sl);
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
      // The refinement's target, read at the first keyframes for the chroma weight's
      // calibration, is read again at these (prepare_fine): it goes now rather than after the
      // stage below (37 bytes per pixel and first keyframe at the finer width: 145 MB for 15
      // at 512 px, held beside this stage's own target and the denoised frames it keeps).
      drop_fine_target();
      activity("reading the " + std::to_string(choice.frames.size()) + " keyframes chosen");
      TargetOptions o = to;
      o.frames = choice.frames;
      o.keep_denoised = to.keep_denoised && refine_w > 0;
      o.denoised_from = nullptr;
      if (to.stabilise) o.shake_from = &target;
      keyed_target = load_target_compact(*target_path, size.width, size.height, o, keyed_raw);
      // The refinement's target is read now, from the denoised keyframes this load kept, before
      // this stage's fitter is made rather than after the stage: they go as it takes them, and
      // it is held through the stage compact and packed (fit_job.cpp's prepare_fine: deflated
      // 8-bit raw, runs of white and the mask) where they were float RGB at the denoising's size
      // (12 bytes per pixel and keyframe: 107 MB for the twemoji dog's 34 keyframes at 512 px).
      // The same load from the same frames, so the same bits; a target it cannot read is
      // reported by the refinement, as before.
      coarse_target = &*keyed_target;  // the refinement's frames and denoised keyframes
      if (refine_w > 0) {
        try {
          prepare_fine();
          release_compiler_pages("the refinement's blur matching");
        } catch (const Error&) {
        }
      }
      FitOptions ko = coarse_options;
      // The new keyframes start close (warm-started from the most alike fitted keyframe) and
      // every keyframe is refined jointly: a quarter of the budget, ended by the plateau test.
      ko.iterations = std::max(1, static_cast<int>(std::lround(kKeyedShare * fo.iterations)));
      keyed = std::make_unique<Fitter>(*rt, fit_scene, *keyed_target, ko);
      std::vector<int> from = closest_sources(target.source_index, target, keyed_target->source_index, *keyed_target);
      std::vector<char> fresh(from.size(), 0);
      for (size_t k = 0; k < from.size(); ++k)
        fresh[k] = !std::binary_search(target.source_index.begin(), target.source_index.end(), keyed_target->source_index[k]);
      keyed->adopt_keyframes(*fitter, from, fresh);
      // The first load's frames are not read again (the first fitter is only counted from
      // here on): their memory goes.
      for (auto* v : {&target.raw, &target.rgba, &target.sdf}) std::vector<float>().swap(*v);
      std::vector<uint8_t>().swap(target.mask);
      target_raw = {};
      fitter->release_loss_memory();
      key_report["started_from"] = from;
      if (!job.quiet) log::info("fit: %s", choice.reason.c_str());
      coarse_target = &*keyed_target;
      const int before = coarse_iters;
      coarse_iters += ko.iterations;
      total_iters = coarse_iters + refine_iters;
      total_work = work(total_iters);
      bar->keyed_start(keyed->keyframes(), ko.iterations, seconds_in());
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
  if (bar) bar->choice_done(seconds_in());
}

// The refinement: every keyframe at the finer width, from the coarse result (not
// checkpointed: a resumed fit redoes it from the checkpoint above, which records that the
// coarse stage had ended, so it is the same refinement).
void FitRun::refine() {
  Fitter& cfit = coarse_fit();
  const TargetFrames& ctarget = *coarse_target;
  if (refine_w > 0 && !stopped) {
    const RenderSize fine_size = render_size(scene, refine_w);
    // Loaded before the keyframes were chosen (the chroma weight's calibration): again, at them.
    if (fine_target && fine_target->keyframes != ctarget.keyframes) drop_fine_target();
    activity("starting the refinement at " + std::to_string(refine_w) + " px");
    // The guard's baseline: how well each coarse keyframe matches the video at the coarse width.
    const std::vector<float> coarse_losses = cfit.evaluate_keyframe_losses();
    // One fitter's loss memory at a time: the coarse one's waits (made again for the guard),
    // freed before the finer target is read (30 keyframes at 256 px: Q and R 31 MB, the
    // residual chunk 32 MB and the tape pool; the same losses: evaluating reads the parameters
    // only, and the finer fitter's start below reads the coarse one's as they stand).
    cfit.release_loss_memory();
    trim_heap();
    // The coarse target from here on is the guard's loss (its rgba) and the clip's timing: the
    // gate and the preview judge the refined fit against the finer target. Its frames before
    // cleanup, distance field and mask go (9 bytes per pixel and keyframe at the coarse width).
    TargetFrames& coarse_frames = coarse_target == &target ? target : *keyed_target;
    std::vector<float>().swap(coarse_frames.raw);
    (coarse_target == &target ? target_raw : keyed_raw) = {};
    std::vector<float>().swap(coarse_frames.sdf);
    std::vector<uint8_t>().swap(coarse_frames.mask);
    const double scale = static_cast<double>(fine_size.width) / size.width;
    // Through the refinement neither target's rgba is read (the coarse fitter's loss waits for
    // the guard; every finer keyframe is active, so no warm start reads the finer one, whose Q
    // and R are made before its iterations): each is packed as runs of exact white
    // (fit/target/white_runs.h) until the stage ends, the coarse one before the finer fitter
    // is built, the finer one before its Q and R are made.
    WhiteRuns coarse_rgba = pack_white_runs(coarse_frames.rgba);
    const auto unpack = [&] {
      if (fine) fine->release_loss_memory();
      unpack_fine_rgba();
      if (fine) fine->read_targets_whole();
      coarse_frames.rgba = unpack_white_runs(coarse_rgba);
    };
    try {
      prepare_fine();
      fine_options.chroma_weight = chroma_weight;
      // Built from the packed frames when the calibration loaded them (the loss reads them
      // below, a keyframe at a time): their floats (88 MB) are never unpacked for it.
      fill_distance_fields(*fine_target);  // dropped after the load (prepare_fine)
      fine = std::make_unique<Fitter>(*rt, fit_scene, *fine_target, fine_options);
      // The fitter has its distance field on the device and nothing reads the target's mask
      // after the load's checks: 5 bytes per pixel and keyframe (21 MB for 16 keyframes at 512 px).
      std::vector<float>().swap(fine_target->sdf);
      std::vector<uint8_t>().swap(fine_target->mask);
      fine->adopt_coarse(cfit, scale);
      log::debug("fit: refining every keyframe at %dx%d for %d iterations", fine_size.width, fine_size.height,
                 refine_iters);
      // Packed before its Q and R are made, which read it a keyframe at a time from the runs:
      // its floats (88 MB for 21 keyframes at 512 px) and Q and R are never held together.
      pack_fine_rgba();
      const size_t frame_px = static_cast<size_t>(fine_size.width) * fine_size.height;
      fine->read_targets_from([this, frame_px](int k, float* out) {
        unpack_white_runs_range(fine_rgba, static_cast<size_t>(k) * frame_px, frame_px, out);
      });
      fine->prepare_loss_memory();
      trim_heap();  // the loss constants' temporaries (double frames at 512 px)
      log::debug("fit: the targets' frames packed through the refinement: %.1f MB at %d px, %.1f MB at %d px",
                 fine_rgba.bytes() / 1048576.0, fine_size.width, coarse_rgba.bytes() / 1048576.0, size.width);
      release_compiler_pages("the finer fitter's programs");
      run_stage(*fine, coarse_iters, false);
    } catch (...) {
      unpack();  // whoever reports the failure may read them
      throw;
    }
    bar->refine_done(seconds_in());
    // The guard below reads the coarse target only: the finer one's floats (88 MB for 21
    // keyframes at 512 px) are unpacked after it, once the coarse loss memory it makes is gone.
    fine->release_loss_memory();
    coarse_frames.rgba = unpack_white_runs(coarse_rgba);
    if (!stopped) {
      // The refinement's guard. A keyframe the refinement made worse at the coarse width (the
      // snail's pupil, off by more than the fine loss's reach, shrank to a hairline at 512 px:
      // 47.4 -> 36.5 dB at 256 px in keyframes 2-4) keeps its coarse fit. Both are judged by
      // the coarse fitter against the coarse target: the refined fit is brought down to it.
      const FitState coarse_fit_state = cfit.state();
      cfit.adopt_coarse(*fine, 1 / scale);
      const std::vector<float> refined_losses = cfit.evaluate_keyframe_losses();
      cfit.restore(coarse_fit_state);
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
      // The guard's loss memory (Q and R, the residual chunk, the tape pool at the coarse
      // width: ~60 MB for 21 keyframes at 256 px) is not needed by the outputs, which render
      // and read the targets; an evaluation after this would make it again.
      cfit.release_loss_memory();
      trim_heap();
    }
    // The finer target's frames stay packed to the end: the gate reads them a keyframe at a
    // time (FitRun::final_cleaned_reader), the preview reads the compact frames before cleanup,
    // and the fitter's loss, were it evaluated again, reads them from the runs (set above).
    // Unpacked here, they were the run's peak with many keyframes: 16 bytes per pixel and
    // keyframe, 142 MB for the twemoji dog's 34 at 512 px, beside every other target and fitter.
  }
}

}  // namespace svgm
