// Points along a path's cubics, for the geometry that reads a drawing's shape (the part rig:
// part_rig.cpp, stroke_rig.cpp, outline_lobes.cpp; fit/plan/coincident_paths.cpp): from its curves,
// not from its control points (a circle's handles lie 0.14 of its radius beyond it; a sketch's
// handles reach far past its strokes). And the distance to the chords between such samples,
// and a control polygon's area.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "svgmotion/scene.h"

namespace svgm {

// `steps` points per cubic of `sp`, at t = k / steps for k = 0 .. steps - 1 (t = 1 is the next
// cubic's t = 0), appended to `out`; then the subpath's last point when `with_end`.
void append_curve_samples(const Subpath& sp, int steps, bool with_end, std::vector<Vec2>& out);

// Every subpath of `p` sampled so, each with its last point.
std::vector<Vec2> curve_samples(const Path& p, int steps);

// The distance from q to the segment from a to b (to a, when the two coincide).
inline double segment_distance(Vec2 q, Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double len2 = d.x * d.x + d.y * d.y;
  const double t = len2 > 0 ? std::clamp(((q.x - a.x) * d.x + (q.y - a.y) * d.y) / len2, 0.0, 1.0) : 0.0;
  const Vec2 n = a + t * d;
  return std::hypot(q.x - n.x, q.y - n.y);
}

// The signed area of the polygon `p` (closed back to its first point; positive
// counter-clockwise in y-up axes): a fill's area from its control polygon.
inline double shoelace(const std::vector<Vec2>& p) {
  double s = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    const Vec2& a = p[i];
    const Vec2& b = p[(i + 1) % p.size()];
    s += a.x * b.y - b.x * a.y;
  }
  return 0.5 * s;
}

}  // namespace svgm
