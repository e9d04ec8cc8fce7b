// What each point of a drawing's line art rides on (see detail_binding.h).
#include "procedural/detail_binding.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "geometry/curve_samples.h"

namespace svgm {

namespace {

// Rule 1: a still fill goes with a moving line when at least this share of its points lie on
// the line (within its stroke width of its middle). An outline drawn round a wing holds all of
// them; a long outline passing along a body's edge holds a few of the body's.
constexpr double kTracedShare = 0.6;

// A path's region as a host, and its line as line art. A fill as the polygons of its subpaths'
// control points (the curve stays within its control polygon's hull, and an outline drawn on a
// fill's edge lies within a stroke width of it); a coloured stroke as the band round its line.
struct Shape {
  int part = -1;
  bool filled = false, stroked = false, line_art = false, host = false;
  double width = 0;  // stroke width (0 without a stroke)
  double area = 0;   // to prefer the most specific host
  RigBox box;        // control points, grown by half the stroke width
  std::vector<const std::vector<Vec2>*> rings;
  std::vector<std::vector<Vec2>> lines;  // the curve, sampled, per subpath
};

// Nonzero winding of the rings about q.
bool inside(const Shape& f, Vec2 q) {
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

double edge_distance(const Shape& f, Vec2 q) {
  double best = 1e300;
  for (const auto* ring : f.rings)
    for (size_t i = 0, n = ring->size(); i < n; ++i) best = std::min(best, segment_distance(q, (*ring)[i], (*ring)[(i + 1) % n]));
  return best;
}

double line_distance(const Shape& f, Vec2 q) {
  double best = 1e300;
  for (const auto& l : f.lines)
    for (size_t i = 0; i + 1 < l.size(); ++i) best = std::min(best, segment_distance(q, l[i], l[i + 1]));
  return best;
}

bool near_box(const RigBox& b, Vec2 q, double reach) {
  return q.x >= b.x0 - reach && q.x <= b.x1 + reach && q.y >= b.y0 - reach && q.y <= b.y1 + reach;
}

// q lies on host h, drawn by a line `reach` wide.
bool lies_on(const Shape& h, Vec2 q, double reach) {
  if (!near_box(h.box, q, reach)) return false;
  if (h.filled) return inside(h, q) || (reach > 0 && edge_distance(h, q) <= reach);
  return line_distance(h, q) <= 0.5 * h.width + reach;
}

Shape shape_of(const Path& P, int part, bool detail) {
  Shape s;
  s.part = part;
  s.filled = P.has_fill && (P.fill.a > 0 || P.fill_gradient >= 0);
  s.stroked = P.has_stroke && P.stroke.width > 0;
  s.width = s.stroked ? P.stroke.width : 0;
  s.line_art = (s.stroked && !s.filled) || detail;
  s.host = s.filled || s.stroked;
  for (const Subpath& sp : P.subpaths) {
    if (s.filled && sp.points.size() >= 3) {
      s.rings.push_back(&sp.points);
      s.area += std::fabs(shoelace(sp.points));
    }
    for (const Vec2& q : sp.points) s.box.add(q);
    if (s.stroked && !sp.points.empty()) {
      s.lines.emplace_back();
      append_curve_samples(sp, 8, true, s.lines.back());
    }
  }
  if (!s.filled) {
    double len = 0;
    for (const auto& l : s.lines)
      for (size_t i = 0; i + 1 < l.size(); ++i) len += std::hypot(l[i + 1].x - l[i].x, l[i + 1].y - l[i].y);
    s.area = len * s.width;
  }
  if (!s.box.empty()) s.box = {s.box.x0 - 0.5 * s.width, s.box.y0 - 0.5 * s.width, s.box.x1 + 0.5 * s.width, s.box.y1 + 0.5 * s.width};
  return s;
}

// The share of the points on host h's curve (not its handles) lying on line o.
double traced_share(const Path& H, const Shape& h, const Shape& o) {
  int n = 0, on = 0;
  const double reach = o.width + (h.filled ? 0.0 : 0.5 * h.width);
  for (const Subpath& sp : H.subpaths)
    for (size_t i = 0; i < sp.points.size(); i += 3) {
      ++n;
      if (near_box(o.box, sp.points[i], reach) && line_distance(o, sp.points[i]) <= reach) ++on;
    }
  return n > 0 ? static_cast<double>(on) / n : 0.0;
}

// A moving line's points on no host take the owner of the nearest bound point of their subpath
// (by the number of points between), so the line is never cut between two motions.
void fill_from_neighbours(std::vector<int>& owner, size_t first, size_t n) {
  std::vector<int> was(owner.begin() + static_cast<long>(first), owner.begin() + static_cast<long>(first + n));
  for (size_t i = 0; i < n; i += 3) {
    if (was[i] != -1) continue;
    size_t best = n;
    for (size_t j = 0; j < n; j += 3)
      if (was[j] >= 0 && (best == n || std::labs(static_cast<long>(j) - static_cast<long>(i)) < std::labs(static_cast<long>(best) - static_cast<long>(i))))
        best = j;
    if (best < n) owner[first + i] = was[best];
  }
}

}  // namespace

std::vector<std::vector<int>> bind_to_hosts(const Scene& scene, const Rig& rig, const std::vector<char>& moves, const std::vector<char>& fixed) {
  const size_t N = std::min(scene.paths.size(), rig.part_of_path.size());
  const int G = static_cast<int>(rig.parts.size());
  std::vector<std::vector<int>> bound(scene.paths.size());
  auto moved = [&](size_t p) { return p < moves.size() && moves[p]; };
  std::vector<Shape> shapes(N);
  for (size_t pi = 0; pi < N; ++pi) {
    const int g = rig.part_of_path[pi];
    if (g < 0 || g >= G || rig.parts[g].role == Role::Background || (g < static_cast<int>(fixed.size()) && fixed[g])) continue;
    shapes[pi] = shape_of(scene.paths[pi], g, rig.parts[g].role == Role::Detail);
  }
  // Rule 1: still fills traced by a moving line go with it.
  std::vector<int> lead(N, -1);
  for (size_t h = 0; h < N; ++h) {
    if (!shapes[h].host || moved(h)) continue;
    double best = kTracedShare;
    for (size_t o = h + 1; o < N; ++o) {
      const Shape& O = shapes[o];
      if (!moved(o) || !O.line_art || !O.stroked || O.part == shapes[h].part) continue;
      // A line whose band does not reach the fill's box traces none of it (scenes hold thousands
      // of paths: the pairs are many, the overlapping ones few).
      const RigBox& hb = shapes[h].box;
      if (hb.empty() || O.box.empty() || O.box.x0 - O.width > hb.x1 || O.box.x1 + O.width < hb.x0 ||
          O.box.y0 - O.width > hb.y1 || O.box.y1 + O.width < hb.y0)
        continue;
      const double share = traced_share(scene.paths[h], shapes[h], O);
      if (share >= best) best = share, lead[h] = static_cast<int>(o);
    }
  }
  // Rule 2: line art rides on the fill it is drawn on.
  for (size_t pi = 0; pi < N; ++pi) {
    const Shape& O = shapes[pi];
    if (lead[pi] >= 0) {
      size_t n = 0;
      for (const Subpath& sp : scene.paths[pi].subpaths) n += sp.points.size();
      bound[pi].assign(n, lead[pi]);
      continue;
    }
    if (!O.line_art) continue;
    // -1 on no host, -2 on a host that moves as this path does (it keeps its own motion).
    auto host_of = [&](Vec2 q) {
      int best = -1;
      double best_area = 1e300;
      for (size_t h = 0; h < pi; ++h) {
        const Shape& H = shapes[h];
        if (!H.host || H.part == O.part || !lies_on(H, q, O.width)) continue;
        const int e = lead[h] >= 0 ? lead[h] : static_cast<int>(h);
        if (e == static_cast<int>(pi)) return -2;
        if (moved(pi) && !moved(static_cast<size_t>(e))) continue;
        if (H.area < best_area) best = e, best_area = H.area;
      }
      return best;
    };
    std::vector<int> owner;
    bool any = false;
    for (const Subpath& s : scene.paths[pi].subpaths) {
      const size_t first = owner.size(), n = s.points.size();
      owner.resize(first + n, -1);
      for (size_t i = 0; i < n; i += 3) owner[first + i] = host_of(s.points[i]);
      if (moved(pi)) fill_from_neighbours(owner, first, n);
      for (size_t i = 0; i < n; i += 3) owner[first + i] = std::max(owner[first + i], -1);
      // The points on the curve decide; a handle goes with the point it leaves from or arrives
      // at ({p0, c1, c2, p1, ...}), so a curve's tangent at a point turns with the point.
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
