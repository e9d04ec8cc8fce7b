// A launched figure's axis and nose from its drawn shape (see flight_axis.h).
#include "procedural/flight_axis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "procedural/support_band.h"

namespace svgm {

namespace {

// The figure's shape as occupied cells (square, `cell` wide, from the figure box's corner).
struct Grid {
  int nx = 0, ny = 0;
  double cell = 1;
  Vec2 origin;
  std::vector<char> on;
  bool at(int i, int j) const { return i >= 0 && j >= 0 && i < nx && j < ny && on[j * nx + i]; }
  Vec2 centre(int i, int j) const { return {origin.x + (i + 0.5) * cell, origin.y + (j + 0.5) * cell}; }
};

// Even-odd inside test of the closed polygon `pts`.
bool inside(const std::vector<Vec2>& pts, Vec2 q) {
  bool in = false;
  for (size_t k = 0, n = pts.size(); k < n; ++k) {
    const Vec2 a = pts[k], b = pts[(k + 1) % n];
    if ((a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
  }
  return in;
}

// An element's outline: its cubics (a start point and three points a cubic: one subpath) at
// kCubicSteps points each, or its control points as they are (subpaths of a hole merged in). The
// control polygon of a round nose is a blunt one: a rocket's nose read as wide as its tail.
std::vector<Vec2> outline(const std::vector<Vec2>& pts) {
  constexpr int kCubicSteps = 8;
  if (pts.size() < 4 || pts.size() % 3 != 1) return pts;
  std::vector<Vec2> out{pts[0]};
  for (size_t k = 0; k + 3 < pts.size(); k += 3)
    for (int j = 1; j <= kCubicSteps; ++j) {
      const double t = static_cast<double>(j) / kCubicSteps, u = 1 - t;
      out.push_back(u * u * u * pts[k] + 3 * u * u * t * pts[k + 1] + 3 * u * t * t * pts[k + 2] + t * t * t * pts[k + 3]);
    }
  return out;
}

Grid shape_grid(const Rig& rig) {
  Grid g;
  const RigBox& F = rig.figure;
  g.cell = std::max(F.w(), F.h()) / kAxisGrid;
  g.nx = std::max(1, static_cast<int>(std::ceil(F.w() / g.cell)));
  g.ny = std::max(1, static_cast<int>(std::ceil(F.h() / g.cell)));
  g.origin = {F.x0, F.y0};
  g.on.assign(static_cast<size_t>(g.nx * g.ny), 0);
  auto mark = [&](Vec2 p) {
    const int i = static_cast<int>(std::floor((p.x - F.x0) / g.cell)), j = static_cast<int>(std::floor((p.y - F.y0) / g.cell));
    if (i >= 0 && j >= 0 && i < g.nx && j < g.ny) g.on[j * g.nx + i] = 1;
  };
  // A ground band the figure stands on (a runway under a plane: support_band.h) is not of it.
  const std::vector<char> band = support_paths(rig);
  for (const RigElement& e : rig.elements) {
    if (e.points.empty() || (e.path >= 0 && static_cast<size_t>(e.path) < band.size() && band[e.path])) continue;
    const std::vector<Vec2> line = outline(e.points);
    // Every element's lines (a thin stroke is only its line; a fill thinner than a cell too).
    for (size_t k = 0; k + 1 < line.size(); ++k) {
      const Vec2 a = line[k], b = line[k + 1];
      const int n = std::max(1, static_cast<int>(std::ceil(2 * std::hypot(b.x - a.x, b.y - a.y) / g.cell)));
      for (int s = 0; s <= n; ++s) mark({a.x + (b.x - a.x) * s / n, a.y + (b.y - a.y) * s / n});
    }
    if (e.thin) continue;
    const int i0 = std::max(0, static_cast<int>((e.box.x0 - F.x0) / g.cell)), i1 = std::min(g.nx - 1, static_cast<int>((e.box.x1 - F.x0) / g.cell));
    const int j0 = std::max(0, static_cast<int>((e.box.y0 - F.y0) / g.cell)), j1 = std::min(g.ny - 1, static_cast<int>((e.box.y1 - F.y0) / g.cell));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i)
        if (!g.on[j * g.nx + i] && inside(line, g.centre(i, j))) g.on[j * g.nx + i] = 1;
  }
  return g;
}

// The share of the shape its mirror image about the line through `c` along `d` covers (IoU).
double mirror_cover(const Grid& g, const std::vector<Vec2>& cells, Vec2 c, Vec2 d) {
  size_t hits = 0;
  for (Vec2 p : cells) {
    const Vec2 r = p - c;
    const double along = r.x * d.x + r.y * d.y;
    const Vec2 m{c.x + 2 * along * d.x - r.x, c.y + 2 * along * d.y - r.y};
    hits += g.at(static_cast<int>(std::floor((m.x - g.origin.x) / g.cell)), static_cast<int>(std::floor((m.y - g.origin.y) / g.cell)));
  }
  return static_cast<double>(hits) / static_cast<double>(2 * cells.size() - hits);
}

// The mean width (across `d`) of the cells whose place along `d` lies in [from, to), in 2 * bins
// slices of the length.
double end_width(const std::vector<Vec2>& cells, Vec2 c, Vec2 d, double from, double to, double cell) {
  constexpr int kSlices = 10;
  std::vector<double> lo(kSlices, 1e300), hi(kSlices, -1e300);
  for (Vec2 p : cells) {
    const Vec2 r = p - c;
    const double along = r.x * d.x + r.y * d.y, across = -r.x * d.y + r.y * d.x;
    if (along < from || along >= to) continue;
    const int s = std::clamp(static_cast<int>((along - from) / (to - from) * kSlices), 0, kSlices - 1);
    lo[s] = std::min(lo[s], across), hi[s] = std::max(hi[s], across);
  }
  double sum = 0;
  int n = 0;
  for (int s = 0; s < kSlices; ++s)
    if (hi[s] >= lo[s]) sum += hi[s] - lo[s] + cell, ++n;
  return n > 0 ? sum / n : 0;
}

// The occupied cells' centres and their centroid (empty when the shape is unread).
std::vector<Vec2> shape_cells(const Grid& g, Vec2& c) {
  std::vector<Vec2> cells;
  c = {0, 0};
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      if (g.at(i, j)) cells.push_back(g.centre(i, j)), c = c + g.centre(i, j);
  if (!cells.empty()) c = (1.0 / static_cast<double>(cells.size())) * c;
  return cells;
}

}  // namespace

UprightMirror upright_mirror(const Rig& rig) {
  UprightMirror out;
  if (rig.figure.empty() || rig.figure.w() <= 0 || rig.figure.h() <= 0) return out;
  const Grid g = shape_grid(rig);
  Vec2 c;
  const std::vector<Vec2> cells = shape_cells(g, c);
  if (cells.size() < 8) return out;
  RigBox box;
  for (Vec2 p : cells) box.add(p);
  out.wide = (box.w() + g.cell) / (box.h() + g.cell);
  out.cover = mirror_cover(g, cells, c, {0, 1});
  return out;
}

FlightAxis flight_axis(const Rig& rig) {
  FlightAxis out;
  if (rig.figure.empty() || rig.figure.w() <= 0 || rig.figure.h() <= 0) return out;
  const Grid g = shape_grid(rig);
  Vec2 c;
  const std::vector<Vec2> cells = shape_cells(g, c);
  if (cells.size() < 8) return out;
  // The mirror line, every 3 degrees.
  double best = 0;
  Vec2 axis{0, 0};
  for (int deg = 0; deg < 180; deg += 3) {
    const Vec2 d{std::cos(deg * M_PI / 180), std::sin(deg * M_PI / 180)};
    if (const double m = mirror_cover(g, cells, c, d); m > best) best = m, axis = d;
  }
  char buf[240];
  if (best >= kMirrorCover) std::snprintf(buf, sizeof buf, "mirrored about its length (%.2f of it)", best);
  else {
    // The long axis: the larger eigenvector of the cells' covariance.
    double sxx = 0, syy = 0, sxy = 0;
    for (Vec2 p : cells) sxx += (p.x - c.x) * (p.x - c.x), syy += (p.y - c.y) * (p.y - c.y), sxy += (p.x - c.x) * (p.y - c.y);
    const double tr = sxx + syy, det = sxx * syy - sxy * sxy, root = std::sqrt(std::max(0.0, tr * tr / 4 - det));
    const double l1 = tr / 2 + root, l2 = std::max(tr / 2 - root, 1e-12);
    const double longer = std::sqrt(l1 / l2);
    if (longer < kLongAxis) {
      std::snprintf(buf, sizeof buf, "no axis: not mirrored (%.2f) and not long (%.2f times its width)", best, longer);
      out.why = buf;
      return out;
    }
    const double angle = 0.5 * std::atan2(2 * sxy, sxx - syy);
    axis = {std::cos(angle), std::sin(angle)};
    std::snprintf(buf, sizeof buf, "long (%.2f times its width)", longer);
  }
  const std::string shape = buf;
  double lo = 1e300, hi = -1e300;
  for (Vec2 p : cells) {
    const double along = (p.x - c.x) * axis.x + (p.y - c.y) * axis.y;
    lo = std::min(lo, along), hi = std::max(hi, along);
  }
  hi += g.cell;  // the last cell's far side (cells are read at their near corners' slices)
  const double L = hi - lo;
  auto ends = [&](double share) {
    return std::pair{end_width(cells, c, axis, lo, lo + share * L, g.cell), end_width(cells, c, axis, hi - share * L, hi, g.cell)};
  };
  const auto [a1, b1] = ends(kNoseShare);
  const auto [a2, b2] = ends(kNoseShare / 2);
  const double back = a1 + a2, front = b1 + b2;  // widths at the axis's negative and positive ends
  if (std::min(back, front) > kNoseStep * std::max(back, front)) {
    std::snprintf(buf, sizeof buf, "%s, but its ends are alike (%.2f and %.2f of its length wide)", shape.c_str(), back / 2 / L, front / 2 / L);
    out.why = buf;
    return out;
  }
  out.nose = front < back ? axis : Vec2{-axis.x, -axis.y};
  out.found = true;
  std::snprintf(buf, sizeof buf, "%s, its nose the narrower end (%.2f of its length wide, the other %.2f), %.0f degrees above the right",
                shape.c_str(), std::min(back, front) / 2 / L, std::max(back, front) / 2 / L, std::atan2(-out.nose.y, out.nose.x) * 180 / M_PI);
  out.why = buf;
  return out;
}

}  // namespace svgm
