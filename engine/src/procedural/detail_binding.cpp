// What each point of a drawing's details rides on (see detail_binding.h).
#include "procedural/detail_binding.h"

#include <algorithm>
#include <cmath>

namespace svgm {

namespace {

// A fill as the polygons of its subpaths' control points: the curve stays within its control
// polygon's hull, and an outline drawn on a fill's edge lies within a stroke width of it.
struct FillShape {
  int part = -1;
  double area = 0;  // the part's, to prefer the most specific part a point lies on
  RigBox box;
  std::vector<const std::vector<Vec2>*> rings;
};

// Nonzero winding of the rings about q.
bool inside(const FillShape& f, Vec2 q) {
  int wind = 0;
  for (const auto* ring : f.rings) {
    const size_t n = ring->size();
    for (size_t i = 0; i < n; ++i) {
      const Vec2 a = (*ring)[i], b = (*ring)[(i + 1) % n];
      if (a.y <= q.y) {
        if (b.y > q.y && (b.x - a.x) * (q.y - a.y) - (q.x - a.x) * (b.y - a.y) > 0) ++wind;
      } else if (b.y <= q.y && (b.x - a.x) * (q.y - a.y) - (q.x - a.x) * (b.y - a.y) < 0) {
        --wind;
      }
    }
  }
  return wind != 0;
}

double edge_distance(const FillShape& f, Vec2 q) {
  double best = 1e300;
  for (const auto* ring : f.rings) {
    const size_t n = ring->size();
    for (size_t i = 0; i < n; ++i) {
      const Vec2 a = (*ring)[i], b = (*ring)[(i + 1) % n];
      const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
      const double u = len2 > 0 ? std::clamp(((q.x - a.x) * dx + (q.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
      best = std::min(best, std::hypot(q.x - a.x - u * dx, q.y - a.y - u * dy));
    }
  }
  return best;
}

}  // namespace

std::vector<std::vector<int>> bind_detail_points(const Scene& scene, const Rig& rig) {
  std::vector<std::vector<int>> bound(scene.paths.size());
  const int G = static_cast<int>(rig.parts.size());
  auto takes_points = [&](int g) {
    const Role r = rig.parts[g].role;
    return g != rig.root && r != Role::Detail && r != Role::Background;
  };
  std::vector<FillShape> fills;
  for (size_t pi = 0; pi < scene.paths.size() && pi < rig.part_of_path.size(); ++pi) {
    const int g = rig.part_of_path[pi];
    const Path& P = scene.paths[pi];
    if (g < 0 || g >= G || !takes_points(g) || !P.has_fill || (P.fill.a <= 0 && P.fill_gradient < 0)) continue;
    FillShape f;
    f.part = g;
    f.area = rig.parts[g].area > 0 ? rig.parts[g].area : rig.parts[g].box.area();
    for (const Subpath& s : P.subpaths)
      if (s.points.size() >= 3) {
        f.rings.push_back(&s.points);
        for (const Vec2& q : s.points) f.box.add(q);
      }
    if (!f.rings.empty()) fills.push_back(std::move(f));
  }
  if (fills.empty()) return bound;
  for (size_t pi = 0; pi < scene.paths.size() && pi < rig.part_of_path.size(); ++pi) {
    const int g = rig.part_of_path[pi];
    if (g < 0 || g >= G || rig.parts[g].role != Role::Detail) continue;
    const Path& P = scene.paths[pi];
    // An outline drawn on a fill's edge: within its stroke's width of it (half on either side,
    // and the fill's own edge drawn half a width in or out of the line's middle).
    const double reach = P.has_stroke ? P.stroke.width : 0.0;
    std::vector<int> owner;
    bool any = false;
    auto on_fill = [&](Vec2 q) {
      int best = -1;
      double best_area = 1e300;
      for (const FillShape& f : fills) {
        if (f.part == g || f.area >= best_area) continue;
        if (q.x < f.box.x0 - reach || q.x > f.box.x1 + reach || q.y < f.box.y0 - reach || q.y > f.box.y1 + reach) continue;
        if (inside(f, q) || (reach > 0 && edge_distance(f, q) <= reach)) best = f.part, best_area = f.area;
      }
      return best;
    };
    for (const Subpath& s : P.subpaths) {
      // The points on the curve decide; a handle goes with the point it leaves from or arrives
      // at ({p0, c1, c2, p1, ...}), so a curve's tangent at a point turns with the point (a
      // handle reaching over a neighbour's fill took the neighbour's motion alone).
      const size_t first = owner.size(), n = s.points.size();
      for (size_t i = 0; i < n; i += 3) {
        owner.resize(first + i + 1, -1);
        owner[first + i] = on_fill(s.points[i]);
      }
      owner.resize(first + n, -1);
      for (size_t i = 1; i < n; ++i)
        if (i % 3 == 1) owner[first + i] = owner[first + i - 1];
        else if (i % 3 == 2 && i + 1 < n) owner[first + i] = owner[first + i + 1];
      for (size_t i = first; i < first + n; ++i) any = any || owner[i] >= 0;
    }
    if (any) bound[pi] = std::move(owner);
  }
  return bound;
}

}  // namespace svgm
