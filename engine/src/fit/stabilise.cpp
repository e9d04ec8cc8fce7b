// Camera-shake removal: see stabilise.h for the method and why it is off by default.
#include "fit/stabilise.h"

#include <cmath>

#include <Eigen/Dense>

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
    // The low-pass is a Gaussian-weighted parabola through the path around i, taken at i
    // (local quadratic regression): a steady drift and a constant acceleration (a hop's arc, a
    // swing's turn) pass through whole, also where the window runs past either end of the
    // clip. A straight line (local linear) bends off a curving motion by a share of its
    // curvature, which then counted as shake; on non-rigid 49-frame clips with 1-2 px shake
    // the parabola over a 0.2 s window left 0.53-0.59 px of the shake, the line over 0.125 s
    // 0.57-0.98 px.
    Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
    Eigen::Matrix<double, 3, 2> b = Eigen::Matrix<double, 3, 2>::Zero();
    for (int j = std::max(0, i - r); j <= std::min(n - 1, i + r); ++j) {
      const double t = j - i, w = std::exp(-0.5 * t * t / (sigma_frames * sigma_frames));
      const Eigen::Vector3d basis(1, t, t * t);
      const auto& p = path_[static_cast<size_t>(j)];
      a.noalias() += w * basis * basis.transpose();
      b.col(0) += w * p[0] * basis;
      b.col(1) += w * p[1] * basis;
    }
    // Too few frames for a parabola (a clip of one or two): the weighted mean.
    Eigen::Matrix<double, 3, 2> c = Eigen::Matrix<double, 3, 2>::Zero();
    if (std::fabs(a.determinant()) > 1e-9) c = a.ldlt().solve(b);
    else c.row(0) = b.row(0) / a(0, 0);
    const auto& p = path_[static_cast<size_t>(i)];
    out[static_cast<size_t>(i)] = {(p[0] - c(0, 0)) * scale_, (p[1] - c(0, 1)) * scale_};
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
