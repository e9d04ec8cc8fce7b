// The motion plan (see motion_plan.h): which parts each verb of the prompt moves and how. Its
// frames are drawn by motion_frames.cpp, kept inside the canvas by motion_fit.cpp and written
// to motion.json by motion_report.cpp.
#include "procedural/motion_plan.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>

#include "svgmotion/error.h"
#include "procedural/carried_flight.h"
#include "procedural/clause_target.h"
#include "procedural/front_face.h"
#include "procedural/figure_pieces.h"
#include "procedural/flight_aim.h"
#include "procedural/depth_travel.h"
#include "procedural/leave_way.h"
#include "procedural/invisible_spin.h"
#include "procedural/gait_travel.h"
#include "procedural/limb_qualifiers.h"
#include "procedural/motion_plan_internal.h"
#include "procedural/hang_support.h"
#include "procedural/seat_support.h"
#include "procedural/support_band.h"
#include "procedural/sway_base.h"
#include "procedural/part_locator.h"
#include "procedural/self_movers.h"
#include "procedural/toss_and_stroke.h"
#include "procedural/turn_agreement.h"

namespace svgm {

namespace motion_plan_internal {

// The unit of a primitive's amplitude (motion_verbs.h), as motion.json names it.
const char* unit_of(Primitive p) {
  switch (p) {
    case Primitive::Swing: case Primitive::Rock: case Primitive::Bend: case Primitive::Sway: return "degrees";
    case Primitive::Spin: case Primitive::Turn: case Primitive::Windmill: return "turns";
    case Primitive::Pulse: case Primitive::Stretch: return "fraction of size";
    case Primitive::Fall: return "canvas heights";
    case Primitive::Undulate: return "figure lengths";
    case Primitive::Toss: return "share of the arc";
    case Primitive::Slide: return "figure widths";
    default: return "figure heights";
  }
}

bool whole_only(Primitive p) {
  return p == Primitive::Rock || p == Primitive::Sway || p == Primitive::Hop || p == Primitive::Bob || p == Primitive::Slide ||
         p == Primitive::Squash || p == Primitive::Stretch || p == Primitive::Shake;
}

bool is_limb_target(Target t) { return t == Target::Arms || t == Target::Legs || t == Target::Limbs || t == Target::Tail; }
bool is_part_target(Target t) {
  return t != Target::Named && t != Target::Whole && t != Target::Repeated && t != Target::Background;
}

std::string join(const std::vector<std::string>& v, const char* sep) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : sep) + x;
  return s;
}

// Whether the clause says the figure acts forward ("thrusts his foil forward"; apply_modifier
// keeps the word and sets nothing: which side is forward is the drawing's).
bool says_forward(const Modifiers& m) {
  return std::any_of(m.words.begin(), m.words.end(), [](const std::string& w) { return w == "forward" || w == "forwards" || w == "ahead" || w == "onward" || w == "onwards"; });
}

// The part whose region bends for a limb role that has no part of its own. Arms: the widest
// of the root and the parts hanging from it whose middle is in the figure's upper part (a
// sweater drawn with both sleeves is wider than the trousers that are the largest part); the
// other roles: the root.
int region_host(const Rig& rig, Target t) {
  int best = rig.root;
  if (t != Target::Arms && t != Target::Limbs) return best;
  const RigBox& F = rig.figure;
  for (size_t i = 0; i < rig.parts.size(); ++i) {
    const RigPart& P = rig.parts[i];
    if (P.parent != rig.root || P.role == Role::Background || P.box.empty()) continue;
    if (P.box.centre().y > F.y0 + kArmHostTop * F.h() || P.box.h() < kArmHostMinHeight * F.h()) continue;
    if (P.box.w() > kArmHostWider * rig.parts[best].box.w()) best = static_cast<int>(i);
  }
  return best;
}

// Which side of part `host` its head is on, as the viewer sees it (-1 left, 1 right; 0 when
// no head part shows it or it is over the middle): the middle of the parts whose role is the
// head, by area. A tail bends at the other end: by the seed's coin it was the head of half the
// mermaids that flicked it. Not the silhouette's head limbs: a cat's tail raised in a curl is
// labelled a head there, and its head end bent instead.
int head_side(const Rig& rig, int host) {
  // A drawn eye (eye_cue.h) shows the head's end first: the rig's head parts come from names
  // and groups, which an animal drawn in one piece does not have.
  if (rig.eye_side != 0) return rig.eye_side;
  const RigBox& B = rig.parts[host].box;
  double sum = 0, weight = 0;
  for (size_t i = 0; i < rig.parts.size(); ++i)
    if (rig.parts[i].role == Role::Head && static_cast<int>(i) != host && !rig.parts[i].box.empty()) {
      const double w = std::max(rig.parts[i].box.area(), 1e-12);
      sum += w * rig.parts[i].box.centre().x;
      weight += w;
    }
  if (weight == 0) return 0;
  const double dx = sum / weight - B.centre().x;
  return std::fabs(dx) < kHeadOffCentre * B.w() ? 0 : dx < 0 ? -1 : 1;
}

// The still core of a Sides bend: the arms are what reaches out beyond the body below them.
// When the bending part sits on the root (a shirt with its sleeves above the trousers), the
// root's width; when it is the root (a ghost, a bat), the width of its lowest quarter (the
// hem, the feet). Each side between kCoreMin and kCoreMax of the part's width from its middle.
void side_core(const Rig& rig, PlannedAction& a) {
  const RigPart& P = rig.parts[a.parts[0]];
  const double W = std::max(P.box.w(), 1e-9), cx = P.box.centre().x;
  double x0 = P.base_x0, x1 = P.base_x1;
  if (a.parts[0] != rig.root && rig.root >= 0) {
    x0 = rig.parts[rig.root].box.x0;
    x1 = rig.parts[rig.root].box.x1;
  }
  if (x1 < x0) x0 = x1 = cx;
  a.core_left = std::clamp(cx - x0, kCoreMin * W, kCoreMax * W);
  a.core_right = std::clamp(x1 - cx, kCoreMin * W, kCoreMax * W);
}

