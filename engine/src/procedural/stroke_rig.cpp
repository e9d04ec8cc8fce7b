// Line drawings' geometry for the part rig (see stroke_rig.h).
#include "procedural/stroke_rig.h"

#include <algorithm>
#include <cmath>

#include "geometry/curve_samples.h"

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
// is_loop_stroke: a wheel's stroke turns one way through at least this share of a full turn
// (a sketched wheel drawn as one cubic loop leaves a gap: 0.69 and 0.73 in livesketch's biking),
// its curve encloses at least this share of the ellipse its box holds, and its box is at most
// this many times longer than wide (a wheel seen at a slant is an oval, not a sliver).
constexpr double kLoopTurn = 0.6;
constexpr double kLoopFill = 0.6;
constexpr double kLoopAspect = 2.5;

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

bool is_loop_stroke(const Path& p) {
  if (!is_open_stroke(p)) return false;
  const std::vector<Vec2> on = stroke_curve(p);
  double turn = 0, area = 0;
  for (size_t i = 0; i + 1 < on.size(); ++i) area += on[i].x * on[i + 1].y - on[i + 1].x * on[i].y;
  area += on.back().x * on.front().y - on.front().x * on.back().y;
  for (size_t i = 1; i + 1 < on.size(); ++i) {
    const Vec2 u = on[i] - on[i - 1], v = on[i + 1] - on[i];
    if (std::hypot(u.x, u.y) < 1e-9 || std::hypot(v.x, v.y) < 1e-9) continue;  // a repeated point
    turn += std::atan2(u.x * v.y - u.y * v.x, u.x * v.x + u.y * v.y);
  }
  const RigBox b = stroke_box(p);
  const double lo = std::min(b.w(), b.h()), hi = std::max(b.w(), b.h());
  const double ellipse = 0.25 * M_PI * b.w() * b.h();
  return lo > 0 && hi <= kLoopAspect * lo && std::fabs(turn) >= kLoopTurn * 2 * M_PI &&
         0.5 * std::fabs(area) >= kLoopFill * ellipse;
}

Affine loop_plane(const Path& p) {
  // Second moments of the region the closed curve bounds (Green's theorem over its polygon),
  // about its centroid: for an ellipse with semi-axes a, b they are a^2/4, b^2/4 along its axes.
  const std::vector<Vec2> on = stroke_curve(p);
  double A = 0, cx = 0, cy = 0, xx = 0, yy = 0, xy = 0;
  for (size_t i = 0; i < on.size(); ++i) {
    const Vec2 u = on[i], v = on[(i + 1) % on.size()];
    const double w = u.x * v.y - v.x * u.y;
    A += w;
    cx += (u.x + v.x) * w;
    cy += (u.y + v.y) * w;
    xx += (u.x * u.x + u.x * v.x + v.x * v.x) * w;
    yy += (u.y * u.y + u.y * v.y + v.y * v.y) * w;
    xy += (u.x * v.y + 2 * u.x * u.y + 2 * v.x * v.y + v.x * u.y) * w;
  }
  if (std::fabs(A) < 1e-9) return {};
  A *= 0.5;
  cx /= 6 * A;
  cy /= 6 * A;
  const double sxx = xx / (12 * A) - cx * cx, syy = yy / (12 * A) - cy * cy, sxy = xy / (24 * A) - cx * cy;
  // Symmetric square root of [[sxx sxy] [sxy syy]]: sqrt(S) = (S + sqrt(det) I) / sqrt(tr + 2 sqrt(det)).
  const double det = sxx * syy - sxy * sxy;
  if (!(det > 0) || !(sxx > 0)) return {};
  const double r = std::sqrt(det), k = 1 / std::sqrt(sxx + syy + 2 * r);
  const Affine m{(sxx + r) * k, sxy * k, sxy * k, (syy + r) * k, 0, 0};
  const double s = 1 / std::sqrt(m.det());
  return {m.a * s, m.b * s, m.c * s, m.d * s, 0, 0};
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
