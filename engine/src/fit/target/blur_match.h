// Blur matching: how much softer the target video is than our render, measured on the rest pose.
//
// Video models, codecs and resizing soften edges. A loss that blurs render and target alike
// (the paper's σ = 1 Gaussian) then sees a blurred target as a thinner, rounder drawing and
// pulls thin parts and corners in to match (parrot, non-rigid target blurred σ 1.5 px at 512:
// -5.1 dB against its clean fit). Keyframe 0 is the drawing at rest (FitOptions::
// pin_rest_keyframe), so comparing it with our own render of the rest pose measures the blur:
// the render σ of the loss (raster/loss_taps.h) for which G_r ∗ render best matches
// G_t ∗ target is the target's blur as the loss sees it, and fitting with it matches a soft
// video by blurring the drawing instead of deforming it.
#pragma once

#include <vector>

#include "svgmotion/png_io.h"

namespace svgm {

struct BlurMatch {
  double render_sigma = 1;  // the loss's render σ to fit with (1: the paper's, no blur matched)
  double best_sigma = 1;    // the best σ found, whether adopted or not
  double residual_ratio = 1;  // best residual / residual at σ = 1
  double rest_psnr_db = 0;    // of the blurred rest pose against the blurred first frame, at the best σ
  // Chroma: the σ of the render's chroma blur in YCbCr (raster/loss_taps.h, render_blur), luma
  // staying at render_sigma. Equal to render_sigma unless adopted.
  double chroma_sigma = 1;
  double best_chroma_sigma = 1;       // the best found, whether adopted or not
  double chroma_luma_sigma = 1;       // the luma σ of that pair (adopted as render_sigma with it)
  double chroma_residual_ratio = 1;   // its residual / the residual at render_sigma alone
  double chroma_rest_psnr_db = 0;     // as rest_psnr_db, at the best chroma σ
};

// `rest`: our render of the rest pose over white at the fitting size; `target_rgba`: the
// target's keyframe 0 at that size (H * W * 4 floats, straight RGB in [0, 1]). Searches σ from
// 1 to 2 in steps of 0.05 and adopts the best when it lowers the residual by a tenth or more
// and the frame matches the rest pose at 38 dB or better (a first frame that is not the rest
// pose, e.g. a video the user brings, is hardly matched better by blurring alone).
//
// Then chroma alone: codecs keep luma sharp and soften chroma (4:2:0 subsampling, JPEG-like
// quantisation), which a blur of all channels alike cannot match; the fitter then moves edges
// between colours of similar luma to imitate the soft chroma. With luma at the render σ just
// chosen, σ_chroma is searched from there to 2 in the same steps, then luma again (1 up to
// σ_chroma) with chroma fixed, then chroma again; the pair replaces the render σ by the same
// rule (a tenth off the luma-only residual, the rest pose at 38 dB).
BlurMatch match_render_blur(const RgbaImage& rest, const std::vector<float>& target_rgba);

}  // namespace svgm
