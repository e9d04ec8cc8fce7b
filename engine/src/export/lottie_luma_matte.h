// A luminance mask's content rewritten so that its alpha is the mask's value: the content of an
// alpha matte (`tt` 1) that every Lottie player draws the way SVG draws the mask.
//
// Why not a luma matte (`tt` 3): lottie-web 5.13's canvas renderer throws on the first frame of
// any composition holding one ("assetLoader.loadLumaCanvas is not a function", lottie-web issue
// #3202) and draws nothing at all, and where it works it takes alpha = 0.3 (R + G + B), which is
// neither Rec. 709's luminance nor times alpha. Alpha mattes are drawn alike by lottie-web (svg
// and canvas), librlottie and ThorVG.
//
// SVG's luminance mask value is L = 0.2125 R + 0.7154 G + 0.0721 B of the content composited
// premultiplied (raster/layer_compositor.cpp), and L is linear in the colour, so a path of
// straight colour c and alpha a contributes L(c) a. Painting each path white with alpha L(c) a
// makes the alpha of one path, or of paths that do not overlap, exactly the mask's value. Where
// paths overlap, source-over composites alpha as a1 + a2 (1 - a1) but the mask as
// L1 a1 + L2 a2 (1 - a1): the two agree when the upper path is white (L1 = 1). A black upper
// path (L1 = 0, the usual cut-out) gives a2 (1 - a1): the lower content under an inverted alpha
// matte (`tt` 2) of the upper path, which the composer writes (`cut`). Any other grey drawn over
// other content is written white at L a and named as approximate.
//
// Gradient stops interpolate straight colour and alpha linearly, so L(c(t)) a(t) is quadratic
// between two stops where both change: stops are added in between until the white gradient's
// linear alpha is within 1/512 of it.
#pragma once

#include <vector>

#include "svgmotion/scene.h"

namespace svgm::lottie {

struct AlphaMatteContent {
  std::vector<Path> paths;          // the mask's paths, painted white at alpha L a
  std::vector<Gradient> gradients;  // their gradients, white with alpha stops; the paths index these
  std::vector<bool> cut;            // per path: black everywhere over earlier content (an inverted matte)
  bool exact = true;                // false when a grey path lies over earlier content
};

// `mask`'s content for an alpha matte (see above); `gradients` are the scene's.
AlphaMatteContent luminance_as_alpha(const Mask& mask, const std::vector<Gradient>& gradients);

}  // namespace svgm::lottie
