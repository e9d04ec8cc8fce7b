// The camera's path read off the part of the figure that holds still.
//
// A character animation seldom moves everything: the man waves one arm, the caterpillar nods its
// head, and the rest of the drawing stays where it is. On such a clip camera shake is exactly
// the translation that puts the still part back onto the first frame, and it can be measured to
// a few hundredths of a pixel from that part alone. Without it (every part of the figure moving)
// the shake can only be told from the motion by the motion's smoothness over time, which leaves
// a share of the shake in (fit/target/stabilise.h: about sigma * sqrt(p / N) of it).
//
// The still part is not known in advance, so it is found and used in turn (a robust
// registration with a mask learnt across the whole clip):
//  1. Each frame is registered to the first by a translation, started at their phase
//     correlation and refined by Gauss-Newton on the blurred ink (1 - grey) with Tukey's
//     biweight on the residual: pixels of moving parts leave the fit.
//  2. A pixel is still when its squared residual, averaged over the clip after the frames are
//     registered, is within a small factor of the lowest such averages among edge pixels: a
//     part that moves even a tenth of a pixel in some frames shows there, while the codec's and
//     resampling's noise is the same on every frame. (Per frame, a slowly moving edge and a
//     still one re-sampled at another sub-pixel phase leave residuals of the same size, and a
//     per-frame robust fit is pulled towards the motion by tenths of a pixel.)
//  3. Every frame is registered again by least squares on the still pixels alone, and 2-3
//     repeat until the mask settles.
// The still part is accepted when its edges' residual, in pixels of displacement (residual over
// gradient), stays at noise level; a figure with no still part scores several times higher.
#pragma once

#include <array>
#include <vector>

#include <opencv2/core.hpp>

namespace svgm {

struct StillRegionPath {
  bool found = false;                        // a still part was found and registered
  std::vector<std::array<double, 2>> path;   // translation of each frame against the first, px
  double still_share = 0;                    // the still part's share of the first frame's edges
  double still_residual_px = 0;              // its median residual in px of displacement
  double conditioning = 0;                   // its edges' normal matrix: min / max eigenvalue
};

// `greys`: the clip's frames as 8- or 16-bit grey, all the same size (white paper, dark ink).
StillRegionPath register_still_region(const std::vector<cv::Mat>& greys);

}  // namespace svgm
