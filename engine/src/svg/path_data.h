// SVG path data ("d") into subpaths of cubic Béziers.
#pragma once

#include <string_view>
#include <vector>

#include "svgmotion/scene.h"

namespace svgm::svg {

struct PathDataResult {
  bool ok = true;             // false: an error stopped parsing at error_offset
  size_t error_offset = 0;
  bool out_of_range = false;  // a number overflowed or spelled nan/inf
};

// Appends the subpaths of `d` (user units, untransformed) to `out`. Every command becomes
// cubics: lines with control points at thirds, quadratics elevated exactly, arcs split into
// pieces of at most 90 degrees (SVG 1.1 implementation notes F.6). As SVG specifies, an error
// keeps everything before the bad segment.
PathDataResult parse_path_data(std::string_view d, std::vector<Subpath>& out);

// Appends cubic control points (after the current point) approximating the SVG arc from `p0`
// to `p1`; a zero radius gives a straight line, radii too small are scaled up.
void arc_to_cubics(Vec2 p0, double rx, double ry, double x_axis_rotation_deg, bool large_arc,
                   bool sweep, Vec2 p1, std::vector<Vec2>& out);

}  // namespace svgm::svg
