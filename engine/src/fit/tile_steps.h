// The camera's step from each frame to the next as a fixed blend of local steps, for clips in
// which nothing holds still (fit/stabilise.h, model "smooth").
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

namespace svgm {

// `inks`: the clip's frames as ink (1 - grey, 0..1), CV_32F, all the same size, smoothed a
// little (Gauss-Newton needs gradients wider than a pixel). `starts[t]`: the whole frame's step
// from frame t to t + 1 (frame t + 1 shows frame t's content moved by it), nothing where the
// step did not register (it then stays as it is: no camera motion). Returns one step per pair
// of frames, or nothing when no tile has texture throughout (a blank or plain clip) or the
// tiles pin only one direction.
std::optional<std::vector<std::array<double, 2>>> blended_steps(
    const std::vector<cv::Mat>& inks, const std::vector<std::optional<std::array<double, 2>>>& starts);

}  // namespace svgm
