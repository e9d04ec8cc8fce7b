// Does the target video start at the drawing's rest pose?
//
// An image-to-video model starts from the input image, so keyframe 0 is pinned to the drawing
// as it is (FitOptions::pin_rest_keyframe). A video the user brings may start mid-motion (a
// clip cut from a longer one, a loop started anywhere): pinned there, keyframe 0 shows the
// wrong pose and the spline drags the first frames toward it. The fit asks the target: the
// foreground of our render of the rest pose against the foreground of the video's first frame.
#pragma once

#include "svgmotion/png_io.h"
#include "svgmotion/target_video.h"

namespace svgm {

// Below this foreground IoU the first frame is not the rest pose. A first frame at rest scores
// 0.96-1 (codec noise and antialiasing move a boundary pixel here and there; both masks are
// dilated alike); a figure a few pixels off its rest pose already scores below 0.9.
constexpr double kRestStartIou = 0.9;

struct RestStart {
  bool at_rest = true;
  double iou = 1;  // of the rest render's foreground and the first frame's (both dilated alike)
};

// `rest`: our render of the rest pose over white at the target's size; `target`: the fit's
// target (keyframe 0 is its first frame); `white_threshold` and `dilate_px` as the target's
// mask was made (TargetOptions).
RestStart judge_rest_start(const RgbaImage& rest, const TargetFrames& target, double white_threshold, int dilate_px,
                           double min_iou = kRestStartIou);

}  // namespace svgm
