// Paths drawn on top of one another with the same outline are one shape to the eye, and fitted
// as one.
//
// Illustrator's exports (the Noto emoji, most clipart) build shading by stacking: a rounded
// screen in a dark gradient, then the same outline twice more in light, mostly transparent
// gradients for the bevel. Each of the overlays is a top-level path, a part of its own, so the
// fitter gave each its own homography and field. The video moves them together and a fit at
// 256 px barely sees them part (a few tenths of a pixel, a faint anti-aliased line), but at
// 1024 px the light overlay's edge stands out as a grey rim round the dark screen
// (emoji_u1f9d1_200d_1f4bb, keyframe 8). Fitted in the group of the path they cover, they move
// by the same map and field, which carries equal points to equal points: the outlines cannot
// part.
#pragma once

#include <string>
#include <vector>

#include "svgmotion/scene.h"

namespace svgm {

// Two outlines coincide when every point of each lies within this share of the canvas's larger
// side of the other (the technologist's bevel is offset 0.17 of 128 units: 0.0013).
constexpr double kCoincidentShare = 0.005;

// `scene` with every path that is alone in its unit (in no group, or in a group of its own) and
// whose outline coincides with an earlier path's moved into that path's fit group (a new group
// named after it when it has none); groups left empty go. One line per covered path that took
// others in `notes` (may be null). Unchanged when no outlines coincide. A path among others in
// a group stays there: the group is a part that moves together already.
Scene merge_coincident_paths(const Scene& scene, std::vector<std::string>* notes);

}  // namespace svgm
