// Small shapes a bending region carries move rigidly (carried_shapes.h).
#include "procedural/carried_shapes.h"

#include <array>
#include <cmath>

#include "motion/arap.h"
#include "procedural/shape_overlap.h"

namespace svgm {

std::vector<std::vector<size_t>> carried_shapes(const Scene& scene, const std::vector<double>& bend_size,
                                                const std::vector<std::vector<int>>& rides_on) {
  const size_t P = scene.paths.size();
  std::vector<size_t> first(P + 1, 0);  // each path's first point within a frame
  for (size_t p = 0; p < P; ++p) {
    size_t n = 0;
    for (const auto& sp : scene.paths[p].subpaths) n += sp.points.size();
    first[p + 1] = first[p] + n;
  }
  std::vector<PartShape> fills(P);
  for (size_t p = 0; p < P; ++p)
    if (bend_size[p] > 0 && scene.paths[p].has_fill) fills[p] = part_shape(scene, {static_cast<int>(p)});
  std::vector<std::vector<size_t>> out;
  for (size_t p = 0; p < P; ++p) {
    if (bend_size[p] <= 0) continue;
    size_t start = first[p];
    for (size_t si = 0; si < scene.paths[p].subpaths.size(); ++si) {
      const Subpath& sp = scene.paths[p].subpaths[si];
      const size_t begin = start;
      start += sp.points.size();
      if (!sp.closed || sp.points.size() < 4) continue;
      RigBox box;
      for (const Vec2& q : sp.points) box.add(q);
      if (std::hypot(box.w(), box.h()) > kCarriedShare * bend_size[p]) continue;
      // Inside the fill of a bent path painted before it: every on-curve point.
      bool inside = false;
      for (size_t h = 0; h < p && !inside; ++h) {
        if (fills[h].rings.empty() || fills[h].box.x0 > box.x0 || fills[h].box.x1 < box.x1 || fills[h].box.y0 > box.y0 ||
            fills[h].box.y1 < box.y1)
          continue;
        inside = true;
        for (size_t k = 0; k < sp.points.size() && inside; k += 3) inside = shape_contains(fills[h], sp.points[k]);
      }
      if (!inside) continue;
      std::vector<size_t> shape;
      for (size_t k = 0; k < sp.points.size(); ++k) shape.push_back(begin + k);
      // The line art riding on it: the points of other paths that take this path's motion and
      // lie in its box (a path of one subpath: every rider).
      for (size_t r = 0; r < P; ++r) {
        if (r == p || rides_on.size() <= r || rides_on[r].empty()) continue;
        size_t k = 0;
        for (const auto& rsp : scene.paths[r].subpaths)
          for (const Vec2& q : rsp.points) {
            const bool on = rides_on[r][k] == static_cast<int>(p) &&
                            (scene.paths[p].subpaths.size() == 1 || (q.x >= box.x0 && q.x <= box.x1 && q.y >= box.y0 && q.y <= box.y1));
            if (on) shape.push_back(first[r] + k);
            ++k;
          }
      }
      out.push_back(std::move(shape));
    }
  }
  return out;
}

void keep_carried_rigid(const Scene& scene, const std::vector<std::vector<size_t>>& shapes, int frames, std::vector<Vec2>& pts) {
  if (shapes.empty() || frames <= 0) return;
  std::vector<Vec2> rest;
  for (const Path& p : scene.paths)
    for (const auto& sp : p.subpaths) rest.insert(rest.end(), sp.points.begin(), sp.points.end());
  const size_t per = pts.size() / static_cast<size_t>(frames);
  for (const auto& shape : shapes)
    for (int f = 0; f < frames; ++f) {
      Vec2* moved = &pts[static_cast<size_t>(f) * per];
      Vec2 c0{0, 0}, c1{0, 0};
      for (size_t i : shape) c0 = c0 + rest[i], c1 = c1 + moved[i];
      c0 = (1.0 / shape.size()) * c0;
      c1 = (1.0 / shape.size()) * c1;
      // The rotation that best takes the rest points about their centre onto the moved ones
      // (the ARAP local step's closed form).
      std::array<double, 4> m{};
      for (size_t i : shape) {
        const Vec2 e = rest[i] - c0, f = moved[i] - c1;
        m[0] += f.x * e.x, m[1] += f.x * e.y, m[2] += f.y * e.x, m[3] += f.y * e.y;
      }
      const double a = best_rotation_angle(m), cs = std::cos(a), sn = std::sin(a);
      for (size_t i : shape) {
        const Vec2 r = rest[i] - c0;
        moved[i] = c1 + Vec2{cs * r.x - sn * r.y, sn * r.x + cs * r.y};
      }
    }
}

}  // namespace svgm
