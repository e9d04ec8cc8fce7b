// The double-precision CPU reference of kernels/stroke_backward.cl: the vector-Jacobian product
// of stroke expansion (ref::stroke). See the kernel's essay for the maths of every piece.
#pragma once

#include <limits>
#include <vector>

#include "raster/raster_plan.h"

namespace svgm::ref {

// pts: n_pts (x, y) pairs of one frame (the polylines are read). grad_pts: n_pts (x, y) pairs;
// the gradients of the stroke outline points are read and, for every stroked subpath, the
// gradient with respect to its polyline vertices is ADDED at the vertices' places. Constants
// (half widths, miter limits, joins, caps) get no gradient. On the branch the geometry selects
// (the forward's own tests decide it) the result is that branch's exact derivative.
void stroke_backward(const RasterPlan& plan, const std::vector<double>& pts,
                     std::vector<double>& grad_pts);

// Which branches the stroke of `pts` takes, counted per (join vertex, side) and per cap, and
// how close any branch condition is to switching: `margin` is the smallest distance of a
// test's value from its threshold over every test of the forward (segment length from the
// degenerate threshold, |turn|, 1 + c, the miter ratio test, the inner point test). Exactly
// degenerate segments (length 0) and straight joins by inheritance (both directions from the
// same segment) are stable under small moves and do not count. Finite differences are only
// meaningful with steps well below the margin.
struct StrokeBranches {
  int inner_x = 0, inner_pivot = 0;               // inner side of a turn
  int miter = 0, miter_clip = 0, miter_over = 0;  // outer: miter fits / clipped / falls to bevel
  int bevel = 0, round = 0;                       // outer: bevel and round joins
  int straight = 0;                               // both directions from one segment
  int square_caps = 0, round_caps = 0;
  int inherited = 0;  // segments whose direction comes from another segment
  int dots = 0;       // subpaths without any valid segment
  double margin = std::numeric_limits<double>::infinity();
};
StrokeBranches stroke_branches(const RasterPlan& plan, const std::vector<double>& pts);

}  // namespace svgm::ref
