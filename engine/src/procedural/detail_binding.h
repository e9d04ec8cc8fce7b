// What each point of a drawing's details rides on: an outline drawn over a limb's fill moves with
// the limb.
//
// Many drawings keep their colours and their line art apart: openmoji draws every shape's fill in
// one group and every black outline in another, twemoji and clipart often lay a shading or a
// contour over the fill it shades. The rig (part_rig.h) makes the line group one Detail part
// hanging from the root, so when a limb swings its fill went and its outline stayed: a turtle's
// green neck slid out of its black contour. Here each control point of a Detail part's paths is
// bound to the most specific moving part whose fill it lies on (inside the fill, or within the
// detail's stroke width of its edge, as an outline drawn on the edge does). A point lying only on
// the root, or on nothing, keeps its own part's motion, so details that were right stay as they
// were, bit for bit. A stroke that runs from a limb onto the body has points of both: it stretches
// across the joint with them instead of being cut.
#pragma once

#include <vector>

#include "procedural/part_rig.h"
#include "svgmotion/scene.h"

namespace svgm {

// Per path, per control point (subpaths in order, points in order): the part whose motion the
// point takes, or -1 where it keeps its path's own part (rig.part_of_path). Empty inner vectors
// for paths that are not details or have no point bound elsewhere. Points are bound to parts
// that are neither the root, a detail nor the background: heads, limbs, tails, wheels and what
// hangs from them.
std::vector<std::vector<int>> bind_detail_points(const Scene& scene, const Rig& rig);

}  // namespace svgm
