// A bird's wing drawn over its body (see body_wing.h).
#include "procedural/body_wing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

namespace svgm {

namespace {

double overlap_area(const RigBox& a, const RigBox& b) {
  const double ox = std::min(a.x1, b.x1) - std::max(a.x0, b.x0), oy = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
  return ox > 0 && oy > 0 ? ox * oy : 0;
}

// Where the head is: the drawn eye, else the rig's head parts (by area), else the tips of the
// silhouette's head limbs; false when none shows it.
bool head_point(const Rig& rig, Vec2& at) {
  if (rig.eye_side != 0) return at = rig.eye, true;
  Vec2 sum;
  double weight = 0;
  for (const RigPart& P : rig.parts)
    if (P.role == Role::Head && !P.box.empty()) {
      const double w = std::max(P.box.area(), 1e-12);
      sum = sum + w * P.box.centre();
      weight += w;
    }
  if (weight == 0)
    for (const ArmLobe& l : rig.limbs)
      if (l.kind == LobeKind::Head) sum = sum + l.tip, weight += 1;
  if (weight == 0) return false;
  at = (1 / weight) * sum;
  return true;
}

// Whether element e has a twin mirrored across the figure's middle: another element of like
// size (kTwinSize) whose middle, reflected, lies within kTwinNear of the figure's width of e's.
bool mirrored(const Rig& rig, const std::vector<RigElement>& E, int e) {
  const RigBox& b = E[e].box;
  const double cx = rig.figure.centre().x, near = kTwinNear * rig.figure.w();
  for (size_t j = 0; j < E.size(); ++j) {
    const RigBox& o = E[j].box;
    if (static_cast<int>(j) == e || o.area() < (1 - kTwinSize) * b.area() || o.area() > (1 + kTwinSize) * b.area()) continue;
    if (std::hypot(2 * cx - o.centre().x - b.centre().x, o.centre().y - b.centre().y) <= near) return true;
  }
  return false;
}

}  // namespace

LocatedPart wing_on_body(const Rig& rig) {
  LocatedPart out;
  const auto& E = rig.elements;
  int body = -1;
  for (size_t i = 0; i < E.size(); ++i)
    if (body < 0 || E[i].box.area() > E[body].box.area()) body = static_cast<int>(i);
  if (body < 0 || rig.figure.empty()) return out;
  const RigBox& B = E[body].box;
  const double D = std::max(rig.figure.w(), rig.figure.h());
  Vec2 head;
  const bool has_head = head_point(rig, head);
  int wing = -1;
  for (size_t i = 0; i < E.size(); ++i) {
    const RigBox& b = E[i].box;
    if (static_cast<int>(i) == body || E[i].thin || b.area() <= 0) continue;
    if (overlap_area(b, B) < 0.9 * b.area()) continue;  // drawn inside the body's box
    if (b.area() < kWingMinShare * B.area() || b.area() > kWingMaxShare * B.area()) continue;
    if (b.centre().y > B.y0 + kWingLow * B.h()) continue;
    // On the silhouette's core, not in one of its limbs (the head and neck, the tail, a leg).
    if (std::any_of(rig.limbs.begin(), rig.limbs.end(), [&](const ArmLobe& l) { return lobe_depth(l, b.centre()) > 0; })) continue;
    // Not the head's: no eye in it, its middle away from the eye.
    const Vec2 e = rig.eye;
    if (rig.eye_side != 0 && ((e.x >= b.x0 && e.x <= b.x1 && e.y >= b.y0 && e.y <= b.y1) ||
                              std::hypot(b.centre().x - e.x, b.centre().y - e.y) < kWingFromEye * D))
      continue;
    // Not one of a mirrored pair (a bat seen from the front: its wing's panels left and right).
    if (mirrored(rig, E, static_cast<int>(i))) continue;
    if (wing < 0 || b.area() > E[wing].box.area()) wing = static_cast<int>(i);
  }
  if (wing < 0) return out;
  // The wing with what is drawn on it (its feathers, its outline over its fill): elements
  // inside its box, or over the same place (each box covering half of the other).
  const RigBox& W = E[wing].box;
  std::vector<int> els = {wing};
  for (size_t i = 0; i < E.size(); ++i) {
    const RigBox& b = E[i].box;
    if (static_cast<int>(i) == wing || static_cast<int>(i) == body) continue;
    const double o = overlap_area(b, W);
    if ((b.area() < W.area() && o >= 0.8 * b.area()) || (o >= 0.5 * b.area() && o >= 0.5 * W.area() && o > 0)) els.push_back(static_cast<int>(i));
  }
  // Its shoulder: its point nearest the head, else nearest the body's middle.
  const Vec2 to = has_head ? head : B.centre();
  Vec2 pivot = E[wing].points.empty() ? W.centre() : E[wing].points[0];
  for (Vec2 q : E[wing].points)
    if (std::hypot(q.x - to.x, q.y - to.y) < std::hypot(pivot.x - to.x, pivot.y - to.y)) pivot = q;
  std::set<int> paths;
  bool whole_paths = true;
  for (int e : els) {
    paths.insert(E[e].path);
    whole_paths = whole_paths && E[e].subpath < 0;
  }
  out.lobes.push_back(lobe_over_elements(rig, els, pivot));
  // Paths of its own turn whole about the shoulder; a wing drawn as a subpath of a path that
  // draws more (an outline layer) bends within its hull only.
  out.lobes.back().rigid = whole_paths;
  out.paths.assign(paths.begin(), paths.end());
  char box[96];
  std::snprintf(box, sizeof box, " (at %s), about its point nearest the %s", fmt_box(rig, W).c_str(), has_head ? "head" : "body's middle");
  out.why = "the largest shape drawn inside the body's box away from the head" + std::string(box);
  return out;
}

void beat_drawn_wing(const Rig& rig, PlannedAction& a, const LocatedPart& wing, std::string& note) {
  a.parts = {rig.root};
  a.region = Region::Located;
  a.lobes = wing.lobes;
  a.silhouette = true;
  a.lobe_paths = wing.paths;
  a.held_paths = wing.holds;
  a.region_side = 0;
  a.sign = {1};
  a.phase = {0};
  note = "no separate wings: the wing drawn over the body turns, " + wing.why;
}

}  // namespace svgm
