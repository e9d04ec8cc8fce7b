// The limbs a prompt's qualifier picks (see limb_qualifiers.h).
#include "procedural/limb_qualifiers.h"

#include <algorithm>
#include <cmath>

#include "procedural/body_facing.h"
#include "procedural/motion_plan_internal.h"
#include "procedural/shape_facing.h"

namespace svgm {

namespace {

// The flight verbs whose arms' action is a wing beat (the verb table's fly, hover, soar and buzz).
bool beats_wings_in_flight(const Verb& v) { return v.name == "fly" || v.name == "hover" || v.name == "soar" || v.name == "buzz"; }

// A head part off the figure's middle by less than this share of its width shows no facing.
constexpr double kHeadOffCentre = 0.1;

// A person's eye shows a facing only this share of the figure's width off its middle.
constexpr double kPersonEyeOffCentre = 0.15;

// The viewer's side of the figure's middle `x` is on: -1, +1, or 0 on the middle itself.
int side_of(const Rig& rig, double x) {
  const double dx = x - rig.figure.centre().x;
  return dx < 0 ? -1 : dx > 0 ? 1 : 0;
}

template <class Keep>
std::string keep_if(const Rig& rig, const Modifiers& mods, size_t n, Keep&& keep) {
  if ((mods.end == 0 && mods.level == 0) || n == 0) return "";
  std::string said = mods.end > 0 ? "front" : mods.end < 0 ? "rear" : "";
  if (mods.level) said += std::string(said.empty() ? "" : ", ") + (mods.level > 0 ? "upper" : "lower");
  std::string why;
  const int facing = mods.end != 0 ? facing_side(rig, &why) : 0;
  if (mods.end != 0 && facing == 0) return "'" + said + "': the figure's facing is not known; every one of them moves";
  // Along the facing axis: positive ahead of the figure's middle.
  auto picked = [&](Vec2 at) {
    if (mods.end != 0 && side_of(rig, at.x) * facing != mods.end) return false;
    if (mods.level != 0 && (at.y < rig.figure.centre().y ? 1 : -1) != mods.level) return false;
    return true;
  };
  const size_t kept = keep(picked);
  if (kept == 0) return "'" + said + "': none of them there; every one of them moves";
  return "'" + said + "': " + std::to_string(kept) + " of " + std::to_string(n) + (mods.end != 0 ? ", the figure faces " + std::string(facing < 0 ? "left" : "right") + " (" + why + ")" : "");
}

}  // namespace

int facing_side(const Rig& rig, FigureClass figure, std::string* why) {
  if (rig.figure.empty()) return 0;
  // A vehicle's front from its outline (shape_facing.h), else a rider's eye; never its "head"
  // part (the part above its body: a fire engine's ladder, a lorry's trailer, read as the head,
  // turned four of the vehicles probed the wrong way) nor its skeleton (no legs, no head limb).
  if (figure == FigureClass::Wheeled) {
    if (const int side = shape_facing(rig, figure, why); side != 0) return side;
    if (rig.eye_side != 0 && why) *why = "its eye";
    return rig.eye_side;
  }
  // A drawn eye (eye_cue.h): the plainest sign of the head's end. A person's only beyond
  // kPersonEyeOffCentre of the width off the middle: a person drawn from the front with a tool
  // beside them has one dark dot a little off the middle (the cue's bound was that until a long
  // tail put a shark's and a dolphin's eye nearer the middle), and a person must stay unturned.
  const bool eye_off = figure != FigureClass::Biped || std::fabs(rig.eye.x - rig.figure.centre().x) >= kPersonEyeOffCentre * rig.figure.w();
  if (rig.eye_side != 0 && eye_off) {
    if (why) *why = "its eye";
    return rig.eye_side;
  }
  // The rig's head parts, by area.
  double sum = 0, weight = 0;
  for (const RigPart& P : rig.parts)
    if (P.role == Role::Head && !P.box.empty()) {
      const double w = std::max(P.box.area(), 1e-12);
      sum += w * P.box.centre().x;
      weight += w;
    }
  if (weight > 0 && std::fabs(sum / weight - rig.figure.centre().x) >= kHeadOffCentre * rig.figure.w()) {
    if (why) *why = "its head";
    return side_of(rig, sum / weight);
  }
  // An animal's silhouette (body_facing.h): its head held out beyond its feet, slimmer than its
  // rump. Before the skeleton's cues, which read a coin's worth (below).
  if (const int side = body_facing(rig, figure, why); side != 0) return side;
  // The skeleton's head limbs that lead the legs: based beyond every leg's base.
  double lo = 1e300, hi = -1e300;
  int left = 0, right = 0;
  for (const ArmLobe& l : rig.limbs)
    if (l.kind == LobeKind::Leg) {
      lo = std::min(lo, l.pivot.x), hi = std::max(hi, l.pivot.x);
      (side_of(rig, l.pivot.x) < 0 ? left : right) += 1;
    }
  for (const RigPart& P : rig.parts)
    if (P.role == Role::LowerLimb && !P.box.empty()) (side_of(rig, P.box.centre().x) < 0 ? left : right) += 1;
  int ahead = 0;
  for (const ArmLobe& l : rig.limbs)
    if (l.kind == LobeKind::Head && lo <= hi && (l.pivot.x < lo || l.pivot.x > hi)) ahead += side_of(rig, l.tip.x);
  if (ahead != 0) {
    if (why) *why = "its head ahead of the legs";
    return ahead < 0 ? -1 : 1;
  }
  // Legs gather under the front of a body.
  if (left != right && left + right >= 3) {
    if (why) *why = "its legs gather at that end";
    return left > right ? -1 : 1;
  }
  return 0;
}

std::string keep_qualified(const Rig& rig, const Modifiers& mods, std::vector<int>& parts) {
  return keep_if(rig, mods, parts.size(), [&](auto picked) {
    std::vector<int> out;
    for (int p : parts)
      if (picked(rig.parts[p].box.centre())) out.push_back(p);
    if (!out.empty()) parts = out;
    return out.size();
  });
}

std::string keep_qualified(const Rig& rig, const Modifiers& mods, std::vector<ArmLobe>& limbs) {
  return keep_if(rig, mods, limbs.size(), [&](auto picked) {
    std::vector<ArmLobe> out;
    for (const ArmLobe& l : limbs)
      if (picked(l.pivot)) out.push_back(l);
    if (!out.empty()) limbs = out;
    return out.size();
  });
}

std::string arms_left_out(const Verb& v, size_t i, FigureClass figure, FigureClass clause_figure, const Rig& rig) {
  const Action& act = v.actions[i];
  if (act.target != Target::Arms) return "";
  if (i > 0 && v.actions[0].target == Target::Legs && figure != FigureClass::None && figure != FigureClass::Biped)
    return std::string("a ") + figure_class_name(figure) + " has no arms: " + v.name + "'s arm swing left out";
  if (!beats_wings_in_flight(v)) return "";
  if (clause_figure != FigureClass::None && !is_creature(clause_figure))
    return std::string("a flying ") + figure_class_name(clause_figure) + " has no wings to beat: " + v.name + "'s wing beat left out";
  const bool limbs_apart = std::any_of(rig.parts.begin(), rig.parts.end(), [](const RigPart& P) { return P.role == Role::UpperLimb; });
  if (clause_figure == FigureClass::None && !limbs_apart)
    return "a flying figure of no kind the prompt names, with no wings drawn apart: " + v.name + "'s wing beat left out";
  return "";
}

std::string wings_left_out(const Verb& v, const PlannedAction& a) {
  if (!beats_wings_in_flight(v) || a.region != Region::Sides || !a.lobes.empty()) return "";
  return "no wings found to beat: " + v.name + "'s wing beat would bend the body's sides, left out";
}

int lone_or_raised_side(const Rig& rig, int part, Target target, bool one_sided) {
  int sides = 0, raised = 0;  // bits: 1 left, 2 right
  auto count = [&](const ArmLobe& l) {
    const int bit = l.side < 0 ? 1 : l.side > 0 ? 2 : 0;
    sides |= bit;
    if (l.pivot.y - l.tip.y > std::fabs(l.tip.x - l.pivot.x)) raised |= bit;
  };
  if (target == Target::Arms && part >= 0)
    for (const ArmLobe& l : rig.parts[static_cast<size_t>(part)].arm_lobes) count(l);
  for (const ArmLobe& l : rig.limbs)
    if (motion_plan_internal::lobe_serves(l.kind, target)) count(l);
  if (sides == 1 || sides == 2) return sides == 1 ? -1 : 1;
  if (target == Target::Arms && one_sided && (raised == 1 || raised == 2)) return raised == 1 ? -1 : 1;
  return 0;
}

}  // namespace svgm
