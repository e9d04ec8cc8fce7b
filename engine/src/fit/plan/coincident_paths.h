// Paths drawn on top of one another with the same outline are one shape to the eye, and fitted
// as one.
//
// Illustrator's exports (the Noto emoji, most clipart) build shading by stacking: a rounded
// screen in a dark gradient, then the same outline twice more in light, mostly transparent
// gradients for the bevel. Each of the overlays is a top-level path, a part of its own, so the
// fitter gave each its own homography and field. The video moves them together and a fit at
// 256 px barely sees them part (a few tenths of a pixel, a faint anti-aliased line), but at
// 1024 px the light overlay's edge stands out as a grey rim round the dark screen
// (emoji_u1f9d1_200d_1f4bb, keyframe 8). Fitted in the group of the path they cover (the fit
// plan's path hosts, fit_plan.h), they move by the same map and field, which carries equal
// points to equal points: the outlines cannot part.
#pragma once

#include <vector>

#include "svgmotion/scene.h"

namespace svgm {

// Two outlines coincide when every point of each lies within this share of the canvas's larger
// side of the other (the technologist's bevel is offset 0.17 of 128 units: 0.0013).
constexpr double kCoincidentShare = 0.005;

// For every path alone in its unit (in no group, or in a group of its own: the reader gives each
// top-level path one), the first earlier path whose outline coincides with its own (within
// `share` of the canvas's larger side); -1 for the others. fit_plan.h's path hosts take it: the
// path is fitted in that path's group.
std::vector<int> coincident_hosts(const Scene& scene, double share = kCoincidentShare);

}  // namespace svgm
