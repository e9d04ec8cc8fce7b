// The fold and cut check of a deformed mesh: see mesh_quality.h.
#include "motion/mesh_quality.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "svgmotion/error.h"

namespace svgm {

namespace {

double signed_area2(Vec2 a, Vec2 b, Vec2 c) {
  const Vec2 u = b - a, v = c - a;
  return u.x * v.y - u.y * v.x;
}

double length(Vec2 a) { return std::hypot(a.x, a.y); }

}  // namespace

MeshQuality mesh_quality(const ShapeMesh& mesh, const std::vector<Vec2>& deformed) {
  if (deformed.size() != mesh.vertices.size())
    throw Error("mesh_quality: one deformed position per vertex is needed");
  MeshQuality q;
  q.min_area_ratio = std::numeric_limits<double>::infinity();
  q.max_area_ratio = -std::numeric_limits<double>::infinity();
  const auto& x = mesh.vertices;
  const auto& p = deformed;
  for (const auto& t : mesh.triangles) {
    const double rest = signed_area2(x[t[0]], x[t[1]], x[t[2]]);
    if (rest == 0) continue;
    const double ratio = signed_area2(p[t[0]], p[t[1]], p[t[2]]) / rest;
    // A NaN ratio (a vertex not finite) counts as a fold: !(ratio > 0).
    if (!(ratio > 0)) ++q.flipped;
    q.min_area_ratio = std::min(q.min_area_ratio, std::isnan(ratio) ? -std::numeric_limits<double>::infinity() : ratio);
    q.max_area_ratio = std::max(q.max_area_ratio, std::isnan(ratio) ? std::numeric_limits<double>::infinity() : ratio);
    for (int k = 0; k < 3; ++k) {
      const int i = t[k], j = t[(k + 1) % 3];
      const double l0 = length(x[i] - x[j]), l1 = length(p[i] - p[j]);
      const double s = l1 > 0 ? std::max(l1 / l0, l0 / l1) : std::numeric_limits<double>::infinity();
      q.max_stretch = std::max(q.max_stretch, std::isnan(s) ? std::numeric_limits<double>::infinity() : s);
    }
  }
  if (q.min_area_ratio > q.max_area_ratio) q.min_area_ratio = q.max_area_ratio = 1;  // no triangles
  return q;
}

}  // namespace svgm
