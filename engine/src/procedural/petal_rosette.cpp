// Petals round a flower's centre (see petal_rosette.h): a rosette outline or a ring of
// repeated elements, as one lobe about the centre.
#include "procedural/petal_rosette.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace svgm {

namespace {

constexpr int kRosetteLobes = 5;        // rises and falls of the outline's reach: a square's 4 corners are no petals
constexpr double kRosetteDip = 0.15;    // each dip at least this share of the farthest reach in
constexpr double kRosetteHigh = 0.6;    // a rise reaches this share of the way from the nearest to the farthest reach,
constexpr double kRosetteLow = 0.35;    // a fall this share (hysteresis: a wobbling curve counts once)
constexpr double kRingSpread = 0.4;     // a ring's elements lie within this share of their mean distance of it
constexpr double kRingGap = 150;        // degrees: no side of the centre without a petal wider than this
constexpr double kInside = 0.8;         // an element drawn inside the flower: this share of its box within
constexpr double kOutlineGrow = 1.06;   // the lobe's disc: the farthest reach grown by this factor
constexpr double kTau = 6.283185307179586;

double dist(Vec2 a, Vec2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

double overlap_area(const RigBox& a, const RigBox& b) {
  const double ox = std::min(a.x1, b.x1) - std::max(a.x0, b.x0), oy = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
  return ox > 0 && oy > 0 ? ox * oy : 0;
}

// Drawn in the flower: most of its box within `box` (a straight stroke's box without area:
// its middle within), or drawn over the same place (a fill under its outline stroke).
bool drawn_in(const RigBox& b, const RigBox& box) {
  if (b.area() <= 0) {
    const Vec2 c = b.centre();
    return !b.empty() && c.x >= box.x0 && c.x <= box.x1 && c.y >= box.y0 && c.y <= box.y1;
  }
  const double o = overlap_area(b, box);
  return o >= kInside * b.area() || (o >= 0.5 * b.area() && o >= 0.5 * box.area());
}

// The number of petals of a rosette outline about `c` (its control points in order round it),
// 0 when the points do not go round `c` or their reach barely changes.
int rosette_lobes(const std::vector<Vec2>& pts, Vec2 c) {
  if (pts.size() < 13) return 0;
  std::vector<double> r(pts.size());
  int sectors = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    r[i] = dist(pts[i], c);
    const double a = std::atan2(pts[i].y - c.y, pts[i].x - c.x);
    sectors |= 1 << std::clamp(static_cast<int>(std::floor((a + M_PI) / (kTau / 8))), 0, 7);
  }
  if (sectors != 0xff) return 0;  // not all the way round
  const auto [lo_it, hi_it] = std::minmax_element(r.begin(), r.end());
  const double lo = *lo_it, hi = *hi_it;
  if (hi <= 0 || (hi - lo) < kRosetteDip * hi) return 0;
  const double rise = lo + kRosetteHigh * (hi - lo), fall = lo + kRosetteLow * (hi - lo);
  // Round once from the nearest point, counting the rises.
  const size_t start = static_cast<size_t>(lo_it - r.begin());
  int n = 0;
  bool up = false;
  for (size_t k = 0; k < r.size(); ++k) {
    const double v = r[(start + k) % r.size()];
    if (!up && v >= rise) up = true, ++n;
    else if (up && v <= fall) up = false;
  }
  return n;
}

// The lobe over every point of elements `els`: a disc about `c` past their farthest point, its
// base behind all of them, so every point of the flower is in it.
ArmLobe disc_lobe(const Rig& rig, const std::vector<int>& els, Vec2 c) {
  ArmLobe l;
  l.pivot = c;
  l.tip = c;
  for (int e : els)
    for (Vec2 q : rig.elements[e].points)
      if (dist(q, c) > dist(l.tip, c)) l.tip = q;
  const double R = std::max(dist(l.tip, c), 1e-9) * kOutlineGrow;
  const Vec2 u = (1 / std::max(dist(l.tip, c), 1e-9)) * (l.tip - c), n = {-u.y, u.x};
  const Vec2 b = c - 1.1 * R * u;
  l.base0 = b - 1.2 * R * n;
  l.base1 = b + 1.2 * R * n;
  for (int k = 0; k < 32; ++k) {
    const double a = kTau * k / 32;
    l.outline.push_back(c + R * Vec2{std::cos(a), std::sin(a)});
  }
  l.side = 1;
  l.kind = LobeKind::Other;
  return l;
}

std::string path_list(const Rig& rig, const std::vector<int>& els) {
  std::set<int> ps;
  for (int e : els) ps.insert(rig.elements[e].path + 1);
  std::string s;
  for (int p : ps) s += (s.empty() ? "" : "+") + std::to_string(p);
  return "path " + s;
}

}  // namespace

