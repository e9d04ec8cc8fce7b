// Questions the motion plan asks of the rig's tree of parts: whether one part hangs from
// another, the box of a part with what hangs from it, the topmost of a set of parts, which of
// several limbs reaches out (the one a one-sided verb moves), and which limbs of the
// silhouette's skeleton a limb role bends.
#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "procedural/motion_plan_internal.h"

namespace svgm::motion_plan_internal {

// Keeps only the parts whose ancestors are not also in the set (a limb's segments follow it).
std::vector<int> topmost(const Rig& rig, std::vector<int> parts) {
  std::set<int> in(parts.begin(), parts.end());
  std::vector<int> out;
  for (int p : parts) {
    bool covered = false;
    for (int a = rig.parts[p].parent, guard = 0; a >= 0 && guard < 64; a = rig.parts[a].parent, ++guard)
      covered = covered || in.count(a) > 0;
    if (!covered) out.push_back(p);
  }
  return out;
}

// Whether part p is at or under part a (a descendant through the parents).
bool part_under(const Rig& rig, int p, int a) {
  for (int g = p, guard = 0; g >= 0 && guard < 64; g = rig.parts[g].parent, ++guard)
    if (g == a) return true;
  return false;
}

// The box of part a with everything that hangs from it.
RigBox chain_box(const Rig& rig, int a) {
  RigBox b;
  for (size_t h = 0; h < rig.parts.size(); ++h)
    if (part_under(rig, static_cast<int>(h), a)) b.add(rig.parts[h].box);
  return b;
}

// Of several limbs, the one whose chain (the limb and what hangs from it) reaches clearly
// farthest from the root's middle: the drawing shows it in action (a punch thrown, an arm
// raised to wave, a leg out in a kick). -1 when none reaches kReachLead farther than every other
// (the seed picks). A chain's reach is the farthest corner of its box.
int reaching_out(const Rig& rig, const std::vector<int>& limbs) {
  if (rig.root < 0 || limbs.size() < 2) return -1;
  const Vec2 c = rig.parts[rig.root].box.centre();
  std::vector<double> reach;
  for (int l : limbs) {
    const RigBox b = chain_box(rig, l);
    double far = 0;
    for (Vec2 q : {Vec2{b.x0, b.y0}, Vec2{b.x1, b.y0}, Vec2{b.x0, b.y1}, Vec2{b.x1, b.y1}}) far = std::max(far, std::hypot(q.x - c.x, q.y - c.y));
    reach.push_back(far);
  }
  const size_t best = std::max_element(reach.begin(), reach.end()) - reach.begin();
  for (size_t i = 0; i < reach.size(); ++i)
    if (i != best && reach[best] < kReachLead * reach[i]) return -1;
  return limbs[best];
}

// Which limbs of a silhouette's skeleton a limb role bends.
bool lobe_serves(LobeKind k, Target t) {
  switch (t) {
    case Target::Arms: return k == LobeKind::Arm;
    case Target::Legs: return k == LobeKind::Leg;
    case Target::Head: return k == LobeKind::Head;
    case Target::Tail: return k == LobeKind::Tail;
    case Target::Limbs: return k == LobeKind::Arm || k == LobeKind::Leg || k == LobeKind::Other;
    default: return false;
  }
}

}  // namespace svgm::motion_plan_internal
