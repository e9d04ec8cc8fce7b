// The motion plan and its frames (see motion_plan.h).
#include "video/motion_plan.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>

#include "svgmotion/error.h"
#include "geometry/rigid_bodies.h"
#include "video/wheel_riders.h"

namespace svgm {

// The riders evenly spaced round the spinning `parts` (defined with animate_plan's wheel loads).
int spin_symmetry(const Rig& rig, const std::vector<int>& parts);

namespace {

constexpr double kTau = 2 * M_PI;
// Golden-ratio spacing of the phases of repeated elements: no two drops fall in step.
constexpr double kPhaseSpacing = 0.6180339887498949;
// A prompt with no motion word: the figure's top leans this many degrees (a Sway), once.
constexpr double kFallbackSwayDeg = 6;
// fit_plan: a point in the canvas margin at rest may come this close to the edge (share of the
// margin); and it gives up after this many steps of 0.8 (7 % of the size).
constexpr double kMarginUse = 0.9;
constexpr int kScaleAttempts = 12;
// fit_plan: a clause whose largest motion is under this share of the figure's diagonal is
// raised to it (a viewer must see the motion the prompt asked for; the pixel ranker calls a video
// where under 0.5 % of the foreground changes 'no motion'), by at most this factor.
constexpr double kVisibleTravel = 0.08;  // of the figure's diagonal (the floor)
constexpr double kMaxBoost = 4;
// region_host: a part carries the arms when its middle is above this share of the figure's
// height, it is at least this share of the figure tall, and this much wider than the root.
constexpr double kArmHostTop = 0.6;
constexpr double kArmHostMinHeight = 0.2;
constexpr double kArmHostWider = 1.15;
// Wheels: round parts at least this share of the widest one's width; and parts whose centre is
// within this share of a wheel's width from its centre turn with it.
constexpr double kWheelShare = 0.5;
constexpr double kConcentric = 0.1;
// A part hanging from a spinning part turns with it when this share of its box is inside (a
// stand reaching into the wheel's box is not carried).
constexpr double kSpinInsideShare = 0.9;
// A Sides bend's still core, each side, in shares of the bending part's width (side_core): at
// least the middle quarter of it (kCore below), at most 70 % of it (the outer 15 % each side
// still bends: a ghost's stubby arms).
constexpr double kCoreMin = 0.12, kCoreMax = 0.35;

// The usual amplitude of each primitive on one part, in its unit (motion_verbs.h), in the order
// of Primitive: for a whole-figure verb a prompt aims at a part ("his legs squatting").
constexpr double kPartAmplitude[] = {20, 1, 0.07, 0.04, 0.04, 6, 0.05, 15, 0.01, 0.08, 0.08, 0.08, 0.12, 6};
static_assert(sizeof kPartAmplitude / sizeof kPartAmplitude[0] == static_cast<size_t>(Primitive::Sway) + 1);
// A Sway's hinge, in shares of the figure's height from its top: the lower 45 % stays planted
// (a wine glass's stem and foot, a saxophonist's legs); above it the lean grows over kRamp of
// the height (bend_region's ramp) to the full angle.
constexpr double kSwayHinge = 0.55;
// A whole-figure wave is anchored at a side of the figure where thin parts (at most kPoleWidth
// of the figure's extent across that side) lying within kPoleEnd of it together span kPoleSpan
// of the figure along it: a flag's pole. The wave then runs away from that side.
constexpr double kPoleWidth = 0.05, kPoleEnd = 0.1, kPoleSpan = 0.7;
// A figure whose longer side is less than this many times its shorter one is compact: it swims
// with its lower limbs, not by a wave along its body (Builder::add).
constexpr double kElongated = 1.6;
// A chain hanging from the root that reaches the lowest this share of the figure stands on the
// ground (animate_plan): a saxophonist's legs stay while his upper body sways about the hips.
constexpr double kPlanted = 0.15;

// The unit of a primitive's amplitude (motion_verbs.h), as motion.json names it.
const char* unit_of(Primitive p) {
  switch (p) {
    case Primitive::Swing: case Primitive::Rock: case Primitive::Bend: case Primitive::Sway: return "degrees";
    case Primitive::Spin: return "turns";
    case Primitive::Pulse: case Primitive::Stretch: return "fraction of size";
    case Primitive::Fall: return "canvas heights";
    case Primitive::Undulate: return "figure lengths";
    case Primitive::Slide: return "figure widths";
    default: return "figure heights";
  }
}

// Arms: an upper limb whose box is less than this share of the largest one's is left out.
constexpr double kArmMinShare = 0.2;

// A one-sided verb with no side named moves the limb reaching this many times farther from the
// body than the others (reaching_out): a boxer's extended arm reaches 1.4 times as far as the
// arm he keeps in guard.
constexpr double kReachLead = 1.2;

// fit_plan: a part at the canvas's edge holds still when the whole figure cannot move otherwise,
// if it and what hangs from it cover at most this share of the figure's box (a splash, not the
// body).
constexpr double kHeldMaxShare = 0.1;

// A rock aimed at a part turns it by at most this many times the rock's angle (Builder::add).
constexpr double kRockToPartMax = 4;

bool whole_only(Primitive p) {
  return p == Primitive::Rock || p == Primitive::Sway || p == Primitive::Hop || p == Primitive::Bob || p == Primitive::Slide ||
         p == Primitive::Squash || p == Primitive::Stretch || p == Primitive::Shake;
}

bool is_limb_target(Target t) {
  return t == Target::Arms || t == Target::Legs || t == Target::Limbs || t == Target::Tail;
}

std::string join(const std::vector<std::string>& v, const char* sep) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : sep) + x;
  return s;
}

bool part_has_word(const RigPart& P, const std::string& noun) {
  for (const auto& w : P.words)
    if (word_matches(noun, w) || word_matches(w, noun)) return true;
  return false;
}

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

std::vector<int> with_role(const Rig& rig, std::initializer_list<Role> roles) {
  std::vector<int> v;
  for (size_t i = 0; i < rig.parts.size(); ++i)
    if (std::find(roles.begin(), roles.end(), rig.parts[i].role) != roles.end() && static_cast<int>(i) != rig.root)
      v.push_back(static_cast<int>(i));
  return topmost(rig, v);
}

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
      std::vector<int> big;
      for (size_t i = 0; i < rig.parts.size(); ++i)
        if (rig.parts[i].round && rig.parts[i].role != Role::Background && rig.parts[i].box.w() >= kWheelShare * widest)
          big.push_back(static_cast<int>(i));
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
  if (!v.empty() || rig.root < 0) return v;
  // Stand-ins: the parts hanging from the root that are not details, else the highest part
  // other than the root (a head for a nod, a single limb for a wave).
  std::vector<int> any = attached();
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

// The pole's parts at `side` of the figure (1 left, 2 right, 3 top, 4 bottom): the thin parts
// (at most kPoleWidth of the figure's extent across that side) lying within kPoleEnd of it.
std::vector<int> pole_parts(const Rig& rig, int side) {
  const RigBox& F = rig.figure;
  const bool across_x = side <= 2;  // a left or right pole: thin in x, spanning y
  const double L = std::max(across_x ? F.w() : F.h(), 1e-9);
  std::vector<int> out;
  for (size_t i = 0; i < rig.parts.size(); ++i) {
    const RigPart& P = rig.parts[i];
    if (P.role == Role::Background || P.box.empty()) continue;
    const double a0 = across_x ? P.box.x0 : P.box.y0, a1 = across_x ? P.box.x1 : P.box.y1;
    const double s0 = across_x ? F.x0 : F.y0, s1 = across_x ? F.x1 : F.y1;
    const bool near = side % 2 == 1 ? a1 <= s0 + kPoleEnd * L : a0 >= s1 - kPoleEnd * L;
    if (near && a1 - a0 <= kPoleWidth * L) out.push_back(static_cast<int>(i));
  }
  return out;
}

