// What a figure hangs from (hang_support.h).
#include "procedural/hang_support.h"

#include <algorithm>
#include <cmath>

#include "procedural/motion_plan_internal.h"
#include "procedural/part_rig_internal.h"

namespace svgm {

namespace {

// A straight piece is at least kStraight times as long as it is thick (a branch, its outline, a
// highlight drawn along it; a paw's or a limb's outline curves). The support's longest piece is at
// least kLong of the figure's extent along it; all its pieces together cover kAcross of that
// extent (the branch reaches past what hangs from it). Pieces lie on its line when their axes turn
// at most kTurnDeg from it and their middles lie within kOff of the figure's size from it.
// Hanging: at least kBelow of the rest of the figure's points lie below the line.
constexpr double kStraight = 5, kLong = 0.4, kAcross = 0.75, kTurnDeg = 10, kOff = 0.08, kBelow = 0.7;

// A path's main axis through its control points' mean, and its extents along and across it.
struct Axis {
  Vec2 mid, dir;
  double along = 0, across = 0;
};

Axis axis_of(const Path& p) {
  Axis a;
  std::vector<Vec2> pts;
  for (const Subpath& s : p.subpaths) pts.insert(pts.end(), s.points.begin(), s.points.end());
  if (pts.size() < 2) return a;
  for (const Vec2& q : pts) a.mid = a.mid + q;
  a.mid = (1.0 / pts.size()) * a.mid;
  double sxx = 0, sxy = 0, syy = 0;
  for (const Vec2& q : pts) {
    const Vec2 d = q - a.mid;
    sxx += d.x * d.x, sxy += d.x * d.y, syy += d.y * d.y;
  }
  const double th = 0.5 * std::atan2(2 * sxy, sxx - syy);
  a.dir = {std::cos(th), std::sin(th)};
  double lo = 0, hi = 0, clo = 0, chi = 0;
  for (const Vec2& q : pts) {
    const Vec2 d = q - a.mid;
    const double u = d.x * a.dir.x + d.y * a.dir.y, v = -d.x * a.dir.y + d.y * a.dir.x;
    lo = std::min(lo, u), hi = std::max(hi, u), clo = std::min(clo, v), chi = std::max(chi, v);
  }
  a.along = hi - lo;
  a.across = chi - clo + (p.has_stroke ? p.stroke.width : 0);
  return a;
}

// The extent of points along dir.
void extent(const std::vector<Vec2>& pts, Vec2 dir, double& lo, double& hi) {
  for (const Vec2& q : pts) {
    const double u = q.x * dir.x + q.y * dir.y;
    lo = std::min(lo, u), hi = std::max(hi, u);
  }
}

}  // namespace

std::string hang_words(const ParsedPrompt& prompt, const Rig& rig) {
  using motion_plan_internal::parts_for;
  for (const Clause& c : prompt.clauses) {
    if (std::any_of(c.verbs.begin(), c.verbs.end(), [](const Verb* v) { return v && (v->name == "takeoff" || v->name == "land"); }))
      continue;
    for (const auto& n : c.nouns) {
      if (!n.object_of_preposition || n.preposition != "from" || n.owned) continue;
      // A known part's noun is a thing of the scene here ("from the branch": the sloth's own
      // limbs are no branch), unless the figure's own ("from its branch").
      std::string ignore;
      if (n.target != Target::Named || parts_for(rig, Target::Named, n.word, &ignore).empty()) return "from the " + n.word;
    }
  }
  return "";
}

HangSupport hang_support(const Scene& scene, const Rig& rig) {
  HangSupport out;
  const size_t n = scene.paths.size();
  out.paths.assign(n, 0);
  const RigBox& F = rig.figure;
  if (F.empty()) return out;
  auto figure_path = [&](size_t i) {
    const int g = i < rig.part_of_path.size() ? rig.part_of_path[i] : -1;
    return g < 0 || rig.parts[g].role != Role::Background;
  };
  std::vector<Axis> ax(n);
  std::vector<Vec2> corners{{F.x0, F.y0}, {F.x1, F.y0}, {F.x0, F.y1}, {F.x1, F.y1}};
  int longest = -1;
  for (size_t i = 0; i < n; ++i) {
    if (!figure_path(i)) continue;
    ax[i] = axis_of(scene.paths[i]);
    const Axis& a = ax[i];
    if (a.along < kStraight * std::max(a.across, 1e-9)) continue;
    double lo = 1e300, hi = -1e300;
    extent(corners, a.dir, lo, hi);
    if (a.along < kLong * (hi - lo)) continue;
    if (longest < 0 || a.along > ax[longest].along) longest = static_cast<int>(i);
  }
  if (longest < 0) return out;
  const Axis L = ax[longest];
  const double off = kOff * std::max(F.w(), F.h()), cos_turn = std::cos(kTurnDeg * M_PI / 180);
  const Vec2 normal{-L.dir.y, L.dir.x};
  double lo = 1e300, hi = -1e300;
  std::vector<Vec2> rest;
  for (size_t i = 0; i < n; ++i) {
    if (!figure_path(i)) continue;
    const Axis& a = ax[i];
    const Vec2 d = a.mid - L.mid;
    const bool on_line = a.along >= kStraight * std::max(a.across, 1e-9) && std::fabs(a.dir.x * L.dir.x + a.dir.y * L.dir.y) >= cos_turn &&
                         std::fabs(d.x * normal.x + d.y * normal.y) <= off;
    if (on_line) {
      out.paths[i] = 1;
      for (const Subpath& s : scene.paths[i].subpaths) extent(s.points, L.dir, lo, hi);
    } else {
      for (const Subpath& s : scene.paths[i].subpaths) rest.insert(rest.end(), s.points.begin(), s.points.end());
    }
  }
  double flo = 1e300, fhi = -1e300;
  extent(corners, L.dir, flo, fhi);
  // The line's side below: the normal pointing down the canvas (y grows downwards).
  const Vec2 down = normal.y >= 0 ? normal : Vec2{-normal.x, -normal.y};
  size_t below = 0;
  Vec2 centre;
  for (const Vec2& q : rest) {
    below += (q - L.mid).x * down.x + (q - L.mid).y * down.y > 0;
    centre = centre + q;
  }
  if (rest.empty() || hi - lo < kAcross * (fhi - flo) || below < kBelow * rest.size()) {
    std::fill(out.paths.begin(), out.paths.end(), 0);
    return out;
  }
  // The grip: the point of the line nearest the middle of what hangs from it.
  centre = (1.0 / rest.size()) * centre;
  const double u = (centre - L.mid).x * L.dir.x + (centre - L.mid).y * L.dir.y;
  out.grip = L.mid + u * L.dir;
  out.found = true;
  return out;
}

Affine pendulum(const PlannedAction& a, double amp, double t, Vec2 grip) {
  const double deg = a.direction * amp * motion_plan_internal::oscillation(a, a.cycles * t);
  return Affine::translate(grip.x, grip.y) * Affine::rotate_deg(deg) * Affine::translate(-grip.x, -grip.y);
}

}  // namespace svgm