// Signs and phases of the parts of one action.
void pair_up(const Rig& rig, PlannedAction& a, Pairing pairing, std::mt19937& rng) {
  const Vec2 rc = rig.root >= 0 ? rig.parts[rig.root].box.centre() : rig.figure.centre();
  std::vector<int> parts = a.parts;
  std::sort(parts.begin(), parts.end(), [&](int x, int y) { return rig.parts[x].box.centre().x < rig.parts[y].box.centre().x; });
  a.parts = parts;
  a.sign.clear();
  a.phase.clear();
  const double first = (rng() & 1) ? 1 : -1;  // which way the first swing goes (mirrored pairs both ways)
  for (size_t i = 0; i < parts.size(); ++i) {
    // Mirror: a part on the viewer's left turns the other way from one on the right, so a pair
    // of wings both rise; a part in the middle turns by the seed's direction.
    const double dx = rig.parts[parts[i]].box.centre().x - rc.x;
    const double mirror = std::fabs(dx) < 1e-9 ? first : (dx < 0 ? 1 : -1);
    if (pairing == Pairing::Alternating) {
      a.sign.push_back(mirror);
      a.phase.push_back(i % 2 ? 0.5 : 0);
    } else if (pairing == Pairing::Same) {
      a.sign.push_back(first);
      a.phase.push_back(0);
    } else {
      a.sign.push_back(mirror);
      a.phase.push_back(0);
    }
  }
}

// A compact figure (an octopus, a frog) does not swim by a wave along its body, which would heave
// its head as much as its arms: its lower limbs paddle, alternating (Builder::add), and the
// swim is then a verb of the limbs (plan_from_prompt).
bool paddles(const Verb& verb, const Rig& rig) {
  const RigBox& F = rig.figure;
  const double aspect = std::max(F.w(), F.h()) / std::max(std::min(F.w(), F.h()), 1e-9);
  return verb.name == "swim" && !verb.actions.empty() && verb.actions[0].primitive == Primitive::Undulate &&
         aspect < kElongated && anchored_side(rig, false) == 0;
}

struct Builder {
  const Rig& rig;
  std::mt19937 rng;
  MotionPlan plan;
  FigureClass figure = FigureClass::None;  // what the prompt says the figure is (its first clause's)
  FlightAim flight;                        // where its launches and landings go (flight_aim.h)

  // Whether the whole figure, spun, turns about its vertical axis: it is not round (a wheel, a
  // clock face, a wheeled figure: those spin in the image's plane, their shape the same at every
  // angle). Anything else spun in the plane stands on its head half the loop and sweeps the
  // circle round its box.
  bool stands() const {
    if (figure == FigureClass::Biped) return true;
    return figure != FigureClass::Wheeled && !(rig.root >= 0 && rig.parts[rig.root].round);
  }

  // What a verb's action becomes on what it is aimed at: limbs beat instead of throbbing and
  // swing instead of spinning, a located part swings on its joint, a figure spun whole turns
  // about its vertical axis. Changes the primitive, its amplitude and target; returns why.
  std::string recast(PlannedAction& a, Target& target, double& amp, bool& rock_on_part, const Action& base,
                     const LocatedPart* located) const {
    std::string beat;
    // Limbs do not throb: a rhythmic verb of size aimed at them ("the dove beats its wings",
    // "her heart beats" is a pulse of the named heart) beats them back and forth. The pulse of a
    // dove's wings had found no wing and throbbed a detail.
    if (a.primitive == Primitive::Pulse && is_limb_target(target)) {
      a.primitive = Primitive::Swing;
      amp = kPartAmplitude[static_cast<size_t>(Primitive::Swing)];
      beat = "limbs beat back and forth: a swing";
    }
    // Nor do they turn full circle: a spin aimed at a head, a tail or a limb ("the owl swivels
    // its head") turns it on its joint and back. Spun round, the owl's head had no part to turn
    // and the plan dropped it for the owl's own flap. Wheels, rotors and named parts still spin.
    if (a.primitive == Primitive::Spin && (is_limb_target(target) || target == Target::Head)) {
      a.primitive = Primitive::Swing;
      amp = kPartAmplitude[static_cast<size_t>(Primitive::Swing)];
      beat = "heads, tails and limbs turn on their joints, not round: a swing";
    }
    // A located part (part_locator.h) turns on its joint, at least by a part's usual angle: a
    // verb of the whole figure aimed at it ("the elephant swings its trunk": a rock of 7 degrees
    // about the figure's base), of size, or of a head's small nods ("spouts" read as eat, 6
    // degrees) would barely move it.
    // Petals that open ("the petals open", "bloom") keep the verb's growth: they spread from the
    // flower's centre (petal_rosette.h); turned on a joint, a flower head only twisted.
    if (located && located->shape == PartShape::Petals && a.primitive == Primitive::Pulse) {
      rock_on_part = false;
      return "petals open: they spread from the flower's centre";
    }
    // A rising plume swells, a rotor spins (self_movers.h); swung, "steam rises" went side to side.
    if (std::string own = own_motion(rig, located, a.primitive, amp); !own.empty()) return rock_on_part = false, own;
    if (located) {
      if (a.primitive != Primitive::Swing || base.primitive != Primitive::Swing) amp = 0;
      a.primitive = Primitive::Swing;
      amp = std::max(amp, kPartAmplitude[static_cast<size_t>(Primitive::Swing)]);
      rock_on_part = false;
    }
    // A figure spun whole ("she pirouettes", "he turns around", "the tornado whirls") turns
    // about its vertical axis unless it is round. Spun in the image's plane, a dancer stood on
    // her head half the loop, left the canvas at any size and every candidate was 'chaotic
    // motion'.
    if (a.primitive == Primitive::Spin && (target == Target::Root || target == Target::Whole) && stands()) {
      a.primitive = Primitive::Turn;
      target = a.target = Target::Whole;
      beat = "a figure that is not round turns about its vertical axis";
    }
    return beat;
  }

