// Camera-shake removal for targets: a hand-held or generated clip whose whole frame jitters by a
// pixel or two from frame to frame. The fitter would copy that jitter into the animation (every
// part of the drawing twitching together), and at display size it costs more than any other
// defect of a real video (bug, non-rigid target, 1-2 px shake in a 512-px clip: -14 dB at
// 1024 px).
//
// Shake and motion are told apart by one of two priors, whichever the clip supports:
//  - Part of the figure holds still (fit/target/still_region.h). The translation that puts the still
//    part back onto the first frame is the camera's path, measured to a few hundredths of a
//    pixel. When that path is white (its low-pass is no larger than a white path's would be),
//    the figure did not move and all of it is shake (model "still"); when it has a course of
//    its own (the whole figure drifting or hopping), only what its low-pass leaves is
//    (model "still_smooth").
//  - Nothing holds still: the path of frame-to-frame steps, minus its low-pass over time (model
//    "smooth"). Each step is a fixed blend of tile steps started at the whole frame's phase
//    correlation and ECC (fit/target/tile_steps.h), so the figure's motion enters the path smoothly.
//    This leaves about sigma * sqrt(p / N) of the shake in (p the low-pass's degrees of freedom
//    over N frames): nothing in such a clip tells that part apart from the motion. On the
//    non-rigid bench clips (49 frames, 1.6 px rms shake at 512 px) it is 0.44-0.48 px, as much
//    as an ideal low-pass of the motion's own band leaves (0.47).
// The low-pass is a Gaussian-weighted local parabola, so a steady drift or acceleration passes
// whole. On a loop (the last frame registers onto the first as well as a still frame would) it
// runs round the loop, and the last frame's shake is the first's plus the camera's move between
// them, so the stabilised clip closes and the fit's loop seam does not jump. This is the classic smoothed-camera-path stabiliser (e.g. Matsushita et al. 2006,
// "Full-frame video stabilization"; here with translation only, which is what shake of a fixed
// camera is), with the still part as its reference where there is one.
// Off by default: a whole figure that genuinely moves quickly (a hop) would be damped too.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace svgm {

// The shake of every frame, in the frame's own pixels (x, y): the frame shows the scene moved by
// this much, so shifting it by minus this stabilises it. And how it was told from the motion.
struct ShakeEstimate {
  std::vector<std::array<double, 2>> shake;
  std::string model;             // "still", "still_smooth" or "smooth" (see above)
  double still_share = 0;        // the still part's share of the first frame's edges
  double still_residual_px = 0;  // its median residual, px of displacement at the measuring width
  double path_lowpass_ratio = 0; // the still part's path: low-pass energy over a white path's
  bool loop = false;             // the clip ends as it began: the low-pass ran round the loop
};

// Accumulates the frames of a clip one at a time and reports the shake of each.
class ShakeEstimator {
 public:
  // `width`: the width frames are measured at (a thumbnail keeps this cheap). Every frame is
  // kept at it until estimate(): 49 frames of a 512-px clip take 13 MB.
  explicit ShakeEstimator(int width) : width_(width) {}

  // The next frame of the clip, 8-bit or 16-bit BGR(A) or grey, any size.
  void add(const cv::Mat& frame);

  // The shake of every frame added. `sigma_frames` is the low-pass's standard deviation in
  // frames.
  ShakeEstimate estimate(double sigma_frames) const;
  std::vector<std::array<double, 2>> shake(double sigma_frames) const { return estimate(sigma_frames).shake; }

 private:
  int width_;
  double scale_ = 1;                       // frame pixels per measuring pixel
  std::vector<cv::Mat> greys_;             // every frame, grey at the measuring width (own depth)
};

// A camera path summed from frame-to-frame steps round a loop, closed: its first-to-last move
// made equal to `closure` (the camera's move from the first frame to the last, registered
// directly) by spreading the difference evenly over the steps. A constant error per step
// (a ramp) comes back out whole.
std::vector<std::array<double, 2>> close_loop(const std::vector<std::array<double, 2>>& path,
                                              const std::array<double, 2>& closure);

// `frame` moved by (-shake), same size, edges repeated (the background continues).
cv::Mat remove_shake(const cv::Mat& frame, const std::array<double, 2>& shake);

}  // namespace svgm
