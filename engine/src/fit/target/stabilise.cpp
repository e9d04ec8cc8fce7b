// Camera-shake removal: see stabilise.h for the method and why it is off by default.
#include "fit/target/stabilise.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "fit/target/still_region.h"
#include "fit/target/tile_steps.h"

#include <Eigen/Dense>

#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

namespace svgm {

namespace {

// A phase-correlation peak weaker than this is not a translation of the frame (a cut, a blank
// frame, content replaced): the step is taken as no camera motion.
constexpr double kMinResponse = 0.05;

// When the still part's path has a low-pass no larger than this many times a white path's of
// the same high-pass energy, the figure is taken as not moving: all of the path is shake. (A
// white path scores about 1; a drift of a pixel over the clip, tens.)
constexpr double kWhitePathRatio = 3;

// A clip is a loop when its last frame registers onto its first with a residual under this
// share of the mean step's between frames kLoopIntervals apart over the clip (the fitter's
// loop test with its default 15 keyframes).
constexpr double kLoopResidualShare = 0.25;
constexpr int kLoopIntervals = 14;
// ... and when the camera's move between them is within this many times the rms shake a
// straight low-pass finds (or half a pixel): a figure that slid along is not a loop.
constexpr double kLoopShakeRms = 4;
// The ink is smoothed by this (measuring pixels) for the tiles' Gauss-Newton.
constexpr double kTileInkBlur = 1.0;

// The frame as grey at `width` pixels wide, in its own depth (8 or 16 bits).
cv::Mat grey_at(const cv::Mat& frame, int width) {
  cv::Mat grey;
  if (frame.channels() >= 3)
    cv::cvtColor(frame, grey, frame.channels() == 4 ? cv::COLOR_BGRA2GRAY : cv::COLOR_BGR2GRAY);
  else
    grey = frame;
  const int w = std::min(width, grey.cols);
  const int h = std::max(1, static_cast<int>(std::lround(static_cast<double>(w) * grey.rows / grey.cols)));
  cv::Mat small;
  cv::resize(grey, small, cv::Size(w, h), 0, 0, w < grey.cols ? cv::INTER_AREA : cv::INTER_LINEAR);
  return small;
}

// 1 - grey in [0, 1], as 64-bit floats (phaseCorrelate's precision).
cv::Mat ink_of(const cv::Mat& grey) {
  cv::Mat ink;
  grey.convertTo(ink, CV_64F, grey.depth() == CV_16U ? -1.0 / 65535 : -1.0 / 255, 1.0);
  return ink;
}

// The low-pass as a matrix, row by row: row i holds the weights (from frame first[i] on) that
// give the Gaussian-weighted parabola through the path around i, taken at i (local quadratic
// regression). A steady drift and a constant acceleration (a hop's arc, a swing's turn) pass
// through whole, also where the window runs past either end of the clip. A straight line
// (local linear) bends off a curving motion by a share of its curvature, which then counted as
// shake; on non-rigid 49-frame clips with 1-2 px shake the parabola over a 0.2 s window left
// 0.53-0.59 px of the shake, the line over 0.125 s 0.57-0.98 px.
struct LowPass {
  std::vector<int> first;
  std::vector<std::vector<double>> rows;
};

LowPass local_parabola(int n, double sigma_frames) {
  LowPass lp;
  const int r = static_cast<int>(std::ceil(3 * sigma_frames));
  for (int i = 0; i < n; ++i) {
    const int j0 = std::max(0, i - r), j1 = std::min(n - 1, i + r);
    Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
    std::vector<double> w;
    for (int j = j0; j <= j1; ++j) {
      const double t = j - i;
      w.push_back(std::exp(-0.5 * t * t / (sigma_frames * sigma_frames)));
      const Eigen::Vector3d basis(1, t, t * t);
      a.noalias() += w.back() * basis * basis.transpose();
    }
    std::vector<double> row(w.size());
    if (std::fabs(a.determinant()) > 1e-9) {
      // The parabola's value at i is e0' A^-1 sum_j w_j b_j p_j: row_j = w_j (A^-1 e0) . b_j.
      const Eigen::Vector3d c = a.ldlt().solve(Eigen::Vector3d(1, 0, 0));
      for (int j = j0; j <= j1; ++j) {
        const double t = j - i;
        row[static_cast<size_t>(j - j0)] = w[static_cast<size_t>(j - j0)] * (c[0] + c[1] * t + c[2] * t * t);
      }
    } else {
      // Too few frames for a parabola (a clip of one or two): the weighted mean.
      double sum = 0;
      for (double v : w) sum += v;
      for (size_t k = 0; k < w.size(); ++k) row[k] = w[k] / sum;
    }
    lp.first.push_back(j0);
    lp.rows.push_back(std::move(row));
  }
  return lp;
}

std::vector<std::array<double, 2>> apply_lowpass(const LowPass& lp, const std::vector<std::array<double, 2>>& path) {
  std::vector<std::array<double, 2>> out(path.size(), {0, 0});
  for (size_t i = 0; i < path.size(); ++i)
    for (size_t k = 0; k < lp.rows[i].size(); ++k) {
      const auto& p = path[static_cast<size_t>(lp.first[i]) + k];
      out[i][0] += lp.rows[i][k] * p[0];
      out[i][1] += lp.rows[i][k] * p[1];
    }
  return out;
}

// How much larger the path's low-pass (about its mean) is than a white path's would be, given
// the noise its high-pass shows. For a white path p = mu + e (variance s² per axis), the
// low-pass L p - mean has expected energy s² tr((L - J)'(L - J)) = s² (sum L² - 1) per axis (L
// keeps constants, so its rows sum to 1; J averages), and the high-pass p - L p has
// s² tr((I - L)'(I - L)) = s² (n - 2 tr L + sum L²).
double lowpass_ratio(const LowPass& lp, const std::vector<std::array<double, 2>>& path) {
  const size_t n = path.size();
  const auto smooth = apply_lowpass(lp, path);
  std::array<double, 2> mean{0, 0};
  for (const auto& p : path) mean[0] += p[0] / static_cast<double>(n), mean[1] += p[1] / static_cast<double>(n);
  double low = 0, high = 0, sum_l2 = 0, trace = 0;
  for (size_t i = 0; i < n; ++i) {
    for (int a = 0; a < 2; ++a) {
      low += (smooth[i][a] - mean[a]) * (smooth[i][a] - mean[a]);
      high += (path[i][a] - smooth[i][a]) * (path[i][a] - smooth[i][a]);
    }
    for (size_t k = 0; k < lp.rows[i].size(); ++k) {
      sum_l2 += lp.rows[i][k] * lp.rows[i][k];
      if (static_cast<size_t>(lp.first[i]) + k == i) trace += lp.rows[i][k];
    }
  }
  const double low_dof = sum_l2 - 1, high_dof = static_cast<double>(n) - 2 * trace + sum_l2;
  if (!(low_dof > 1e-9) || !(high_dof > 1e-9)) return 0;
  const double noise = high / high_dof;
  if (!(noise > 0)) return low > 0 ? std::numeric_limits<double>::infinity() : 0;
  return (low / low_dof) / noise;
}

// The translation that carries ink image `a` onto `b` (b shows a's content moved by it), and
// the mean absolute difference left once `b` is moved back by it; nothing when the two do not
// correlate (a cut, a blank frame). Phase correlation finds the step whole (several pixels,
// robust to the figure's own motion), but its sub-pixel centroid is biased by a few hundredths
// of a pixel even between identical frames; enhanced correlation (ECC, Evangelidis and
// Psarakis 2008), a Gauss-Newton fit of the translation started there, makes it exact.
struct Registration {
  cv::Point2d step;
  double residual = 0;
};
std::optional<Registration> register_translation(const cv::Mat& a, const cv::Mat& b) {
  if (a.size() != b.size() || !(cv::sum(a)[0] > 0) || !(cv::sum(b)[0] > 0)) return std::nullopt;
  cv::Mat window;
  cv::createHanningWindow(window, a.size(), CV_64F);
  double response = 0;
  // On copies: with a window and sizes the DFT takes as they are, OpenCV 4.6 multiplies the
  // window into its inputs in place (seen here: the previous frame came back windowed).
  const cv::Point2d d = cv::phaseCorrelate(a.clone(), b.clone(), window, &response);
  if (!(response >= kMinResponse) || !std::isfinite(d.x) || !std::isfinite(d.y)) return std::nullopt;
  cv::Mat warp = (cv::Mat_<float>(2, 3) << 1, 0, static_cast<float>(d.x), 0, 1, static_cast<float>(d.y));
  Registration r{d, 0};
  cv::Mat fa, fb;
  a.convertTo(fa, CV_32F);
  b.convertTo(fb, CV_32F);
  try {
    cv::findTransformECC(fa, fb, warp, cv::MOTION_TRANSLATION,
                         cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 100, 1e-5), cv::noArray(), 3);
    const cv::Point2d refined(warp.at<float>(0, 2), warp.at<float>(1, 2));
    // Kept only when it stays near the whole step (ECC can slide off on a frame whose figure
    // moved more than the camera).
    if (std::isfinite(refined.x) && std::isfinite(refined.y) && std::hypot(refined.x - d.x, refined.y - d.y) < 1.0) r.step = refined;
  } catch (const cv::Exception&) {
    // A degenerate frame (ECC found no correlation): the phase estimate stands.
  }
  cv::Mat back;
  const cv::Matx23d m(1, 0, r.step.x, 0, 1, r.step.y);  // samples b at x + step: a's frame
  cv::warpAffine(fb, back, m, fb.size(), cv::INTER_LINEAR | cv::WARP_INVERSE_MAP, cv::BORDER_REPLICATE);
  r.residual = cv::mean(cv::abs(back - fa))[0];
  return r;
}

// The camera's path when nothing holds still: the steps from each frame to the next, summed (a
// step that does not register counts as no camera motion). Each step is the whole frame's
// registration, refined into a fixed blend of tile steps where the clip has the texture for it
// (fit/target/tile_steps.h: a whole-frame registration of a deforming figure wobbles from step to step).
std::vector<std::array<double, 2>> consecutive_path(const std::vector<cv::Mat>& greys) {
  std::vector<std::optional<std::array<double, 2>>> starts;
  TileStepBlend blend(greys.empty() ? cv::Size() : greys[0].size());  // all frames are this size
  cv::Mat prev, prev_smooth;
  for (const cv::Mat& grey : greys) {
    const cv::Mat ink = ink_of(grey);
    cv::Mat smooth;  // the ink as the tiles want it
    ink.convertTo(smooth, CV_32F);
    cv::GaussianBlur(smooth, smooth, cv::Size(), kTileInkBlur, kTileInkBlur, cv::BORDER_REPLICATE);
    if (!prev.empty()) {
      const auto r = register_translation(prev, ink);
      starts.push_back(r ? std::optional(std::array<double, 2>{r->step.x, r->step.y}) : std::nullopt);
      blend.add(prev_smooth, smooth, starts.back());
    }
    prev = ink;
    prev_smooth = smooth;
  }
  const auto blended = blend.steps();
  std::vector<std::array<double, 2>> path{{0, 0}};
  for (size_t t = 0; t < starts.size(); ++t) {
    std::array<double, 2> step{0, 0};
    if (blended) step = (*blended)[t];
    else if (starts[t]) step = *starts[t];
    path.push_back({path.back()[0] + step[0], path.back()[1] + step[1]});
  }
  return path;
}

// Where the clip may end as it began (a loop: the last frame shows the first's figure, moved
// only by the camera), the camera's move from the first frame to the last; nothing otherwise.
// The rule is the fitter's loop test on its keyframes (fit_job's returns_to_start: the first
// and last differ by under a quarter of a mean step between keyframes, at their default
// spacing), with the last frame registered onto the first. The caller still checks that the
// move is shake-sized: a figure that only slid along keeps its shape too.
std::optional<std::array<double, 2>> loop_closure(const std::vector<cv::Mat>& greys) {
  const int n = static_cast<int>(greys.size());
  if (n < 4) return std::nullopt;
  const cv::Mat first = ink_of(greys.front());
  const auto closure = register_translation(first, ink_of(greys.back()));
  if (!closure) return std::nullopt;
  const int stride = std::max(1, static_cast<int>(std::lround((n - 1) / static_cast<double>(kLoopIntervals))));
  double sum = 0;
  int count = 0;
  cv::Mat prev = first;
  for (int i = 0; i + stride < n; i += stride, ++count) {
    cv::Mat next = ink_of(greys[static_cast<size_t>(i + stride)]);
    sum += cv::mean(cv::abs(prev - next))[0];
    prev = next;
  }
  if (count == 0 || !(closure->residual <= kLoopResidualShare * sum / count)) return std::nullopt;
  return std::array<double, 2>{closure->step.x, closure->step.y};
}

// The shake in `path` (the camera's path plus the figure's common motion): the path less its
// low-pass. On a loop the motion is periodic with the clip's length less one (the last frame
// is the first again), so the low-pass runs round the loop: every frame has a whole window (at
// the ends the parabola otherwise leans on one side, and there it left a 1-2 px shake in the
// last frame, a jump at every pass of the loop's seam), and the last frame's shake is the
// first's plus the camera's move between them (`closure`), measured directly: the stabilised
// clip ends exactly where it began. `closure` is taken only when it is shake-sized (within
// kLoopShakeRms rms of the straight estimate, or half a pixel); `*loop` says whether it was.
std::vector<std::array<double, 2>> shake_of(const std::vector<std::array<double, 2>>& path, double sigma_frames,
                                            const std::optional<std::array<double, 2>>& closure, bool* loop) {
  const size_t n = path.size();
  std::vector<std::array<double, 2>> shake(n);
  const auto smooth = apply_lowpass(local_parabola(static_cast<int>(n), sigma_frames), path);
  double ms = 0;
  for (size_t i = 0; i < n; ++i) {
    shake[i] = {path[i][0] - smooth[i][0], path[i][1] - smooth[i][1]};
    ms += (shake[i][0] * shake[i][0] + shake[i][1] * shake[i][1]) / static_cast<double>(n);
  }
  *loop = closure && std::hypot((*closure)[0], (*closure)[1]) <= std::max(0.5, kLoopShakeRms * std::sqrt(ms));
  if (!*loop) return shake;
  const int period = static_cast<int>(n) - 1;
  const auto closed = close_loop(path, *closure);
  const int r = std::min(static_cast<int>(std::ceil(3 * sigma_frames)), 4 * period);
  std::vector<std::array<double, 2>> ring(static_cast<size_t>(period + 2 * r));
  for (int j = 0; j < period + 2 * r; ++j) ring[static_cast<size_t>(j)] = closed[static_cast<size_t>(((j - r) % period + period) % period)];
  const auto round = apply_lowpass(local_parabola(period + 2 * r, sigma_frames), ring);
  for (int i = 0; i < period; ++i) {
    const auto& m = round[static_cast<size_t>(i + r)];
    shake[static_cast<size_t>(i)] = {closed[static_cast<size_t>(i)][0] - m[0], closed[static_cast<size_t>(i)][1] - m[1]};
  }
  shake[n - 1] = {shake[0][0] + (*closure)[0], shake[0][1] + (*closure)[1]};
  return shake;
}

}  // namespace