  void add(const Verb& verb, const Action& base_in, Target target, const std::vector<int>& named_parts,
           const std::string& target_word, const Modifiers& mods, bool plural, const std::string& words,
           bool primary_retargeted, const std::string& instead = "", const LocatedPart* located = nullptr) {
    Action base = base_in;
    std::string paddle;
    if (base.primitive == Primitive::Toss || base.primitive == Primitive::Windmill)  // toss_and_stroke.h: else an arm swing
      if (auto own = plan_round_motion(rig, verb, base_in, mods, words, rng(), base, target, paddle)) return plan.actions.push_back(std::move(*own));
    if (&base_in == &verb.actions[0] && target == Target::Whole && paddles(verb, rig)) {
      base = {Primitive::Swing, Target::Legs, kPartAmplitude[static_cast<size_t>(Primitive::Swing)], 2 * base.cycles, Pairing::Alternating};
      target = Target::Legs;
      paddle = "a compact figure: its lower limbs paddle";
    }
    PlannedAction a;
    a.verb = verb.name;
    a.words = words;
    a.primitive = base.primitive;
    a.target = target;
    double amp = base.amp;
    bool rock_on_part = false;  // a rock's degrees, about the figure's base, now on a part
    // A plant's bloom on one stem, or a portrait's head, turns for a bend or a head's turn (bloom_or_bust_head).
    LocatedPart bloom;
    if (!located && !(bloom = bloom_or_bust_head(rig, a.primitive, target, figure, target_word)).lobes.empty()) {
      located = &bloom;
      target = a.target = Target::Named;
      // It droops to the side the head leans and back, not up past the stem as well.
      const ArmLobe& l = bloom.lobes[0];
      if (a.primitive == Primitive::Bend) a.one_sided = (l.tip.x >= l.pivot.x ? 1 : -1) * (l.side < 0 ? 1 : -1);
    }
    if (primary_retargeted && whole_only(a.primitive) && target != Target::Whole) {
      // When the verb's amplitude is in another unit than the part's primitive (a squat's
      // figure heights, a swing's degrees), the part's primitive gets its usual size.
      if (unit_of(verb.on_part) != unit_of(a.primitive)) amp = kPartAmplitude[static_cast<size_t>(verb.on_part)];
      else {
        rock_on_part = a.primitive == Primitive::Rock || a.primitive == Primitive::Sway;
        // A sway leans the figure's top about its middle: about the base, the top moves as far
        // at this share of the angle.
        if (a.primitive == Primitive::Sway) amp *= kSwayHinge;
      }
      a.primitive = verb.on_part;
    }
    const std::string beat = recast(a, target, amp, rock_on_part, base, located);
    const bool whole_turns = a.primitive == Primitive::Spin || a.primitive == Primitive::Turn;
    a.amp = amp * mods.size * (whole_turns ? 1 : 0.85 + 0.3 * std::uniform_real_distribution<double>(0, 1)(rng));
    a.cycles = std::max(1, static_cast<int>(std::lround(base.cycles * mods.speed)));
    a.cycles = mods.once > 0 ? 1 : mods.once < 0 ? std::max(2, a.cycles) : a.cycles;  // "once", "again and again"
    if (whole_turns) {
      a.amp = std::max(1.0, std::round((base.primitive == Primitive::Spin ? base.amp : 1) * (mods.speed > 1 ? 2 : 1)));  // whole turns
      a.cycles = 1;
    }
    // A launch climbs (never below where it stood), along its nose (flight_aim.h), and rumbles sideways.
    a.apart = verb.name == "tumble" && target == Target::Whole;
    a.vertical = mods.vertical || verb.name != "takeoff" || a.primitive == Primitive::Slide ? mods.vertical : 1;
    std::string heading;
    if (target == Target::Whole && !flight.aim(rig, figure, a, verb.name, heading)) return;
    if (a.primitive == Primitive::Undulate && target == Target::Whole) a.anchored = anchored_side(rig, true);
    if (a.primitive == Primitive::Bend && target == Target::Whole) a.anchored = bend_anchor(rig, verb.name == "flicker" ? FigureClass::Flame : figure);
    a.direction = mods.side != 0 ? mods.side : ((rng() & 1) ? 1 : -1);
    // Where the prompt sends the figure ("drifts to the right"): a slide of the whole figure
    // goes that way first, in the viewer's frame.
    if (mods.travel != 0 && a.primitive == Primitive::Slide && target == Target::Whole) a.direction = mods.travel;
    a.travel = mods.travel;
    std::string note;
    if (located) {
      // Its lobes turn, on the root's box for the frames (bend_region); only its paths move; a portrait's head nods out of the plane (head_turn.h).
      a.parts = {rig.root};
      a.region = Region::Located;
      a.lobes = located->lobes;
      a.silhouette = true;
      a.lobe_paths = located->paths;
      a.held_paths = located->holds;
      a.sign = {1};
      a.phase = {0};
      note = "the " + (target_word.empty() ? std::string("head") : target_word) + " found as " + part_shape_name(located->shape) + ": " + located->why + plan_head_turn(rig, *located, verb.name, mods.size, a);
    } else if (target == Target::Named) a.parts = named_parts;
    else if (target != Target::Whole && target != Target::Repeated) a.parts = parts_for(rig, target, target_word, &note);
    // "its hind legs": which of them, by where they are on the figure.
    std::string which = is_limb_target(target) && note.empty() ? keep_qualified(rig, mods, a.parts) : "";
    if (rock_on_part && !a.parts.empty()) {
      // The same degrees about a part's pivot move its tips as far as the part is long, not
      // as the figure is tall: a sway of the leaves turns them by as much more as the figure is
      // larger than the largest of them (at most kRockToPartMax times), so they move as far
      // as the whole tree would have.
      double longest = 0;
      for (int p : a.parts) longest = std::max(longest, std::hypot(rig.parts[p].box.w(), rig.parts[p].box.h()));
      const double figure = std::hypot(rig.figure.w(), rig.figure.h());
      a.amp *= std::clamp(figure / std::max(longest, 1e-9), 1.0, kRockToPartMax);
    }
    // Wheels a verb implies (pedalling) but the prompt does not name are never the root: a
    // bicycle drawn as one round-ish part must not spin as a whole. A named wheel may be.
    if (target == Target::Wheels && !primary_retargeted) {
      a.parts.erase(std::remove(a.parts.begin(), a.parts.end(), rig.root), a.parts.end());
      // ... nor up in the figure (a rider's round collar is not a wheel of the bicycle).
      a.parts.erase(std::remove_if(a.parts.begin(), a.parts.end(), [&](int p) { return rig.parts[p].box.centre().y < rig.figure.centre().y; }),
                    a.parts.end());
      if (a.parts.empty() && note.empty()) note = "no round part other than the root for the wheels";
    }
    // No separate part for a limb role: a region of the root bends instead (when it swings).
    const bool limb_role = target == Target::Arms || target == Target::Legs || target == Target::Limbs ||
                           target == Target::Head || target == Target::Tail;
    // A figure held by a pole (a flag) has no limbs: a limb verb ("a waving flag") is the wave
    // from the pole, as a ripple, not a bend of a region (the flag's edge along the pole swung
    // 36 degrees across it and the fit dragged the pole's strokes along), nor a swing of the
    // strokes that a line drawing's rig takes for limbs (a flag's folds swung as arms about
    // their ends).
    if (limb_role && rig.root >= 0 && a.primitive == Primitive::Swing && anchored_side(rig, false) != 0)
      if (const Verb* ripple = find_verb_by_name("ripple")) {
        add(*ripple, ripple->actions[0], Target::Whole, {}, "", mods, plural, words, false,
            verb.name + " has no " + target_name(target) + " on a figure held by a pole: it ripples");
        return;
      }
    if (std::string why; target == Target::Tail && !note.empty() && a.primitive == Primitive::Swing && !(why = tail_not_drawn(rig)).empty())  // front_face.h
      return add(verb, base_in, Target::Whole, {}, "", mods, plural, words, false, why + "; the whole figure " + verb.name + "s");
    if (limb_role && !note.empty() && rig.root >= 0 && a.primitive == Primitive::Swing)
      bend_region(a, target, base, mods, plural, note, which);
    if (std::string why = wings_left_out(verb, a); !why.empty()) return plan.notes.push_back(why);
    // A fall with nothing drawn apart to fall (no drops; "the maple leaf tumbles") is the figure's own (self_movers.h).
    // So does a figure in pieces the prompt names ("the leaves tumble": a fall moved no limb), or one with only a stand-in
    // for the part named (a fall moves no part: "leaves tumbling in the wind" on one leaf moved nothing, every candidate flagged).
    if (const Verb* tumble = find_verb_by_name("tumble");
        a.primitive == Primitive::Fall && (target == Target::Repeated ? rig.repeated.empty() || repeated_are_the_figure(rig)
                                           : target != Target::Whole && (a.parts.empty() || (!located && !note.empty()) || piece_count(figure_pieces(rig)) >= 2))) {
      Modifiers down = mods;
      down.vertical = -1;  // down and back
      for (const Action& t : tumble->actions) add(*tumble, t, Target::Whole, {}, "", down, false, words, false, "nothing drawn apart to fall: the figure falls itself");
      return;
    }
    if (target == Target::Repeated && rig.repeated.empty()) {
      plan.warnings.push_back("'" + words + "': no repeated elements (drops, stars) found; " + verb.name + " is left out");
      return;
    }
    if (target != Target::Whole && target != Target::Repeated && a.parts.empty()) {
      plan.warnings.push_back("'" + words + "': " + (note.empty() ? std::string("no part for it") : note) + "; " + verb.name + " is left out");
      return;
    }
    // A wheel with riders evenly spaced round it (a ferris wheel's cabins) looks the same after
    // one spacing of a turn: it turns by that much a loop, so the loop goes on where it began.
    // A whole turn went 24 degrees a keyframe, past half the spacing of eight spokes, and the
    // fitter followed each spoke back to its neighbour's place.
    std::string spacing;
    if (a.primitive == Primitive::Spin)
      if (const int n = spin_symmetry(rig, a.parts); n > 0) {
        a.amp = (mods.speed > 1 ? 2.0 : 1.0) / n;
        spacing = std::to_string(n) + " riders evenly round it: " + (mods.speed > 1 ? "two spacings" : "one spacing") + " of a turn a loop";
      }
    pick_sides(a, base, mods, plural, note);
    // One-sided whole-figure motions (lean, bow) go one way and back.
    if (a.primitive == Primitive::Rock && base.pairing == Pairing::OneSide) a.vertical = 2;
    explain(a, verb, target, words, mods, {note, which, paddle, beat, instead, spacing, heading, root_plant(a, rig, figure)});  // roots a plant: sway_base.h
    if (!repeats(agreed(a, mods))) plan.actions.push_back(std::move(a));
  }

