// Does the target video start at the drawing's rest pose?
//
// An image-to-video model starts from the input image, so keyframe 0 is pinned to the drawing
// as it is (FitOptions::pin_rest_keyframe). A video the user brings may start mid-motion (a
// clip cut from a longer one, a loop started anywhere): pinned there, keyframe 0 shows the
// wrong pose and the spline drags the first frames toward it. The fit asks the target: the
// foreground of our render of the rest pose against the foreground of the video's first frame.
//
// A soft video (a codec, a resize, a model's blur) spreads every edge's ink a pixel or more
// beyond the drawing's outline, so its foreground grows where our sharp render's does not: a
// thin figure's first frame at rest, blurred σ 1.5 px at 512, scored IoU 0.88 at 256 (spider)
// and lost its pin. The render is first blurred as much as the video is softer than it (blur
// matching's render σ, fit/blur_match.h: the video is G_e ∗ render with σ_e² = σ_r² − 1), so
// both foregrounds see the same spread. Pinned again, that spider's blurred fit costs 2.81 dB
// at 1024 px against its clean fit instead of 4.00 (2.01 instead of 1.61 at 256).
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
// mask was made (TargetOptions); `render_sigma`: the loss's render σ blur matching chose for
// this target (BlurMatch::render_sigma; 1, the paper's, when the video is as sharp as the
// render), whose excess over 1 blurs the render before its foreground is taken.
RestStart judge_rest_start(const RgbaImage& rest, const TargetFrames& target, double white_threshold, int dilate_px,
                           double min_iou = kRestStartIou, double render_sigma = 1);

// The Gaussian blur of σ `sigma` (taps to 3σ, normalised) that takes the rest render to what a
// video of blur-matched render σ `render_sigma` shows, applied to `rest` over white; `rest`
// itself when the σ is 1 or less. Exposed for tests.
RgbaImage blur_rest_as_target(const RgbaImage& rest, double render_sigma);

}  // namespace svgm
