// Line drawings' geometry for the part rig (see stroke_rig.h).
#include "video/stroke_rig.h"

#include <algorithm>
#include <cmath>

#include "video/curve_samples.h"

namespace svgm {

namespace {

// A line drawing has at least this many strokes (one or two strokes are a logo, not a figure).
constexpr size_t kMinStrokes = 4;
// Steps per cubic when a stroke's curve is sampled.
constexpr int kCurveSteps = 16;
// A single stroke folds back on itself (a hairpin) when its endpoints lie closer together than
// this share of the farthest reach of its curve from their middle.
constexpr double kStrokeFold = 0.5;
// A stroke lies alongside the root when at least this share of its extent along the root's
// long axis is within the root's.
constexpr double kAlongInside = 0.8;

double dist(Vec2 u, Vec2 v) { return std::hypot(u.x - v.x, u.y - v.y); }

double box_distance(Vec2 q, const RigBox& b) {
  const double dx = std::max({0.0, b.x0 - q.x, q.x - b.x1}), dy = std::max({0.0, b.y0 - q.y, q.y - b.y1});
  return std::hypot(dx, dy);
}

}  // namespace

bool is_open_stroke(const Path& p) {
  const bool filled = p.has_fill && p.fill.a > 0;
  return !filled && p.has_stroke && p.subpaths.size() == 1 && !p.subpaths[0].closed && p.subpaths[0].points.size() >= 4;
}

bool is_line_drawing(const Scene& scene) {
  if (scene.paths.size() < kMinStrokes) return false;
  return std::all_of(scene.paths.begin(), scene.paths.end(), [](const Path& p) { return is_open_stroke(p); });
}

std::vector<Vec2> stroke_curve(const Path& p) { return curve_samples(p, kCurveSteps); }

double stroke_length(const Path& p) {
  const std::vector<Vec2> on = stroke_curve(p);
  double len = 0;
  for (size_t i = 1; i < on.size(); ++i) len += dist(on[i - 1], on[i]);
  return len;
}

RigBox stroke_box(const Path& p) {
  RigBox b;
  for (const Vec2& q : stroke_curve(p)) b.add(q);
  return b;
}

std::array<Vec2, 2> stroke_ends(const Path& p) {
  const std::vector<Vec2> on = stroke_curve(p);
  if (on.empty()) return {Vec2{}, Vec2{}};
  const Vec2 a = on.front(), b = on.back(), mid = 0.5 * (a + b);
  Vec2 apex = mid;
  for (const Vec2& q : on)
    if (dist(q, mid) > dist(apex, mid)) apex = q;
  if (dist(a, b) < kStrokeFold * dist(apex, mid)) return {mid, apex};
  return {a, b};
}

Vec2 stroke_body_end(const Path& p, const RigBox& body, Vec2 joint) {
  const auto e = stroke_ends(p);
  const double g0 = box_distance(e[0], body), g1 = box_distance(e[1], body);
  if (std::fabs(g0 - g1) > 1e-9) return g0 < g1 ? e[0] : e[1];
  return dist(e[0], joint) <= dist(e[1], joint) ? e[0] : e[1];
}

double distance_to_stroke(Vec2 q, const Path& p) {
  double best = 1e300;
  for (const Vec2& c : stroke_curve(p)) best = std::min(best, dist(q, c));
  return best;
}

bool lies_alongside(const RigBox& s, const RigBox& root, double across) {
  if (s.empty() || root.empty()) return false;
  const bool upright = root.h() >= root.w();
  const double s0 = upright ? s.y0 : s.x0, s1 = upright ? s.y1 : s.x1;
  const double r0 = upright ? root.y0 : root.x0, r1 = upright ? root.y1 : root.x1;
  const double inside = std::max(0.0, std::min(s1, r1) - std::max(s0, r0));
  if (inside < kAlongInside * std::max(s1 - s0, 1e-9)) return false;
  const double off = upright ? s.centre().x - root.centre().x : s.centre().y - root.centre().y;
  return std::fabs(off) <= across;
}

}  // namespace svgm