  // `a`, a turn of the whole figure, going the way an earlier one goes, unless the prompt said
  // which way: the two must not cancel (turn_agreement.h).
  PlannedAction& agreed(PlannedAction& a, const Modifiers& mods) const {
    if (agree_with_earlier_turns(plan.actions, a, mods.side != 0)) a.why += "; the same way first as the figure's earlier turn (they would cancel)";
    return a;
  }

  // Whether `a` repeats an action (the same primitive on the same parts: skipped); a larger one
  // of another verb takes its place ("the flying saucer blasts off" kept the flight's bob of 5 %,
  // not the climb of 25 %).
  bool repeats(PlannedAction& a) {
    for (auto& b : plan.actions)
      if (b.primitive == a.primitive && b.target == a.target && b.parts == a.parts && b.region == a.region) {
        if (std::fabs(a.amp) > std::fabs(b.amp) && a.target == Target::Whole && b.verb != a.verb) b = std::move(a);
        return true;
      }
    return false;
  }

  // No separate part for a limb role: a region of a part bends instead (the outline's arms, the
  // silhouette's limbs, or the region of the part that stands in for them), and `note` says so.
  void bend_region(PlannedAction& a, Target target, const Action& base, const Modifiers& mods, bool plural, std::string& note,
                   std::string& which) {
    a.parts = {region_host(rig, target)};
    a.region = target == Target::Arms || target == Target::Limbs ? Region::Sides
               : target == Target::Legs ? Region::Lower : target == Target::Head ? Region::Top : Region::End;
    a.alternating = !mods.together && (base.pairing == Pairing::Alternating || (base.pairing == Pairing::OneAtATime && (mods.both || plural)));
    if (a.region == Region::Sides) side_core(rig, a);
    // (A head or a tail is one: no side to pick.)
    if ((base.pairing == Pairing::OneSide || base.pairing == Pairing::OneAtATime) && !mods.both && !plural &&
        target != Target::Head && target != Target::Tail) {
      // The figure's own side is drawn on the viewer's other side.
      a.region_side = mods.side != 0 ? -mods.side : ((rng() & 1) ? 1 : -1);
      // "thrusts his foil forward": forward is the way the figure faces, the side to which a limb
      // of this kind reaches out farthest across (the fencer's sword arm, not the hand he holds
      // up behind him); the seed's coin stays drawn so the other draws do not change.
      if (mods.side == 0 && says_forward(mods)) {
        const ArmLobe* far = nullptr;
        double best = 0;
        auto consider = [&](const ArmLobe& l) {
          if (const double across = std::fabs(l.tip.x - l.pivot.x); across > best) best = across, far = &l;
        };
        if (target == Target::Arms)
          for (const ArmLobe& l : rig.parts[a.parts[0]].arm_lobes) consider(l);
        for (const ArmLobe& l : rig.limbs)
          if (lobe_serves(l.kind, target)) consider(l);
        if (far) a.region_side = far->side;
      }
      // No side asked: the side its limbs are on, or its raised arm (limb_qualifiers.h).
      if (mods.side == 0)
        if (const int side = lone_or_raised_side(rig, a.parts[0], target, base.pairing == Pairing::OneSide && !says_forward(mods)); side != 0)
          a.region_side = side;
    }
    // Arms drawn in the outline (part_rig.h) bend instead of the sides, when there is one on
    // every side that moves: a girl waving both arms has one lobe, her raised sleeve, and the
    // sides' bend also swings the arm hanging along her body. Only for arms: a flower's petals
    // and an octopus's tentacles (limbs) reach out all round, and one lobe of them is no pair.
    if (a.region == Region::Sides && target == Target::Arms) {
      const auto& lobes = rig.parts[a.parts[0]].arm_lobes;
      auto on = [&](int side) { return std::any_of(lobes.begin(), lobes.end(), [&](const ArmLobe& l) { return l.side == side; }); };
      if (a.region_side != 0 ? on(a.region_side) : on(-1) && on(1)) a.lobes = lobes;
    }
    // Otherwise the limbs of the part's silhouette (skeleton_lobes.h) of the role's kind: a
    // cat's tail, not whichever end of its body the seed picked.
    bool skeletal = false;
    if (a.lobes.empty()) {
      std::vector<ArmLobe> picked;
      for (const ArmLobe& l : rig.limbs)
        if (lobe_serves(l.kind, target)) picked.push_back(l);
      // No limb labelled a tail: the limbs opposite the head (part_locator.h), not the far end
      // of the box, which reached a mermaid's raised hand.
      if (picked.empty() && target == Target::Tail) picked = tail_limbs(rig);
      which = keep_qualified(rig, mods, picked);
      // A winged figure seen from the side (the prompt's bird or insect) shows its far wing
      // rising behind the near one, where the skeleton's labels see an upright body's head:
      // with one arm found, the limbs pointing up are its wings, and they beat together. A
      // dove's near wing bent alone had been no pair, and its whole body's sides swung.
      const bool winged = target == Target::Arms && (figure == FigureClass::Bird || figure == FigureClass::Insect);
      if (winged && picked.size() == 1)
        for (const ArmLobe& l : rig.limbs)
          if (l.kind == LobeKind::Head && l.pivot.y - l.tip.y > std::fabs(l.tip.x - l.pivot.x)) picked.push_back(l);
      // As for the outline's arms: one on the side that moves, or a pair when both do.
      auto on = [&](int side) { return std::any_of(picked.begin(), picked.end(), [&](const ArmLobe& l) { return l.side == side; }); };
      const bool sided = a.region_side != 0 ? on(a.region_side)
                                            : target != Target::Arms || (on(-1) && on(1)) || (winged && picked.size() >= 2);
      if (!picked.empty() && sided) {
        a.lobes = std::move(picked);
        a.silhouette = skeletal = true;
      }
    }
    // A tail leaves the end away from the head; the seed's coin only when no head shows which.
    // (The coin is drawn for a far end only, as before: the other bends' draws stay the seed's.)
    if (a.region == Region::End) {
      const int coin = (rng() & 1) ? 1 : -1;
      const int head = head_side(rig, a.parts[0]);
      a.direction = head != 0 ? -head : coin;
    }
    note = std::string("no separate ") + target_name(target) + ": the " +
           (a.region == Region::Sides ? "sides" : a.region == Region::Lower ? "lower part" : a.region == Region::Top ? "top" : "far end") +
           " of " + rig.parts[a.parts[0]].name + " bend";
    if (skeletal)
      note = std::string("no separate ") + target_name(target) + ": " + std::to_string(a.lobes.size()) + " " +
             (a.lobes.size() > 1 ? "limbs" : "limb") + " of the figure's silhouette skeleton (at " + fmt_lobes(rig, a.lobes) + ") bend" + (a.lobes.size() > 1 ? "" : "s") + " about " + (a.lobes.size() > 1 ? "their bases" : "its base");
    else if (!a.lobes.empty())
      note = std::string("no separate ") + target_name(target) + ": the " + std::to_string(a.lobes.size()) +
             " arm" + (a.lobes.size() > 1 ? "s" : "") + " drawn in the outline of " + rig.parts[a.parts[0]].name + " bend";
    a.sign = {1};
    a.phase = {0};
  }

