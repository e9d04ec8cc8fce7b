// Rotors: blades about a hub, found and moved (see rotor_blades.h).
#include "procedural/rotor_blades.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "procedural/part_rig_internal.h"

namespace svgm {

namespace {

constexpr double kPi = 3.14159265358979323846;

double dist(Vec2 a, Vec2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

// The angle between two directions, in degrees (0 .. 180).
double angle_between(double a, double b) {
  double d = std::fabs(a - b) * 180 / kPi;
  while (d > 360) d -= 360;
  return d > 180 ? 360 - d : d;
}

struct Blade {
  int e;
  Vec2 near, far;  // its end at the hub and its other end
  // A pair of blades drawn as one shape across the hub (its middle there): `far` is one end,
  // and a copy with `opposite` set stands for the other (a direction of its own, no lobe).
  bool through = false, opposite = false;
};

// The blades with an end within `tol` of `hub`, each with that end as `near`; and the shapes
// whose middle is there (within `tol` and kThroughMiddle of their length): a two-bladed
// propeller drawn as one shape (twemoji's small plane 1f6e9 has one across its two blades).
std::vector<Blade> blades_at(const std::vector<int>& cand, const std::vector<ElementAxis>& ax, Vec2 hub, double tol) {
  std::vector<Blade> out;
  for (size_t k = 0; k < cand.size(); ++k) {
    const bool a_near = dist(ax[k].mid_a, hub) <= dist(ax[k].mid_b, hub);
    const Vec2 n = a_near ? ax[k].mid_a : ax[k].mid_b, f = a_near ? ax[k].mid_b : ax[k].mid_a;
    const Vec2 mid = 0.5 * (ax[k].mid_a + ax[k].mid_b);
    // Centred there first: a short shape across the hub has both its ends within `tol` of it.
    if (dist(mid, hub) <= std::min(tol, kThroughMiddle * dist(ax[k].mid_a, ax[k].mid_b)))
      out.push_back({cand[k], mid, ax[k].mid_a, true, false}), out.push_back({cand[k], mid, ax[k].mid_b, true, true});
    else if (dist(n, hub) <= tol)
      out.push_back({cand[k], n, f});
  }
  return out;
}

// The blades grouped by direction from the hub (a fill and the outline over it point one way).
std::vector<std::vector<Blade>> by_direction(const std::vector<Blade>& blades, Vec2 hub) {
  std::vector<std::vector<Blade>> groups;
  std::vector<double> dirs;
  for (const Blade& b : blades) {
    const double d = std::atan2(b.far.y - hub.y, b.far.x - hub.x);
    size_t g = 0;
    while (g < dirs.size() && angle_between(dirs[g], d) > kSameDirection) ++g;
    if (g == dirs.size()) dirs.push_back(d), groups.emplace_back();
    groups[g].push_back(b);
  }
  return groups;
}

// The blades about `hub` grouped by direction, each direction's length (its longest blade), and
// the direction whose length the most others share (within kSameLength): a rotor's blades are
// alike; what else ends at the hub (the nose a propeller is on, a rotor's mast) is not.
struct BladeSpread {
  std::vector<std::vector<Blade>> groups;
  std::vector<double> len;
  size_t best = 0, most = 0;
};

bool alike(double a, double b) { return std::max(a, b) <= (1 + kSameLength) * std::min(a, b); }

BladeSpread spread_at(const std::vector<int>& cand, const std::vector<ElementAxis>& ax, Vec2 hub, double tol) {
  BladeSpread s;
  s.groups = by_direction(blades_at(cand, ax, hub, tol), hub);
  for (const auto& g : s.groups) {
    double l = 0;
    for (const Blade& b : g) l = std::max(l, dist(b.near, b.far));
    s.len.push_back(l);
  }
  for (size_t i = 0; i < s.len.size(); ++i) {
    size_t n = 0;
    for (double l : s.len) n += alike(l, s.len[i]) ? 1 : 0;
    // Of classes as large, the longest blades (a bar's halves, not the mast's it sits on).
    if (n > s.most || (n == s.most && s.len[i] > s.len[s.best])) s.most = n, s.best = i;
  }
  return s;
}

// Whether the rotor's spin axis lies in the picture's plane: blades all in one line through the
// hub (`line`: its direction) held there by something running across that line: an elongated
// element other than the blades (the body included) with an end at the hub, within
// kSameDirection of square to the line: a helicopter's mast under its main rotor, a side view's
// nose behind its propeller. A rotor's disc seen edge on projects to a line square to its axis;
// two blades in line with nothing across them (a helicopter's tail rotor at the boom's end, its
// blades slanting across the boom) are a two-bladed rotor seen face on.
bool held_across(const Rig& rig, const std::set<int>& blades, Vec2 hub, double line, double tol) {
  for (size_t i = 0; i < rig.elements.size(); ++i) {
    if (blades.count(static_cast<int>(i))) continue;
    const ElementAxis a = element_axis(rig.elements[i]);
    if (a.elongation < kBladeElongation && !rig.elements[i].thin) continue;
    if (std::min(dist(a.mid_a, hub), dist(a.mid_b, hub)) > tol) continue;
    const double d = angle_between(line, std::atan2(a.mid_b.y - a.mid_a.y, a.mid_b.x - a.mid_a.x));
    if (std::fabs(d - 90) <= kSameDirection) return true;
  }
  return false;
}

// Whether every lobe lies in line with the first, one way or the other; `line` its direction.
bool lobes_in_line(const std::vector<ArmLobe>& lobes, double& line) {
  if (lobes.empty()) return false;
  const ArmLobe& f = lobes[0];
  line = std::atan2(f.tip.y - f.pivot.y, f.tip.x - f.pivot.x);
  for (const ArmLobe& l : lobes) {
    const double a = angle_between(line, std::atan2(l.tip.y - l.pivot.y, l.tip.x - l.pivot.x));
    if (a > kSameDirection && a < 180 - kSameDirection) return false;
  }
  return true;
}

}  // namespace

LocatedPart rotor_blades(const Rig& rig, int body) {
  LocatedPart out;
  const RigBox& F = rig.figure;
  const double D = std::max(F.w(), F.h()), tol = kHubMeet * D;
  std::vector<int> cand;
  std::vector<ElementAxis> ax;
  for (size_t i = 0; i < rig.elements.size(); ++i) {
    // Not the body, nor its outline drawn over it (each box covering half the other's).
    const RigBox &E = rig.elements[i].box, &B = rig.elements[body].box;
    if (static_cast<int>(i) == body || (part_rig_internal::overlap(E, B) >= 0.5 * E.area() && part_rig_internal::overlap(E, B) >= 0.5 * B.area())) continue;
    const ElementAxis a = element_axis(rig.elements[i]);
    if ((a.elongation < kBladeElongation && !rig.elements[i].thin) || dist(a.mid_a, a.mid_b) < kBladeMinLength * D) continue;
    cand.push_back(static_cast<int>(i));
    ax.push_back(a);
  }
  // The hub: where the most blade directions meet (then the most blades: a fill and its
  // outline), looked for at every blade end (the ends there averaged) and at the middle of
  // every small element (a hub drawn as a disc the blades stop short of).
  // Each look: a point and the disc drawn there (-1: none). The discs first: a tie goes to a
  // drawn hub.
  std::vector<std::pair<Vec2, int>> looks;
  for (size_t i = 0; i < rig.elements.size(); ++i)
    if (std::hypot(rig.elements[i].box.w(), rig.elements[i].box.h()) <= 2 * tol) looks.push_back({rig.elements[i].box.centre(), static_cast<int>(i)});
  for (const ElementAxis& a : ax) looks.push_back({a.mid_a, -1}), looks.push_back({a.mid_b, -1});
  // And at the middle of every blade: two strokes crossing there (openmoji's small plane 1F6E9),
  // no disc and no blade ending there.
  for (const ElementAxis& a : ax) looks.push_back({0.5 * (a.mid_a + a.mid_b), -1});
  size_t best_dirs = 0, best_n = 0;
  bool drawn_hub = false;
  Vec2 hub;
  for (const auto& [at_point, drawn] : looks) {
    const bool disc = drawn >= 0;
    const std::vector<Blade> at = blades_at(cand, ax, at_point, tol);
    // One shape across a point (or a stroke and its outline, one line) is any long shape: a
    // rotor needs a hub drawn apart from it, or a blade ending there, or shapes across it in two
    // lines at least (openmoji's drone E1D2 has a stroke and its outline across each rotor's
    // ring and no hub: none is found, as before).
    std::set<int> shapes;
    size_t across = 0, ends = 0;
    for (const Blade& b : at) shapes.insert(b.e), across += b.through && !b.opposite ? 1 : 0, ends += b.through ? 0 : 1;
    const bool own_disc = disc && !shapes.empty() && !shapes.count(drawn);
    if (shapes.size() < 2 && !own_disc) continue;
    // The middles of the shapes across the hub, averaged: they are centred on it (the nose a
    // propeller sits on ends a little short of it); else the blade ends met there.
    Vec2 c = at_point;
    const bool by_middles = across > 0;
    if (!disc && (across > 0 || ends > 0)) {
      c = {};
      for (const Blade& b : at)
        if (b.through == by_middles && !b.opposite) c = c + (1.0 / (by_middles ? across : ends)) * b.near;
    }
    const size_t dirs = by_direction(at, c).size();
    if (!own_disc && ends == 0 && dirs < 3) continue;
    if (dirs > best_dirs || (dirs == best_dirs && at.size() > best_n)) best_dirs = dirs, best_n = at.size(), hub = c, drawn_hub = own_disc;
  }
  // Two directions at least: one blade alone is any elongated shape (a wing, a leg).
  if (best_dirs < 2) return out;
  // The hub where the rotor's blades meet: the middle of the alike blades' inner ends. Looked
  // for at a helicopter's mast's middle (a small elongated element), the most directions met
  // there were the blades' two and the mast's own two halves; turned about that point, the
  // blades and the mast swung through the cabin (twemoji's 1f681). Moved to the blades' inner
  // ends, the mast only ends there: it is what holds the rotor, not a blade. A hub drawn apart
  // (a disc the blades meet at) stays where it is drawn.
  if (!drawn_hub) {
    const BladeSpread first = spread_at(cand, ax, hub, tol);
    Vec2 inner;
    size_t n = 0;
    for (size_t g = 0; g < first.groups.size(); ++g)
      if (first.most >= 2 && alike(first.len[g], first.len[first.best]))
        for (const Blade& b : first.groups[g])
          if (!b.opposite) inner = inner + b.near, ++n;
    if (n > 0) hub = (1.0 / n) * inner;
  }
  // A rotor's blades are alike: the directions whose blades are as long as those of the most
  // others (within kSameLength) are its blades; what else ends at the hub (the nose a propeller
  // is on, its spinner) is not. A shape across the hub is the rotor's whatever its length (a
  // nose or a tail ends at the hub, it is not centred on it).
  const BladeSpread spread = spread_at(cand, ax, hub, tol);
  const std::vector<std::vector<Blade>>& groups = spread.groups;
  const std::vector<double>& len = spread.len;
  const size_t best = spread.best;
  if (spread.most < 2) return out;
  std::set<int> paths;
  std::string which;
  for (size_t gi = 0; gi < groups.size(); ++gi) {
    const auto& group = groups[gi];
    const bool across = std::any_of(group.begin(), group.end(), [](const Blade& b) { return b.through && !b.opposite; });
    if (!alike(len[gi], len[best]) && !across) continue;
    std::vector<int> els;
    for (const Blade& b : group) {
      // In a direction with a shape across the hub, a blade ending there is the rotor's only
      // when as long as its blades (the nose and the spinner point the same way).
      if (b.opposite || (!b.through && !alike(dist(b.near, b.far), len[best]))) continue;
      els.push_back(b.e);
      paths.insert(rig.elements[b.e].path);
      which += (which.empty() ? "" : "+") + std::to_string(rig.elements[b.e].path + 1);
    }
    if (els.empty()) continue;
    ArmLobe l = lobe_over_elements(rig, els, hub);
    l.side = -1;  // every blade turns the same way
    // Its tip on its middle line (the way to its points' centroid), not at a corner of its end: an
    // edge-on blade squeezes along that line, never across it. A shape across the hub has its
    // centroid there: the way to its far end.
    Vec2 c;
    size_t n = 0;
    for (const Blade& b : group)
      if (!b.through)
        for (Vec2 q : rig.elements[b.e].points) c = c + q, ++n;
    c = n > 0 ? (1.0 / n) * c : std::find_if(group.begin(), group.end(), [](const Blade& b) { return !b.opposite; })->far;
    if (dist(c, hub) > 0) l.tip = hub + (dist(l.tip, hub) / dist(c, hub)) * (c - hub);
    out.lobes.push_back(l);
  }
  out.paths.assign(paths.begin(), paths.end());
  out.why = std::to_string(out.lobes.size()) + " blade direction" + (out.lobes.size() > 1 ? "s" : "") + " (path " + which +
            ") meeting at a hub at " + fmt_box(rig, RigBox{hub.x, hub.y, hub.x, hub.y}) + (rotor_edge_on(rig, out) ? ", in one line across what holds it: seen edge on" : "");
  return out;
}

bool rotor_edge_on(const Rig& rig, const LocatedPart& rotor) {
  double line = 0;
  if (!lobes_in_line(rotor.lobes, line)) return false;
  std::set<int> blades;
  for (size_t i = 0; i < rig.elements.size(); ++i)
    if (std::binary_search(rotor.paths.begin(), rotor.paths.end(), rig.elements[i].path)) blades.insert(static_cast<int>(i));
  return held_across(rig, blades, rotor.lobes[0].pivot, line, kHubMeet * std::max(rig.figure.w(), rig.figure.h()));
}

void rotor_motion(const Rig& rig, const LocatedPart& rotor, Primitive& primitive, double& amp) {
  if (rotor_edge_on(rig, rotor)) primitive = Primitive::Stretch, amp = 1 - kEdgeOnMin;
  else primitive = Primitive::Spin, amp = 1;
}

}  // namespace svgm
