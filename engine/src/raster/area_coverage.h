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

// Coverage of the pixels inside a rectangle (x0, y0, w, h); zero outside it.
struct Coverage {
  int x0 = 0, y0 = 0, w = 0, h = 0;
  std::vector<float> a;  // h * w, row-major
  float at(int x, int y) const {
    return x < x0 || y < y0 || x >= x0 + w || y >= y0 + h ? 0.0f : a[static_cast<size_t>(y - y0) * w + (x - x0)];
  }
};

// Coverage in [0, 1] for draw `draw`, under its fill rule, over the part of the canvas its
// lines' bounding box touches (a small shape costs its own size, not the canvas's).
// `pts`: the frame's points in pixel space (ref::flatten then ref::stroke).
Coverage draw_coverage_box(const RasterPlan& plan, const std::vector<double>& pts, int draw);

// The same for every pixel (height * width).
std::vector<float> draw_coverage(const RasterPlan& plan, const std::vector<double>& pts, int draw);

}  // namespace svgm
