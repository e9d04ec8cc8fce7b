// The part locator (see part_locator.h): a part the prompt names, found on the figure's drawn
// elements by a spatial and shape prior of its kind, as lobes the motion turns.
#include "procedural/part_locator.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "geometry/convex_hull.h"
#include "motion/motion_verbs.h"
#include "procedural/flame_core.h"
#include "procedural/petal_rosette.h"
#include "procedural/plume_stacks.h"
#include "procedural/rotor_blades.h"

namespace svgm {

namespace {

// Priors, in shares of the figure's box (F) or of the body element's box (B).
constexpr double kEarTop = 0.2;        // an ear's top within this share of F's height from F's top
constexpr double kEarMiddle = 0.45;    // its middle above this share of F's height
constexpr double kPartMinSize = 0.1;   // a part's longer side at least this share of F's longer side
constexpr double kPartMaxShare = 0.35; // a part's box at most this share of F's box
constexpr double kEarMaxShare = 0.55;  // an ear's, when none of the usual size sticks out: an
                                       // elephant's ear spans most of its head (openmoji's: 0.45)
constexpr double kEarReach = 0.75;     // an element picked as an ear reaching below this share of F's height is a
                                       // head drawn with its ear (openmoji's elephant: 0.87; twemoji's own ear: 0.65)
constexpr double kEarCut = 0.5;        // and its ear is its stretch above this share of F's height
constexpr double kEarBehind = 0.1;     // an ear's middle at most this share of F's width behind F's middle (eye_cue.h)
constexpr double kPairShare = 0.3;     // the second of a pair at least this share of the first's score
constexpr double kClapperOffCentre = 0.15;  // a clapper's middle within this share of B's width of B's middle
constexpr double kClapperLow = 0.7;    // its middle below this share of B's height
constexpr double kClapperMaxShare = 0.15;   // its box at most this share of B's box
constexpr double kThin = 3;            // a hand is at least this many times longer than wide
constexpr double kHandsMeet = 0.12;    // hands' inner ends within this share of their dial's size
constexpr double kSideOffCentre = 0.2; // a side protrusion's middle this share of F's width off F's middle
constexpr double kInside = 0.8;        // an element inside another: this share of its box within
constexpr double kHullGrow = 0.06;     // a lobe's outline is its hull grown by this share about its middle
constexpr double kGround = 0.03;       // a limb whose outline comes this share of F's height to F's bottom stands
constexpr double kStemMin = 0.3;       // a stem at least this share of F's height
constexpr double kBloomMin = 0.08;     // a bloom's box at least this share of F's box
constexpr double kStrandReach = 0.1;   // a strand's end within this share of F's longer side of the body's box
constexpr double kStrandAlong = 0.5;   // strokes drawn along one strand: boxes overlapping this share of the smaller

double overlap_area(const RigBox& a, const RigBox& b) {
  const double ox = std::min(a.x1, b.x1) - std::max(a.x0, b.x0), oy = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
  return ox > 0 && oy > 0 ? ox * oy : 0;
}

bool inside(const RigBox& inner, const RigBox& outer) {
  // A box without area (a straight stroke's) is inside when it lies within.
  if (inner.area() <= 0)
    return !inner.empty() && inner.within(outer);
  return overlap_area(inner, outer) >= kInside * inner.area();
}

double dist(Vec2 a, Vec2 b) { return std::hypot(a.x - b.x, a.y - b.y); }
// The index of the body: the element with the largest box.
int body_of(const Rig& rig) {
  int best = -1;
  for (size_t i = 0; i < rig.elements.size(); ++i)
    if (best < 0 || rig.elements[i].box.area() > rig.elements[best].box.area()) best = static_cast<int>(i);
  return best;
}

// The elements drawn inside element e's box (its details: an ear's inner colour), and those
// drawn over the same place (a colour fill under its outline stroke: each box covers at least
// half of the other), e included.
std::vector<int> with_details(const Rig& rig, int e, int body) {
  std::vector<int> out = {e};
  const RigBox& E = rig.elements[e].box;
  for (size_t i = 0; i < rig.elements.size(); ++i) {
    const RigBox& b = rig.elements[i].box;
    if (static_cast<int>(i) == e || static_cast<int>(i) == body) continue;
    const double o = overlap_area(b, E);
    if ((b.area() < E.area() && inside(b, E)) || (o >= 0.5 * b.area() && o >= 0.5 * E.area() && o > 0)) out.push_back(static_cast<int>(i));
  }
  return out;
}

// One lobe over elements `els` turning about `pivot`: its tip is their point farthest from the
// pivot, its base the line across the axis through the pivot, moved back behind every point.
ArmLobe lobe_over_points(const Rig& rig, const std::vector<Vec2>& pts, Vec2 pivot) {
  ArmLobe l;
  l.pivot = pivot;
  l.tip = pivot;
  for (Vec2 q : pts)
    if (dist(q, pivot) > dist(l.tip, pivot)) l.tip = q;
  const double len = std::max(dist(l.tip, pivot), 1e-9);
  const Vec2 u = (1 / len) * (l.tip - pivot), n = {-u.y, u.x};
  double back = 0, half = 0;
  for (Vec2 q : pts) {
    back = std::min(back, (q.x - pivot.x) * u.x + (q.y - pivot.y) * u.y);
    half = std::max(half, std::fabs((q.x - pivot.x) * n.x + (q.y - pivot.y) * n.y));
  }
  // Just behind the hindmost point, so every point of the part is beyond it.
  const Vec2 b = pivot + (back - 0.02 * len) * u;
  half = std::max(half * 1.1, 0.05 * len);
  l.base0 = b - half * n;
  l.base1 = b + half * n;
  std::vector<Vec2> hull = convex_hull(pts);
  Vec2 c;
  for (Vec2 q : hull) c = c + (1.0 / hull.size()) * q;
  for (Vec2& q : hull) q = c + (1 + kHullGrow) * (q - c);
  l.outline = hull;
  l.side = l.tip.x < rig.figure.centre().x ? -1 : 1;
  return l;
}

ArmLobe lobe_over(const Rig& rig, const std::vector<int>& els, Vec2 pivot) {
  std::vector<Vec2> pts;
  for (int e : els) pts.insert(pts.end(), rig.elements[e].points.begin(), rig.elements[e].points.end());
  return lobe_over_points(rig, pts, pivot);
}

// The point of elements `els` nearest `to`.
Vec2 nearest_point(const Rig& rig, const std::vector<int>& els, Vec2 to) {
  Vec2 best = to;
  double d = 1e300;
  for (int e : els)
    for (Vec2 q : rig.elements[e].points)
      if (dist(q, to) < d) d = dist(q, to), best = q;
  return best;
}

void add_paths(const Rig& rig, const std::vector<int>& els, std::set<int>& paths) {
  for (int e : els) paths.insert(rig.elements[e].path);
}

// The elements a part may be: not the body, no larger than kPartMaxShare of the figure's box,
// not too small, and not inside another such element (they come with it as its details).
std::vector<int> part_candidates(const Rig& rig, int body, double max_share = kPartMaxShare) {
  const RigBox& F = rig.figure;
  const double D = std::max(F.w(), F.h());
  std::vector<int> c;
  for (size_t i = 0; i < rig.elements.size(); ++i) {
    const RigBox& b = rig.elements[i].box;
    if (static_cast<int>(i) == body || b.area() > max_share * F.area() || std::max(b.w(), b.h()) < kPartMinSize * D) continue;
    c.push_back(static_cast<int>(i));
  }
  std::vector<int> out;
  for (int i : c) {
    bool within = false;
    for (int j : c)
      within = within || (j != i && rig.elements[j].box.area() > rig.elements[i].box.area() && inside(rig.elements[i].box, rig.elements[j].box));
    if (!within) out.push_back(i);
  }
  return out;
}

std::string path_ids(const std::vector<int>& els, const Rig& rig) {
  std::string s;
  for (int e : els) s += (s.empty() ? "" : "+") + std::to_string(rig.elements[e].path + 1);
  return "path " + s;
}

LocatedPart ears(const Rig& rig, int body) {
  LocatedPart out;
  const RigBox& F = rig.figure;
  const RigBox& B = rig.elements[body].box;
  // Sticking out: the share of its box above the body's top counts most. Ears of a part's
  // usual size first (a hare's, whose head is no ear); a large one only when none is found.
  std::vector<std::pair<double, int>> scored;
  for (double max_share : {kPartMaxShare, kEarMaxShare}) {
    for (int i : part_candidates(rig, body, max_share)) {
      const RigBox& b = rig.elements[i].box;
      if (b.y0 > F.y0 + kEarTop * F.h() || b.centre().y > F.y0 + kEarMiddle * F.h()) continue;
      // Ears are at the head's end: with an eye seen (eye_cue.h), not beyond the middle away
      // from it (a dog's raised tail is no ear).
      if (rig.eye_side != 0 && (b.centre().x - F.centre().x) * rig.eye_side < -kEarBehind * F.w()) continue;
      const double above = std::clamp((B.y0 - b.y0) / std::max(b.h(), 1e-9), 0.0, 1.0);
      scored.push_back({rig.elements[i].area * (0.25 + above), i});
    }
    if (!scored.empty()) break;
  }
  std::sort(scored.rbegin(), scored.rend());
  if (scored.empty()) return out;
  std::vector<int> picked = {scored[0].second};
  if (scored.size() > 1 && scored[1].first >= kPairShare * scored[0].first) picked.push_back(scored[1].second);
  std::set<int> paths;
  std::string where;
  bool cut = false;
  for (int e : picked) {
    const auto els = with_details(rig, e, body);
    // An ear hangs from the head's top: an element reaching down into the figure's lower
    // quarter is a head drawn in one outline with its ear (an elephant's, its trunk hanging
    // from it), and its ear is its stretch above the middle; the trunk below holds.
    const double low = F.y0 + kEarCut * F.h();
    bool upper = false;
    if (rig.elements[e].box.y1 > F.y0 + kEarReach * F.h()) {
      std::vector<Vec2> pts, own;
      for (int i : els)
        for (Vec2 q : rig.elements[i].points)
          if (q.y <= low) (i == e ? own : pts).push_back(q);
      if (!own.empty()) {
        Vec2 pivot = own[0];
        for (Vec2 q : own)
          if (dist(q, B.centre()) < dist(pivot, B.centre())) pivot = q;
        pts.insert(pts.end(), own.begin(), own.end());
        out.lobes.push_back(lobe_over_points(rig, pts, pivot));
        cut = upper = true;
      }
    }
    if (!upper) out.lobes.push_back(lobe_over(rig, els, nearest_point(rig, {e}, B.centre())));
    add_paths(rig, els, paths);
    where += (where.empty() ? "" : " and ") + path_ids(els, rig) + " at " + fmt_box(rig, rig.elements[e].box);
  }
  out.paths.assign(paths.begin(), paths.end());
  out.why = std::to_string(picked.size()) + (picked.size() > 1 ? " elements stick" : " element sticks") +
            " out at the figure's top (" + where + "), each turning about its end nearest the body" +
            (cut ? "; of one reaching the figure's lower quarter (a head drawn with its ear) only its stretch above the middle" : "");
  return out;
}

LocatedPart jet(const Rig& rig) {
  LocatedPart out;
  // What is drawn above its source's top, less what stands under it (plume_stacks.h).
  size_t stacked = 0;
  const std::vector<int> els = plume_elements(rig, stacked);
  if (els.empty()) return out;
  RigBox box;
  for (int i : els) box.add(rig.elements[i].box);
  out.lobes.push_back(lobe_over(rig, els, {box.centre().x, box.y1}));
  std::set<int> paths;
  add_paths(rig, els, paths);
  out.paths.assign(paths.begin(), paths.end());
  out.why = std::to_string(els.size()) + " element" + (els.size() > 1 ? "s" : "") + " drawn above the body's top (" +
            path_ids(els, rig) + " at " + fmt_box(rig, box) + "), turning about their lowest middle" +
            (stacked ? "; " + std::to_string(stacked) + " with another drawn on them edge to edge stay" : "");
  return out;
}

// Flames (of a candle, a lamp, a torch): the tips of what is drawn above the body's top, each
// element there with nothing else of it drawn above it (a candle carries its flame: the flame
// is the tip, the candle under it holds), with its details, each flickering about its lowest
// middle. A fire drawn as one blaze has nothing above its body: none found, the whole figure
// flickers (motion_plan.cpp).
LocatedPart flames(const Rig& rig, int body) {
  LocatedPart out;
  const RigBox& B = rig.elements[body].box;
  std::vector<int> above;
  for (size_t i = 0; i < rig.elements.size(); ++i)
    if (static_cast<int>(i) != body && rig.elements[i].box.centre().y < B.y0 && rig.elements[i].box.area() < B.area())
      above.push_back(static_cast<int>(i));
  std::set<int> taken, paths;
  std::vector<int> tips;
  RigBox all;
  for (int e : above) {
    const RigBox& E = rig.elements[e].box;
    bool covered = false;  // another element over it: its middle higher, across its width, not inside it
    for (int o : above) {
      const RigBox& O = rig.elements[o].box;
      covered = covered || (o != e && O.centre().y < E.y0 + 0.25 * E.h() && O.centre().x > E.x0 && O.centre().x < E.x1 && !inside(O, E));
    }
    if (covered || taken.count(e)) continue;
    const std::vector<int> els = with_details(rig, e, body);
    RigBox box;
    for (int d : els) taken.insert(d), box.add(rig.elements[d].box);
    out.lobes.push_back(lobe_over(rig, els, {box.centre().x, box.y1}));
    add_paths(rig, els, paths);
    tips.push_back(e);
    all.add(box);
  }
  if (tips.empty()) return out;
  out.paths.assign(paths.begin(), paths.end());
  out.why = std::to_string(tips.size()) + " tip" + (tips.size() > 1 ? "s" : "") + " drawn above the body's top with nothing above them (" +
            path_ids(tips, rig) + " at " + fmt_box(rig, all) + "), each about its lowest middle";
  return out;
}

LocatedPart clapper(const Rig& rig, int body) {
  LocatedPart out;
  const RigBox& B = rig.elements[body].box;
  std::vector<int> fits;
  int best = -1;
  for (size_t i = 0; i < rig.elements.size(); ++i) {
    const RigBox& b = rig.elements[i].box;
    if (static_cast<int>(i) == body || b.area() > kClapperMaxShare * B.area()) continue;
    if (std::fabs(b.centre().x - B.centre().x) > kClapperOffCentre * B.w() || b.centre().y < B.y0 + kClapperLow * B.h()) continue;
    fits.push_back(static_cast<int>(i));
    if (best < 0 || b.centre().y > rig.elements[best].box.centre().y) best = static_cast<int>(i);
  }
  if (best < 0) return out;
  // The clapper is every element there that overlaps the lowest (openmoji's bell: its outline's
  // lower arc, 1F514, and the disc of colour under it, which rose behind the bell's rim), with
  // their details; it hangs from the middle of their top. The arc alone swung off its colour.
  std::set<int> mine;
  for (int i : fits)
    if (overlap_area(rig.elements[i].box, rig.elements[best].box) > 0)
      for (int e : with_details(rig, i, body)) mine.insert(e);
  const std::vector<int> els(mine.begin(), mine.end());
  RigBox b;
  for (int e : els) b.add(rig.elements[e].box);
  // It hangs free: bent from a ramp at its top, or through a mesh with the bell, its top stayed
  // and it folded (the mesh held openmoji's clapper to 4.3 % of the figure's size). It hangs
  // from its top inside the body, or from the body's bottom when drawn wholly below it (turned
  // about its own flat top, twemoji's half disc, 1f514, raised a corner over the bell's rim).
  out.lobes.push_back(lobe_over(rig, els, {b.centre().x, std::min(b.y0, B.y1)}));
  out.lobes.back().rigid = true;
  std::set<int> paths;
  add_paths(rig, els, paths);
  out.paths.assign(paths.begin(), paths.end());
  out.why = "the lowest small element centred under the body, with what overlaps it (" + path_ids(els, rig) + " at " +
            fmt_box(rig, b) + "), swinging whole about its top";
  return out;
}

using Axis = ElementAxis;
Axis axis_of(const RigElement& e) {
  Axis ax;
  if (e.points.size() < 2) return ax;
  Vec2 c;
  for (Vec2 q : e.points) c = c + (1.0 / e.points.size()) * q;
  double sxx = 0, syy = 0, sxy = 0;
  for (Vec2 q : e.points) sxx += (q.x - c.x) * (q.x - c.x), syy += (q.y - c.y) * (q.y - c.y), sxy += (q.x - c.x) * (q.y - c.y);
  const double ang = 0.5 * std::atan2(2 * sxy, sxx - syy);
  const Vec2 u = {std::cos(ang), std::sin(ang)}, n = {-u.y, u.x};
  double lo = 1e300, hi = -1e300, w0 = 1e300, w1 = -1e300;
  for (Vec2 q : e.points) {
    const double s = (q.x - c.x) * u.x + (q.y - c.y) * u.y, t = (q.x - c.x) * n.x + (q.y - c.y) * n.y;
    if (s < lo) lo = s, ax.a = q;
    if (s > hi) hi = s, ax.b = q;
    w0 = std::min(w0, t);
    w1 = std::max(w1, t);
  }
  ax.elongation = (hi - lo) / std::max(w1 - w0, 1e-9);
  ax.mid_a = c + lo * u, ax.mid_b = c + hi * u;
  return ax;
}

LocatedPart hands(const Rig& rig, int body) {
  LocatedPart out;
  // Thin elements inside a larger one (the dial).
  struct Hand { int e; Axis ax; int dial; };
  std::vector<Hand> thin;
  for (size_t i = 0; i < rig.elements.size(); ++i) {
    if (static_cast<int>(i) == body) continue;
    const Axis ax = axis_of(rig.elements[i]);
    if (ax.elongation < kThin && !rig.elements[i].thin) continue;
    int dial = -1;
    for (size_t j = 0; j < rig.elements.size(); ++j)
      if (j != i && rig.elements[j].box.area() >= 4 * rig.elements[i].box.area() && inside(rig.elements[i].box, rig.elements[j].box) &&
          (dial < 0 || rig.elements[j].box.area() < rig.elements[dial].box.area()))
        dial = static_cast<int>(j);
    if (dial >= 0) thin.push_back({static_cast<int>(i), ax, dial});
  }
  // The centre most of them meet at with one end, in their dial.
  int best_n = 0;
  Vec2 centre;
  int dial = -1;
  for (const Hand& h : thin)
    for (Vec2 end : {h.ax.a, h.ax.b}) {
      const RigBox& d = rig.elements[h.dial].box;
      const double tol = kHandsMeet * std::max(d.w(), d.h());
      int n = 0;
      Vec2 sum;
      for (const Hand& k : thin) {
        if (k.dial != h.dial) continue;
        const Vec2 near = dist(k.ax.a, end) < dist(k.ax.b, end) ? k.ax.a : k.ax.b;
        if (dist(near, end) <= tol) ++n, sum = sum + near;
      }
      // Nearer the dial's middle wins a tie (hands turn about it, a tick mark does not).
      const Vec2 c = (1.0 / std::max(n, 1)) * sum;
      if (n > best_n || (n == best_n && n > 0 && dist(c, d.centre()) < dist(centre, rig.elements[dial].box.centre())))
        best_n = n, centre = c, dial = h.dial;
    }
  if (best_n < 1 || dial < 0) return out;
  const RigBox& d = rig.elements[dial].box;
  const double tol = kHandsMeet * std::max(d.w(), d.h());
  // A single thin element counts only when its end is at the dial's middle.
  if (best_n == 1 && dist(centre, d.centre()) > 2 * tol) return out;
  std::set<int> paths;
  std::string which;
  for (const Hand& k : thin) {
    if (k.dial != dial) continue;
    const Vec2 near = dist(k.ax.a, centre) < dist(k.ax.b, centre) ? k.ax.a : k.ax.b;
    if (dist(near, centre) > tol) continue;
    ArmLobe l = lobe_over(rig, {k.e}, centre);
    l.side = -1;  // every hand turns the same way
    out.lobes.push_back(l);
    add_paths(rig, {k.e}, paths);
    which += (which.empty() ? "" : "+") + std::to_string(rig.elements[k.e].path + 1);
  }
  out.paths.assign(paths.begin(), paths.end());
  out.why = std::to_string(out.lobes.size()) + " thin element" + (out.lobes.size() > 1 ? "s" : "") + " (path " + which +
            ") inside path " + std::to_string(rig.elements[dial].path + 1) + " meet at one end, the centre they turn about";
  return out;
}

LocatedPart side_pair(const Rig& rig, int body) {
  LocatedPart out;
  const RigBox& F = rig.figure;
  const RigBox& B = rig.elements[body].box;
  const double cx = F.centre().x;
  // Protrusions: elements off the middle, each with the elements overlapping it on its side
  // (an arm and the pincer drawn at its end).
  std::vector<int> cand = part_candidates(rig, body);
  auto cluster = [&](int e) {
    std::vector<int> c = {e};
    const int side = rig.elements[e].box.centre().x < cx ? -1 : 1;
    for (size_t i = 0; i < rig.elements.size(); ++i) {
      const RigBox& b = rig.elements[i].box;
      if (static_cast<int>(i) == e || static_cast<int>(i) == body || (b.centre().x < cx ? -1 : 1) != side) continue;
      if (overlap_area(b, rig.elements[e].box) > 0 && b.centre().y < B.centre().y) c.push_back(static_cast<int>(i));
    }
    return c;
  };
  double best = 0;
  int bl = -1, br = -1;
  for (int l : cand)
    for (int r : cand) {
      const RigBox &a = rig.elements[l].box, &b = rig.elements[r].box;
      if (a.centre().x >= cx - kSideOffCentre * F.w() || b.centre().x <= cx + kSideOffCentre * F.w()) continue;
      // Mirrored: as far out, at the same height, of like size.
      const double mirror = std::fabs((cx - a.centre().x) - (b.centre().x - cx)) / F.w() + std::fabs(a.centre().y - b.centre().y) / F.h();
      const double size = std::min(a.area(), b.area()) / std::max(std::max(a.area(), b.area()), 1e-12);
      if (mirror > 0.25 || size < 0.4) continue;
      // Forward (up) and large.
      const double up = 1 - ((a.centre().y + b.centre().y) / 2 - F.y0) / std::max(F.h(), 1e-9);
      const double score = (a.area() + b.area()) / F.area() * (0.5 + up) * (1 - mirror);
      if (score > best) best = score, bl = l, br = r;
    }
  if (bl < 0) return out;
  std::set<int> paths;
  std::string where;
  for (int e : {bl, br}) {
    std::vector<int> els;
    for (int c : cluster(e))
      for (int d : with_details(rig, c, body))
        if (std::find(els.begin(), els.end(), d) == els.end()) els.push_back(d);
    out.lobes.push_back(lobe_over(rig, els, nearest_point(rig, els, B.centre())));
    add_paths(rig, els, paths);
    where += (where.empty() ? "" : " and ") + path_ids(els, rig);
  }
  out.paths.assign(paths.begin(), paths.end());
  out.why = "the largest mirrored pair of protrusions at the figure's sides, farthest forward (" + where +
            "), each turning about its point nearest the body";
  return out;
}

// Whether a limb stands on the ground: its outline reaches the figure's bottom. A limb the
// skeleton labelled a leg because it points down (an elephant's trunk hanging beside legs too
// stout to be limbs) does not.
bool stands(const Rig& rig, const ArmLobe& l) {
  double low = -1e300;
  for (Vec2 q : l.outline) low = std::max(low, q.y);
  return low >= rig.figure.y1 - kGround * rig.figure.h();
}

LocatedPart branch(const Rig& rig) {
  LocatedPart out;
  // The longest limb of the silhouette that does not stand on the ground (legs do).
  int best = -1;
  double longest = 0;
  for (size_t i = 0; i < rig.limbs.size(); ++i) {
    const ArmLobe& l = rig.limbs[i];
    if (l.kind == LobeKind::Leg && stands(rig, l)) continue;
    const double len = dist(l.pivot, l.tip);
    if (len > longest) longest = len, best = static_cast<int>(i);
  }
  if (best < 0) return out;
  out.lobes.push_back(rig.limbs[best]);
  // Every figure path within the limb moves (the outline drawn over its fill).
  std::set<int> paths;
  for (const RigElement& e : rig.elements)
    for (Vec2 q : e.points)
      if (lobe_depth(rig.limbs[best], q) > 0) {
        paths.insert(e.path);
        break;
      }
  out.paths.assign(paths.begin(), paths.end());
  RigBox b;
  for (Vec2 q : rig.limbs[best].outline) b.add(q);
  out.why = "the longest limb of the silhouette's skeleton that does not stand on the ground (at " + fmt_box(rig, b) + "), bending about its base";
  return out;
}

// How far q lies outside box b (0 inside).
double box_distance(const RigBox& b, Vec2 q) {
  return std::hypot(std::max({b.x0 - q.x, 0.0, q.x - b.x1}), std::max({b.y0 - q.y, 0.0, q.y - b.y1}));
}

// Puts element e with the strand in `groups` it is drawn along (its box and the strand's
// first one's overlap by kStrandAlong of the smaller), else in a strand of its own; true then.
bool join_along(const Rig& rig, std::vector<std::vector<int>>& groups, int e) {
  const RigBox& b = rig.elements[e].box;
  for (auto& g : groups) {
    const RigBox& lead = rig.elements[g[0]].box;
    const double smaller = std::max(std::min(b.area(), lead.area()), 1e-12);
    if (overlap_area(b, lead) >= kStrandAlong * smaller) {
      g.push_back(e);
      return false;
    }
  }
  groups.push_back({e});
  return true;
}

LocatedPart strands(const Rig& rig, int body) {
  LocatedPart out;
  const RigBox& F = rig.figure;
  const RigBox& B = rig.elements[body].box;
  const double D = std::max(F.w(), F.h());
  // What strands hang from: the body and the stout elements joined to it, in turn (a squid's
  // head drawn between its mantle and its arms: measured from the mantle alone, 2 of its 7 arms
  // reached it and only those two moved).
  std::vector<RigBox> trunk = {B};
  std::vector<char> joined(rig.elements.size(), 0);
  for (size_t n = 0; n != trunk.size();) {
    n = trunk.size();
    for (size_t i = 0; i < rig.elements.size(); ++i) {
      const RigElement& e = rig.elements[i];
      if (!joined[i] && static_cast<int>(i) != body && !e.thin && axis_of(e).elongation < kThin &&
          std::any_of(trunk.begin(), trunk.end(), [&](const RigBox& t) { return overlap_area(t, e.box) > 0; }))
        joined[i] = 1, trunk.push_back(e.box);
    }
  }
  auto from_trunk = [&](Vec2 q) {
    double d = 1e300;
    for (const RigBox& t : trunk) d = std::min(d, box_distance(t, q));
    return d;
  };
  // Elongated elements hanging below the body (their middles below its bottom: a highlight
  // drawn on the bell is no tentacle), one end at the trunk: each with its end there.
  std::vector<std::pair<int, Vec2>> hanging;
  for (size_t i = 0; i < rig.elements.size(); ++i) {
    const RigElement& e = rig.elements[i];
    if (static_cast<int>(i) == body || e.box.centre().y <= B.y1 || e.box.area() > kPartMaxShare * F.area() ||
        std::max(e.box.w(), e.box.h()) < kPartMinSize * D)
      continue;
    const Axis ax = axis_of(e);
    if (ax.elongation < kThin && !e.thin) continue;
    const Vec2 end = from_trunk(ax.a) < from_trunk(ax.b) ? ax.a : ax.b;
    if (from_trunk(end) <= kStrandReach * D) hanging.push_back({static_cast<int>(i), end});
  }
  // Strokes drawn along one strand (a colour under its outline) are one strand: the longest
  // leads, its end the pivot.
  std::sort(hanging.begin(), hanging.end(), [&](const auto& x, const auto& y) {
    const RigBox &a = rig.elements[x.first].box, &b = rig.elements[y.first].box;
    return std::hypot(a.w(), a.h()) > std::hypot(b.w(), b.h());
  });
  std::vector<std::vector<int>> groups;
  std::vector<Vec2> ends;
  for (const auto& [e, end] : hanging)
    if (join_along(rig, groups, e)) ends.push_back(end);
  if (groups.size() < 2) return out;
  std::set<int> paths;
  for (size_t g = 0; g < groups.size(); ++g) {
    ArmLobe l = lobe_over(rig, groups[g], ends[g]);
    l.side = -1;  // every strand turns the same way: mirrored, the two middle ones crossed
    std::set<int> own;
    add_paths(rig, groups[g], own);
    l.paths.assign(own.begin(), own.end());  // each strand's strokes turn with it (owner_lobe)
    out.lobes.push_back(l);
    add_paths(rig, groups[g], paths);
  }
  out.paths.assign(paths.begin(), paths.end());
  RigBox all;
  for (const auto& g : groups)
    for (int e : g) all.add(rig.elements[e].box);
  std::string ids;
  for (const auto& g : groups) ids += (ids.empty() ? "" : ", ") + path_ids(g, rig);
  out.why = std::to_string(groups.size()) + " elongated elements hang below the body (" + ids + " at " + fmt_box(rig, all) +
            "), each turning about its end at the body";
  return out;
}

LocatedPart bloom(const Rig& rig) {
  LocatedPart out;
  const RigBox& F = rig.figure;
  // Stems: long upright elongated elements, the strokes drawn along one stem together.
  std::vector<std::pair<double, int>> upright;
  for (size_t i = 0; i < rig.elements.size(); ++i) {
    const RigElement& e = rig.elements[i];
    const Axis ax = axis_of(e);
    if ((ax.elongation < kThin && !e.thin) || e.box.h() < kStemMin * F.h() || e.box.h() < e.box.w()) continue;
    upright.push_back({e.box.h(), static_cast<int>(i)});
  }
  std::sort(upright.rbegin(), upright.rend());
  std::vector<std::vector<int>> stems;
  for (const auto& u : upright) join_along(rig, stems, u.second);
  if (stems.size() != 1) return out;
  const std::vector<int>& stem = stems[0];
  const Axis ax = axis_of(rig.elements[stem[0]]);
  const Vec2 neck = ax.a.y < ax.b.y ? ax.a : ax.b;
  // The head: the largest element drawn above the neck (its box's middle) and at it, with the
  // elements above the neck that overlap it, or one of them, in turn (its petals). A leaf
  // reaching up beside the head from lower on the stem is not among them.
  std::vector<int> above;
  for (size_t i = 0; i < rig.elements.size(); ++i)
    if (std::find(stem.begin(), stem.end(), static_cast<int>(i)) == stem.end() && rig.elements[i].box.centre().y < neck.y)
      above.push_back(static_cast<int>(i));
  int seed = -1;
  for (int i : above)
    if (box_distance(rig.elements[i].box, neck) <= kStrandReach * std::max(F.w(), F.h()) &&
        (seed < 0 || rig.elements[i].box.area() > rig.elements[seed].box.area()))
      seed = i;
  if (seed < 0) return out;
  std::vector<int> head = {seed};
  for (bool grew = true; grew;) {
    grew = false;
    for (int i : above)
      if (std::find(head.begin(), head.end(), i) == head.end() &&
          std::any_of(head.begin(), head.end(), [&](int h) { return overlap_area(rig.elements[i].box, rig.elements[h].box) > 0; })) {
        head.push_back(i);
        grew = true;
      }
  }
  RigBox box;
  for (int h : head) box.add(rig.elements[h].box);
  // A head is a good share of the plant.
  if (box.area() < kBloomMin * F.area()) return out;
  out.lobes.push_back(lobe_over(rig, head, neck));
  std::set<int> paths;
  add_paths(rig, head, paths);
  out.paths.assign(paths.begin(), paths.end());
  out.why = std::to_string(head.size()) + " element" + (head.size() > 1 ? "s" : "") + " drawn above the top of the one stem (" +
            path_ids(stem, rig) + ") at " + fmt_box(rig, box) + ", turning about the stem's top";
  return out;
}

bool any_stem(std::string_view w, std::initializer_list<std::string_view> stems) {
  for (auto s : stems)
    if (word_matches(w, s)) return true;
  return false;
}

}  // namespace

ElementAxis element_axis(const RigElement& e) { return axis_of(e); }
ArmLobe lobe_over_elements(const Rig& rig, const std::vector<int>& els, Vec2 pivot) { return lobe_over(rig, els, pivot); }
ArmLobe lobe_over_point_set(const Rig& rig, const std::vector<Vec2>& pts, Vec2 pivot) { return lobe_over_points(rig, pts, pivot); }

// A box in shares of the figure's box, for the notes: "0.10,0.20-0.40,0.55".
std::string fmt_box(const Rig& rig, const RigBox& b) {
  const RigBox& F = rig.figure;
  char s[96];
  std::snprintf(s, sizeof s, "%.2f,%.2f-%.2f,%.2f", (b.x0 - F.x0) / std::max(F.w(), 1e-9), (b.y0 - F.y0) / std::max(F.h(), 1e-9),
                (b.x1 - F.x0) / std::max(F.w(), 1e-9), (b.y1 - F.y0) / std::max(F.h(), 1e-9));
  return s;
}

std::string fmt_lobes(const Rig& rig, const std::vector<ArmLobe>& lobes) {
  static const char* kinds[] = {"arm", "leg", "head", "tail", "other"};
  std::string s;
  for (const ArmLobe& l : lobes) {
    RigBox b;
    for (Vec2 q : l.outline) b.add(q);
    s += (s.empty() ? "" : ", ") + std::string(kinds[static_cast<int>(l.kind)]) + " " + fmt_box(rig, b);
  }
  return s;
}

PartShape part_shape_of(std::string_view w, FigureClass figure) {
  const bool animal = figure == FigureClass::Biped || figure == FigureClass::Quadruped || figure == FigureClass::Bird ||
                      figure == FigureClass::FishOrSnake || figure == FigureClass::Insect;
  if (any_stem(w, {"ear", "antenna", "antennae"})) return PartShape::Ears;
  if (any_stem(w, {"spout", "plume", "jet", "spray", "steam", "smok", "fountain", "geyser"})) return PartShape::Jet;
  if (any_stem(w, {"flame", "flamelet"})) return PartShape::Flames;
  if (any_stem(w, {"clapper", "pendulum"})) return PartShape::Clapper;
  if (figure == FigureClass::Object && any_stem(w, {"hand", "needl", "pointer"})) return PartShape::Hands;
  if (any_stem(w, {"claw", "pincer", "nipper", "mandibl", "chela"})) return PartShape::SidePair;
  if (animal && any_stem(w, {"trunk", "proboscis", "snout"})) return PartShape::Branch;
  if (any_stem(w, {"petal"})) return PartShape::Petals;
  if (any_stem(w, {"tentacl", "tendril", "strand"})) return PartShape::Strands;
  if (any_stem(w, {"propell", "rotor", "blade", "vane"})) return PartShape::Rotor;
  return PartShape::None;
}

const char* part_shape_name(PartShape s) {
  switch (s) {
    case PartShape::Ears: return "ears";
    case PartShape::Jet: return "jet";
    case PartShape::Flames: return "flames";
    case PartShape::Clapper: return "clapper";
    case PartShape::Hands: return "hands";
    case PartShape::SidePair: return "side pair";
    case PartShape::Branch: return "branch";
    case PartShape::Petals: return "petals";
    case PartShape::Strands: return "strands";
    case PartShape::Bloom: return "bloom";
    case PartShape::Rotor: return "rotor";
    case PartShape::None: break;
  }
  return "none";
}

std::vector<RigElement> figure_elements(const Scene& scene, const Rig& rig) {
  std::vector<RigElement> out;
  for (size_t pi = 0; pi < scene.paths.size(); ++pi) {
    const Path& p = scene.paths[pi];
    const int g = pi < rig.part_of_path.size() ? rig.part_of_path[pi] : -1;
    if (g >= 0 && rig.parts[g].role == Role::Background) continue;
    const bool filled = p.has_fill && p.fill.a > 0;
    // Subpaths apart (no one's box inside another's) are elements of their own; one inside
    // another (a hole, a detail) goes with it.
    std::vector<RigBox> boxes;
    for (const auto& sp : p.subpaths) {
      RigBox b;
      for (Vec2 q : sp.points) b.add(q);
      boxes.push_back(b);
    }
    std::vector<int> owner(p.subpaths.size(), -1);
    for (size_t i = 0; i < p.subpaths.size(); ++i)
      for (size_t j = 0; j < p.subpaths.size(); ++j)
        if (i != j && !boxes[i].empty() && boxes[j].area() > boxes[i].area() && inside(boxes[i], boxes[j]) &&
            (owner[i] < 0 || boxes[j].area() < boxes[owner[i]].area()))
          owner[i] = static_cast<int>(j);
    std::vector<RigElement> mine;
    std::vector<int> index(p.subpaths.size(), -1);
    for (size_t i = 0; i < p.subpaths.size(); ++i) {
      if (owner[i] >= 0 || boxes[i].empty()) continue;
      RigElement e;
      e.path = static_cast<int>(pi);
      e.subpath = static_cast<int>(i);
      index[i] = static_cast<int>(mine.size());
      mine.push_back(e);
    }
    for (size_t i = 0; i < p.subpaths.size(); ++i) {
      int top = static_cast<int>(i);
      for (int guard = 0; owner[top] >= 0 && guard < 64; ++guard) top = owner[top];
      if (index[top] < 0) continue;
      RigElement& e = mine[index[top]];
      const auto& pts = p.subpaths[i].points;
      for (Vec2 q : pts) e.box.add(q), e.points.push_back(q);
      double s = 0, len = 0;
      for (size_t k = 0; k + 1 < pts.size(); ++k) {
        s += pts[k].x * pts[k + 1].y - pts[k + 1].x * pts[k].y;
        len += dist(pts[k], pts[k + 1]);
      }
      if (filled) e.area += (static_cast<int>(i) == top ? 1 : -1) * 0.5 * std::fabs(s);
      else e.area += len * (p.has_stroke ? p.stroke.width : 1);
      e.thin = !filled && p.has_stroke && !p.subpaths[i].closed;
      if (filled && p.opacity > 0) e.lightness = 0.299 * p.fill.r + 0.587 * p.fill.g + 0.114 * p.fill.b;
    }
    if (mine.size() == 1) mine[0].subpath = -1;
    for (auto& e : mine) e.area = std::max(e.area, 0.0);
    out.insert(out.end(), mine.begin(), mine.end());
  }
  return out;
}

LocatedPart locate_part(const Rig& rig, PartShape shape) {
  LocatedPart out;
  const int body = body_of(rig);
  if (body < 0 || rig.figure.empty()) return out;
  switch (shape) {
    case PartShape::Ears: out = ears(rig, body); break;
    case PartShape::Jet: out = jet(rig); break;
    case PartShape::Flames: out = flames(rig, body), out = out.lobes.empty() ? flames_over_core(rig, body) : out; break;
    case PartShape::Clapper: out = clapper(rig, body); break;
    case PartShape::Hands: out = hands(rig, body); break;
    case PartShape::SidePair: out = side_pair(rig, body); break;
    case PartShape::Branch: out = branch(rig); break;
    case PartShape::Petals: out = find_petals(rig); break;
    case PartShape::Strands: out = strands(rig, body); break;
    case PartShape::Bloom: out = bloom(rig); break;
    case PartShape::Rotor: out = rotor_blades(rig, body); break;
    case PartShape::None: break;
  }
  out.shape = shape;
  return out;
}

}  // namespace svgm
