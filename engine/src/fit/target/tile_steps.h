// The camera's step from each frame to the next as a fixed blend of local steps, for clips in
// which nothing holds still (fit/target/stabilise.h, model "smooth").
//
// Such a clip's camera path is the sum of frame-to-frame steps, each measured over the whole
// figure, and then low-passed: the figure's own motion is smooth over time, the shake is not.
// A whole-frame registration (phase correlation, ECC) of a deforming figure answers with a
// blend of its parts' motions, but with weights that change from frame to frame: which edges
// dominate the fit depends on the pose, on sub-pixel phase and on codec noise. The blend then
// wobbles by a few tenths of a pixel from one step to the next (0.2-0.7 px rms on the non-rigid
// bench clips at 512 px), at every frequency, and the low-pass leaves that wobble in as shake.
//
// Here each step is measured in tiles instead: a Lucas-Kanade translation per tile (inverse
// compositional Gauss-Newton, Baker and Matthews 2004), started at the whole frame's step, and
// the tiles' steps d_k(t) are combined with weights W_k fixed over the whole clip (each tile's
// normal matrix, averaged over the clip): step(t) = (sum W_k)^-1 sum W_k d_k(t). The shake moves
// every tile alike and comes through whole; the figure's motion comes through as one fixed
// blend of its parts' smooth motions, which is smooth, and the low-pass takes it. On the bench
// clips the steps' error outside the motion's band fell from 0.18-0.67 px to 0.04-0.05.
// A tile that lacks texture in either direction, or whose fit leaves its start by more than a
// few pixels, at any step is left out of every step, so the weights stay fixed.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/core/matx.hpp>

namespace svgm {

// Fed the clip's frames a pair at a time (only two frames are held: a long clip's frames are
// not all kept as floats), it blends once the last step is in.
class TileStepBlend {
 public:
  // `size`: the frames' size.
  explicit TileStepBlend(cv::Size size);
  ~TileStepBlend();

  // The step from frame `a` to the next, `b`, both as ink (1 - grey, 0..1), CV_32F, smoothed a
  // little (Gauss-Newton needs gradients wider than a pixel). `start`: the whole frame's step
  // (b shows a's content moved by it); nothing where it did not register, and that step then
  // stays no camera motion.
  void add(const cv::Mat& a, const cv::Mat& b, const std::optional<std::array<double, 2>>& start);

  // One step per add(), or nothing when no tile had texture throughout (a blank or plain clip)
  // or the tiles pin only one direction: the caller keeps the whole frame's steps then.
  std::optional<std::vector<std::array<double, 2>>> steps() const;

 private:
  struct Tile {  // a tile stays usable only while every step fits in it
    cv::Rect rect;
    bool usable = true;
    cv::Matx22d weight = cv::Matx22d::zeros();  // sum over the steps of its normal matrices
    std::vector<cv::Vec2d> step;                // per registered step
  };

  cv::Size size_;
  std::vector<Tile> tiles_;
  std::vector<bool> registered_;  // per add(): was there a start
};

}  // namespace svgm