// The side of the figure a pole holds (PlannedAction::anchored: 1 left, 2 right, 3 top, 4
// bottom), 0 for none: where the pole's parts together span kPoleSpan of the figure.
int anchored_side(const Rig& rig) {
  const RigBox& F = rig.figure;
  for (int side = 1; side <= 4; ++side) {
    const bool across_x = side <= 2;
    const double span = std::max(across_x ? F.h() : F.w(), 1e-9);
    std::vector<std::pair<double, double>> spans;
    for (int p : pole_parts(rig, side)) {
      const RigBox& b = rig.parts[p].box;
      spans.push_back(across_x ? std::make_pair(b.y0, b.y1) : std::make_pair(b.x0, b.x1));
    }
    std::sort(spans.begin(), spans.end());
    double covered = 0, lo = 0, hi = -1e300;
    for (const auto& [b0, b1] : spans) {
      if (b0 > hi) {
        covered += std::max(0.0, hi - lo);
        lo = b0;
        hi = b1;
      } else {
        hi = std::max(hi, b1);
      }
    }
    covered += std::max(0.0, hi - lo);
    if (covered >= kPoleSpan * span) return side;
  }
  return 0;
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

// A compact figure (an octopus, a frog) does not swim by a wave along its body, which would heave
// its head as much as its arms: its lower limbs paddle, alternating (Builder::add), and the
// swim is then a verb of the limbs (plan_from_prompt).
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

bool paddles(const Verb& verb, const Rig& rig) {
  const RigBox& F = rig.figure;
  const double aspect = std::max(F.w(), F.h()) / std::max(std::min(F.w(), F.h()), 1e-9);
  return verb.name == "swim" && !verb.actions.empty() && verb.actions[0].primitive == Primitive::Undulate &&
         aspect < kElongated && anchored_side(rig) == 0;
}

struct Builder {
  const Rig& rig;
  std::mt19937 rng;
  MotionPlan plan;

  void add(const Verb& verb, const Action& base_in, Target target, const std::vector<int>& named_parts,
           const std::string& target_word, const Modifiers& mods, bool plural, const std::string& words,
           bool primary_retargeted, const std::string& instead = "") {
    Action base = base_in;
    std::string paddle;
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
    std::uniform_real_distribution<double> U(0, 1);
    a.amp = amp * mods.size * (a.primitive == Primitive::Spin ? 1 : 0.85 + 0.3 * U(rng));
    a.cycles = std::max(1, static_cast<int>(std::lround(base.cycles * mods.speed)));
    if (mods.once > 0) a.cycles = 1;
    if (mods.once < 0) a.cycles = std::max(2, a.cycles);
    if (a.primitive == Primitive::Spin) {
      a.amp = std::max(1.0, std::round(base.amp * (mods.speed > 1 ? 2 : 1)));  // whole turns
      a.cycles = 1;
    }
    a.vertical = mods.vertical;
    if (a.primitive == Primitive::Undulate && target == Target::Whole) a.anchored = anchored_side(rig);
    a.direction = mods.side != 0 ? mods.side : ((rng() & 1) ? 1 : -1);
    // Where the prompt sends the figure ("drifts to the right"): a slide of the whole figure
    // goes that way first, in the viewer's frame.
    if (mods.travel != 0 && a.primitive == Primitive::Slide && target == Target::Whole) a.direction = mods.travel;
    std::string note;
    if (target == Target::Named) a.parts = named_parts;
    else if (target != Target::Whole && target != Target::Repeated) a.parts = parts_for(rig, target, target_word, &note);
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
    if (limb_role && rig.root >= 0 && a.primitive == Primitive::Swing && anchored_side(rig) != 0)
      if (const Verb* ripple = find_verb_by_name("ripple")) {
        add(*ripple, ripple->actions[0], Target::Whole, {}, "", mods, plural, words, false,
            verb.name + " has no " + target_name(target) + " on a figure held by a pole: it ripples");
        return;
      }
    if (limb_role && !note.empty() && rig.root >= 0 && a.primitive == Primitive::Swing) {
      a.parts = {region_host(rig, target)};
      a.region = target == Target::Arms || target == Target::Limbs ? Region::Sides
                 : target == Target::Legs ? Region::Lower : target == Target::Head ? Region::Top : Region::End;
      a.alternating = base.pairing == Pairing::Alternating || (base.pairing == Pairing::OneAtATime && (mods.both || plural));
      if (a.region == Region::Sides) side_core(rig, a);
      // (A head or a tail is one: no side to pick.)
      if ((base.pairing == Pairing::OneSide || base.pairing == Pairing::OneAtATime) && !mods.both && !plural &&
          target != Target::Head && target != Target::Tail) {
        // The figure's own side is drawn on the viewer's other side.
        a.region_side = mods.side != 0 ? -mods.side : ((rng() & 1) ? 1 : -1);
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
        // As for the outline's arms: one on the side that moves, or a pair when both do.
        auto on = [&](int side) { return std::any_of(picked.begin(), picked.end(), [&](const ArmLobe& l) { return l.side == side; }); };
        const bool sided = a.region_side != 0 ? on(a.region_side) : target != Target::Arms || (on(-1) && on(1));
        if (!picked.empty() && sided) {
          a.lobes = std::move(picked);
          a.silhouette = skeletal = true;
        }
      }
      a.direction = a.region == Region::End ? ((rng() & 1) ? 1 : -1) : a.direction;
      note = std::string("no separate ") + target_name(target) + ": the " +
             (a.region == Region::Sides ? "sides" : a.region == Region::Lower ? "lower part" : a.region == Region::Top ? "top" : "far end") +
             " of " + rig.parts[a.parts[0]].name + " bend";
      if (skeletal)
        note = std::string("no separate ") + target_name(target) + ": " + std::to_string(a.lobes.size()) + " " +
               (a.lobes.size() > 1 ? "limbs" : "limb") + " of the figure's silhouette skeleton bend" + (a.lobes.size() > 1 ? "" : "s") + " about " + (a.lobes.size() > 1 ? "their bases" : "its base");
      else if (!a.lobes.empty())
        note = std::string("no separate ") + target_name(target) + ": the " + std::to_string(a.lobes.size()) +
               " arm" + (a.lobes.size() > 1 ? "s" : "") + " drawn in the outline of " + rig.parts[a.parts[0]].name + " bend";
      a.sign = {1};
      a.phase = {0};
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
    Pairing pairing = base.pairing;
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
    // One-sided whole-figure motions (lean, bow) go one way and back.
    if (a.primitive == Primitive::Rock && base.pairing == Pairing::OneSide) a.vertical = 2;
    // Skip a repeat: the same primitive on the same parts.
    for (const auto& b : plan.actions)
      if (b.primitive == a.primitive && b.target == a.target && b.parts == a.parts && b.region == a.region) return;
    std::vector<std::string> names;
    for (int p : a.parts) names.push_back(rig.parts[p].name);
    a.why = "'" + words + "': " + verb.name + " moves the " +
            (target == Target::Whole ? std::string("whole figure")
             : target == Target::Repeated ? rig.repeated_why
             : std::string(target_name(target)) + " (" + join(names, ", ") + ")");
    if (!note.empty()) a.why += "; " + note;
    if (!paddle.empty()) a.why += "; " + paddle;
    if (!instead.empty()) a.why += "; " + instead;
    if (!spacing.empty()) a.why += "; " + spacing;
    if (a.anchored != 0) {
      static const char* sides[] = {"", "left", "right", "top", "bottom"};
      a.why += std::string("; held by a pole at its ") + sides[a.anchored] + ": the wave runs from there";
    }
    if (!mods.words.empty()) a.why += "; " + join(mods.words, ", ");
    plan.actions.push_back(std::move(a));
  }
};

}  // namespace

std::string MotionPlan::summary() const {
  std::string s;
  for (const auto& a : actions) {
    char amp[64];
    const char* unit = a.primitive == Primitive::Swing || a.primitive == Primitive::Rock || a.primitive == Primitive::Bend || a.primitive == Primitive::Sway ? " deg"
                       : a.primitive == Primitive::Spin ? " turn" : "";
    std::snprintf(amp, sizeof amp, " %.3g%s x%d", amplitude(a), unit, a.cycles);
    std::string who = a.target == Target::Whole ? "whole" : a.target == Target::Repeated ? "repeated" : "";
    if (who.empty()) {
      for (int p : a.parts) who += (who.empty() ? "" : "+") + std::to_string(p);
    }
    s += (s.empty() ? "" : "; ") + a.verb + " (" + primitive_name(a.primitive) + ") " + who + amp;
  }
  return s;
}

MotionPlan plan_from_prompt(const ParsedPrompt& prompt, const Rig& rig, uint32_t seed) {
  Builder b{rig, std::mt19937(seed), {}};
  b.plan.source = "prompt";
  std::vector<std::string> unknown;
  // Does the prompt say which limbs move ("waving its arms", "sways its tentacles")? Then the
  // whole-figure accents of its limb verbs (cheering's hop, flapping's bob, dancing's rock) are
  // left out: they move every part, the ones the prompt keeps still too, and outweigh the
  // limbs it names.
  bool names_limbs = false;
  for (const Clause& c : prompt.clauses)
    for (const auto& n : c.nouns)
      names_limbs = names_limbs || (!n.object_of_preposition && !n.own_predicate && is_limb_target(n.target));
  std::vector<std::string> accents_left_out;
  // The clause's targets: known part nouns, and other words that name a part of the drawing.
  struct ClauseTarget {
    Target target = Target::Whole;
    std::vector<int> named;
    std::string word;
    bool plural = false, have = false;
  };
  auto target_of = [&](const Clause& c, std::vector<std::string>* unknown_words) {
    ClauseTarget ct;
    for (const auto& n : c.nouns) {
      std::vector<int> hits;
      if (n.target == Target::Named) {
        std::string ignore;
        hits = parts_for(rig, Target::Named, n.word, &ignore);
        if (hits.empty()) {
          if (unknown_words) unknown_words->push_back(n.word);
          continue;
        }
        // The verb's object naming only the backdrop ("rides the waves") is where the figure
        // moves, not what moves: the backdrop moves when it is the subject ("the waves roll").
        bool backdrop = true;
        for (int h : hits) backdrop = backdrop && rig.parts[h].role == Role::Background;
        if (backdrop && n.after_verb) continue;
      }
      if (ct.have || n.object_of_preposition || n.own_predicate) continue;
      ct.have = true;
      ct.target = n.target;
      ct.named = hits;
      ct.word = n.word;
      ct.plural = n.plural;
    }
    return ct;
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
    const ClauseTarget ct = target_of(c, &unknown);
    const Target target = ct.target;
    const std::vector<int>& named = ct.named;
    const std::string& target_word = ct.word;
    const bool plural = ct.plural, have = ct.have;
    for (const Verb* v : c.verbs)
      for (size_t i = 0; i < v->actions.size(); ++i) {
        const Action& act = v->actions[i];
        const bool retarget = i == 0 && have;
        if (i == 0 && !have && act.target == Target::Whole && aimed.count(v->name)) {
          restated.push_back("'" + c.text + "'");
          break;
        }
        if (i > 0 && act.target == Target::Whole && names_limbs && (is_limb_target(v->actions[0].target) || paddles(*v, rig))) {
          accents_left_out.push_back(v->name + "'s " + primitive_name(act.primitive));
          continue;
        }
        b.add(*v, act, retarget ? target : act.target, retarget ? named : std::vector<int>{}, target_word, c.mods,
              retarget && plural, c.text, retarget);
      }
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
          v = n.motion;
          what = "'" + n.word + "'";
          break;
        }
      if (!v && c.figure != FigureClass::None && (v = default_verb(c.figure))) what = std::string("a ") + figure_class_name(c.figure);
      if (!v) continue;
      for (const Action& act : v->actions) b.add(*v, act, act.target, {}, "", c.mods, false, c.text, false);
      b.plan.notes.push_back(what + " moves by itself: " + v->name + " (no verb in '" + c.text + "')");
      break;
    }
  b.plan.readings = prompt.readings;
  b.plan.not_understood = unknown;
  for (const auto& w : prompt.unplaced)
    if (std::find(unknown.begin(), unknown.end(), w) == unknown.end()) b.plan.not_understood.push_back(w);
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
  return b.plan;
}

