// Points along a path's cubics, for the part rig's geometry (part_rig.cpp, stroke_rig.cpp,
// outline_lobes.cpp): each reads a drawing's shape from its curves, not from its control points
// (a circle's handles lie 0.14 of its radius beyond it; a sketch's handles reach far past its
// strokes).
#pragma once

#include <vector>

#include "svgmotion/scene.h"

namespace svgm {

// `steps` points per cubic of `sp`, at t = k / steps for k = 0 .. steps - 1 (t = 1 is the next
// cubic's t = 0), appended to `out`; then the subpath's last point when `with_end`.
void append_curve_samples(const Subpath& sp, int steps, bool with_end, std::vector<Vec2>& out);

// Every subpath of `p` sampled so, each with its last point.
std::vector<Vec2> curve_samples(const Path& p, int steps);

}  // namespace svgm
