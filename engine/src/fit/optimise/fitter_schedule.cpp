// The fitter's schedule (see fitter.h): when the next keyframe becomes active (the paper's
// interval, or sooner once the newest one has settled) and when the fit has stopped improving.
#include "fit/optimise/fitter.h"

#include <algorithm>

namespace svgm {

int Fitter::activation_iteration(int k) const {
  if (k <= 0 || K_ <= 1) return 0;
  const int interval = std::max(1, static_cast<int>(opt_.activation_share * opt_.iterations / (K_ - 1)));
  // A pinned rest keyframe has nothing to fit: keyframe 1 starts at once instead of after an
  // interval in which no parameter moves (the paper's schedule spent its first 100 of 2000
  // iterations there); the interval goes to the joint refinement.
  return (opt_.pin_rest_keyframe ? k - 1 : k) * interval;
}

LossTerms Fitter::step() {
  while (active_ < K_ && activation_due()) {
    activate_keyframe(active_);
    ++active_;
    last_activation_ = iteration_;
    plateau_ref_.clear();
    newest_ref_ = -1;
  }
  // Keyframe 0 fitted freely (a video that starts mid-motion): carried from the rest pose
  // toward its frame before its first step, as every later keyframe is from the one before.
  if (iteration_ == 0 && active_ == 1 && !opt_.pin_rest_keyframe && opt_.track && !started_) warm_start(0, 0);
  started_ = true;
  const LossTerms t = fit_iteration();
  ++iteration_;
  check_plateau();
  return t;
}

namespace {

double mean_of(const std::vector<float>& v) {
  double m = 0;
  for (float x : v) m += x;
  return v.empty() ? 0 : m / static_cast<double>(v.size());
}

// Whether a loss fell from `before` to `after` by more than `tol` of `before` or `floor`,
// whichever is larger (the adaptive activation's and the plateau's test: a loss matched almost
// exactly wobbles by more than the tolerance of itself, and the floor keeps that from counting).
bool fell(double before, double after, double tol, double floor) {
  return before - after > tol * std::max(before, floor);
}

}  // namespace

bool Fitter::activation_due() {
  // The paper's schedule: keyframe 1 (after a pinned rest keyframe) at once, then one every
  // interval; never later than that after the previous activation.
  const int w = opt_.activation_window;
  if (w <= 0) return iteration_ >= activation_iteration(active_);
  const int since = iteration_ - last_activation_;
  if (since >= activation_iteration(active_) - activation_iteration(active_ - 1)) return true;
  if (since == 0 || since % w != 0) return false;
  // The newest keyframe's loss after the last iteration (read_frame_losses: the active ones);
  // its fall is measured against its loss or the active keyframes' mean, whichever is larger
  // (a keyframe matched almost exactly wobbles by more than the tolerance of its tiny loss).
  const std::vector<float> losses = raster_->read_frame_losses();
  const float now = losses.back();
  const bool settled = newest_ref_ >= 0 && !fell(newest_ref_, now, opt_.activation_tol, mean_of(losses));
  newest_ref_ = now;
  return settled;
}

void Fitter::check_plateau() {
  const int w = opt_.plateau_window;
  if (w <= 0 || active_ < K_ || (iteration_ - last_activation_) % w != 0) return;
  // The losses of the iteration just done. The fit has converged when the keyframes' mean loss
  // fell by less than plateau_tol over the window, and no keyframe's by more than
  // plateau_tol_keyframe of its own loss or the mean, whichever is larger: a keyframe still
  // settling (the last activated: tens of percent per window) keeps the fit going however flat
  // the mean is, while Adam's wobble (single keyframes up and down by 1-2 % per window while
  // the mean moves 0.1 %: kite) does not.
  const std::vector<float> now = raster_->read_frame_losses();
  if (!plateau_ref_.empty()) {
    const double ref_mean = mean_of(plateau_ref_);
    bool flat = !fell(ref_mean, mean_of(now), opt_.plateau_tol, 0);
    for (size_t k = 0; k < now.size() && flat; ++k)
      flat = !fell(plateau_ref_[k], now[k], opt_.plateau_tol_keyframe, ref_mean);
    converged_ = flat;
  }
  plateau_ref_ = now;
}

}  // namespace svgm