MotionPlan plan_from_steps(const std::vector<ExplicitStep>& steps, const Rig& rig, uint32_t seed) {
  Builder b{rig, std::mt19937(seed), {}};
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

namespace {

// The oscillation of a back-and-forth action at phase u (in cycles): about rest on both sides
// (sin), or, one-sided, out to one side and back (0 at rest, +-1 at the far end of the swing).
double oscillation(const PlannedAction& a, double u) {
  return a.one_sided == 0 ? std::sin(kTau * u) : a.one_sided * (0.5 - 0.5 * std::cos(kTau * u));
}

// The rigid motion of one action at time t on a part (or the figure) with box `box` and
// attachment `pivot`; `H`, `W` the figure's size (units of the translations).
Affine rigid(const PlannedAction& a, double amp, double sign, double phase, double t, const RigBox& box, Vec2 pivot,
             double W, double H, const Affine& plane = {}) {
  const double u = a.cycles * t + phase;
  const double s = oscillation(a, u), k = 0.5 - 0.5 * std::cos(kTau * u);
  const Vec2 base{box.centre().x, box.y1}, centre = box.centre();
  auto about = [](Vec2 c, const Affine& m) { return Affine::translate(c.x, c.y) * m * Affine::translate(-c.x, -c.y); };
  switch (a.primitive) {
    case Primitive::Swing: return about(pivot, Affine::rotate_deg(sign * amp * s));
    case Primitive::Spin: return about(centre, plane * Affine::rotate_deg(360.0 * amp * a.direction * t) * plane.inverse());
    case Primitive::Rock:
      return about(a.parts.empty() ? base : pivot, Affine::rotate_deg(a.vertical == 2 ? a.direction * amp * k : sign * amp * s));
    case Primitive::Bob: {
      const double ty = a.vertical == 1 ? -amp * H * k : a.vertical == -1 ? amp * H * k : -amp * H * s;
      return Affine::translate(0, ty);
    }
    case Primitive::Slide: return Affine::translate(a.direction * amp * W * s, 0);
    case Primitive::Shake:
      return Affine::translate(amp * H * s, 0.6 * amp * H * std::sin(kTau * (std::max(1, a.cycles - 1) * t + phase)));
    case Primitive::Pulse: {
      const double f = 1 + amp * k;
      return about(centre, Affine::scale(f, f));
    }
    case Primitive::Squash: {
      const double sy = 1 - 1.2 * amp * k;
      return about(base, Affine::scale(1 + 0.5 * amp * k, sy));
    }
    case Primitive::Stretch: {
      const double f = 1 + amp * k;
      if (box.w() >= box.h()) return about({box.x0, centre.y}, Affine::scale(f, 1 / std::sqrt(f)));
      return about(base, Affine::scale(1 / std::sqrt(f), f));
    }
    case Primitive::Hop: {
      // Per cycle: a fifth on the ground squashing, then the flight (stretched rising,
      // squashed a little falling), landing where it started.
      const double c = u - std::floor(u);
      double ty = 0, sy = 1;
      if (c < 0.2) sy = 1 - 0.6 * amp * std::sin(M_PI * c / 0.2);
      else {
        const double v = (c - 0.2) / 0.8;
        ty = -amp * H * std::sin(M_PI * v);
        sy = 1 + 0.4 * amp * std::sin(kTau * v);
      }
      return Affine::translate(0, ty) * about(base, Affine::scale(1 / std::sqrt(sy), sy));
    }
    default: return {};
  }
}

// Deformations of the shape: a wave along the long axis (Undulate) or a bend (Bend).
Vec2 deform(const PlannedAction& a, double amp, double t, const RigBox& box, Vec2 q) {
  const bool horizontal = box.w() >= box.h();
  const double L = std::max(horizontal ? box.w() : box.h(), 1e-9);
  const double u = horizontal ? (q.x - box.x0) / L : (q.y - box.y0) / L;
  double d = 0;
  if (a.primitive == Primitive::Undulate && a.anchored != 0) {
    // Held at one side (a flag at its pole): the wave runs away from there, growing to the far
    // side, across the pole whatever the figure's long axis.
    const bool across_x = a.anchored <= 2;
    const double len = std::max(across_x ? box.w() : box.h(), 1e-9);
    const double f = across_x ? (q.x - box.x0) / len : (q.y - box.y0) / len;
    const double v = a.anchored % 2 == 1 ? f : 1 - f;
    const double e = amp * len * v * (std::sin(kTau * (a.cycles * t - v)) - std::sin(kTau * (-v)));
    return across_x ? Vec2{q.x, q.y + e} : Vec2{q.x + e, q.y};
  } else if (a.primitive == Primitive::Undulate) {
    const double w = 0.4 + 0.6 * std::fabs(2 * u - 1);  // the ends move most
    d = amp * L * w * (std::sin(kTau * (a.cycles * t - u)) - std::sin(kTau * (-u)));
  } else if (a.primitive == Primitive::Bend) {
    d = std::tan(amp * M_PI / 180) * L * 2 * (u - 0.5) * (u - 0.5) * oscillation(a, a.cycles * t) * a.direction;
  }
  return horizontal ? Vec2{q.x, q.y + d} : Vec2{q.x + d, q.y};
}

bool is_deformation(const PlannedAction& a) {
  return a.primitive == Primitive::Undulate || a.primitive == Primitive::Bend || a.primitive == Primitive::Sway ||
         a.region != Region::None;
}

double smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3 - 2 * x);
}

Vec2 rotate_about(Vec2 q, Vec2 c, double deg) {
  const double r = deg * M_PI / 180, cs = std::cos(r), sn = std::sin(r);
  const Vec2 d = q - c;
  return c + Vec2{cs * d.x - sn * d.y, sn * d.x + cs * d.y};
}

// Region bends (virtual limbs); the fractions of the part's box are where a figure drawn as
// one shape usually has its joints: the core of a body is the middle quarter of its width
// (kCore each side), hips at 60 % of its height, a neck at 30 %, a tail the last 30 %.
constexpr double kCore = 0.12, kHip = 0.6, kNeck = 0.3, kTailStart = 0.3, kRamp = 0.25;
// An arm lobe's turn grows over this share of its base's width beyond the base.
constexpr double kLobeRamp = 0.5;

