// The progress estimate of a fit (see fit_progress.h).
#include "fit/fit_progress.h"

#include <algorithm>

namespace svgm {

FitProgress::FitProgress(int keyframes, int coarse_budget, int refine_budget,
                         double fine_cost, int plateau_window)
    : k_(std::max(1, keyframes)), coarse_budget_(std::max(0, coarse_budget)),
      refine_budget_(std::max(0, refine_budget)),
      tail_(plateau_window > 0 ? 2 * plateau_window : 0),
      fine_cost_(fine_cost) {}

void FitProgress::coarse_step(int iteration, int active) {
  done_ += active + 1; // a rollback re-runs iterations: their work counts again
  coarse_it_ = iteration;
  active_ = active;
  if (active >= k_ && all_active_at_ < 0)
    all_active_at_ = iteration;
}

void FitProgress::coarse_done() { coarse_done_ = true; }

void FitProgress::refine_step(int iteration) {
  coarse_done_ = true;
  done_ += (k_ + 1) * fine_cost_;
  refine_it_ = iteration;
}

double FitProgress::remaining() const {
  // Iterations of a stage still expected after its activations: the tail, or
  // the whole budget without a plateau test; never fewer than a tenth of the
  // tail while the stage runs (it has not said it ended). A quarter kept the
  // man's bar at 84 % with "ETA 10 s" over the last 4 s.
  const auto tail_left = [&](int since, int now, int budget_left) {
    const int tail =
        tail_ > 0 ? std::max(tail_ / 10, since + tail_ - now) : budget_left;
    return std::clamp(tail, 0, std::max(0, budget_left));
  };
  double left = 0;
  if (!coarse_done_) {
    int budget_left = coarse_budget_ - coarse_it_;
    if (active_ < k_) {
      // Iterations per activation so far (the first keyframe is active from the
      // start); before the second activation, the paper's schedule: 70 % of the
      // budget over K - 1 activations.
      const double pace = active_ > 1
                              ? static_cast<double>(coarse_it_) / (active_ - 1)
                              : 0.7 * coarse_budget_ / std::max(1, k_ - 1);
      const double n =
          std::min(pace * (k_ - active_), static_cast<double>(budget_left));
      left += n * ((active_ + k_) / 2.0 + 1);
      budget_left -= static_cast<int>(n);
      left += tail_left(coarse_it_ + static_cast<int>(n),
                        coarse_it_ + static_cast<int>(n), budget_left) *
              (k_ + 1.0);
    } else {
      left += tail_left(all_active_at_, coarse_it_, budget_left) * (k_ + 1.0);
    }
  }
  if (refine_budget_ > 0)
    left += tail_left(0, refine_it_, refine_budget_ - refine_it_) * (k_ + 1.0) *
            fine_cost_;
  return left;
}

double FitProgress::fraction() {
  const double total = done_ + remaining();
  const double f = total > 0 ? (1 - kWriteShare) * done_ / total : 0;
  shown_ = std::clamp(f, shown_, 1 - kWriteShare);
  return shown_;
}

} // namespace svgm
