// The fold and cut check of a deformed mesh (shape_mesh.h, arap.h): how far a frame's
// deformation is from one the drawing can show. A flipped triangle is a fold (the shape turned
// over on itself), an area ratio near 0 a pinch (a hand thinned to a sliver), a large edge
// stretch a tear about to happen. The planner rejects a frame, or scales its amplitude down,
// before it becomes a candidate.
#pragma once

#include <vector>

#include "motion/shape_mesh.h"

namespace svgm {

struct MeshQuality {
  int flipped = 0;              // triangles whose signed area changed sign (or became 0)
  double min_area_ratio = 1;    // smallest deformed / rest signed area (negative when flipped)
  double max_area_ratio = 1;    // largest deformed / rest signed area
  double max_stretch = 1;       // largest max(len'/len, len/len') over the triangles' edges (>= 1)
};

// `deformed`: one position per vertex of mesh (rest: mesh.vertices). Triangles of zero rest
// area are skipped. Throws svgm::Error on a size mismatch.
MeshQuality mesh_quality(const ShapeMesh& mesh, const std::vector<Vec2>& deformed);

}  // namespace svgm
