// The camera's path from the figure's still part: see still_region.h for the method and why.
#include "fit/target/still_region.h"

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
// Pixels sampled at all: gradient above this share of the contrast (the edges and their blurred
// tails; the first, robust registration needs the tails: on edges alone it settled, on a
// non-rigid clip, 0.2 px off towards the motion, from where the still mask never recovered).
constexpr double kSampleShare = 0.005;
// Still: a mean squared residual within kStillFactor² of the lowest kLowestShare of the edges'.
constexpr double kLowestShare = 0.05;
constexpr double kStillFactor = 2;
// Accepted as still: the part's median residual in px of displacement, and its share of the
// edges. On non-rigid test clips with a still body it was 0.03-0.10 px (0.10-0.14 of the edges);
// with every part moving, the least moving 5% of the edges scored 0.6-0.8 px.
constexpr double kStillMaxPx = 0.25;
constexpr double kMinStillShare = 0.02;
constexpr int kMinEdgePixels = 50;
// The still edges' normal matrix: smaller eigenvalue over larger at least this (a disc: 1; the
// still part of a drawing of straight vertical strokes: near 0).
constexpr double kMinConditioning = 0.05;
constexpr int kRounds = 6;
constexpr int kMaxIterations = 40;
// A phase-correlation peak weaker than this is not a translation (fit/target/stabilise.cpp's bound).
constexpr double kMinResponse = 0.05;

cv::Mat ink_of(const cv::Mat& grey) {
  cv::Mat ink;
  grey.convertTo(ink, CV_32F, grey.depth() == CV_16U ? -1.0 / 65535 : -1.0 / 255, 1.0);
  cv::GaussianBlur(ink, ink, cv::Size(), kInkBlur, kInkBlur, cv::BORDER_REPLICATE);
  return ink;
}

// The first frame's edge pixels, where all the information on a translation is (a pixel of
// zero gradient adds nothing to Gauss-Newton's sums), as 1 x M rows: only they are sampled,
// a tenth or less of the frame.
struct Reference {
  cv::Mat xs, ys;        // pixel positions, CV_32F
  cv::Mat ink, gx, gy;   // the first frame's ink and central differences there, CV_32F
  cv::Mat grad;          // |gradient|
  double tukey_c = 0;
};

struct Registration {
  std::array<double, 2> t{0, 0};
  cv::Mat residual;  // ink(x + t) - reference ink(x) at the edge pixels, CV_32F
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
// matrix changes only with the weights. `mask` (CV_32F 0/1 per edge pixel) weighs the pixels
// when given; otherwise Tukey's biweight of each residual does.
Registration register_frame(const cv::Mat& ink, const Reference& ref, std::array<double, 2> t, const cv::Mat& mask) {
  Registration out;
  cv::Mat r = residual_at(ink, ref, t), w, gxw, gyw;
  for (int it = 0; it < kMaxIterations; ++it) {
    if (!mask.empty()) {
      w = mask;
    } else {
      cv::Mat one_minus = 1.0 - r.mul(r, 1.0 / (ref.tukey_c * ref.tukey_c));
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

  double lo = 0, contrast = 0;
  cv::minMaxLoc(inks[0], &lo, &contrast);
  if (contrast < 0.02) return out;  // a blank first frame
  cv::Mat gx, gy, grad;
  cv::Sobel(inks[0], gx, CV_32F, 1, 0, 1, 0.5, 0, cv::BORDER_REPLICATE);
  cv::Sobel(inks[0], gy, CV_32F, 0, 1, 1, 0.5, 0, cv::BORDER_REPLICATE);
  cv::magnitude(gx, gy, grad);
  // Two samplings of the first frame: `wide` (edges and their tails) for the robust start,
  // `ref` (edges alone) for the mask and the registrations on it.
  auto reference_at = [&](double share) {
    Reference r;
    r.tukey_c = kTukeyShare * contrast;
    std::vector<float> xs, ys, i0, gxs, gys, gs;
    for (int y = 0; y < grad.rows; ++y)
      for (int x = 0; x < grad.cols; ++x)
        if (grad.at<float>(y, x) > share * contrast) {
          xs.push_back(static_cast<float>(x)), ys.push_back(static_cast<float>(y));
          i0.push_back(inks[0].at<float>(y, x)), gs.push_back(grad.at<float>(y, x));
          gxs.push_back(gx.at<float>(y, x)), gys.push_back(gy.at<float>(y, x));
        }
    auto row = [](const std::vector<float>& v) { return cv::Mat(v, true).reshape(1, 1); };
    if (!xs.empty()) r.xs = row(xs), r.ys = row(ys), r.ink = row(i0), r.gx = row(gxs), r.gy = row(gys), r.grad = row(gs);
    return r;
  };
  const Reference ref = reference_at(kEdgeShare);
  const int edge_count = ref.xs.cols;
  if (edge_count < kMinEdgePixels) return out;
  const Reference wide = reference_at(kSampleShare);

  // 1. Robust registration of every frame, each started at its phase correlation with the first.
  cv::Mat window, ref64;
  cv::createHanningWindow(window, inks[0].size(), CV_64F);
  inks[0].convertTo(ref64, CV_64F);
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
    t[i] = register_frame(inks[i], wide, start, no_mask).t;
    cv::accumulateSquare(residual_at(inks[i], ref, t[i]), sum_sq);
  }

  // 2-3. The still mask from the residuals over the whole clip, and registration on it alone.
  cv::Mat mask, still, prev_still;
  for (int round = 0; round < kRounds; ++round) {
    const double base = std::max(quantile(std::vector<float>(sum_sq.begin<float>(), sum_sq.end<float>()), kLowestShare), 1e-12);
    still = sum_sq <= kStillFactor * kStillFactor * base;
    if (!prev_still.empty() && cv::countNonZero(still != prev_still) == 0) break;  // settled
    prev_still = still;
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
  for (int k = 0; k < prev_still.cols; ++k)
    if (prev_still.at<uchar>(0, k))
      px_residual.push_back(static_cast<float>(std::sqrt(sum_sq.at<float>(0, k) / static_cast<double>(n - 1)) /
                                               std::max(ref.grad.at<float>(0, k), 1e-6f)));
  out.still_share = static_cast<double>(px_residual.size()) / edge_count;
  out.still_residual_px = quantile(px_residual, 0.5);
  // And its edges must run in more than one direction: a still part of parallel edges pins the
  // translation across them only (the aperture problem).
  cv::Mat still_f;
  prev_still.convertTo(still_f, CV_32F, 1.0 / 255);
  const cv::Mat gxm = still_f.mul(ref.gx), gym = still_f.mul(ref.gy);
  const double h00 = gxm.dot(ref.gx), h01 = gxm.dot(ref.gy), h11 = gym.dot(ref.gy);
  const double mid = 0.5 * (h00 + h11), half = std::sqrt(0.25 * (h00 - h11) * (h00 - h11) + h01 * h01);
  out.conditioning = mid + half > 0 ? (mid - half) / (mid + half) : 0;
  out.found = !px_residual.empty() && out.still_share >= kMinStillShare && out.still_residual_px <= kStillMaxPx &&
              out.conditioning >= kMinConditioning;
  out.path = t;
  return out;
}

}  // namespace svgm
