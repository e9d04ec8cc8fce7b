// Splitting long Bézier segments exactly (see segment_split.h).
#include "fit/plan/segment_split.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "svgmotion/error.h"

namespace svgm {

namespace {

Vec2 lerp(Vec2 a, Vec2 b, double t) { return a + t * (b - a); }

// Appends the cubic (p0, p1, p2, p3) cut into n pieces of equal parameter, without p0: each
// piece's two handles and end point. The cuts are made one after another on the remainder
// (at t = 1/n, then 1/(n-1) of what is left, ...), which is the same curve cut at k/n.
void append_pieces(Vec2 p0, Vec2 p1, Vec2 p2, Vec2 p3, int n, std::vector<Vec2>& out) {
  for (int left = n; left > 1; --left) {
    const double t = 1.0 / left;
    const Vec2 a = lerp(p0, p1, t), b = lerp(p1, p2, t), c = lerp(p2, p3, t);
    const Vec2 d = lerp(a, b, t), e = lerp(b, c, t), f = lerp(d, e, t);
    out.insert(out.end(), {a, d, f});
    p0 = f, p1 = e, p2 = c;
  }
  out.insert(out.end(), {p1, p2, p3});  // the last piece ends exactly where the segment did
}

}  // namespace

SplitPlan plan_segment_split(const Scene& scene, double max_length, int max_pieces) {
  SplitPlan plan(scene.paths.size());
  for (size_t p = 0; p < scene.paths.size(); ++p)
    for (const Subpath& sp : scene.paths[p].subpaths) {
      std::vector<int> pieces(sp.segment_count(), 1);
      for (size_t s = 0; s < pieces.size() && max_length > 0; ++s) {
        double len = 0;
        for (size_t j = 3 * s; j < 3 * s + 3; ++j)
          len += std::hypot(sp.points[j + 1].x - sp.points[j].x, sp.points[j + 1].y - sp.points[j].y);
        // Clamped as a double: a tiny max_length or huge coordinates must not overflow an int.
        const double n = std::isfinite(len) ? std::ceil(len / max_length) : 1.0;
        pieces[s] = static_cast<int>(std::clamp(n, 1.0, static_cast<double>(std::max(1, max_pieces))));
      }
      plan[p].push_back(std::move(pieces));
    }
  return plan;
}

Path split_path(const Path& path, const std::vector<std::vector<int>>& pieces) {
  if (pieces.size() != path.subpaths.size())
    throw Error("internal: a segment split planned for " + std::to_string(pieces.size()) + " subpaths applied to " +
                std::to_string(path.subpaths.size()) + " (" + path.id + ")");
  Path out = path;
  for (size_t i = 0; i < path.subpaths.size(); ++i) {
    const Subpath& sp = path.subpaths[i];
    if (pieces[i].size() != sp.segment_count())
      throw Error("internal: a segment split planned for " + std::to_string(pieces[i].size()) +
                  " segments applied to " + std::to_string(sp.segment_count()) + " (" + path.id + ")");
    if (std::all_of(pieces[i].begin(), pieces[i].end(), [](int n) { return n == 1; })) continue;
    std::vector<Vec2> pts{sp.points.front()};
    for (size_t s = 0; s < pieces[i].size(); ++s)
      append_pieces(sp.points[3 * s], sp.points[3 * s + 1], sp.points[3 * s + 2], sp.points[3 * s + 3],
                    pieces[i][s], pts);
    out.subpaths[i].points = std::move(pts);
  }
  return out;
}

Scene split_scene(const Scene& scene, const SplitPlan& plan) {
  if (plan.size() != scene.paths.size()) throw Error("internal: a segment split planned for another scene");
  Scene out = scene;
  for (size_t p = 0; p < scene.paths.size(); ++p) out.paths[p] = split_path(scene.paths[p], plan[p]);
  return out;
}

int added_points(const SplitPlan& plan) {
  int n = 0;
  for (const auto& path : plan)
    for (const auto& sub : path)
      for (int k : sub) n += 3 * (k - 1);
  return n;
}

}  // namespace svgm
