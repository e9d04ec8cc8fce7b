// The scenery of a scene: a figure drawn on a landscape (a railway carriage before mountains,
// on a track, on a meadow) that a grouper put in one part with the ground under it. The whole
// part then drove with the carriage, the mountains' meadow and the rails with it.
//
// A drawing is a scene when one of its paths is a backdrop by its box (scene/backdrop.h) and the
// frame cuts it, with the other paths painted early that reach an edge (the layers of a
// landscape: sky, mountains, meadow, rails), along kBackdropCut of a side. Its subject is
// the largest cluster (by the area of its box) of the paths that reach no edge of the drawing's
// own canvas (within kBackdropEdge) and are no backdrop, joined where their boxes overlap: the
// carriage's body, windows and wheels. Every other path is scenery: bands from edge to edge
// (a meadow, the rails), the pieces of the landscape at its edges, and what lies apart from the
// subject (a bush, the sleepers under the rails). A subject smaller than kSubjectMin of the
// canvas (a cloud, when the figure itself runs off the canvas's edge) is none: nothing is
// scenery. The rig takes scenery out of the parts that hold subject paths too (part_rig.h).
#pragma once

#include <vector>

#include "svgmotion/scene.h"

namespace svgm {

constexpr double kSubjectMin = 0.15;  // of the drawing's canvas: the subject's box at least (a
                                      // carriage before mountains: 0.42; a cloud: under 0.1)

// Per path of `scene`: 1 when it is the scenery of a scene (see above); all 0 when the drawing
// is no scene or has no subject apart from its scenery.
std::vector<char> scenery_paths(const Scene& scene);

// Whether the paths' box runs from edge to edge of the drawing's own canvas (Scene::room), left
// to right or top to bottom, within kBackdropEdge: a band of scenery (the rails under a carriage,
// a meadow) rather than a piece at one edge (a splash cut off by the frame, a board running off
// it: those may be the figure's).
bool edge_to_edge(const Scene& scene, const std::vector<int>& paths);

}  // namespace svgm
