// How much two parts' drawn shapes overlap, for the part rig's choice of what a part hangs from.
//
// The rig hangs each part from the larger part it overlaps most. Measured on bounding boxes, a
// long diagonal object wins over the surface a detail really sits on: man_demon's trident, held
// up across his head, has a box that holds the whole horn, while the hood the horn grows from
// holds only its base; the horn hung from the trident and swung off the head with the arm in the
// target video. The shapes themselves overlap where the horn sits, not where the shaft passes.
#pragma once

#include <vector>

#include "svgmotion/scene.h"
#include "procedural/part_rig.h"

namespace svgm {

// A part's filled outlines as polygons (its paths' cubics sampled), with their box.
struct PartShape {
  std::vector<std::vector<Vec2>> rings;  // one per subpath
  std::vector<int> path;                 // the path each ring belongs to (consecutive)
  std::vector<FillRule> rules;           // the fill rule of each ring's path
  RigBox box;
};

PartShape part_shape(const Scene& scene, const std::vector<int>& paths);

// Is `q` inside the shape: inside any of its paths by that path's fill rule. Rings of one path
// count together (a ring drawn the other way round is a hole).
bool shape_contains(const PartShape& s, Vec2 q);

// The area both shapes cover, estimated on a 24 x 24 grid of cell centres over the overlap of
// their boxes (0 when the boxes do not meet).
double shape_overlap(const PartShape& a, const PartShape& b);

}  // namespace svgm