Vec2 bend_region(const PlannedAction& a, double amp, double t, const RigBox& box, Vec2 q) {
  const double W = std::max(box.w(), 1e-9), H = std::max(box.h(), 1e-9);
  const Vec2 c = box.centre();
  auto wave = [&](double phase) { return oscillation(a, a.cycles * t + phase); };
  // Limbs drawn in the part's outline, or read from its silhouette's skeleton: each bends about
  // the middle of its base, the turn growing from nothing at the base over half its width (the
  // outline stays in one piece).
  if (!a.lobes.empty()) {
    for (const ArmLobe& l : a.lobes) {
      if (a.region_side != 0 && l.side != a.region_side) continue;
      const double depth = lobe_depth(l, q);
      if (depth <= 0) continue;
      const double base = std::hypot(l.base1.x - l.base0.x, l.base1.y - l.base0.y);
      const double w = smoothstep(depth / std::max(kLobeRamp * base, 1e-9));
      const double ang = amp * (l.side < 0 ? 1 : -1) * wave(a.alternating && l.side > 0 ? 0.5 : 0) * w;
      return rotate_about(q, l.pivot, ang);
    }
    return q;
  }
  switch (a.region) {
    case Region::Sides: {
      const double dx = q.x - c.x;
      const int side = dx < 0 ? -1 : 1;  // as the viewer sees it
      const double core = a.core_left > 0 ? (side < 0 ? a.core_left : a.core_right) : kCore * W;
      if (std::fabs(dx) <= core) return q;
      if (a.region_side != 0 && side != a.region_side) return q;
      const double w = smoothstep((std::fabs(dx) - core) / (kRamp * W));
      // Mirrored: both sides rise together; alternating: half a cycle apart.
      const double ang = amp * (side < 0 ? 1 : -1) * wave(a.alternating && side > 0 ? 0.5 : 0) * w;
      return rotate_about(q, {c.x + side * core, c.y}, ang);
    }
    case Region::Lower: {
      const double hip = box.y0 + kHip * H;
      if (q.y <= hip) return q;
      const int side = q.x < c.x ? -1 : 1;
      if (a.region_side != 0 && side != a.region_side) return q;
      const double w = smoothstep((q.y - hip) / (kRamp * H));
      const double ang = amp * wave(a.alternating && side > 0 ? 0.5 : 0) * w * (a.alternating ? 1 : (side < 0 ? 1 : -1));
      return rotate_about(q, {c.x + side * kCore * W, hip}, ang);
    }
    case Region::Top: {
      const double neck = box.y0 + kNeck * H;
      if (q.y >= neck) return q;
      return rotate_about(q, {c.x, neck}, amp * wave(0) * smoothstep((neck - q.y) / (kRamp * H)));
    }
    case Region::End: {
      const double start = a.direction > 0 ? box.x1 - kTailStart * W : box.x0 + kTailStart * W;
      const double beyond = a.direction * (q.x - start);
      if (beyond <= 0) return q;
      return rotate_about(q, {start, c.y}, amp * wave(0) * smoothstep(beyond / (kRamp * W)));
    }
    case Region::None: break;
  }
  return q;
}

// A part hanging beside a bending shape, outside its box (not under its middle half, where legs
// hang from a torso and keep to the rig): moved whole as the bend
// moves the point where it attaches, turned as the bend turns there. Bent point by point it
// would not move at all (outside the region's box nothing bends): woman_wave's lowered hand,
// drawn as its own shapes beyond the sweater's box, stayed where it was while the sleeve above
// it swung out, 10-15 px off the cuff in the target and so in the fit.
Vec2 carried_by_bend(const PlannedAction& a, double amp, double t, const RigBox& box, Vec2 pivot, Vec2 q) {
  const double eps = 1e-3 * std::max(box.w(), 1e-9);
  const Vec2 p = bend_region(a, amp, t, box, pivot), e = bend_region(a, amp, t, box, pivot + Vec2{eps, 0});
  const double ang = std::atan2(e.y - p.y, e.x - p.x);
  const double cs = std::cos(ang), sn = std::sin(ang), dx = q.x - pivot.x, dy = q.y - pivot.y;
  return p + Vec2{cs * dx - sn * dy, sn * dx + cs * dy};
}

// A Sway of the figure with box `box`: above the hinge the points lean about the hinge's middle,
// the lean growing smoothly over kRamp of the height (the shape stays in one piece); below it
// they hold.
Vec2 sway_lean(const PlannedAction& a, double amp, double t, const RigBox& box, Vec2 q) {
  const double H = std::max(box.h(), 1e-9), hinge = box.y0 + kSwayHinge * H;
  if (q.y >= hinge) return q;
  const double w = smoothstep((hinge - q.y) / (kRamp * H));
  return rotate_about(q, {box.centre().x, hinge}, a.direction * amp * oscillation(a, a.cycles * t) * w);
}

// The share of box a inside box b.
double overlap_share(const RigBox& a, const RigBox& b) {
  const double ox = std::min(a.x1, b.x1) - std::max(a.x0, b.x0), oy = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
  return ox > 0 && oy > 0 ? ox * oy / std::max(a.area(), 1e-12) : 0;
}

// What each spinning part moves (wheel_riders.h): per part, the spinning part it turns with (in
// its own frame: itself, or an ancestor holding at least kSpinInsideShare of its box, its spokes
// and hub, not its stand), or the one it rides round upright (a small part on its rim, a ferris
// wheel's cabin, whatever the rig hangs it from; a small part stacked under a rider rides with
// it), where each rider hangs from and the box of its stack. A stack hangs from the middle of
// the top of its piece whose top lies nearest the rim (a cabin's roof; its body below rides
// with it, a bracket reaching in towards the hub does not lift it), which goes round the
// wheel's centre. Turned with the wheel, or carried round by its middle, a cabin hanging below
// the rim at the bottom came to stand out above it at the top, and left the canvas; its roof
// and body hanging each from its own top parted as they went round.
struct WheelLoads {
  std::vector<int> turns_with, rides;
  std::vector<Vec2> hang;
  std::vector<RigBox> stack;
};

WheelLoads wheel_loads(const Rig& rig, const std::vector<char>& spins) {
  const int G = static_cast<int>(rig.parts.size());
  WheelLoads L{std::vector<int>(G, -1), std::vector<int>(G, -1), std::vector<Vec2>(G), std::vector<RigBox>(G)};
  auto free_part = [&](int g) { return g != rig.root && rig.parts[g].role != Role::Background; };
  for (int g = 0; g < G; ++g) {
    const RigBox& gb = rig.parts[g].box;
    for (int a = g, guard = 0; a >= 0 && guard < 64; a = rig.parts[a].parent, ++guard)
      if (spins[a] && (a == g || (rig.parts[g].carried && a == rig.parts[g].parent) || overlap_share(gb, rig.parts[a].box) >= kSpinInsideShare)) {
        (a != g && !rig.parts[g].carried && rides_wheel(gb, rig.parts[a].box) ? L.rides : L.turns_with)[g] = a;
        break;
      }
    for (int a = 0; a < G && L.turns_with[g] < 0 && L.rides[g] < 0 && free_part(g) && !rig.parts[g].carried; ++a)
      if (spins[a] && a != g && rides_wheel(gb, rig.parts[a].box)) L.rides[g] = a;
  }
  for (bool grew = true; grew;) {
    grew = false;
    for (int g = 0; g < G; ++g) {
      if (L.turns_with[g] >= 0 || L.rides[g] >= 0 || !free_part(g)) continue;
      for (int h = 0; h < G && L.rides[g] < 0; ++h)
        if (L.rides[h] >= 0 && rig.parts[g].box.area() <= kRideMaxArea * rig.parts[L.rides[h]].box.area() &&
            riders_stack(rig.parts[g].box, rig.parts[h].box)) {
          L.rides[g] = L.rides[h];
          grew = true;
        }
    }
  }
  for (int a = 0; a < G; ++a) {
    if (!spins[a]) continue;
    std::vector<int> riders;
    std::vector<RigBox> boxes;
    for (int g = 0; g < G; ++g)
      if (L.rides[g] == a) {
        riders.push_back(g);
        boxes.push_back(rig.parts[g].box);
      }
    // Only riders in sets ride (in_rider_sets); a piece drawn once stays where the rig has it.
    const std::vector<char> in_set = in_rider_sets(boxes);
    for (size_t i = riders.size(); i-- > 0;)
      if (!in_set[i]) {
        L.rides[riders[i]] = -1;
        riders.erase(riders.begin() + static_cast<long>(i));
        boxes.erase(boxes.begin() + static_cast<long>(i));
      }
    const std::vector<RigBox> stacks = rider_stacks(boxes);
    const Vec2 c = rig.parts[a].box.centre();
    const double R = 0.5 * rig.parts[a].box.w();
    for (size_t i = 0; i < riders.size(); ++i) {
      L.stack[riders[i]] = stacks[i];
      double best = 1e300;
      for (size_t j = 0; j < riders.size(); ++j) {
        if (!(stacks[j].x0 == stacks[i].x0 && stacks[j].y0 == stacks[i].y0 && stacks[j].x1 == stacks[i].x1 && stacks[j].y1 == stacks[i].y1))
          continue;
        const Vec2 top{boxes[j].centre().x, boxes[j].y0};
        const double off = std::fabs(std::hypot(top.x - c.x, top.y - c.y) - R);
        if (off < best) { best = off; L.hang[riders[i]] = top; }
      }
    }
  }
  return L;
}

}  // namespace