  // Which of the action's parts move, and how the pair of them moves (`note` says why a side).
  void pick_sides(PlannedAction& a, const Action& base, const Modifiers& mods, bool plural, std::string& note) {
    Pairing pairing = mods.together ? Pairing::Mirrored : base.pairing;
    if (pairing == Pairing::OneSide && (mods.both || plural)) pairing = Pairing::Mirrored;
    if (pairing == Pairing::OneAtATime) pairing = mods.both || plural ? Pairing::Alternating : Pairing::OneSide;
    if (pairing == Pairing::OneSide && a.parts.size() > 1 && a.region == Region::None) {
      int want = mods.side;
      std::vector<int> sided;
      for (int p : a.parts)
        if (want != 0 && rig.parts[p].side == want) sided.push_back(p);
      if (sided.empty()) {
        // No side asked (or none there): the limb the drawing shows reaching out (a boxer's
        // extended fist, not the one folded in guard), else the seed's pick.
        const int out = reaching_out(rig, a.parts);
        sided = {out >= 0 ? out : a.parts[rng() % a.parts.size()]};
        if (want != 0) note = std::string("no part on the figure's ") + (want > 0 ? "right" : "left") + "; " + rig.parts[sided[0]].name + " instead";
        else if (out >= 0) note = rig.parts[out].name + " reaches out farthest";
      }
      a.parts = {sided[0]};
    }
    // One limb of a one-at-a-time verb turns as it would in the pair (mirrored about the body:
    // a fist swings the same way on either side); a one-sided verb's by the seed.
    if (a.region == Region::None)
      pair_up(rig, a, pairing != Pairing::OneSide ? pairing : base.pairing == Pairing::OneAtATime ? Pairing::Mirrored : Pairing::Same, rng);
  }

