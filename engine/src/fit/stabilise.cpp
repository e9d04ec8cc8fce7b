// Camera-shake removal: see stabilise.h for the method and why it is off by default.
#include "fit/stabilise.h"

#include <cmath>

#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

namespace svgm {

namespace {

// A phase-correlation peak weaker than this is not a translation of the frame (a cut, a blank
// frame, content replaced): the step is taken as no camera motion.
constexpr double kMinResponse = 0.05;

// 1 - grey in [0, 1] at `width` pixels wide, as 64-bit floats (phaseCorrelate's precision).
cv::Mat ink_of(const cv::Mat& frame, int width) {
  cv::Mat grey;
  if (frame.channels() >= 3)
    cv::cvtColor(frame, grey, frame.channels() == 4 ? cv::COLOR_BGRA2GRAY : cv::COLOR_BGR2GRAY);
  else
    grey = frame;
  const int w = std::min(width, grey.cols);
  const int h = std::max(1, static_cast<int>(std::lround(static_cast<double>(w) * grey.rows / grey.cols)));
  cv::Mat small;
  cv::resize(grey, small, cv::Size(w, h), 0, 0, w < grey.cols ? cv::INTER_AREA : cv::INTER_LINEAR);
  cv::Mat ink;
  small.convertTo(ink, CV_64F, grey.depth() == CV_16U ? -1.0 / 65535 : -1.0 / 255, 1.0);
  return ink;
}

}  // namespace

void ShakeEstimator::add(const cv::Mat& frame) {
  cv::Mat ink = ink_of(frame, width_);
  scale_ = static_cast<double>(frame.cols) / ink.cols;
  std::array<double, 2> at = path_.empty() ? std::array<double, 2>{0, 0} : path_.back();
  if (!prev_.empty() && prev_.size() == ink.size() && cv::sum(prev_)[0] > 0 && cv::sum(ink)[0] > 0) {
    // Phase correlation finds the step whole (several pixels, robust to the figure's own
    // motion), but its sub-pixel centroid is biased by a few hundredths of a pixel even between
    // identical frames; enhanced correlation (ECC, Evangelidis and Psarakis 2008), a
    // Gauss-Newton fit of the translation started there, makes it exact.
    cv::Mat window;
    cv::createHanningWindow(window, ink.size(), CV_64F);
    double response = 0;
    // On copies: with a window and sizes the DFT takes as they are, OpenCV 4.6 multiplies the
    // window into its inputs in place (seen here: the previous frame came back windowed).
    const cv::Point2d d = cv::phaseCorrelate(prev_.clone(), ink.clone(), window, &response);
    if (response >= kMinResponse && std::isfinite(d.x) && std::isfinite(d.y)) {
      cv::Mat warp = (cv::Mat_<float>(2, 3) << 1, 0, static_cast<float>(d.x), 0, 1, static_cast<float>(d.y));
      cv::Point2d step = d;
      try {
        cv::Mat a, b;
        prev_.convertTo(a, CV_32F);
        ink.convertTo(b, CV_32F);
        cv::findTransformECC(a, b, warp, cv::MOTION_TRANSLATION,
                             cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 100, 1e-5), cv::noArray(), 3);
        const cv::Point2d refined(warp.at<float>(0, 2), warp.at<float>(1, 2));
        // Kept only when it stays near the whole step (ECC can slide off on a frame whose
        // figure moved more than the camera).
        if (std::isfinite(refined.x) && std::isfinite(refined.y) && std::hypot(refined.x - d.x, refined.y - d.y) < 1.0) step = refined;
      } catch (const cv::Exception&) {
        // A degenerate frame (ECC found no correlation): the phase estimate stands.
      }
      at = {at[0] + step.x, at[1] + step.y};
    }
  }
  path_.push_back(at);
  prev_ = ink;
}

std::vector<std::array<double, 2>> ShakeEstimator::shake(double sigma_frames) const {
  const int n = static_cast<int>(path_.size());
  std::vector<std::array<double, 2>> out(static_cast<size_t>(n), {0, 0});
  if (!(sigma_frames > 0)) return out;
  const int r = static_cast<int>(std::ceil(3 * sigma_frames));
  for (int i = 0; i < n; ++i) {
    // The low-pass is a Gaussian-weighted straight line through the path around i, taken at i
    // (local linear regression): a steady drift passes through whole, also where the window
    // runs past either end of the clip, where a plain weighted mean would lag it.
    double s0 = 0, s1 = 0, s2 = 0, sx = 0, sy = 0, sxt = 0, syt = 0;
    for (int j = std::max(0, i - r); j <= std::min(n - 1, i + r); ++j) {
      const double t = j - i, w = std::exp(-0.5 * t * t / (sigma_frames * sigma_frames));
      const auto& p = path_[static_cast<size_t>(j)];
      s0 += w, s1 += w * t, s2 += w * t * t;
      sx += w * p[0], sy += w * p[1], sxt += w * t * p[0], syt += w * t * p[1];
    }
    // Intercept of the weighted fit a + b t: (s2 Σwx − s1 Σwtx) / (s0 s2 − s1²).
    const double det = s0 * s2 - s1 * s1;
    const double lx = det > 1e-12 ? (s2 * sx - s1 * sxt) / det : sx / s0;
    const double ly = det > 1e-12 ? (s2 * sy - s1 * syt) / det : sy / s0;
    const auto& p = path_[static_cast<size_t>(i)];
    out[static_cast<size_t>(i)] = {(p[0] - lx) * scale_, (p[1] - ly) * scale_};
  }
  return out;
}

cv::Mat remove_shake(const cv::Mat& frame, const std::array<double, 2>& shake) {
  const cv::Matx23d m(1, 0, -shake[0], 0, 1, -shake[1]);
  cv::Mat out;
  cv::warpAffine(frame, out, m, frame.size(), cv::INTER_CUBIC, cv::BORDER_REPLICATE);
  return out;
}

}  // namespace svgm