// close_loop (stabilise.h). Each frame-to-frame step is off by a few tenths of a pixel where
// the figure deforms (more under a codec), and round a loop those errors add up: on 49-frame
// non-rigid clips the summed path ended 1.4-3.2 px from where the last frame registers onto the
// first. Read as periodic, such a path jumps by all of that at the seam, and the low-pass
// spreads the jump over the frames near the seam as shake. Spread evenly over the steps
// instead (the least-squares path through the steps and the closing step, all weighted
// alike), it is a ramp, which the low-pass takes whole.
std::vector<std::array<double, 2>> close_loop(const std::vector<std::array<double, 2>>& path, const std::array<double, 2>& closure) {
  const size_t n = path.size();
  std::vector<std::array<double, 2>> out(path);
  if (n < 2) return out;
  const std::array<double, 2> gap{path[n - 1][0] - path[0][0] - closure[0], path[n - 1][1] - path[0][1] - closure[1]};
  for (size_t i = 0; i < n; ++i) {
    const double share = static_cast<double>(i) / static_cast<double>(n - 1);
    out[i] = {path[i][0] - share * gap[0], path[i][1] - share * gap[1]};
  }
  return out;
}

void ShakeEstimator::add(const cv::Mat& frame) {
  greys_.push_back(grey_at(frame, width_));
  scale_ = static_cast<double>(frame.cols) / greys_.back().cols;
}