  // The action's one line for the report: what moves and why, then each non-empty note in order.
  void explain(PlannedAction& a, const Verb& verb, Target target, const std::string& words, const Modifiers& mods,
               const std::vector<std::string>& notes) {
    std::vector<std::string> names;
    for (int p : a.parts) names.push_back(rig.parts[p].name);
    a.why = "'" + words + "': " + verb.name + " moves the " +
            (target == Target::Whole ? std::string("whole figure")
             : target == Target::Repeated ? rig.repeated_why
             : a.region == Region::Located ? std::string("part the prompt names")
             : std::string(target_name(target)) + " (" + join(names, ", ") + ")");
    for (const std::string& n : notes)
      if (!n.empty()) a.why += "; " + n;
    if (a.anchored != 0 && !a.rooted) {  // (a rooted plant's note says where it is held)
      static const char* sides[] = {"", "left", "right", "top", "bottom"};
      if (a.primitive == Primitive::Bend)
        a.why += std::string("; held at its ") + sides[a.anchored] + (pole_parts(rig, a.anchored, true).empty() ? "" : " by a pole") +
                 ": it bends from there";
      else
        a.why += std::string("; held by a pole at its ") + sides[a.anchored] + ": the wave runs from there";
    }
    if (!mods.words.empty()) a.why += "; " + join(mods.words, ", ");
  }
};

}  // namespace motion_plan_internal

using namespace motion_plan_internal;

std::string MotionPlan::summary() const {
  std::string s;
  for (const auto& a : actions) {
    char amp[64];
    const char* unit = a.primitive == Primitive::Swing || a.primitive == Primitive::Rock || a.primitive == Primitive::Bend || a.primitive == Primitive::Sway ? " deg"
                       : a.primitive == Primitive::Spin || a.primitive == Primitive::Turn ? " turn" : "";
    std::snprintf(amp, sizeof amp, " %.3g%s x%d", amplitude(a), unit, a.cycles);
    std::string who = a.target == Target::Whole ? "whole" : a.target == Target::Repeated ? "repeated" : "";
    if (who.empty()) {
      for (int p : a.parts) who += (who.empty() ? "" : "+") + std::to_string(p);
    }
    s += (s.empty() ? "" : "; ") + a.verb + " (" + primitive_name(a.primitive) + ") " + who + amp;
  }
  return s;
}


// Where the prompt sends a figure that gets somewhere by itself ("the dog runs to the right", "the
// bird flies left"), or a gait's way when it says none (gait_travel.h), and its verb has no travel
// of its own: the whole figure slides that way and back, as a vehicle drives (kTravelSlide), the
// gait going on as it goes. Without it the dog ran on the spot. `from`: the clause's first action.
void travel_where_told(Builder& b, const Clause& c, size_t from, const ParsedPrompt& prompt) {
  const Verb* mover = nullptr;
  for (const Verb* v : c.verbs)
    if (!mover && (locomotes(*v) || v->name == "move")) mover = legged_crawl(v, c, b.rig);  // a crawl on legs walks
  if (!mover) return;
  // A gait with no direction said goes the way the figure faces (gait_travel.h).
  Modifiers mods = c.mods;
  std::string why = "told where it goes: the figure goes there steadily and glides back";
  // A swimmer's strokes (toss_and_stroke.h) loop in place: gliding back, a crawl swam backwards.
  // A figure told it leaves ("sails away", "flies off") goes the way it faces (leave_way.h).
  // A thing seen head-on going away, or anything coming nearer, goes in depth (depth_travel.h).
  if (std::string deep; mods.travel == 0 && !stroke_reading(c))
    if (const int way = depth_way(prompt, c, b.rig, &deep)) return travel_in_depth(b.plan, from, way, b.rig, mover->name, c.text, deep);
  if (mods.travel == 0 && !stroke_reading(c)) mods.travel = leaving_side(prompt, c, b.rig, &why);
  if (mods.travel == 0 && (!is_gait(*mover, c.figure) || stroke_reading(c) || (mods.travel = untold_travel(prompt, c, b.rig, &why)) == 0)) return;
  static const Action kTravelSlide{Primitive::Slide, Target::Whole, kTravelReach, 1};
  for (size_t i = from; i < b.plan.actions.size(); ++i)
    if (PlannedAction& a = b.plan.actions[i]; a.primitive == Primitive::Slide && a.parts.empty()) {
      // Its own slide (a crawl's creep, a swim's glide) goes that way, as far as a travel goes
      // (told or not: "crawls slowly to the left" crept 4 % of the snail's width).
      a.amp = std::max(a.amp, kTravelSlide.amp), a.direction = a.travel = mods.travel, a.goes = true, a.why += c.mods.travel ? "" : "; " + why;
      crawl_in_steps(b.plan, from, i, c.figure);
      return turn_round_to_go(b.rig, c.figure, a);  // a crawl's steps do not turn round (gait_travel.h)
    }
  const size_t had = b.plan.actions.size();
  if (mover->name != "move") b.add(*mover, kTravelSlide, Target::Whole, {}, "", mods, false, c.text, false, why);
  // Its reach is the travel's (at the words' size), not under it: add's jitter of 0.85 to 1.15
  // left a walk's and a trot's at 13.4 % of the width where a crawl's own slide had 15 %.
  if (b.plan.actions.size() > had)
    b.plan.actions.back().goes = true, b.plan.actions.back().amp = std::max(b.plan.actions.back().amp, kTravelReach * mods.size),
    turn_round_to_go(b.rig, c.figure, b.plan.actions.back());
}


