// Test-only helpers that build scenes directly (no SVG), so raster tests state their geometry
// exactly and do not depend on the reader; and one that finds a path of a scene by its id.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "svgmotion/scene.h"

namespace svgm::test {

// A closed polygon as a subpath of straight cubics (control points at thirds).
inline Subpath polygon(const std::vector<Vec2>& pts, bool closed = true) {
  Subpath s;
  s.closed = closed;
  s.points.push_back(pts[0]);
  const size_t n = closed ? pts.size() : pts.size() - 1;
  for (size_t i = 0; i < n; ++i) {
    const Vec2 a = pts[i], b = pts[(i + 1) % pts.size()];
    s.points.push_back(a + (1.0 / 3.0) * (b - a));
    s.points.push_back(a + (2.0 / 3.0) * (b - a));
    s.points.push_back(b);
  }
  return s;
}

// A circle from 4 cubics (kappa = 0.5522847498, max radial error 2.7e-4 r).
inline Subpath circle(Vec2 c, double r) {
  const double k = 0.5522847498307936 * r;
  Subpath s;
  s.closed = true;
  s.points = {{c.x + r, c.y},     {c.x + r, c.y + k}, {c.x + k, c.y + r}, {c.x, c.y + r},
              {c.x - k, c.y + r}, {c.x - r, c.y + k}, {c.x - r, c.y},     {c.x - r, c.y - k},
              {c.x - k, c.y - r}, {c.x, c.y - r},     {c.x + k, c.y - r}, {c.x + r, c.y - k},
              {c.x + r, c.y}};
  return s;
}

inline Path filled(Subpath s, Rgba color = {0, 0, 0, 1}, FillRule rule = FillRule::NonZero) {
  Path p;
  p.subpaths.push_back(std::move(s));
  p.fill = color;
  p.fill_rule = rule;
  return p;
}

inline Path stroked(Subpath s, double width, LineJoin join, LineCap cap, Rgba color = {0, 0, 0, 1}) {
  Path p;
  p.subpaths.push_back(std::move(s));
  p.has_fill = false;
  p.has_stroke = true;
  p.stroke.color = color;
  p.stroke.width = width;
  p.stroke.join = join;
  p.stroke.cap = cap;
  return p;
}

inline Scene scene_of(double w, double h, std::vector<Path> paths) {
  Scene s;
  s.width = w;
  s.height = h;
  s.paths = std::move(paths);
  for (size_t i = 0; i < s.paths.size(); ++i) s.paths[i].id = "p" + std::to_string(i + 1);
  return s;
}

// The index of the path with id `id` in `s`, or -1.
inline int path_index(const Scene& s, const std::string& id) {
  for (size_t i = 0; i < s.paths.size(); ++i)
    if (s.paths[i].id == id) return static_cast<int>(i);
  return -1;
}

}  // namespace svgm::test