// The riders evenly spaced round the spinning `parts` (rider_symmetry), the most of any.
int spin_symmetry(const Rig& rig, const std::vector<int>& parts) {
  std::vector<char> spins(rig.parts.size(), 0);
  for (int p : parts) spins[p] = 1;
  const WheelLoads L = wheel_loads(rig, spins);
  int n = 0;
  for (int p : parts) {
    std::vector<RigBox> stacks;
    for (size_t g = 0; g < rig.parts.size(); ++g)
      if (L.rides[g] == p) stacks.push_back(L.stack[g]);
    n = std::max(n, rider_symmetry(stacks, rig.parts[p].box));
  }
  return n;
}

std::vector<Vec2> animate_plan(const Scene& scene, const Rig& rig, const MotionPlan& plan, int frames) {
  const int G = static_cast<int>(rig.parts.size());
  const double W = std::max(rig.figure.w(), 1e-9), H = std::max(rig.figure.h(), 1e-9);
  const double CH = scene.height;
  auto under = [&](int p, int a) { return part_under(rig, p, a); };
  // Repeated elements: which element each path belongs to; and whether they fly free.
  std::vector<int> element_of(scene.paths.size(), -1);
  std::vector<RigBox> element_box(rig.repeated.size());
  for (size_t e = 0; e < rig.repeated.size(); ++e)
    for (int pi : rig.repeated[e]) {
      element_of[pi] = static_cast<int>(e);
      for (const auto& sp : scene.paths[pi].subpaths)
        for (const Vec2& q : sp.points) element_box[e].add(q);
    }
  bool particles = false;
  for (const auto& a : plan.actions) particles = particles || (a.target == Target::Repeated && a.primitive == Primitive::Fall);
  // Each part's box including what hangs from it (the extent a deformation spans).
  std::vector<RigBox> reach(G);
  for (int g = 0; g < G; ++g) reach[g] = chain_box(rig, g);
  // Parts the whole figure's motions leave where they are (fit_plan).
  std::vector<char> held(G, 0);
  for (int g = 0; g < G; ++g)
    for (int h : plan.held) held[g] = held[g] || under(g, h);
  // The pole a wave runs from holds still (the wave's weight is small but not nothing across
  // its width: a flag's pole moved 0.8 px and the fitted one drifted out of the canvas).
  for (const auto& a : plan.actions)
    if (a.primitive == Primitive::Undulate && a.anchored != 0)
      for (int p : pole_parts(rig, a.anchored)) held[p] = 1;
  // Chains hanging from the root that reach the lowest kPlanted of the figure stand on the
  // ground (legs, feet): the root's own swing does not carry them.
  std::vector<char> planted(G, 0);
  for (int g = 0; g < G; ++g)
    planted[g] = rig.parts[g].parent == rig.root && rig.root >= 0 && !reach[g].empty() &&
                 reach[g].y1 >= rig.figure.y1 - kPlanted * rig.figure.h();

  std::vector<char> spinning(G, 0);
  for (const auto& a : plan.actions)
    if (a.primitive == Primitive::Spin)
      for (int p : a.parts) spinning[p] = 1;
  const WheelLoads loads = wheel_loads(rig, spinning);

  std::vector<Vec2> out;
  out.reserve(static_cast<size_t>(frames) * (scene.segment_count() * 3 + scene.paths.size() * 2));
  for (int f = 0; f < frames; ++f) {
    const double t = frames > 1 ? static_cast<double>(f) / (frames - 1) : 0;
    std::vector<Affine> local(G), world(G), spin(G);
    std::vector<char> spins(G, 0);
    Affine whole, root_turn;
    for (const auto& a : plan.actions) {
      const double amp = plan.amplitude(a);
      if (is_deformation(a) || a.target == Target::Repeated) continue;
      if (a.parts.empty()) whole = rigid(a, amp, 1, 0, t, rig.figure, rig.figure.centre(), W, H) * whole;
      for (size_t i = 0; i < a.parts.size(); ++i) {
        const RigPart& P = rig.parts[a.parts[i]];
        Affine& into = a.primitive == Primitive::Spin ? spin[a.parts[i]]
                       : a.parts[i] == rig.root && a.primitive == Primitive::Swing ? root_turn : local[a.parts[i]];
        into = rigid(a, amp, a.sign[i], a.phase[i], t, P.box, P.pivot, W, H, P.wheel_plane) * into;
        if (a.primitive == Primitive::Spin) spins[a.parts[i]] = 1;
      }
    }
    // World transforms down the rig: parents before children (parents are larger, or the root).
    std::vector<int> order(G);
    for (int g = 0; g < G; ++g) order[g] = g;
    auto depth = [&](int g) { int d = 0; for (int p = rig.parts[g].parent; p >= 0 && d < 64; p = rig.parts[p].parent) ++d; return d; };
    std::stable_sort(order.begin(), order.end(), [&](int x, int y) { return depth(x) < depth(y); });
    // The root's own turn (the upper body swaying about the hips) leaves what stands on the
    // ground where it is: the chains hanging from the root that reach down to the figure's feet.
    // The head rides on the turning body upright (the eyes stay level, on the opponent a boxer
    // turns into): it goes where its neck goes without the turn. Turned with the body, a boxer's
    // densely drawn head swung 19 px at its top for a 4-degree turn and outweighed the punch.
    for (int g : order) {
      const int p = rig.parts[g].parent;
      if (g == rig.root) world[g] = local[g] * root_turn;
      else if (p == rig.root && planted[g]) world[g] = local[p] * local[g];
      else if (p == rig.root && rig.parts[g].role == Role::Head) {
        const Vec2 h = rig.parts[g].pivot, to = root_turn.apply(h);
        world[g] = local[p] * Affine::translate(to.x - h.x, to.y - h.y) * local[g];
      }
      else world[g] = p >= 0 ? world[p] * local[g] : local[g];
    }
    // A spinning part turns in its own frame and carries what turns with it; its riders go
    // round upright (wheel_loads).
    for (int g = 0; g < G; ++g) {
      if (loads.turns_with[g] >= 0) world[g] = world[g] * spin[loads.turns_with[g]];
      if (loads.rides[g] < 0) continue;
      const Vec2 hang = loads.hang[g], to = spin[loads.rides[g]].apply(hang);
      world[g] = Affine::translate(to.x - hang.x, to.y - hang.y) * world[g];
    }

    for (size_t pi = 0; pi < scene.paths.size(); ++pi) {
      const int g = rig.part_of_path[pi];
      const int e = element_of[pi];
      const bool background = g >= 0 && (rig.parts[g].role == Role::Background || held[g]);
      const bool free_particle = particles && e >= 0;
      // The element's own motion (falls, twinkles), one phase per element.
      Affine elem;
      if (e >= 0)
        for (const auto& a : plan.actions) {
          if (a.target != Target::Repeated) continue;
          const double phase = std::fmod(e * kPhaseSpacing + a.direction * 0.137, 1.0) + 1.0;
          const RigBox& eb = element_box[e];
          if (a.primitive == Primitive::Fall) {
            const double u = std::fmod(a.cycles * t + phase, 1.0);
            const double room = std::max(0.0, scene.height * (1 - kFrameMargin) - eb.y1);
            const double dist = std::min(plan.amplitude(a) * CH, room);
            const double s = std::min(1.0, 3 * std::sin(M_PI * u));
            const Vec2 c{eb.centre().x, eb.centre().y + dist * u};
            elem = Affine::translate(c.x, c.y) * Affine::scale(s, s) * Affine::translate(-eb.centre().x, -eb.centre().y) * elem;
          } else {
            PlannedAction one = a;
            one.parts = {};
            elem = rigid(one, plan.amplitude(a), 1, phase, t, eb, {eb.centre().x, eb.y1}, W, H) * elem;
          }
        }
      for (const auto& sp : scene.paths[pi].subpaths)
        for (Vec2 q : sp.points) {
          q = elem.apply(q);
          if (!free_particle) {
            for (const auto& a : plan.actions) {
              if (!is_deformation(a)) continue;
              const double amp = plan.amplitude(a);
              if (a.region != Region::None) {
                // The part's own outlines and what hangs from it within its width and not
                // below it (a hand at the end of a sleeve, also one raised above the sleeve's
                // box); what hangs below (legs under a waving torso) keeps its shape and
                // follows the rig. A wheel (and what turns with it) keeps to its own frame: a
                // pedalling leg's bend bent a sketched bicycle's wheels with it.
                if (g >= 0 && g != a.parts[0] && (spins[g] || loads.turns_with[g] >= 0)) continue;
                const RigBox& hb = rig.parts[a.parts[0]].box;
                const Vec2 gc = g >= 0 ? rig.parts[g].box.centre() : Vec2{};
                // Limbs of the whole silhouette: whatever lies in them bends with them (the
                // outline drawn over a tail's fill), whichever part it belongs to.
                if (a.silhouette) {
                  if (!background) q = bend_region(a, amp, t, hb, q);
                } else if (g == a.parts[0] || (g >= 0 && under(g, a.parts[0]) && gc.x >= hb.x0 && gc.x <= hb.x1 && gc.y <= hb.y1))
                  q = bend_region(a, amp, t, hb, q);
                else if (g >= 0 && under(g, a.parts[0]) && (gc.y <= hb.y1 || std::fabs(gc.x - hb.centre().x) > 0.25 * hb.w()))
                  q = carried_by_bend(a, amp, t, hb, rig.parts[g].pivot, q);
              } else if (a.parts.empty()) {
                if (!background) q = a.primitive == Primitive::Sway ? sway_lean(a, amp, t, rig.figure, q) : deform(a, amp, t, rig.figure, q);
              } else {
                for (int p : a.parts)
                  if (g >= 0 && under(g, p)) q = deform(a, amp, t, reach[p], q);
              }
            }
            if (g >= 0) q = world[g].apply(q);
            if (!background) q = whole.apply(q);
          }
          out.push_back(q);
        }
    }
  }
  return out;
}

