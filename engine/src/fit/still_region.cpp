// The camera's path from the figure's still part: see still_region.h for the method and why.
#include "fit/still_region.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

namespace svgm {

namespace {

// The ink is blurred by this (measuring pixels) so Gauss-Newton sees a smooth, sub-pixel
// accurate signal, and a frame re-sampled at another sub-pixel phase differs little.
constexpr double kInkBlur = 1.0;
// Tukey's biweight scale, as a share of the ink's contrast: a still edge's residual (codec and
// re-sampling noise) stays well inside it, an edge moved by a pixel leaves it.
constexpr double kTukeyShare = 0.06;
// An edge pixel of the first frame: gradient above this share of the contrast per pixel (a
// sharp edge blurred by kInkBlur peaks at 0.4 of it).
constexpr double kEdgeShare = 0.055;
// Still: a mean squared residual within kStillFactor² of the lowest kLowestShare of the edges'.
constexpr double kLowestShare = 0.05;
constexpr double kStillFactor = 2;
// Accepted as still: the part's median residual in px of displacement, and its share of the
// edges. On non-rigid test clips with a still body it was 0.03-0.10 px (0.10-0.14 of the edges);
// with every part moving, the least moving 5% of the edges scored 0.6-0.8 px.
constexpr double kStillMaxPx = 0.25;
constexpr double kMinStillShare = 0.02;
constexpr int kMinEdgePixels = 50;
constexpr int kRounds = 6;
constexpr int kMaxIterations = 40;
// A phase-correlation peak weaker than this is not a translation (fit/stabilise.cpp's bound).
constexpr double kMinResponse = 0.05;

cv::Mat ink_of(const cv::Mat& grey) {
  cv::Mat ink;
  grey.convertTo(ink, CV_32F, -1.0 / 255, 1.0);
  cv::GaussianBlur(ink, ink, cv::Size(), kInkBlur, kInkBlur, cv::BORDER_REPLICATE);
  return ink;
}

// The first frame and what every registration against it needs.
struct Reference {
  cv::Mat ink, gx, gy, xs, ys;  // CV_32F: ink, its central differences, the pixel grid
  double tukey_c = 0;
};

struct Registration {
  std::array<double, 2> t{0, 0};
  cv::Mat residual;  // ink(x + t) - reference ink(x), CV_32F
};

cv::Mat residual_at(const cv::Mat& ink, const Reference& ref, const std::array<double, 2>& t) {
  cv::Mat mx, my, warped;
  cv::add(ref.xs, cv::Scalar(t[0]), mx);
  cv::add(ref.ys, cv::Scalar(t[1]), my);
  // Lanczos: on a test figure moved 10 px with one-pixel edges, cubic interpolation's own error
  // shifted the registration by up to 0.055 px, Lanczos's by 0.038.
  cv::remap(ink, warped, mx, my, cv::INTER_LANCZOS4, cv::BORDER_REPLICATE);
  return warped - ref.ink;
}

// The translation t with ink(x + t) closest to the reference: inverse-compositional
// Gauss-Newton (Baker and Matthews 2004), so the gradient is the reference's and the normal
// matrix changes only with the weights. `mask` (CV_32F 0/1) weighs the pixels when given;
// otherwise Tukey's biweight of each residual does.
Registration register_frame(const cv::Mat& ink, const Reference& ref, std::array<double, 2> t, const cv::Mat& mask) {
  Registration out;
  cv::Mat r = residual_at(ink, ref, t), w, gxw, gyw;
  for (int it = 0; it < kMaxIterations; ++it) {
    if (!mask.empty()) {
      w = mask;
    } else {
      cv::Mat u2 = r.mul(r, 1.0 / (ref.tukey_c * ref.tukey_c));
      cv::Mat one_minus = 1.0 - u2;
      cv::max(one_minus, 0.0, one_minus);
      w = one_minus.mul(one_minus);
    }
    gxw = w.mul(ref.gx), gyw = w.mul(ref.gy);
    const double h00 = gxw.dot(ref.gx), h01 = gxw.dot(ref.gy), h11 = gyw.dot(ref.gy);
    const double b0 = gxw.dot(r), b1 = gyw.dot(r);
    const double det = h00 * h11 - h01 * h01;
    if (!(det > 1e-12 * (h00 * h11 + 1e-30))) break;  // no edges weighted: keep t
    const double dx = (h11 * b0 - h01 * b1) / det, dy = (h00 * b1 - h01 * b0) / det;
    if (!std::isfinite(dx) || !std::isfinite(dy)) break;
    t = {t[0] - dx, t[1] - dy};
    r = residual_at(ink, ref, t);
    if (std::max(std::fabs(dx), std::fabs(dy)) < 1e-4) break;
  }
  out.t = t;
  out.residual = std::move(r);
  return out;
}

// The value at `share` of the sorted values (0: the lowest).
double quantile(std::vector<float> v, double share) {
  if (v.empty()) return 0;
  const size_t k = std::min(v.size() - 1, static_cast<size_t>(share * static_cast<double>(v.size())));
  std::nth_element(v.begin(), v.begin() + static_cast<ptrdiff_t>(k), v.end());
  return v[k];
}

}  // namespace

StillRegionPath register_still_region(const std::vector<cv::Mat>& greys) {
  StillRegionPath out;
  const size_t n = greys.size();
  out.path.assign(n, {0, 0});
  if (n < 3) return out;
  std::vector<cv::Mat> inks;
  inks.reserve(n);
  for (const cv::Mat& g : greys) inks.push_back(ink_of(g));

  Reference ref;
  ref.ink = inks[0];
  double lo = 0, contrast = 0;
  cv::minMaxLoc(ref.ink, &lo, &contrast);
  if (contrast < 0.02) return out;  // a blank first frame
  ref.tukey_c = kTukeyShare * contrast;
  cv::Sobel(ref.ink, ref.gx, CV_32F, 1, 0, 1, 0.5, 0, cv::BORDER_REPLICATE);
  cv::Sobel(ref.ink, ref.gy, CV_32F, 0, 1, 1, 0.5, 0, cv::BORDER_REPLICATE);
  ref.xs.create(ref.ink.size(), CV_32F);
  ref.ys.create(ref.ink.size(), CV_32F);
  for (int y = 0; y < ref.ink.rows; ++y)
    for (int x = 0; x < ref.ink.cols; ++x) ref.xs.at<float>(y, x) = static_cast<float>(x), ref.ys.at<float>(y, x) = static_cast<float>(y);
  cv::Mat grad;
  cv::magnitude(ref.gx, ref.gy, grad);
  const cv::Mat edges = grad > kEdgeShare * contrast;
  const int edge_count = cv::countNonZero(edges);
  if (edge_count < kMinEdgePixels) return out;

  // 1. Robust registration of every frame, each started at its phase correlation with the first.
  cv::Mat window, ref64;
  cv::createHanningWindow(window, ref.ink.size(), CV_64F);
  ref.ink.convertTo(ref64, CV_64F);
  std::vector<std::array<double, 2>> t(n, {0, 0});
  cv::Mat sum_sq = cv::Mat::zeros(ref.ink.size(), CV_32F);
  const cv::Mat no_mask;
  for (size_t i = 1; i < n; ++i) {
    cv::Mat ink64;
    inks[i].convertTo(ink64, CV_64F);
    double response = 0;
    // On copies: OpenCV 4.6 multiplies the window into phaseCorrelate's inputs in place.
    const cv::Point2d d = cv::phaseCorrelate(ref64.clone(), ink64, window, &response);
    std::array<double, 2> start = t[i - 1];
    if (response >= kMinResponse && std::isfinite(d.x) && std::isfinite(d.y)) start = {d.x, d.y};
    Registration r = register_frame(inks[i], ref, start, no_mask);
    t[i] = r.t;
    cv::accumulateSquare(r.residual, sum_sq);
  }

  // 2-3. The still mask from the residuals over the whole clip, and registration on it alone.
  cv::Mat mask, prev_mask;
  for (int round = 0; round < kRounds; ++round) {
    std::vector<float> edge_values;
    edge_values.reserve(static_cast<size_t>(edge_count));
    for (int y = 0; y < sum_sq.rows; ++y)
      for (int x = 0; x < sum_sq.cols; ++x)
        if (edges.at<uchar>(y, x)) edge_values.push_back(sum_sq.at<float>(y, x));
    const double base = std::max(quantile(edge_values, kLowestShare), 1e-12);
    const cv::Mat still = (sum_sq <= kStillFactor * kStillFactor * base) & edges;
    if (!prev_mask.empty() && cv::countNonZero(still != prev_mask) == 0) break;  // settled
    prev_mask = still;
    still.convertTo(mask, CV_32F, 1.0 / 255);
    sum_sq.setTo(0);
    for (size_t i = 1; i < n; ++i) {
      Registration r = register_frame(inks[i], ref, t[i], mask);
      t[i] = r.t;
      cv::accumulateSquare(r.residual, sum_sq);
    }
  }

  // Accept the still part when its residual is at noise level.
  std::vector<float> px_residual;
  for (int y = 0; y < sum_sq.rows; ++y)
    for (int x = 0; x < sum_sq.cols; ++x)
      if (prev_mask.at<uchar>(y, x))
        px_residual.push_back(static_cast<float>(std::sqrt(sum_sq.at<float>(y, x) / static_cast<double>(n - 1)) /
                                                 std::max(grad.at<float>(y, x), 1e-6f)));
  out.still_share = static_cast<double>(px_residual.size()) / edge_count;
  out.still_residual_px = quantile(px_residual, 0.5);
  out.found = !px_residual.empty() && out.still_share >= kMinStillShare && out.still_residual_px <= kStillMaxPx;
  out.path = t;
  return out;
}

}  // namespace svgm
