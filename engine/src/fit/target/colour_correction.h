// Per-frame colour correction of a target video against the colours the drawing is made of.
//
// Video models (and cameras and codecs) do not keep a flat drawing's colours: the background
// drifts to off-white, the whole frame takes a tint that grows over the clip, parts pick up
// soft shading, and compression adds noise inside flat regions. Every one of these makes the
// blurred-MSE loss pull the drawing's edges towards the wrong place. The drawing itself tells
// us what the frame should contain: its own flat colours (or the recolouring palette) and the
// white background. So, per frame:
//   1. flat pixels (every 8-neighbour within kFlatTolerance) are matched to the nearest of
//      those colours, accepting only clear matches (close, and much closer than the second
//      nearest: a ratio test, as in feature matching); a flat pixel that no colour clearly
//      explains is matched by hue (the colour whose multiple by a gain in 0.7..1.3 is
//      nearest), since shading darkens a part towards other colours of the drawing without
//      changing its hue;
//   2. an affine colour map c' = A c + b is fitted to the matches by least squares, each colour
//      weighing the same however many pixels show it, with a ridge towards the identity so a
//      frame showing two colours cannot make up the other dimensions (Eigen solves the 4x4
//      normal equations); steps 1-2 alternate a few times, as in ICP;
//   3. shading: each flat pixel's gain against its colour, smoothed into a field over 1/12 of
//      the frame (normalised convolution), divides the frame where there is evidence;
//   4. the map is applied to the whole frame (off the flats, only its change of luma: the
//      codec's chroma there is smeared, not shifted), and flat pixels that clearly match a
//      colour are set to it exactly (the shading and noise the steps above leave).
// Edge pixels keep their corrected values: they hold the sub-pixel edge positions we fit.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace svgm {

struct ColourCorrection {
  std::array<float, 12> map{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};  // rows of [A | b]
  int colours_matched = 0;  // palette colours (white included) with enough flat pixels
  size_t pixels_snapped = 0;
  size_t pixels_shaded = 0;  // pixels divided by the smoothed shading gain
  bool applied = false;     // false: the frame was left as it was (too little evidence)
};

// Corrects one frame in place: `rgba` is width*height*4 straight floats in [0, 1] (A ignored).
// `palette` holds the drawing's colours; white is always added. Deterministic.
ColourCorrection correct_colours(float* rgba, int width, int height,
                                 const std::vector<std::array<float, 3>>& palette);

}  // namespace svgm
