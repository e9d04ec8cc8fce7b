// The progress estimate of a fit (see fit_progress.h).
#include "fit/fit_progress.h"

#include <algorithm>

namespace svgm {

FitProgress::FitProgress(const Plan &plan)
    : plan_(plan), k_(std::max(1, plan.keyframes)) {
  plan_.coarse_budget = std::max(0, plan.coarse_budget);
  plan_.refine_budget = std::max(0, plan.refine_budget);
  plan_.choice_frames = std::max(0, plan.choice_frames);
}

void FitProgress::step(double units, double now, bool refine) {
  auto &t = refine ? fine_t_ : coarse_t_;
  auto &u = refine ? fine_u_ : coarse_u_;
  t.push_back(now);
  u.push_back((u.empty() ? 0 : u.back()) + units);
  if (t.size() > kPaceWindow + 1) {
    t.erase(t.begin());
    u.erase(u.begin());
  }
  if (!refine)
    coarse_pace_ = pace(t, u, coarse_pace_);
}

void FitProgress::coarse_step(int iteration, int active, double now) {
  coarse_it_ = iteration;
  active_ = active;
  // The fitter activates before an iteration runs: the last activation came
  // after `iteration - 1` iterations (the plateau tests count from there).
  if (active >= k_ && all_active_at_ < 0)
    all_active_at_ = iteration - 1;
  // A rollback re-runs iterations: their time and work count again.
  step(active + kBase, now, false);
}

void FitProgress::coarse_done(double) {
  if (phase_ == Phase::Coarse)
    phase_ = plan_.choice_frames > 0 ? Phase::Choice : Phase::Refine;
}

void FitProgress::keyed_start(int keyframes, int budget, double) {
  k_ = std::max(k_, keyframes);
  keyed_budget_ = std::max(0, budget);
  keyed_it_ = 0;
  reload_fine_ = true;
  phase_ = Phase::Keyed;
  // The judging of frames before it is not an iteration: the pace starts afresh
  // (coarse_pace_ stands in until it is measured again).
  coarse_t_.clear();
  coarse_u_.clear();
}

void FitProgress::keyed_step(int iteration, double now) {
  keyed_it_ = iteration;
  step(k_ + kBase, now, false);
}

void FitProgress::choice_done(double) {
  if (phase_ == Phase::Choice || phase_ == Phase::Keyed)
    phase_ = Phase::Refine;
}

void FitProgress::refine_step(int iteration, double now) {
  phase_ = Phase::Refine;
  refine_it_ = iteration;
  step((k_ + kBase) * plan_.fine_pixels * kFineCost, now, true);
}

void FitProgress::refine_done(double) {
  phase_ = Phase::Refine;
  refine_over_ = true;
}

double FitProgress::pace(const std::vector<double> &t,
                         const std::vector<double> &u, double fallback) const {
  if (t.size() < kPaceWindow / 5 + 1 || u.back() <= u.front())
    return fallback;
  return (t.back() - t.front()) / (u.back() - u.front());
}

int FitProgress::iterations_left(int since, int now, int budget,
                                 int first_end) const {
  const int w = plan_.plateau_window;
  const int budget_left = std::max(0, budget - now);
  if (w <= 0)
    return budget_left;
  // Tests at since + m * w; the end expected at test `first_end`, or at the next
  // one after `now` (a test at `now` did not end it: the stage still runs), and
  // then a share of a window more (the stage may outlive that test too).
  const int m = std::max(first_end, std::max(0, now - since) / w + 1);
  const int end = since + m * w + (2 * w) / 5;
  return std::clamp(end - now, 0, budget_left);
}

double FitProgress::seconds_left() const {
  const double K = k_;
  double coarse = 0, fine = 0; // keyframe-iterations at each width
  if (phase_ == Phase::Coarse) {
    const int budget_left = plan_.coarse_budget - coarse_it_;
    if (active_ < k_) {
      // Iterations per activation so far (the first keyframe is active from the
      // start); before the second activation, the paper's schedule: 70 % of the
      // budget over K - 1 activations.
      const double per =
          active_ > 1 ? static_cast<double>(coarse_it_) / (active_ - 1)
                      : 0.7 * plan_.coarse_budget / std::max(1, k_ - 1);
      const int n = static_cast<int>(std::min(
          per * (k_ - active_), static_cast<double>(std::max(0, budget_left))));
      coarse += n * ((active_ + K) / 2 + kBase);
      const int at = coarse_it_ + n;
      coarse += iterations_left(at, at, plan_.coarse_budget, kCoarseEndTest) * (K + kBase);
    } else {
      coarse += iterations_left(all_active_at_, coarse_it_, plan_.coarse_budget,
                                kCoarseEndTest) *
                (K + kBase);
    }
  }
  if (phase_ == Phase::Coarse || phase_ == Phase::Choice)
    coarse += kChoicePerFrame * plan_.choice_frames;
  if (phase_ == Phase::Keyed)
    coarse += iterations_left(0, keyed_it_, keyed_budget_, kCoarseEndTest) *
              (K + kBase);
  const double per_refine = (K + kBase) * plan_.fine_pixels * kFineCost;
  if (plan_.refine_budget > 0 && !refine_over_) {
    if (phase_ != Phase::Refine || refine_it_ == 0) {
      fine += kRefineSetup * per_refine;
      if (reload_fine_)
        coarse += kFineLoadPerKeyframe * K;
    }
    fine += iterations_left(0, refine_it_, plan_.refine_budget, kRefineEndTest) *
            per_refine;
  }
  if (plan_.refine_budget > 0)
    fine += kEndRefined * per_refine;
  else
    coarse += kEnd * (K + kBase);
  return coarse_pace_ * coarse + pace(fine_t_, fine_u_, coarse_pace_) * fine;
}

double FitProgress::fraction(double now) {
  // The pace of a coarse fit with few keyframes active says little of the rest's:
  // on a loaded machine an iteration's cost grew 3.5x more than its keyframes did
  // between 3 and 21 of them (the bar's first estimate was 13 s for 126 s).
  const bool early = phase_ == Phase::Coarse && 2 * active_ < k_;
  if (coarse_pace_ <= 0 || now <= 0 || early)
    return shown_;
  const double f = now / (now + seconds_left());
  shown_ = std::clamp(f, shown_, 0.999);
  return shown_;
}

} // namespace svgm