namespace {

// Why `pts` (frames of animate_plan) moves a point that is not `exempt` farther than kMaxStep
// between two of K keyframes, or "".
std::string limit_broken_steps(const Scene& scene, const std::vector<Vec2>& pts, const std::vector<char>& exempt, int frames, int K) {
  const double max_step = kMaxStep * std::hypot(scene.width, scene.height);
  const size_t per = pts.size() / frames;
  for (int k = 1; k < K; ++k) {
    const int fa = static_cast<int>(std::lround((k - 1) * (frames - 1.0) / (K - 1)));
    const int fb = static_cast<int>(std::lround(k * (frames - 1.0) / (K - 1)));
    for (size_t i = 0; i < per; ++i) {
      if (exempt[i]) continue;
      const Vec2 d = pts[fb * per + i] - pts[fa * per + i];
      if (std::hypot(d.x, d.y) > max_step) return "would move too far between keyframes for the fitter to follow";
    }
  }
  return "";
}

// Why `pts` (frames of animate_plan) breaks a limit of fit_plan, or "" when it does not.
std::string limit_broken(const Scene& scene, const std::vector<Vec2>& pts, const std::vector<char>& exempt,
                         const std::vector<char>& by_curve, int frames, int K) {
  const double m = kFrameMargin * std::min(scene.width, scene.height);
  const double x0 = m, y0 = m, x1 = scene.width - m, y1 = scene.height - m;
  auto outside = [&](Vec2 q) { return std::max({0.0, x0 - q.x, q.x - x1, y0 - q.y, q.y - y1}); };
  const size_t per = pts.size() / frames;
  // A control point inside the canvas at rest stays inside (a point inside the margin band at
  // rest, a drawing touching the edge, may use the band). One already outside the canvas (a
  // line drawing's handle: one 0.7 px out froze a galloping horse) may move: its curve is
  // held instead, each cubic at t = 0, 1/4, 1/2, 3/4, a point of it already outside at rest
  // going at most 0.9 of the margin farther out. The points of a spinning part are held by their
  // curves too: a turning circle stays where it is while its handles (0.55 of the radius off
  // the circle) sweep out beyond it, past the edge of a canvas the wheel fills; held by
  // the handles, no turn of a ferris wheel could stay in.
  auto allowed_for = [&](double rest) { return rest > m ? rest + kMarginUse * m : rest > 0 ? std::max(rest, kMarginUse * m) : 0.0; };
  auto at = [&](int f, size_t i, double t) {
    const Vec2* c = &pts[f * per + i];
    const double u = 1 - t;
    return u * u * u * c[0] + 3 * u * u * t * c[1] + 3 * u * t * t * c[2] + t * t * t * c[3];
  };
  size_t i = 0;
  for (const Path& p : scene.paths)
    for (const auto& sp : p.subpaths) {
      const size_t n = sp.points.size();
      for (size_t k = 0; k < n; ++k) {
        const double rest = outside(pts[i + k]);
        if (rest > m || by_curve[i + k]) {
          // The segments this point shapes: the one it starts or ends, or whose handle it is.
          const size_t s0 = k / 3 * 3, first = (k % 3 == 0 && k >= 3) ? s0 - 3 : s0;
          for (size_t s = first; s <= s0 && s + 3 < n; s += 3)
            for (double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {
              const double allowed = allowed_for(outside(at(0, i + s, t)));
              for (int f = 1; f < frames; ++f)
                if (outside(at(f, i + s, t)) > allowed + 1e-6) return "would leave the canvas";
            }
          continue;
        }
        const double allowed = allowed_for(rest);
        for (int f = 1; f < frames; ++f)
          if (outside(pts[f * per + i + k]) > allowed + 1e-6) return "would leave the canvas";
      }
      i += n;
    }
  return limit_broken_steps(scene, pts, exempt, frames, K);
}

// Why a swing of `plan` breaks the turn limit (kMaxTurn between two of the K keyframes spread
// over `frames`), or "" when none does. The angle of a swing is amplitude * sin(2 pi (cycles t +
// phase)) (rigid), so its turn between keyframes is known without the frames. Only parts: a
// part of its own turning far slides behind or out from its neighbours (its visible area jumps),
// a region of one shape bending (bend_region) keeps its outline whole; capped, a dancer's
// sleeves bent 18 degrees instead of 29 and his squat outweighed them (fitted share 0.70 -> 0.66).
std::string turn_broken(const MotionPlan& plan, int frames, int K) {
  for (const auto& a : plan.actions) {
    if (a.primitive != Primitive::Swing || a.region != Region::None) continue;
    const double amp = plan.amplitude(a);
    for (double phase : a.phase)
      for (int k = 1; k < K; ++k) {
        const double ta = std::lround((k - 1) * (frames - 1.0) / (K - 1)) / std::max(frames - 1.0, 1.0);
        const double tb = std::lround(k * (frames - 1.0) / (K - 1)) / std::max(frames - 1.0, 1.0);
        const double turn = amp * std::fabs(oscillation(a, a.cycles * tb + phase) - oscillation(a, a.cycles * ta + phase));
        if (turn > kMaxTurn + 1e-9) return "would turn a part too far between keyframes for the tracker to follow";
      }
  }
  return "";
}

// A verb's whole-figure accents (a gallop's rock and bob) keep their size next to its limbs'
// swing: when the turn or step limit scaled the limbs' swing down, its accents of the same
// words scale down with it. At full size beside legs cut to half, a galloping horse rocked and
// bobbed more than its legs moved (share of the motion on the legs 0.35).
void accents_follow_limbs(MotionPlan& plan) {
  for (auto& a : plan.actions) {
    if (a.target != Target::Whole || a.primitive == Primitive::Spin) continue;
    double limbs = 1;
    for (const auto& b : plan.actions)
      if (&b != &a && b.verb == a.verb && b.words == a.words && is_limb_target(b.target) && b.primitive == Primitive::Swing)
        limbs = std::min(limbs, b.scale);
    if (limbs >= a.scale) continue;
    a.scale = limbs;
    char line[240];
    std::snprintf(line, sizeof line, "%s (%s) of the whole figure scaled to %.0f %% with its limbs' swing", a.verb.c_str(),
                  primitive_name(a.primitive), limbs * 100);
    plan.notes.push_back(line);
  }
}

// The largest distance a point that is not `exempt` travels from rest over the frames `pts`.
double largest_travel(const std::vector<Vec2>& pts, const std::vector<char>& exempt, int frames) {
  const size_t per = pts.size() / frames;
  double largest = 0;
  for (int f = 1; f < frames; ++f)
    for (size_t i = 0; i < per; ++i)
      if (!exempt[i]) largest = std::max(largest, std::hypot(pts[f * per + i].x - pts[i].x, pts[f * per + i].y - pts[i].y));
  return largest;
}

bool oscillates(const PlannedAction& a) {
  return a.primitive == Primitive::Swing || a.primitive == Primitive::Rock || a.primitive == Primitive::Bend ||
         a.primitive == Primitive::Sway || a.region != Region::None;
}

// The fewest keyframes, from `K` up to `K_hi`, between which `one`'s frames break neither the
// step nor the turn limit; 0 when even `K_hi` do not.
int keyframes_to_follow(const Scene& scene, const std::vector<Vec2>& pts, const MotionPlan& one, const std::vector<char>& exempt,
                        int frames, int K, int K_hi) {
  auto follows = [&](int k) {
    return limit_broken_steps(scene, pts, exempt, frames, k).empty() && turn_broken(one, frames, k).empty();
  };
  if (!follows(K_hi)) return 0;
  for (int k = K; k < K_hi; ++k)  // searched from below: more keyframes are not always closer
    if (follows(k)) return k;       // (rounding moves them), the fewest that follow win
  return K_hi;
}

// fit_plan's scaling of `plan` (see motion_plan.h). True when a motion of the whole figure
// would break a limit even at its smallest scale (a warning says so).
bool fit_scales(const Scene& scene, const Rig& rig, MotionPlan& plan, int frames, int keyframes) {
  bool whole_failed = false;
  // Points exempt from the step limit: falling elements (they jump back while invisible) and
  // spinning parts (whole turns cannot be scaled; rotation is what flow tracking follows best).
  std::vector<char> exempt, by_curve;
  {
    std::set<int> spinning;
    for (const auto& a : plan.actions)
      if (a.primitive == Primitive::Spin)
        for (int p : a.parts) spinning.insert(p);
    bool falls = false;
    for (const auto& a : plan.actions) falls = falls || a.primitive == Primitive::Fall;
    std::set<int> falling;
    if (falls)
      for (const auto& el : rig.repeated) falling.insert(el.begin(), el.end());
    for (size_t pi = 0; pi < scene.paths.size(); ++pi) {
      bool spin = false;
      for (int g = rig.part_of_path[pi], guard = 0; g >= 0 && guard < 64; g = rig.parts[g].parent, ++guard)
        spin = spin || spinning.count(g) > 0;
      const bool ex = spin || falling.count(static_cast<int>(pi)) > 0;
      for (const auto& sp : scene.paths[pi].subpaths) {
        exempt.insert(exempt.end(), sp.points.size(), ex);
        by_curve.insert(by_curve.end(), sp.points.size(), spin);
      }
    }
  }
  const int K = std::clamp(keyframes, 2, frames);
  // The fitter may take up to twice as many keyframes as it was given (the fitter plugin reads
  // motion.json's "keyframes"): a motion too fast for K keyframes gets more of them before its
  // amplitude is cut. Cut to follow 15 keyframes, a butterfly's wings, a snake and a skier moved
  // 11-64 % of what their verbs ask, too little to see.
  const int K_hi = std::min(frames, 2 * (K - 1) + 1);
  auto alone = [&](const std::vector<size_t>& keep) {
    MotionPlan one = plan;
    for (size_t j = 0; j < one.actions.size(); ++j)
      if (std::find(keep.begin(), keep.end(), j) == keep.end()) one.actions[j].amp = 0;
    return one;
  };
  // Too small to see: the moving parts travel at least kVisibleTravel of the figure's size. Each
  // clause's actions (one verb's words: a walk's legs, arms and bob) grow together, by at most
  // kMaxBoost; the canvas then scales them back where they would not fit.
  {
    const double floor = kVisibleTravel * std::hypot(rig.figure.w(), rig.figure.h());
    std::vector<char> done(plan.actions.size(), 0);
    for (size_t i = 0; i < plan.actions.size(); ++i) {
      if (done[i]) continue;
      std::vector<size_t> clause;
      for (size_t j = i; j < plan.actions.size(); ++j)
        if (plan.actions[j].verb == plan.actions[i].verb && plan.actions[j].words == plan.actions[i].words) {
          clause.push_back(j);
          done[j] = 1;
        }
      bool measurable = true;
      for (size_t j : clause)
        measurable = measurable && plan.actions[j].primitive != Primitive::Spin && plan.actions[j].primitive != Primitive::Fall;
      if (!measurable) continue;
      const double travel = largest_travel(animate_plan(scene, rig, alone(clause), frames), exempt, frames);
      if (travel <= 0 || travel >= floor) continue;
      const double boost = std::min(kMaxBoost, floor / travel);
      for (size_t j : clause) plan.actions[j].scale *= boost;
      char line[240];
      std::snprintf(line, sizeof line, "%s raised to %.0f %%: it moved %.1f %% of the figure's size, too little to see",
                    plan.actions[i].verb.c_str(), boost * 100, 100 * travel / std::hypot(rig.figure.w(), rig.figure.h()));
      plan.notes.push_back(line);
    }
  }
  // Why `one` at its scales breaks a limit ("" when none): the canvas, then the steps and turns
  // between K_hi keyframes.
  auto broken = [&](const MotionPlan& one) {
    const std::vector<Vec2> pts = animate_plan(scene, rig, one, frames);
    std::string why = limit_broken(scene, pts, exempt, by_curve, frames, K_hi);
    if (why.empty()) why = turn_broken(one, frames, K_hi);
    return why;
  };
  // Each action alone first, then all together.
  for (size_t i = 0; i <= plan.actions.size(); ++i) {
    const bool all = i == plan.actions.size();
    if (all) accents_follow_limbs(plan);
    if (!all && plan.actions[i].primitive == Primitive::Spin) continue;
    const std::string what = all ? "the motion" : plan.actions[i].verb + " (" + primitive_name(plan.actions[i].primitive) + ")";
    // The largest scale (from the current one down by 0.8) at which `one` keeps the limits, and
    // why the first scale tried did not; -1 when none of kScaleAttempts does.
    auto search = [&](MotionPlan one, double start, std::string* first_why) {
      double scale = start;
      for (int attempt = 0; attempt <= kScaleAttempts; ++attempt, scale *= 0.8) {
        if (!all) one.actions[i].scale = scale;
        else one.scale = scale;
        const std::string why = broken(one);
        if (why.empty()) return scale;
        if (first_why->empty()) *first_why = why;
      }
      return -1.0;
    };
    MotionPlan one = all ? plan : alone({i});
    double& scale = all ? plan.scale : plan.actions[i].scale;
    std::string first_why;
    double best = search(one, scale, &first_why);
    // A back-and-forth action the canvas stops on one side (a raised hand at the top edge of an
    // emoji swinging out past it) swings to the other side only, at full size, rather than
    // shrinking both ways to nothing.
    if (!all && best < scale && oscillates(plan.actions[i]) && first_why == "would leave the canvas")
      for (int side : {1, -1}) {
        MotionPlan sided = one;
        sided.actions[i].one_sided = side;
        std::string why;
        const double s = search(sided, scale, &why);
        if (s > best * 1.05) {
          best = s;
          plan.actions[i].one_sided = side;
        }
      }
    if (best < 0) {
      scale *= std::pow(0.8, kScaleAttempts);
      plan.warnings.push_back(what + " " + first_why + " even at " + std::to_string(static_cast<int>(scale * 100)) + " % of its size");
      whole_failed = whole_failed || (!all && plan.actions[i].target == Target::Whole);
      continue;
    }
    if (!all && plan.actions[i].one_sided != 0)
      plan.notes.push_back(what + " swings to one side only: the other " + first_why);
    if (best < scale) {
      char line[240];
      std::snprintf(line, sizeof line, "%s scaled to %.0f %%: at full size %s %s", all ? "all amplitudes" : ("the amplitude of " + what).c_str(),
                    best * 100, all ? "the motion" : "it", first_why.c_str());
      plan.notes.push_back(line);
    }
    scale = best;
  }
  // The keyframes the fitter needs for the motion as scaled.
  const int need = keyframes_to_follow(scene, animate_plan(scene, rig, plan, frames), plan, exempt, frames, K, K_hi);
  plan.keyframes = need > 0 ? need : K_hi;
  if (plan.keyframes > K)
    plan.notes.push_back("the fitter takes " + std::to_string(plan.keyframes) + " keyframes instead of " + std::to_string(K) +
                         ": between " + std::to_string(K) + " the motion moves too far to follow");
  return whole_failed;
}

}  // namespace

void fit_plan(const Scene& scene, const Rig& rig, MotionPlan& plan, int frames, int keyframes) {
  const MotionPlan asked = plan;
  if (!fit_scales(scene, rig, plan, frames, keyframes)) return;
  // The whole figure cannot move in the canvas at all: small parts of it at the canvas's edge
  // (a splash running off the picture beside a surfer who fills it) hold it there. Those parts
  // hold, as the background does, and the rest moves; kept when it then fits.
  const double m = kFrameMargin * std::min(scene.width, scene.height);
  std::vector<int> edge;
  for (size_t i = 0; i < rig.parts.size(); ++i) {
    const RigPart& P = rig.parts[i];
    if (static_cast<int>(i) == rig.root || P.role == Role::Background || P.box.empty()) continue;
    if (P.box.x0 <= m || P.box.y0 <= m || P.box.x1 >= scene.width - m || P.box.y1 >= scene.height - m) edge.push_back(static_cast<int>(i));
  }
  edge = topmost(rig, edge);
  std::vector<int> held;
  for (int e : edge)
    if (chain_box(rig, e).area() <= kHeldMaxShare * rig.figure.area()) held.push_back(e);
  if (held.empty()) return;
  MotionPlan retry = asked;
  retry.held = held;
  if (fit_scales(scene, rig, retry, frames, keyframes)) return;
  std::vector<std::string> names;
  for (int h : held) names.push_back(rig.parts[h].name);
  retry.notes.push_back("the whole figure could not move inside the canvas: " + join(names, ", ") + " at its edge hold" +
                        (held.size() > 1 ? "" : "s") + " still");
  plan = retry;
}

nlohmann::json motion_report(const Scene& scene, const Rig& rig, const MotionPlan& plan) {
  using nlohmann::json;
  json parts = json::array();
  for (const auto& P : rig.parts) {
    json p = {{"name", P.name},
              {"group", P.group >= 0 && P.group < static_cast<int>(scene.groups.size()) ? scene.groups[P.group].id : ""},
              {"role", role_name(P.role)},
              {"named_in_document", P.named},
              {"side", P.side > 0 ? "right" : P.side < 0 ? "left" : "centre"},
              {"parent", P.parent >= 0 ? rig.parts[P.parent].name : ""},
              {"pivot", {std::round(P.pivot.x * 100) / 100, std::round(P.pivot.y * 100) / 100}},
              {"why", P.why}};
    p["box"] = {std::round(P.box.x0 * 10) / 10, std::round(P.box.y0 * 10) / 10, std::round(P.box.x1 * 10) / 10, std::round(P.box.y1 * 10) / 10};
    json ids = json::array();
    for (size_t pi = 0; pi < rig.part_of_path.size(); ++pi)
      if (&rig.parts[rig.part_of_path[pi] >= 0 ? rig.part_of_path[pi] : 0] == &P && rig.part_of_path[pi] >= 0) ids.push_back(scene.paths[pi].id);
    p["paths"] = ids;
    if (P.round) p["round"] = true;
    parts.push_back(p);
  }
  json actions = json::array();
  for (const auto& a : plan.actions) {
    json names = json::array(), pivots = json::array();
    for (int p : a.parts) {
      names.push_back(rig.parts[p].name);
      const Vec2 c = a.primitive == Primitive::Spin ? rig.parts[p].box.centre() : rig.parts[p].pivot;
      pivots.push_back({std::round(c.x * 100) / 100, std::round(c.y * 100) / 100});
    }
    const char* unit = unit_of(a.primitive);
    actions.push_back({{"verb", a.verb},
                       {"motion", primitive_name(a.primitive)},
                       {"target", target_name(a.target)},
                       {"parts", a.target == Target::Whole ? json("whole figure") : a.target == Target::Repeated ? json(std::to_string(rig.repeated.size()) + " repeated elements") : names},
                       {"pivots", pivots},
                       {"amplitude", std::round(plan.amplitude(a) * 1e4) / 1e4},
                       {"unit", unit},
                       {"cycles", a.cycles},
                       {"region", a.region == Region::None ? "" : a.region == Region::Sides ? "sides" : a.region == Region::Lower ? "lower part"
                                  : a.region == Region::Top ? "top" : "far end"},
                       {"one_sided", a.one_sided},
                       {"why", a.why}});
  }
  std::string root = rig.root >= 0 ? rig.parts[rig.root].name : "";
  json held = json::array();
  for (int h : plan.held) held.push_back(rig.parts[h].name);
  return {{"source", plan.source},
          {"held", held},
          {"root", root},
          {"parts", parts},
          {"repeated_elements", rig.repeated.size()},
          {"plan", actions},
          {"amplitude_scale", std::round(plan.scale * 1e4) / 1e4},
          {"keyframes", plan.keyframes},
          {"not_understood", plan.not_understood},
          {"readings", plan.readings},
          {"warnings", plan.warnings},
          {"notes", plan.notes}};
}

std::vector<PathMotion> path_motion(const Scene& scene, const std::vector<Vec2>& pts, int frames,
                                    std::vector<std::vector<Affine>>* body_maps) {
  std::vector<PathMotion> out(scene.paths.size());
  const size_t per = frames > 0 ? pts.size() / frames : 0;
  size_t i = 0;
  for (size_t p = 0; p < scene.paths.size(); ++p) {
    PathMotion& m = out[p];
    double sum = 0;
    for (const auto& sp : scene.paths[p].subpaths)
      for (const Vec2& rest : sp.points) {
        double far = 0;
        m.rest.add(rest);
        for (int f = 0; f < frames; ++f) {
          const Vec2 q = pts[f * per + i];
          far = std::max(far, std::hypot(q.x - rest.x, q.y - rest.y));
        }
        m.max_travel = std::max(m.max_travel, far);
        m.travel.push_back(static_cast<float>(far));
        sum += far;
        ++m.points;
        ++i;
      }
    m.mean_travel = m.points ? sum / m.points : 0;
  }
  // To a ten-thousandth of the canvas's diagonal: the rig's maps are exact in double, and a
  // bending region's points leave any one map by far more.
  RigidBodies rb = rigid_bodies(scene, pts, frames, 1e-4 * std::hypot(scene.width, scene.height));
  for (size_t p = 0; p < out.size(); ++p) out[p].body = rb.body[p];
  if (body_maps) *body_maps = std::move(rb.maps);
  // The box each path's curves sweep: every cubic at t = 0, 1/4, 1/2, 3/4, 1 in every frame
  // (the drawing, not its handles: a turning circle's handles sweep beyond the circle).
  for (int f = 0; f < frames; ++f) {
    size_t j = 0;
    for (size_t p = 0; p < scene.paths.size(); ++p)
      for (const auto& sp : scene.paths[p].subpaths) {
        const Vec2* c = &pts[f * per + j];
        for (size_t s = 0; s + 3 < sp.points.size(); s += 3)
          for (double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {
            const double u = 1 - t;
            out[p].swept.add(u * u * u * c[s] + 3 * u * u * t * c[s + 1] + 3 * u * t * t * c[s + 2] + t * t * t * c[s + 3]);
          }
        if (sp.points.size() < 4)
          for (size_t s = 0; s < sp.points.size(); ++s) out[p].swept.add(c[s]);
        j += sp.points.size();
      }
  }
  return out;
}

nlohmann::json body_maps_json(const std::vector<std::vector<Affine>>& maps) {
  auto r = [](double v) { return std::round(v * 1e6) / 1e6; };
  nlohmann::json a = nlohmann::json::array();
  for (const auto& body : maps) {
    nlohmann::json frames = nlohmann::json::array();
    for (const Affine& m : body) frames.push_back({r(m.a), r(m.b), r(m.c), r(m.d), r(m.e), r(m.f)});
    a.push_back(frames);
  }
  return a;
}

nlohmann::json path_motion_json(const Scene& scene, const std::vector<PathMotion>& motion) {
  auto r = [](double v) { return std::round(v * 100) / 100; };
  nlohmann::json a = nlohmann::json::array();
  for (size_t p = 0; p < motion.size(); ++p) {
    const PathMotion& m = motion[p];
    nlohmann::json pt = nlohmann::json::array();
    size_t k = 0;
    auto r1 = [](double v) { return std::round(v * 10) / 10; };
    for (const auto& sp : scene.paths[p].subpaths)
      for (const Vec2& q : sp.points) {
        pt.push_back(r1(q.x));
        pt.push_back(r1(q.y));
        pt.push_back(r1(k < m.travel.size() ? m.travel[k] : 0));
        ++k;
      }
    a.push_back({{"id", scene.paths[p].id},
                 {"point_travel", pt},
                 {"points", m.points},
                 {"max_travel", r(m.max_travel)},
                 {"mean_travel", r(m.mean_travel)},
                 {"body", m.body},
                 {"rest", {r(m.rest.x0), r(m.rest.y0), r(m.rest.x1), r(m.rest.y1)}},
                 {"swept", {r(m.swept.x0), r(m.swept.y0), r(m.swept.x1), r(m.swept.y1)}}});
  }
  return a;
}

}  // namespace svgm
