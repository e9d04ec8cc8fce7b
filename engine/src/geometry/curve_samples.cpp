// Points along a path's cubics (see curve_samples.h).
#include "geometry/curve_samples.h"

namespace svgm {

void append_curve_samples(const Subpath& sp, int steps, bool with_end, std::vector<Vec2>& out) {
  const auto& c = sp.points;
  for (size_t s = 0; s + 3 < c.size(); s += 3)
    for (int k = 0; k < steps; ++k) {
      const double t = static_cast<double>(k) / steps, u = 1 - t;
      out.push_back(u * u * u * c[s] + 3 * u * u * t * c[s + 1] + 3 * u * t * t * c[s + 2] + t * t * t * c[s + 3]);
    }
  if (with_end && !c.empty()) out.push_back(c.back());
}

std::vector<Vec2> curve_samples(const Path& p, int steps) {
  std::vector<Vec2> out;
  for (const Subpath& sp : p.subpaths) append_curve_samples(sp, steps, true, out);
  return out;
}

}  // namespace svgm