LocatedPart find_petals(const Rig& rig) {
  LocatedPart out;
  out.shape = PartShape::Petals;
  std::vector<int> els;
  Vec2 centre;
  RigBox flower;
  std::string what;
  // A rosette: the largest element whose outline goes round its middle in petals.
  int best = -1, lobes = 0;
  for (size_t i = 0; i < rig.elements.size(); ++i) {
    const RigElement& e = rig.elements[i];
    const int n = rosette_lobes(e.points, e.box.centre());
    if (n >= kRosetteLobes && (best < 0 || e.box.area() > rig.elements[best].box.area())) best = static_cast<int>(i), lobes = n;
  }
  if (best >= 0) {
    flower = rig.elements[best].box;
    centre = flower.centre();
    what = "an outline of " + std::to_string(lobes) + " petals round its middle (path " + std::to_string(rig.elements[best].path + 1) +
           " at " + fmt_box(rig, flower) + ")";
  } else if (rig.repeated.size() >= 3) {
    // A ring: the repeated elements round the mean of their middles.
    std::vector<Vec2> mids;
    for (const auto& element : rig.repeated) {
      RigBox b;
      for (const ElementPiece& piece : element)
        for (const RigElement& e : rig.elements)
          if (e.path == piece.path && (piece.subpath < 0 || e.subpath < 0 || e.subpath == piece.subpath)) b.add(e.box);
      if (!b.empty()) mids.push_back(b.centre()), flower.add(b);
    }
    if (mids.size() < 3) return out;
    for (Vec2 m : mids) centre = centre + (1.0 / mids.size()) * m;
    double mean = 0;
    for (Vec2 m : mids) mean += dist(m, centre) / mids.size();
    std::vector<double> angles;
    for (Vec2 m : mids) {
      if (mean <= 0 || std::fabs(dist(m, centre) - mean) > kRingSpread * mean) return out;
      angles.push_back(std::atan2(m.y - centre.y, m.x - centre.x) * 360 / kTau);
    }
    std::sort(angles.begin(), angles.end());
    double gap = 360 - (angles.back() - angles.front());
    for (size_t k = 1; k < angles.size(); ++k) gap = std::max(gap, angles[k] - angles[k - 1]);
    if (gap > kRingGap) return out;
    what = std::to_string(mids.size()) + " repeated elements in a ring round their middle (at " + fmt_box(rig, flower) + ")";
  } else {
    return out;
  }
  // The flower: what is drawn within its box (its heart, the outline over its fill).
  for (size_t i = 0; i < rig.elements.size(); ++i)
    if (static_cast<int>(i) == best || drawn_in(rig.elements[i].box, flower)) els.push_back(static_cast<int>(i));
  if (els.empty()) return out;
  out.lobes.push_back(disc_lobe(rig, els, centre));
  std::set<int> paths;
  for (int e : els) paths.insert(rig.elements[e].path);
  out.paths.assign(paths.begin(), paths.end());
  out.why = what + " with what is drawn in it (" + path_list(rig, els) + "), spreading from the centre";
  return out;
}

}  // namespace svgm
