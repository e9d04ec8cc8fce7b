// A tail the skeleton's labels missed (see part_locator.h's tail_limbs): the limbs of the
// silhouette opposite the head, found by where the head is and how long each limb is. Apart
// from the part locator's priors: it reads the skeleton's limbs, not the drawn elements.
#include <algorithm>
#include <cmath>

#include "procedural/part_locator.h"

namespace svgm {

namespace {

constexpr double kTailMaxLength = 0.5;  // a tail no longer than this share of the figure's longer side

double dist(Vec2 a, Vec2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

}  // namespace

std::vector<ArmLobe> tail_limbs(const Rig& rig) {
  // Where the head is: a drawn eye (eye_cue.h), else the rig's head parts, else the tips of the
  // skeleton's head limbs.
  Vec2 head;
  double weight = 0;
  if (rig.eye_side != 0) head = rig.eye, weight = 1;
  if (weight == 0)
    for (const RigPart& P : rig.parts)
      if (P.role == Role::Head && !P.box.empty()) {
        const double w = std::max(P.box.area(), 1e-12);
        head = head + w * P.box.centre();
        weight += w;
      }
  if (weight == 0)
    for (const ArmLobe& l : rig.limbs)
      if (l.kind == LobeKind::Head) head = head + l.tip, weight += 1;
  if (weight == 0 || rig.figure.empty()) return {};
  head = (1 / weight) * head;
  const Vec2 c = rig.figure.centre(), front = head - c;
  int best = -1;
  for (size_t i = 0; i < rig.limbs.size(); ++i) {
    const ArmLobe& l = rig.limbs[i];
    if (l.kind == LobeKind::Head || l.kind == LobeKind::Leg) continue;
    // As long as half the figure: the body itself (a lying bar with a head on it), no tail.
    if (dist(l.pivot, l.tip) > kTailMaxLength * std::max(rig.figure.w(), rig.figure.h())) continue;
    const Vec2 to = l.tip - c;
    if (to.x * front.x + to.y * front.y >= 0) continue;  // on the head's side of the middle
    if (best < 0 || dist(l.tip, head) > dist(rig.limbs[best].tip, head)) best = static_cast<int>(i);
  }
  if (best < 0) return {};
  const ArmLobe& tail = rig.limbs[best];
  const double base = dist(tail.base0, tail.base1);
  std::vector<ArmLobe> out = {tail};
  for (size_t i = 0; i < rig.limbs.size(); ++i) {
    const ArmLobe& l = rig.limbs[i];
    if (static_cast<int>(i) != best && l.kind != LobeKind::Head && l.kind != LobeKind::Leg && dist(l.pivot, tail.pivot) <= base)
      out.push_back(l);
  }
  return out;
}

}  // namespace svgm