namespace {

// The end of plan_from_prompt: with no action, the fallback sway and a warning naming the words
// not understood; else a warning naming the verbs the lexicon could not place.
void sway_or_name_missed(Builder& b, const ParsedPrompt& prompt, const std::vector<std::string>& unknown) {
  if (b.plan.actions.empty()) {
    const std::string words = unknown.empty() ? "no words" : join(unknown, ", ");
    b.plan.warnings.push_back("no motion understood in the prompt (not understood: " + words + "); the figure sways gently");
    const Verb* sway = find_verb_by_name("sway");
    Action gentle = sway->actions[0];
    gentle.amp = kFallbackSwayDeg;
    b.add(*sway, gentle, Target::Whole, {}, "", Modifiers{}, false, "(fallback)", false);
  } else {
    // Verbs the lexicon could not place, and words in -ing (a participle no table knows).
    std::vector<std::string> verbs_missed = prompt.unplaced;
    for (const auto& w : unknown)
      if (w.size() > 4 && w.compare(w.size() - 3, 3, "ing") == 0 && std::find(verbs_missed.begin(), verbs_missed.end(), w) == verbs_missed.end())
        verbs_missed.push_back(w);
    if (!verbs_missed.empty()) b.plan.warnings.push_back("words not understood: " + join(verbs_missed, ", "));
  }
}

}  // namespace

MotionPlan plan_from_prompt(const ParsedPrompt& said, const Rig& rig, uint32_t seed) {
  const ParsedPrompt prompt = travel_across(said, rig);
  Builder b{rig, std::mt19937(seed), {}, FigureClass::None, {}};
  for (const Clause& c : prompt.clauses)
    if (b.figure == FigureClass::None) b.figure = c.figure;
  b.plan.source = "prompt";
  std::vector<std::string> unknown;
  b.plan.ground = ground_words(prompt, rig);
  b.plan.hang = hang_words(prompt, rig);
  b.plan.seat = seat_words(prompt, rig);
  auto locatable = [&](const PromptNoun& n) { return locatable_noun(n, rig, b.figure); };
  // Does the prompt say which limbs move ("waving its arms", "sways its tentacles")? Then the
  // whole-figure accents of its limb verbs (cheering's hop, flapping's bob, dancing's rock) are
  // left out: they move every part, the ones the prompt keeps still too, and outweigh the
  // limbs it names.
  bool names_limbs = false;
  for (const Clause& c : prompt.clauses)
    for (const auto& n : c.nouns)
      names_limbs = names_limbs || (!n.object_of_preposition && !n.own_predicate && (is_limb_target(n.target) || locatable(n)));
  std::vector<std::string> accents_left_out;
  auto target_of = [&](const Clause& c, std::vector<std::string>* unknown_words) {
    return clause_target(c, prompt, rig, b.figure, b.plan.ground, unknown_words);
  };
  // Verbs the prompt aims at a part in some clause ("his upper body sways"): the same verb with
  // no part elsewhere ("performs with a rhythmic sway") says that motion again, and on the whole
  // figure it would move the parts the aimed clause keeps still (the legs under the body).
  std::set<std::string> aimed;
  for (const Clause& c : prompt.clauses)
    if (const ClauseTarget ct = target_of(c, nullptr); ct.have && ct.target != Target::Whole && ct.target != Target::Repeated)
      for (const Verb* v : c.verbs) aimed.insert(v->name);
  std::vector<std::string> restated;
  for (const Clause& c : prompt.clauses) {
    const size_t first_action = b.plan.actions.size();
    ClauseTarget ct = target_of(c, &unknown);  // then a fire's or a light's flames when no part is named (self_movers.h)
    if (LocatedPart lit; !ct.have && !(lit = flames_of_light(c, rig)).lobes.empty()) ct = {Target::Named, {}, "flames", lit.lobes.size() > 1, true, lit};
    const Target target = ct.target;
    const std::vector<int>& named = ct.named;
    const std::string& target_word = ct.word;
    const bool plural = ct.plural, have = ct.have;
    const LocatedPart* located = ct.located.lobes.empty() ? nullptr : &ct.located;
    // A located part with no motion word for it ("the rabbit twitches its ears", "the whale
    // spouts a jet"): it swings as a tail wags, the clause's words say how no better.
    if (located && c.verbs.empty())
      if (const Verb* wag = find_verb_by_name("wag"))
        b.add(*wag, wag->actions[0], Target::Named, {}, target_word, c.mods, plural, c.text, true,
              "no motion word for the " + target_word + ": it swings", located);
    for (const Verb* v : clause_verbs(c, rig, located))
      for (size_t i = 0; i < v->actions.size(); ++i) {
        const Action& act = v->actions[i];
        // A ball a limb's verb acts on ("throws the ball", "kicks the ball") goes with the limb:
        // the arm or the leg moves, not the ball in its place. A whole-figure verb's ball is what
        // moves ("bounces the ball").
        const bool handled = target == Target::Wheels && word_matches(target_word, "ball") && is_limb_target(act.target);
        const bool retarget = i == 0 && have && !handled;
        if (i == 0 && !have && act.target == Target::Whole && aimed.count(v->name)) {
          restated.push_back("'" + c.text + "'");
          break;
        }
        if (std::string why = retarget ? "" : arms_left_out(*v, i, b.figure, c.figure, rig); !why.empty()) {  // a named part moves
          b.plan.notes.push_back(why);
          continue;
        }
        if (i > 0 && act.target == Target::Whole && (carries_figure(*v) ? !keeps_whole(*v, c, target_word) : (names_limbs || located) && (is_limb_target(v->actions[0].target) || paddles(*v, rig) || located))) {
          accents_left_out.push_back(v->name + "'s " + primitive_name(act.primitive));
          continue;
        }
        // Repeated elements named as what moves ("snowflakes drift") take all of a whole-figure
        // verb's motion: the float's rock is theirs too (it rocked the cloud they fall from).
        const bool elements_too = i > 0 && have && target == Target::Repeated && act.target == Target::Whole &&
                                  v->actions[0].target == Target::Whole;
        b.add(*v, act, retarget || elements_too ? target : act.target, retarget ? named : std::vector<int>{}, target_word, c.mods,
              retarget && plural, c.text, retarget, "", retarget ? located : nullptr);
      }
    travel_where_told(b, c, first_action, prompt);
  }
  if (!accents_left_out.empty())
    b.plan.notes.push_back("the prompt names the limbs that move: the whole-figure " + join(accents_left_out, ", ") + " left out");
  if (!restated.empty())
    b.plan.notes.push_back(join(restated, ", ") + ": the prompt aims the same motion at a part elsewhere; the whole figure's left out");
  // Nouns that move by themselves when no verb says how (the lexicon: "the candle's flame" flickers,
  // "rain" falls, "the sea's waves" roll), else the motion of the figure's class.
  if (b.plan.actions.empty())
    for (const Clause& c : prompt.clauses) {
      const Verb* v = nullptr;
      std::string what;
      for (const auto& n : c.nouns)
        if (n.motion && !n.object_of_preposition) {
          v = flame_verb(n.motion, c, rig, nullptr);
          what = "'" + n.word + "'";
          break;
        }
      if (!v && c.figure != FigureClass::None && (v = default_verb(c.figure))) what = std::string("a ") + figure_class_name(c.figure);
      if (!v) continue;
      for (const Action& act : v->actions) b.add(*v, act, act.target, {}, "", c.mods, false, c.text, false);
      b.plan.notes.push_back(what + " moves by itself: " + v->name + " (no verb in '" + c.text + "')");
      break;
    }
  roll_wheels_with_slides(b.plan);
  b.plan.readings = prompt.readings;
  b.plan.not_understood = unknown;
  for (const auto& w : prompt.unplaced)
    if (std::find(unknown.begin(), unknown.end(), w) == unknown.end()) b.plan.not_understood.push_back(w);
  sway_or_name_missed(b, prompt, unknown);
  return b.plan;
}