ShakeEstimate ShakeEstimator::estimate(double sigma_frames) const {
  ShakeEstimate est;
  const size_t n = greys_.size();
  est.shake.assign(n, {0, 0});
  est.model = "smooth";
  if (!(sigma_frames > 0) || n == 0) return est;
  const LowPass lp = local_parabola(static_cast<int>(n), sigma_frames);
  const StillRegionPath still = register_still_region(greys_);
  est.still_share = still.still_share;
  est.still_residual_px = still.still_residual_px;
  std::vector<std::array<double, 2>> shake;
  if (still.found) {
    est.path_lowpass_ratio = lowpass_ratio(lp, still.path);
    if (est.path_lowpass_ratio <= kWhitePathRatio) {
      // The figure held still: every step of the path is the camera's, about its mean (the
      // first frame is shaken too; the mean is where the camera stood).
      est.model = "still";
      std::array<double, 2> mean{0, 0};
      for (const auto& p : still.path) mean[0] += p[0] / static_cast<double>(n), mean[1] += p[1] / static_cast<double>(n);
      for (const auto& p : still.path) shake.push_back({p[0] - mean[0], p[1] - mean[1]});
    } else {
      est.model = "still_smooth";
      // The still part's path is measured against the first frame, so a loop closes on its
      // own last value.
      const std::optional<std::array<double, 2>> own =
          loop_closure(greys_) ? std::optional(still.path.back()) : std::nullopt;
      shake = shake_of(still.path, sigma_frames, own, &est.loop);
    }
  } else {
    shake = shake_of(consecutive_path(greys_), sigma_frames, loop_closure(greys_), &est.loop);
  }
  for (size_t i = 0; i < n; ++i) est.shake[i] = {shake[i][0] * scale_, shake[i][1] * scale_};
  return est;
}

cv::Mat remove_shake(const cv::Mat& frame, const std::array<double, 2>& shake) {
  const cv::Matx23d m(1, 0, -shake[0], 0, 1, -shake[1]);
  cv::Mat out;
  cv::warpAffine(frame, out, m, frame.size(), cv::INTER_CUBIC, cv::BORDER_REPLICATE);
  return out;
}

}  // namespace svgm
