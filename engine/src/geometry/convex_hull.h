// The convex hull of a point set (Andrew's monotone chain, 1979): O(n log n), counter-clockwise
// in a y-up frame (clockwise on screen), without collinear points. Used where a shape is judged
// by the region it spans (the part locator's lobes).
#pragma once

#include <vector>

#include "svgmotion/scene.h"

namespace svgm {

// The hull's corners in order; fewer than three points come back sorted as given.
std::vector<Vec2> convex_hull(std::vector<Vec2> points);

}  // namespace svgm