MotionPlan plan_from_steps(const std::vector<ExplicitStep>& steps, const Rig& rig, uint32_t seed) {
  Builder b{rig, std::mt19937(seed), {}, FigureClass::None, {}};
  b.plan.source = "stages.video.options.motion";
  for (const auto& s : steps) {
    const Verb* v = find_verb_by_name(s.verb);
    std::vector<int> parts;
    for (const auto& pat : s.patterns) {
      const size_t before = parts.size();
      for (size_t i = 0; i < rig.parts.size(); ++i) {
        const RigPart& P = rig.parts[i];
        // A pattern matches a part's name, or its role in the figure's words: "wing*" and
        // "arm*" find upper limbs, "leg*" lower limbs, "body" the root.
        std::vector<std::string> aliases = {P.name, role_name(P.role)};
        if (P.role == Role::UpperLimb) aliases.insert(aliases.end(), {"arm", "wing", "fin", "limb"});
        if (P.role == Role::LowerLimb) aliases.insert(aliases.end(), {"leg", "foot", "limb"});
        if (P.role == Role::Root) aliases.insert(aliases.end(), {"body", "root"});
        if (P.role == Role::Tail) aliases.push_back("limb");
        if (P.round) aliases.push_back("wheel");
        bool hit = false;
        for (const auto& al : aliases) hit = hit || glob_match(pat, al);
        if (hit && std::find(parts.begin(), parts.end(), static_cast<int>(i)) == parts.end()) parts.push_back(static_cast<int>(i));
      }
      if (parts.size() == before && pat != "whole" && pat != "repeated") {
        std::vector<std::string> names;
        for (const auto& P : rig.parts) names.push_back(P.name);
        throw Error("stages.video.options.motion: '" + pat + "' matches no part (parts: " + join(names, ", ") + ")");
      }
    }
    const bool whole = std::find(s.patterns.begin(), s.patterns.end(), "whole") != s.patterns.end();
    const bool repeated = std::find(s.patterns.begin(), s.patterns.end(), "repeated") != s.patterns.end();
    const std::string words = s.verb + (s.patterns.empty() ? "" : ":" + join(s.patterns, "+"));
    if (s.patterns.empty() || whole || repeated) {
      for (size_t i = 0; i < v->actions.size(); ++i) {
        const Target t = i == 0 && whole ? Target::Whole : i == 0 && repeated ? Target::Repeated : v->actions[i].target;
        b.add(*v, v->actions[i], t, {}, "", s.mods, false, words, false);
      }
    } else {
      // Only the primary action, on exactly the parts named.
      b.add(*v, v->actions[0], Target::Named, topmost(rig, parts), "", s.mods, true, words, true);
    }
  }
  return b.plan;
}

}  // namespace svgm
