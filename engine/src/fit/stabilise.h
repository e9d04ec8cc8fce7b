// Camera-shake removal for targets: a hand-held or generated clip whose whole frame jitters by a
// pixel or two from frame to frame. The fitter would copy that jitter into the animation (every
// part of the drawing twitching together), and at display size it costs more than any other
// defect of a real video (bug, non-rigid target, 1-2 px shake in a 512-px clip: -14 dB at
// 1024 px).
//
// The camera path is estimated from the frames themselves: the translation between consecutive
// frames by phase correlation of their "ink" (1 - grey, so the white background weighs nothing),
// summed into a path. Shake is what remains of that path after a low-pass over time (a
// Gaussian-weighted local parabola, so a steady drift or acceleration passes whole);
// the low-pass part, a figure's deliberate drift or a jump's arc, is kept. This is the classic
// smoothed-camera-path stabiliser (e.g. Matsushita et al. 2006, "Full-frame video
// stabilization"; here with translation only, which is what shake of a fixed camera is).
// Off by default: a whole figure that genuinely moves quickly (a hop) would be damped too.
#pragma once

#include <array>
#include <vector>

#include <opencv2/core.hpp>

namespace svgm {

// Accumulates the frames of a clip one at a time and reports the shake of each.
class ShakeEstimator {
 public:
  // `width`: the width frames are measured at (a thumbnail keeps this cheap; sub-pixel phase
  // correlation stays accurate to about a tenth of a pixel at 256 px).
  explicit ShakeEstimator(int width) : width_(width) {}

  // The next frame of the clip, 8-bit or 16-bit BGR(A) or grey, any size.
  void add(const cv::Mat& frame);

  // Shake of every frame added, in the frame's own pixels (x, y): the frame shows the scene
  // moved by this much, so shifting it by minus this stabilises it. `sigma_frames` is the
  // low-pass's standard deviation in frames.
  std::vector<std::array<double, 2>> shake(double sigma_frames) const;

 private:
  int width_;
  double scale_ = 1;                       // frame pixels per measuring pixel
  cv::Mat prev_;                           // the previous frame's ink at the measuring width
  std::vector<std::array<double, 2>> path_;  // accumulated translation, measuring pixels
};

// `frame` moved by (-shake), same size, edges repeated (the background continues).
cv::Mat remove_shake(const cv::Mat& frame, const std::array<double, 2>& shake);

}  // namespace svgm
