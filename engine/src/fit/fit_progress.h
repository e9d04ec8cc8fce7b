// How far a fit has gone, for the progress bar and its ETA: the work done over
// the work done plus an estimate of the work left, never going back.
//
// The work is counted in keyframe-iterations at the fitting width: an iteration
// costs about (active keyframes + 1) of them (measured on the bundled man at
// 256 px: 100 iterations take 1.4 s with 4 keyframes active and 5.2 s with 20),
// and a refinement iteration at width W (W / fitting width)^2 times that. The
// iteration budget is not the estimate: keyframes are activated as soon as the
// newest has settled and the fit ends when the loss stops falling, so the man's
// default fit of 2000 + 250 iterations ends after 770 + 100, and a bar over the
// budget stopped at 57-81 % (issue 37). Instead, the activations left are
// expected at the pace of those so far, then a tail of two plateau windows (the
// coarse fit above ended 70 iterations after its last activation, the
// refinement after 100), each capped by its budget. When an estimate grows, the
// bar holds still until the work catches up; it never moves back. The last
// share (kWriteShare) is left for writing the outputs; the host's bar shows 100
// % when the stage has ended.
#pragma once

namespace svgm {

class FitProgress {
public:
  // `keyframes` K, the coarse and refinement budgets (iterations; 0: no
  // refinement), what a refinement iteration costs per keyframe relative to a
  // coarse one, and the plateau window (0: every iteration of both budgets
  // runs).
  FitProgress(int keyframes, int coarse_budget, int refine_budget,
              double fine_cost, int plateau_window);

  // Coarse iteration `iteration` (1-based) ran with `active` keyframes.
  void coarse_step(int iteration, int active);
  // The coarse fit ended (budget spent or converged): no coarse work is left.
  void coarse_done();
  // Refinement iteration `iteration` (1-based, counted within the refinement)
  // ran.
  void refine_step(int iteration);

  // Monotone, in [0, 1 - kWriteShare].
  double fraction();

  // The share of the bar left for writing the outputs (about 5 % of the man's
  // fit: 3.3 of 71 s).
  static constexpr double kWriteShare = 0.05;

private:
  double remaining() const;

  int k_, coarse_budget_, refine_budget_, tail_;
  double fine_cost_;
  double done_ = 0;
  int coarse_it_ = 0, active_ = 1, all_active_at_ = -1, refine_it_ = 0;
  bool coarse_done_ = false;
  double shown_ = 0;
};

} // namespace svgm
