// The colours a target's colour correction (colour_correction.h) may map and snap the video's
// pixels to, and whether the drawing is flat enough for it at all.
//
// Colour correction assumes a flat-colour drawing: every flat region of a frame shows one of a
// few colours, and a pixel near one of them is that colour, shaded or drifted. A gradient paint
// breaks both halves. Its path's `fill` is only the mean stop colour, which no pixel shows, and
// the smooth ramp it does show is flat by the 8-neighbour test, so its pixels were matched to
// whatever colour was nearest and set to it. On emoji_u1f304 (sun rays in radial gradients over
// a gradient sky) the cleaned target became flat bands of mean colours: the fitter's own rest
// pose matched it at 21.8 dB, and the fit pulled the rays into flags to make up the difference
// (24.9 dB; 35.5 dB with the correction off).
//
// So: gradient-painted paths give no colour, and a drawing whose gradients cover more than
// kMaxGradientShare of the canvas at rest is not corrected (the video is compared as it is).
#pragma once

#include <array>
#include <vector>

#include "opencl/runtime.h"
#include "svgmotion/scene.h"

namespace svgm {

struct CorrectionPalette {
  std::vector<std::array<float, 3>> colours;  // opaque flat fills and strokes, in paint order
  double gradient_share = 0;  // share of the canvas gradient paint covers at rest, at `width`
  bool usable = true;         // false: correcting would flatten the drawing's own gradients
};

// Gradient paint may cover at most this share of the canvas for the correction to run. 2%: a
// highlight or two (the scenes' cheeks and glints) keeps the correction for the flat rest.
inline constexpr double kMaxGradientShare = 0.02;

// The palette of `scene` as the fitter renders it `width` pixels wide (the gradient share is
// measured with one render, only when some path has gradient paint).
CorrectionPalette correction_palette(ClRuntime& rt, const Scene& scene, int width);

}  // namespace svgm
