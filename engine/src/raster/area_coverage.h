// Exact area coverage on the CPU, for the forward render's layer compositor.
//
// The winding integral of every pixel for one draw of a RasterPlan (the box-filtered winding
// number, what kernels/raster.cl computes per band), by signed-area accumulation: every line
// adds the signed area it leaves to its right into the cells of each row it crosses, and a
// running sum along the row completes each pixel's integral (the accumulation of font-rs,
// R. Levien, see third_party_notes.md). One pass over the lines and one over the pixels, so
// many layers cost little; ref::winding_integrals is the slow oracle the tests compare with.
#pragma once

#include <vector>

#include "raster/raster_plan.h"

namespace svgm {

// Coverage in [0, 1] of every pixel (height * width) for draw `draw`, under its fill rule.
// `pts`: the frame's points in pixel space (ref::flatten then ref::stroke).
std::vector<float> draw_coverage(const RasterPlan& plan, const std::vector<double>& pts, int draw);

}  // namespace svgm
