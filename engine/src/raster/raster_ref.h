// The CPU reference of the rasteriser kernels, in double precision, under the kernels' names.
//
// Each function mirrors one kernel of kernels/*.cl for one frame: flatten (F = B P), stroke
// (the same fixed-topology outline construction), and raster. The raster reference is NOT a
// port of the kernel's accumulation: it computes each pixel's winding integral independently,
// by clipping every closed contour to the pixel square (Sutherland-Hodgman) and taking the
// signed area, which is slow and obviously right. Tests compare the kernels with these
// functions under stated error bounds, and the gradient checks use them as the oracle: central
// differences of this forward pass. At an edge lying exactly on a pixel boundary, where the
// loss has a kink, those converge to the mean of the one-sided derivatives, which is what
// kernels/raster_backward.cl computes there; so the oracle needs no gradient code of its own.
#pragma once

#include <vector>

#include "raster/raster_plan.h"

namespace svgm::ref {

// cp: n_cp (x, y) pairs of one frame. Returns n_pts (x, y) pairs: flattened vertices, then the
// stroke outline points.
std::vector<double> flatten(const RasterPlan& plan, const std::vector<double>& cp);
void stroke(const RasterPlan& plan, std::vector<double>& pts);

// The winding integral of every pixel for one draw (height * width values).
std::vector<double> winding_integrals(const RasterPlan& plan, const std::vector<double>& pts,
                                      int draw);

// Premultiplied RGBA (height * width * 4) of one frame, composited in paint order over
// transparent.
std::vector<double> raster(const RasterPlan& plan, const std::vector<double>& pts);

// The whole forward pass of one frame: flatten, stroke, raster.
std::vector<double> render(const RasterPlan& plan, const std::vector<double>& cp);

// Coverage from a winding integral under a fill rule (the prelude's fill_rule_coverage).
double fill_rule_coverage(double a, int rule);

}  // namespace svgm::ref
