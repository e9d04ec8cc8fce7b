// How far a fit has gone, for the progress bar and its ETA: the seconds spent over
// the seconds spent plus an estimate of the seconds left, never going back.
//
// The host draws its ETA from the bar's pace (frontends/cli: the seconds since the
// stage started over the share shown), so the bar is only honest when its share is
// a share of the time. The estimate therefore counts every part of a fit that takes
// time, not only the iterations (issue 37: a bar over iterations alone stood still
// for 35 s between the coarse fit and the refinement, and the ETAs after it were
// 1.95x and 2.5x the time left):
//   - the setup before the first iteration (reading and denoising the video,
//     OpenCL's first launches) is time already spent when the bar first moves;
//   - iterations are counted in keyframe-iterations, (active keyframes + kBase)
//     each, a refinement iteration kFineCost times the pixel ratio more; their
//     seconds come from the pace measured over the last kPaceWindow iterations
//     (the refinement's own once it has run kPaceWindow / 5 of them);
//   - the keyframe choice after the coarse fit, the refinement's setup and the
//     writing of the outputs are expected to cost what they cost on the man
//     (constants below), at the measured pace.
// How many iterations a stage runs is not its budget: keyframes are activated as
// soon as the newest has settled, and a stage ends at the first plateau test (every
// `plateau_window` iterations once every keyframe is active) that finds the loss
// flat, never before the second. The activations left are expected at the pace of
// those so far; the end at the test stages of its kind most often end at
// (kCoarseEndTest, kRefineEndTest), or the next one once the stage has outlived it.
// When an estimate grows, the bar holds still until the time catches up; it never
// moves back, and it stays below 1 (the host shows 100 % when the stage has ended).
// The estimate is 0 until the pace is known: the host shows the activity instead
// (the iteration and the keyframes active).
#pragma once

#include <vector>

namespace svgm {

class FitProgress {
public:
  struct Plan {
    int keyframes = 1;       // K
    int coarse_budget = 0;   // coarse iterations left
    int refine_budget = 0;   // refinement iterations (0: no refinement)
    double fine_pixels = 1;  // a refinement frame's pixels over a coarse one's
    int plateau_window = 0;  // 0: every iteration of each budget runs
    int choice_frames = 0;   // frames the keyframe choice judges (0: it does not run)
  };
  explicit FitProgress(const Plan& plan);

  // Every event gives `now`, seconds since the fit job began.
  // Coarse iteration `iteration` (1-based) ran with `active` keyframes.
  void coarse_step(int iteration, int active, double now);
  // The coarse fit ended (budget spent or converged).
  void coarse_done(double now);
  // The keyframe choice added keyframes: `keyframes` now, fitted jointly for at
  // most `budget` iterations (then the refinement loads its frames again).
  void keyed_start(int keyframes, int budget, double now);
  void keyed_step(int iteration, double now);
  // The keyframe choice (and the joint fit after it) ended.
  void choice_done(double now);
  // Refinement iteration `iteration` (1-based, within the refinement) ran.
  void refine_step(int iteration, double now);
  // The refinement ended (converged or its budget spent): only the end is left.
  void refine_done(double now);

  // Monotone, in [0, 1); 0 until the pace is known (kPaceWindow / 5 iterations,
  // and half the keyframes active).
  double fraction(double now);
  // The seconds the estimate expects after the last event (for tests).
  double seconds_left() const;

  // Iterations the pace is measured over (the first iteration, with the kernels'
  // first launches, is never in it).
  static constexpr int kPaceWindow = 100;
  // An iteration's cost in keyframe-iterations: active keyframes + kBase. The man
  // at 256 px on an idle machine: 5.8 ms per iteration with 6 keyframes active,
  // 14.6 ms with 20 (0.63 ms per keyframe, 2.1 ms besides: 3.3 keyframes' worth);
  // on a loaded one (load average 20 on 2 cores) 22 ms with 5 and 100 ms with 21:
  // about 0 besides.
  static constexpr double kBase = 2;
  // A refinement iteration's cost per keyframe over a coarse one's, per pixel ratio:
  // the man at 512 px after 256 px (4x the pixels) took 43 ms per iteration against
  // 14.6 ms at 256 px with all 21 keyframes active: 2.95x, 0.75 of the ratio.
  static constexpr double kFineCost = 0.75;
  // The keyframe choice, per frame judged, in keyframe-iterations: the man's judged
  // 28 frames in 4.1 s at 0.66 ms per keyframe-iteration (coarse, 21 keyframes).
  static constexpr double kChoicePerFrame = 220;
  // The refinement's setup (its fitter, the guard's baseline), in refinement
  // iterations: 1.6 s on the man, 37 of its iterations; with keyframes added, its
  // frames loaded again: per keyframe, in keyframe-iterations (the man's 21 at 512
  // px with denoising and blur matching: 3.7 s, 5600).
  static constexpr double kRefineSetup = 40, kFineLoadPerKeyframe = 270;
  // The plateau test a stage is expected to end at (counted from its last
  // activation; the first only takes the reference, so the second is the earliest
  // end), then 2/5 of a window more, or the next test after the one it outlived.
  // In the fit.json files of this session's runs (default budgets), 8 coarse fits
  // of 17 ended at the second test, 6 at the third, 3 later; of 15 refinements
  // (at twice the width: its loss starts from the coarse fit's blur) 1 at the
  // second, 8 at the third, 4 at the fourth, 2 at the budget.
  static constexpr int kCoarseEndTest = 2, kRefineEndTest = 3;
  // The end (the refinement's guard, the exports at full size with their tolerance
  // searches for animation.svg and animation.json, the preview, the report): after a
  // refinement, in its iterations, else in iterations with every keyframe active at
  // the coarse width. The man, idle, since animation.json has a search of its own:
  // 5.0 s, about 125 refinement iterations (40 ms each) or 600 coarse ones (8 ms);
  // before it 1.3 s (30 refinement iterations), when an ETA of 1 s had 4.3 s left.
  static constexpr double kEndRefined = 110, kEnd = 550;

private:
  enum class Phase { Coarse, Choice, Keyed, Refine };
  // Iterations a stage is still expected to run: `since` is when its last keyframe
  // became active, `now` the iterations done, `budget` its budget, `first_end` the
  // plateau test it is expected to end at.
  int iterations_left(int since, int now, int budget, int first_end) const;
  // Seconds per keyframe-iteration over the recent steps of the current stage;
  // `fallback` when too few.
  double pace(const std::vector<double>& t, const std::vector<double>& u,
              double fallback) const;
  void step(double units, double now, bool refine);

  Plan plan_;
  int k_;
  Phase phase_ = Phase::Coarse;
  int coarse_it_ = 0, active_ = 1, all_active_at_ = -1;
  int keyed_budget_ = 0, keyed_it_ = 0, refine_it_ = 0;
  bool reload_fine_ = false, refine_over_ = false;
  // The recent steps of the coarse-width stages and of the refinement: time and
  // cumulated keyframe-iterations.
  std::vector<double> coarse_t_, coarse_u_, fine_t_, fine_u_;
  double coarse_pace_ = 0; // seconds per keyframe-iteration, once known
  double shown_ = 0;
};

} // namespace svgm
