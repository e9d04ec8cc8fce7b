// Arm lobes of one outline (see outline_lobes.h).
#include "procedural/outline_lobes.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "geometry/curve_samples.h"

namespace svgm {

namespace {

// Samples per cubic of the outline.
constexpr int kSteps = 16;
// A concavity cuts the outline when it lies this share of the outline's box diagonal inside the
// hull (a ghost's armpits 6-9 %, its neck by a raised arm 6.6 %; a wobble of a hand-drawn edge
// under 1 %).
constexpr double kDefectDepth = 0.03;
// An arm's base's middle lies above this share of the outline's height (arms hang from the
// upper body; a ghost's hem corner starts at 63 %, its arms at 38-51 %), its base is at most
// this share of the height (arms 14-15 %, a hem corner 38 %), and it sticks out at least this
// share of its base (arms 0.6-0.84, a hem corner 0.52 but wide).
constexpr double kArmBaseLow = 0.6;
constexpr double kArmBaseMax = 0.25;
constexpr double kArmReach = 0.5;
// lobe_depth: points this share of the base's width outside the lobe's outline belong to it.
constexpr double kLobeMargin = 0.25;

double cross(Vec2 o, Vec2 a, Vec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }
double dist(Vec2 a, Vec2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

// Indices of the hull's vertices among `p` (Andrew's monotone chain), in no particular order.
std::vector<int> hull_of(const std::vector<Vec2>& p) {
  std::vector<int> idx(p.size());
  std::iota(idx.begin(), idx.end(), 0);
  std::sort(idx.begin(), idx.end(), [&](int a, int b) { return p[a].x < p[b].x || (p[a].x == p[b].x && p[a].y < p[b].y); });
  std::vector<int> h;
  for (int pass = 0; pass < 2; ++pass) {
    const size_t start = h.size();
    for (int i : idx) {
      while (h.size() >= start + 2 && cross(p[h[h.size() - 2]], p[h.back()], p[i]) <= 0) h.pop_back();
      h.push_back(i);
    }
    h.pop_back();  // the last point starts the other chain
    std::reverse(idx.begin(), idx.end());
  }
  return h;
}

}  // namespace

std::vector<ArmLobe> arm_lobes(const Path& outline) {
  std::vector<ArmLobe> out;
  if (outline.subpaths.empty()) return out;
  const auto& c = outline.subpaths[0].points;
  if (c.size() < 13) return out;  // at least four cubics: a lobe needs room
  std::vector<Vec2> p;
  append_curve_samples(outline.subpaths[0], kSteps, false, p);  // closed: its end is its start
  const int n = static_cast<int>(p.size());
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const Vec2& q : p) {
    x0 = std::min(x0, q.x); y0 = std::min(y0, q.y);
    x1 = std::max(x1, q.x); y1 = std::max(y1, q.y);
  }
  const double H = y1 - y0, diag = std::hypot(x1 - x0, H);
  if (!(H > 0)) return out;
  // Concavities: between hull vertices that follow each other along the outline, its point
  // deepest inside the hull's edge.
  std::vector<int> hull = hull_of(p);
  std::sort(hull.begin(), hull.end());
  std::vector<int> cuts;
  for (size_t h = 0; h < hull.size(); ++h) {
    const int a = hull[h], b = h + 1 < hull.size() ? hull[h + 1] : hull[0] + n;
    const Vec2 A = p[a], B = p[b % n];
    const double L = std::max(dist(A, B), 1e-9);
    double deepest = 0;
    int at = -1;
    for (int i = a + 1; i < b; ++i) {
      const double d = std::fabs(cross(A, B, p[i % n])) / L;
      if (d > deepest) { deepest = d; at = i % n; }
    }
    if (at >= 0 && deepest > kDefectDepth * diag) cuts.push_back(at);
  }
  std::sort(cuts.begin(), cuts.end());
  if (cuts.size() < 2) return out;
  const double cx = 0.5 * (x0 + x1);
  for (size_t k = 0; k < cuts.size(); ++k) {
    const int a = cuts[k], b = k + 1 < cuts.size() ? cuts[k + 1] : cuts[0] + n;
    const Vec2 A = p[a], B = p[b % n], mid = 0.5 * (A + B);
    const double L = std::max(dist(A, B), 1e-9);
    int tip = a;
    for (int i = a; i <= b; ++i)
      if (std::fabs(cross(A, B, p[i % n])) > std::fabs(cross(A, B, p[tip % n]))) tip = i;
    const Vec2 T = p[tip % n];
    const double reach = std::fabs(cross(A, B, T)) / L;
    // The base's normal, pointing to the tip.
    Vec2 nrm{(B.y - A.y) / L, -(B.x - A.x) / L};
    if ((T.x - mid.x) * nrm.x + (T.y - mid.y) * nrm.y < 0) nrm = -1.0 * nrm;
    const int side = nrm.x < 0 ? -1 : 1;
    const bool sideways = std::fabs(nrm.x) > std::fabs(nrm.y) && (T.x - cx) * side > 0;
    if (!sideways || mid.y > y0 + kArmBaseLow * H || L > kArmBaseMax * H || reach < kArmReach * L) continue;
    ArmLobe lobe;
    lobe.side = side;
    lobe.base0 = A;
    lobe.base1 = B;
    lobe.pivot = mid;
    lobe.tip = T;
    for (int i = a; i <= b; ++i) lobe.outline.push_back(p[i % n]);
    out.push_back(std::move(lobe));
  }
  std::sort(out.begin(), out.end(), [](const ArmLobe& l, const ArmLobe& r) { return l.side < r.side; });
  return out;
}

double lobe_depth(const ArmLobe& lobe, Vec2 q) {
  const Vec2 A = lobe.base0, B = lobe.base1;
  const double L = std::max(dist(A, B), 1e-9);
  // Beyond the base, on the tip's side.
  const double tip_side = cross(A, B, lobe.tip) > 0 ? 1 : -1;
  const double beyond = tip_side * cross(A, B, q) / L;
  if (beyond <= 0) return 0;
  // Inside the lobe's outline closed by its base (even-odd crossings), or near it.
  const auto& o = lobe.outline;
  bool inside = false;
  double near = 1e300;
  for (size_t i = 0, j = o.size() - 1; i < o.size(); j = i++) {
    const Vec2 a = o[i], b = o[j];
    if ((a.y > q.y) != (b.y > q.y) && q.x < (b.x - a.x) * (q.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
    near = std::min(near, segment_distance(q, a, b));
  }
  return inside || near <= kLobeMargin * L ? beyond : 0;
}

int owner_lobe(const std::vector<ArmLobe>& lobes, int path) {
  for (size_t k = 0; k < lobes.size() && path >= 0; ++k)
    if (std::binary_search(lobes[k].paths.begin(), lobes[k].paths.end(), path)) return static_cast<int>(k);
  return -1;
}

double lobe_owned_depth(const ArmLobe& lobe, Vec2 q) {
  const Vec2 A = lobe.base0, B = lobe.base1;
  const double tip_side = cross(A, B, lobe.tip) > 0 ? 1 : -1;
  return std::max(0.0, tip_side * cross(A, B, q) / std::max(dist(A, B), 1e-9));
}

}  // namespace svgm
