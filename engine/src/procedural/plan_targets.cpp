// Which parts a prompt's target means (motion_plan_internal.h's parts_for): the rig's parts of a
// role or named by a word, the limbs too small to move visibly left out, and the parts that
// stand in when the drawing has none of the role.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "procedural/bust_head.h"
#include "procedural/motion_plan_internal.h"

namespace svgm {

namespace motion_plan_internal {

namespace {

bool part_has_word(const RigPart& P, const std::string& noun) {
  for (const auto& w : P.words)
    if (word_matches(noun, w) || word_matches(w, noun)) return true;
  return false;
}

std::vector<int> with_role(const Rig& rig, std::initializer_list<Role> roles) {
  std::vector<int> v;
  for (size_t i = 0; i < rig.parts.size(); ++i)
    if (std::find(roles.begin(), roles.end(), rig.parts[i].role) != roles.end() && static_cast<int>(i) != rig.root)
      v.push_back(static_cast<int>(i));
  return topmost(rig, v);
}

// Whether part p, with what hangs from it, is too small to move visibly when swung: its box's
// diagonal is under kVisibleTravel of the figure's, so even at 60 degrees its end moves less
// than fit_plan's visible floor. A cactus's 2 px spot taken for its arm moved 0.6 % of the
// figure at four times its swing, and the pixel ranker called every candidate 'no motion'.
bool too_small_to_swing(const Rig& rig, int p) {
  const RigBox b = chain_box(rig, p);
  return std::hypot(b.w(), b.h()) < kVisibleTravel * std::hypot(rig.figure.w(), rig.figure.h());
}

}  // namespace

// The parts a target means, with a note when a fallback had to stand in.
std::vector<int> parts_for(const Rig& rig, Target t, const std::string& noun, std::string* note) {
  auto attached = [&] {
    std::vector<int> v;
    for (size_t i = 0; i < rig.parts.size(); ++i)
      if (rig.parts[i].parent == rig.root && rig.parts[i].role != Role::Detail) v.push_back(static_cast<int>(i));
    return v;
  };
  std::vector<int> v;
  switch (t) {
    case Target::Whole: return {};
    case Target::Root: return rig.root >= 0 ? std::vector<int>{rig.root} : std::vector<int>{};
    case Target::Head: v = with_role(rig, {Role::Head}); break;
    case Target::Arms: {
      // Arms come in similar sizes: an upper limb far smaller than the largest (a beak or an
      // ear beside a bird's raised wing) is no arm to swing.
      v = with_role(rig, {Role::UpperLimb});
      double largest = 0;
      for (int p : v) largest = std::max(largest, rig.parts[p].box.area());
      v.erase(std::remove_if(v.begin(), v.end(), [&](int p) { return rig.parts[p].box.area() < kArmMinShare * largest; }), v.end());
      break;
    }
    case Target::Legs:
      v = with_role(rig, {Role::LowerLimb});
      // A creature wider than tall with nothing below (a spider, a crab seen from above): the
      // limbs at its sides are its legs.
      if (v.empty() && rig.figure.w() > rig.figure.h()) v = with_role(rig, {Role::UpperLimb, Role::Tail});
      break;
    case Target::Limbs: v = with_role(rig, {Role::UpperLimb, Role::LowerLimb, Role::Tail}); break;
    case Target::Tail: v = with_role(rig, {Role::Tail}); break;
    case Target::Background: v = with_role(rig, {Role::Background}); return v;
    case Target::Repeated: return {};
    case Target::Wheels: {
      // The large round parts (a bicycle's two wheels), and the round parts concentric with
      // them (a ferris wheel's rim, inner ring and hub turn together); not small round details.
      double widest = 0;
      for (const auto& P : rig.parts)
        if (P.round && P.role != Role::Background) widest = std::max(widest, P.box.w());
      // One ball ("dribbles the ball") is one round thing: the widest (a player's round knee
      // beside it is no ball).
      const bool one = word_matches(noun, "ball") && noun.back() != 's';
      std::vector<int> big;
      for (size_t i = 0; i < rig.parts.size(); ++i)
        if (rig.parts[i].round && rig.parts[i].role != Role::Background && rig.parts[i].box.w() >= (one ? 1.0 : kWheelShare) * widest)
          big.push_back(static_cast<int>(i));
      if (one && big.size() > 1) big.resize(1);
      // A smaller round part standing on the same ground as a large one is a wheel too (a
      // tractor's front wheel, half as wide as its back one, was left still).
      double ground = -1e300;
      for (int b : big) ground = std::max(ground, rig.parts[b].box.y1);
      const size_t n_big = big.size();
      for (size_t i = 0; i < rig.parts.size() && !one; ++i) {
        const RigPart& P = rig.parts[i];
        if (!P.round || P.role == Role::Background || std::find(big.begin(), big.end(), static_cast<int>(i)) != big.end()) continue;
        bool inside = false;  // a hub within a large wheel is its load, not a wheel beside it
        for (size_t k = 0; k < n_big; ++k) {
          const RigBox& bb = rig.parts[big[k]].box;
          const Vec2 c = P.box.centre();
          inside = inside || (c.x >= bb.x0 && c.x <= bb.x1 && c.y >= bb.y0 && c.y <= bb.y1);
        }
        if (!inside && P.box.w() >= kSmallWheelShare * widest && P.box.y1 >= ground - kWheelGround * widest) big.push_back(static_cast<int>(i));
      }
      for (size_t i = 0; i < rig.parts.size(); ++i) {
        const RigPart& P = rig.parts[i];
        bool keep = std::find(big.begin(), big.end(), static_cast<int>(i)) != big.end();
        for (int b : big) {
          const Vec2 d = P.box.centre() - rig.parts[b].box.centre();
          keep = keep || (P.role != Role::Background && P.box.w() < rig.parts[b].box.w() &&
                          std::hypot(d.x, d.y) <= kConcentric * rig.parts[b].box.w() && (P.round || P.box.w() >= kWheelShare * rig.parts[b].box.w()));
        }
        if (keep) v.push_back(static_cast<int>(i));
      }
      v = topmost(rig, v);
      if (v.empty() && note) *note = "no round part for the wheels";
      return v;
    }
    case Target::Named:
      for (size_t i = 0; i < rig.parts.size(); ++i)
        if (part_has_word(rig.parts[i], noun)) v.push_back(static_cast<int>(i));
      return topmost(rig, v);
  }
  // A limb too small to move visibly is a detail, not a limb to swing (nor a stand-in for one).
  if (is_limb_target(t)) v.erase(std::remove_if(v.begin(), v.end(), [&](int p) { return too_small_to_swing(rig, p); }), v.end());
  if (!v.empty() || rig.root < 0) return v;
  // Stand-ins: the parts hanging from the root that are not details, else the highest part
  // other than the root (a head for a nod, a single limb for a wave).
  std::vector<int> any = attached();
  if (is_limb_target(t)) any.erase(std::remove_if(any.begin(), any.end(), [&](int p) { return too_small_to_swing(rig, p); }), any.end());
  if (t == Target::Head || t == Target::Tail || any.empty()) {
    int best = -1;
    for (int i : any.empty() ? std::vector<int>{} : any) {
      const double y = rig.parts[i].box.centre().y;
      // A head stands in only above the root's middle (a snake's coil beside its raised body
      // is no hood: the top of the root bends instead, Builder::add).
      if (t == Target::Head && y >= rig.parts[rig.root].box.centre().y) continue;
      const double far = std::fabs(rig.parts[i].box.centre().x - rig.parts[rig.root].box.centre().x);
      if (best < 0 || (t == Target::Tail ? far > std::fabs(rig.parts[best].box.centre().x - rig.parts[rig.root].box.centre().x)
                                          : y < rig.parts[best].box.centre().y))
        best = i;
    }
    if (best < 0 && t != Target::Head)
      for (size_t i = 0; i < rig.parts.size(); ++i)
        if (static_cast<int>(i) != rig.root && rig.parts[i].role != Role::Background &&
            (best < 0 || rig.parts[i].box.area() > rig.parts[best].box.area()))
          best = static_cast<int>(i);
    if (best >= 0) v = {best};
  } else {
    v = any;
  }
  if (note)
    *note = v.empty() ? std::string("no part for the ") + target_name(t)
                      : std::string("no ") + target_name(t) + " found; " + rig.parts[v[0]].name + (v.size() > 1 ? " and others" : "") + " stand in";
  return v;
}

// A plant bent whole with a bloom on one stem bends at its neck: the head turns there, the stem
// and its leaves hold (bent from the stem's base, a rose's leaf at mid-height swung as far as its
// head). A plant's head is its bloom too: a nod (any turn of the head) on a plant with no head
// part turns the bloom about the top of its stem. As the top region of the figure's box (a
// person's head above the neck), a daisy's bloom, half the plant's height, bent its upper petals
// out of shape while the rest of it held.
LocatedPart plant_bloom(const Rig& rig, Primitive primitive, Target target, FigureClass figure, const std::string& noun) {
  if (figure != FigureClass::Plant) return {};
  std::string no_head;
  const bool bends = primitive == Primitive::Bend && target == Target::Whole;
  const bool nods = primitive == Primitive::Swing && target == Target::Head && (parts_for(rig, Target::Head, noun, &no_head), !no_head.empty());
  return bends || nods ? locate_part(rig, PartShape::Bloom) : LocatedPart{};
}

LocatedPart bloom_or_bust_head(const Rig& rig, Primitive primitive, Target target, FigureClass figure, const std::string& noun) {
  LocatedPart bloom = plant_bloom(rig, primitive, target, figure, noun);
  // Not said of an animal or a plant ("he shakes his head no" read "no" as an object: no person).
  const bool person = figure == FigureClass::Biped || (!is_creature(figure) && figure != FigureClass::Plant);
  return bloom.lobes.empty() && target == Target::Head && person ? bust_head(rig) : bloom;
}

std::string plan_head_turn(const Rig& rig, const LocatedPart& located, const std::string& verb, double size, PlannedAction& a) {
  if (located.lobes.size() != 1 || !located.lobes[0].rigid || located.lobes[0].kind != LobeKind::Head) return "";
  if ((a.head_axis = head_axis_of(verb)) == HeadAxis::Plane) return "";
  a.amp = std::max(a.amp, kHeadTurnDeg * size);
  if (a.head_axis == HeadAxis::Pitch) a.one_sided = 1;  // a nod dips and comes back up
  // Each path's box, from its elements (a.lobe_paths: the head's paths, sorted).
  std::vector<RigBox> boxes(a.lobe_paths.size());
  for (const RigElement& e : rig.elements)
    if (auto it = std::lower_bound(a.lobe_paths.begin(), a.lobe_paths.end(), e.path); it != a.lobe_paths.end() && *it == e.path)
      boxes[static_cast<size_t>(it - a.lobe_paths.begin())].add(e.box);
  RigBox head;
  for (Vec2 q : located.lobes[0].outline) head.add(q);
  a.head_paths = head_paths(head, boxes);
  return a.head_axis == HeadAxis::Pitch ? "; it dips forward (a pitch)" : "; it turns aside (a yaw)";
}

}  // namespace motion_plan_internal

}  // namespace svgm
