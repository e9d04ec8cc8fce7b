// A scene's backdrops (backdrop.h): the box rule on the drawing's own canvas and the frame's cut.
#include "scene/backdrop.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "geometry/curve_samples.h"

namespace svgm {

namespace {

// Samples per cubic: a rounded corner or a wavy crest along an edge is followed closely enough
// that its straight run is measured within a few per cent.
constexpr int kCutSteps = 8;

// The length of the union of the intervals.
double union_length(std::vector<std::pair<double, double>>& spans) {
  std::sort(spans.begin(), spans.end());
  double total = 0, lo = 0, hi = 0;
  bool open = false;
  for (const auto& [a, b] : spans) {
    if (open && a <= hi) {
      hi = std::max(hi, b);
      continue;
    }
    if (open) total += hi - lo;
    lo = a, hi = b, open = true;
  }
  return open ? total + hi - lo : total;
}

}  // namespace

double frame_cut(const Scene& scene, const std::vector<int>& paths) {
  const double f = 1 + 2 * scene.room, W = scene.width / f, H = scene.height / f;
  if (!(W > 0 && H > 0)) return 0;
  const double ox = scene.room * W, oy = scene.room * H, tx = kBackdropEdge * W, ty = kBackdropEdge * H;
  // Per side (left, top, right, bottom), the stretches of outline within its reach, as intervals
  // along it. A point beyond the edge is within reach too (a shape drawn past the frame).
  std::vector<std::pair<double, double>> spans[4];
  std::vector<Vec2> q;
  for (int pi : paths) {
    const Path& p = scene.paths[static_cast<size_t>(pi)];
    for (const Subpath& sp : p.subpaths) {
      q.clear();
      append_curve_samples(sp, kCutSteps, true, q);
      if (q.size() < 2) continue;
      if (p.has_fill || sp.closed) q.push_back(q.front());  // a fill's outline closes
      for (size_t k = 0; k + 1 < q.size(); ++k) {
        const Vec2 a{q[k].x - ox, q[k].y - oy}, b{q[k + 1].x - ox, q[k + 1].y - oy};
        const auto along = [&](int side, double u, double v) {
          spans[side].push_back({std::min(u, v), std::max(u, v)});
        };
        if (a.x <= tx && b.x <= tx) along(0, a.y, b.y);
        if (a.y <= ty && b.y <= ty) along(1, a.x, b.x);
        if (a.x >= W - tx && b.x >= W - tx) along(2, a.y, b.y);
        if (a.y >= H - ty && b.y >= H - ty) along(3, a.x, b.x);
      }
    }
  }
  // Only the stretch along the side itself counts (clamped to it).
  double cut = 0;
  for (int side = 0; side < 4; ++side) {
    const double len = side % 2 == 0 ? H : W;
    for (auto& s : spans[side]) s = {std::clamp(s.first, 0.0, len), std::clamp(s.second, 0.0, len)};
    cut = std::max(cut, union_length(spans[side]) / len);
  }
  return cut;
}

bool is_backdrop(const Scene& scene, const std::vector<int>& paths, double x0, double y0, double x1, double y1,
                 double paint_position) {
  const double f = 1 + 2 * scene.room, ox = scene.room * scene.width / f, oy = scene.room * scene.height / f;
  return is_backdrop(x0 - ox, y0 - oy, x1 - ox, y1 - oy, paint_position, scene.width / f, scene.height / f) &&
         frame_cut(scene, paths) >= kBackdropCut;
}

}  // namespace svgm
