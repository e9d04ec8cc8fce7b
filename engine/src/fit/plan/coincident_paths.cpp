// Paths with one outline fitted as one: see coincident_paths.h for why.
#include "fit/plan/coincident_paths.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/curve_samples.h"

namespace svgm {

namespace {

// A path's outline as a polyline per subpath (each cubic sampled at eight steps) and its box.
struct Outline {
  std::vector<std::vector<Vec2>> lines;
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
};

constexpr int kSteps = 8;

Outline outline_of(const Path& p) {
  Outline o;
  for (const Subpath& s : p.subpaths) {
    if (s.points.empty()) continue;
    std::vector<Vec2> line;
    append_curve_samples(s, kSteps, true, line);
    if (s.closed) line.push_back(s.points[0]);  // the closing edge
    for (const Vec2& v : line) o.x0 = std::min(o.x0, v.x), o.y0 = std::min(o.y0, v.y), o.x1 = std::max(o.x1, v.x), o.y1 = std::max(o.y1, v.y);
    o.lines.push_back(std::move(line));
  }
  return o;
}

// `b`'s polyline segments bucketed in a uniform grid (cells at least `tol` wide, at most
// kGridCells a side), each segment in every cell its box grown by `tol` touches: a point's
// segments within `tol` are all in its own cell. Linear in the outline's size where a plain
// scan of every segment for every point was quadratic (two duplicated 20000-segment circles:
// four minutes).
constexpr int kGridCells = 256;
// Work beyond this many (cell, segment) entries is not spent: the two are taken as not
// coinciding (fitted apart, as before this rule).
constexpr size_t kMaxGridEntries = size_t{1} << 22;

struct SegmentGrid {
  double x0 = 0, y0 = 0, cell = 1;
  int nx = 1, ny = 1;
  std::vector<std::vector<std::pair<int, int>>> cells;  // (line, segment's end point)
  bool complete = true;
};

SegmentGrid grid_of(const Outline& b, double tol) {
  SegmentGrid g;
  g.x0 = b.x0 - tol, g.y0 = b.y0 - tol;
  g.cell = std::max({tol, (b.x1 - b.x0 + 2 * tol) / kGridCells, (b.y1 - b.y0 + 2 * tol) / kGridCells, 1e-12});
  g.nx = std::max(1, static_cast<int>(std::ceil((b.x1 - b.x0 + 2 * tol) / g.cell)));
  g.ny = std::max(1, static_cast<int>(std::ceil((b.y1 - b.y0 + 2 * tol) / g.cell)));
  g.cells.resize(static_cast<size_t>(g.nx) * g.ny);
  size_t entries = 0;
  for (size_t l = 0; l < b.lines.size(); ++l) {
    const auto& line = b.lines[l];
    for (size_t i = 0; i < line.size(); ++i) {
      const Vec2& p = line[i];
      const Vec2& q = line[i == 0 ? 0 : i - 1];  // a lone point (i = 0) is a segment of its own
      if (i == 0 && line.size() > 1) continue;
      const int cx0 = std::clamp(static_cast<int>((std::min(p.x, q.x) - tol - g.x0) / g.cell), 0, g.nx - 1);
      const int cx1 = std::clamp(static_cast<int>((std::max(p.x, q.x) + tol - g.x0) / g.cell), 0, g.nx - 1);
      const int cy0 = std::clamp(static_cast<int>((std::min(p.y, q.y) - tol - g.y0) / g.cell), 0, g.ny - 1);
      const int cy1 = std::clamp(static_cast<int>((std::max(p.y, q.y) + tol - g.y0) / g.cell), 0, g.ny - 1);
      entries += static_cast<size_t>(cx1 - cx0 + 1) * static_cast<size_t>(cy1 - cy0 + 1);
      if (entries > kMaxGridEntries) {
        g.complete = false;
        return g;
      }
      for (int cy = cy0; cy <= cy1; ++cy)
        for (int cx = cx0; cx <= cx1; ++cx)
          g.cells[static_cast<size_t>(cy) * g.nx + cx].push_back({static_cast<int>(l), static_cast<int>(i)});
    }
  }
  return g;
}

// Every sample of `a` lies within `tol` of `b`'s polylines.
bool within(const Outline& a, const Outline& b, double tol) {
  const SegmentGrid g = grid_of(b, tol);
  if (!g.complete) return false;
  for (const auto& line : a.lines)
    for (const Vec2& p : line) {
      const int cx = static_cast<int>(std::floor((p.x - g.x0) / g.cell)), cy = static_cast<int>(std::floor((p.y - g.y0) / g.cell));
      if (cx < 0 || cy < 0 || cx >= g.nx || cy >= g.ny) return false;  // off the grown box: farther than tol
      bool near = false;
      for (const auto& [l, i] : g.cells[static_cast<size_t>(cy) * g.nx + cx]) {
        const auto& other = b.lines[static_cast<size_t>(l)];
        const Vec2& q = other[static_cast<size_t>(i)];
        const Vec2& r = other[static_cast<size_t>(i == 0 ? 0 : i - 1)];
        if (segment_distance(p, r, q) <= tol) {
          near = true;
          break;
        }
      }
      if (!near) return false;
    }
  return true;
}

bool coincide(const Outline& a, const Outline& b, double tol) {
  if (a.lines.empty() || b.lines.empty()) return false;
  if (std::fabs(a.x0 - b.x0) > tol || std::fabs(a.y0 - b.y0) > tol || std::fabs(a.x1 - b.x1) > tol ||
      std::fabs(a.y1 - b.y1) > tol)
    return false;
  return within(a, b, tol) && within(b, a, tol);
}

}  // namespace

std::vector<int> coincident_hosts(const Scene& scene, double share) {
  const double tol = share * std::max(scene.width, scene.height);
  const size_t n = scene.paths.size();
  std::vector<Outline> outlines;
  outlines.reserve(n);
  for (const Path& p : scene.paths) outlines.push_back(outline_of(p));
  std::vector<int> host(n, -1);
  for (size_t q = 0; q < n; ++q) {
    const int g = scene.paths[q].group;
    if (g >= 0 && scene.groups[static_cast<size_t>(g)].paths.size() > 1) continue;  // a part with others
    for (size_t p = 0; p < q; ++p)
      if (coincide(outlines[q], outlines[p], tol)) {
        host[q] = static_cast<int>(p);
        break;
      }
  }
  return host;
}

}  // namespace svgm
