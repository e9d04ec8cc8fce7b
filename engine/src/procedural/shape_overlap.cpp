// Overlap of two parts' shapes (see shape_overlap.h).
#include "procedural/shape_overlap.h"

#include <algorithm>

#include "geometry/curve_samples.h"

namespace svgm {

namespace {

// The winding number of a closed polygon about q (crossings of the ray to +x, signed).
int winding(const std::vector<Vec2>& ring, Vec2 q) {
  int w = 0;
  const size_t n = ring.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec2 a = ring[i], b = ring[(i + 1) % n];
    if ((a.y <= q.y) == (b.y <= q.y)) continue;
    const double x = a.x + (q.y - a.y) / (b.y - a.y) * (b.x - a.x);
    if (x > q.x) w += b.y > a.y ? 1 : -1;
  }
  return w;
}

}  // namespace

PartShape part_shape(const Scene& scene, const std::vector<int>& paths) {
  PartShape s;
  for (int pi : paths) {
    const Path& p = scene.paths[static_cast<size_t>(pi)];
    for (const auto& sp : p.subpaths) {
      std::vector<Vec2> ring;
      append_curve_samples(sp, 6, true, ring);
      if (ring.size() < 3) continue;
      for (const Vec2& q : ring) s.box.add(q);
      s.rings.push_back(std::move(ring));
      s.path.push_back(pi);
      s.rules.push_back(p.fill_rule);
    }
  }
  return s;
}

bool shape_contains(const PartShape& s, Vec2 q) {
  if (s.box.empty() || q.x < s.box.x0 || q.x > s.box.x1 || q.y < s.box.y0 || q.y > s.box.y1) return false;
  // Rings of one path are consecutive; the path's winding is their sum.
  size_t i = 0;
  while (i < s.rings.size()) {
    int w = 0;
    size_t j = i;
    for (; j < s.rings.size() && s.path[j] == s.path[i]; ++j) w += winding(s.rings[j], q);
    if (s.rules[i] == FillRule::EvenOdd ? (w & 1) != 0 : w != 0) return true;
    i = j;
  }
  return false;
}

double shape_overlap(const PartShape& a, const PartShape& b) {
  if (a.box.empty() || b.box.empty()) return 0;
  const double x0 = std::max(a.box.x0, b.box.x0), x1 = std::min(a.box.x1, b.box.x1);
  const double y0 = std::max(a.box.y0, b.box.y0), y1 = std::min(a.box.y1, b.box.y1);
  if (!(x1 > x0 && y1 > y0)) return 0;
  constexpr int N = 24;
  int hits = 0;
  for (int iy = 0; iy < N; ++iy)
    for (int ix = 0; ix < N; ++ix) {
      const Vec2 q{x0 + (ix + 0.5) * (x1 - x0) / N, y0 + (iy + 0.5) * (y1 - y0) / N};
      hits += shape_contains(a, q) && shape_contains(b, q);
    }
  return hits * (x1 - x0) * (y1 - y0) / (N * N);
}

}  // namespace svgm
