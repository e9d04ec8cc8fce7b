// The frames of a motion plan (animate_plan, motion_plan.h): each action's rigid motion or
// deformation of its parts at every frame, the bends of regions and of the silhouette's limbs,
// and what rides on spinning wheels.
#include "procedural/motion_plan.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "procedural/carried_shapes.h"
#include "procedural/detail_binding.h"
#include "procedural/figure_pieces.h"
#include "procedural/flame_lick.h"
#include "procedural/hang_support.h"
#include "procedural/motion_plan_internal.h"
#include "procedural/region_bend.h"
#include "procedural/rotor_blades.h"
#include "procedural/seat_support.h"
#include "procedural/support_band.h"
#include "procedural/sway_base.h"
#include "procedural/travel_profile.h"
#include "procedural/turn_agreement.h"
#include "geometry/rigid_bodies.h"
#include "procedural/wheel_riders.h"

namespace svgm {

namespace motion_plan_internal {

// The oscillation of a back-and-forth action at phase u (in cycles): about rest on both sides
// (sin), or, one-sided, out to one side and back (0 at rest, +-1 at the far end of the swing).
double oscillation(const PlannedAction& a, double u) {
  return a.one_sided == 0 ? std::sin(kTau * u) : a.one_sided * (0.5 - 0.5 * std::cos(kTau * u));
}

}  // namespace motion_plan_internal

using namespace motion_plan_internal;

namespace {

// The whole figure's motion `so_far` with `m`, the motion of its action `a`, added: after it,
// but a crawl's stretch (PlannedAction::inches) before it. The stretch is about the rear where it
// stands at rest, so it comes first, before the slide (and any other motion of the figure)
// carries it, whatever the plan's order; applied after the slide, it pivoted about the rest rear
// while the rear was elsewhere, and the planted ends slipped while the body gathered up.
Affine compose_whole(const Affine& so_far, const Affine& m, const PlannedAction& a) {
  return a.inches && a.primitive == Primitive::Stretch ? so_far * m : m * so_far;
}

// The motion of piece k (box `box`) of a figure moved apart (figure_pieces.h): the action's own,
// every other piece turning and drifting the other way and each a little shorter than the one
// before (to 3/4), so no two pieces move in step.
Affine piece_motion(const PlannedAction& a, double amp, size_t k, double t, const RigBox& box, const RigBox& figure, double W, double H) {
  if (!a.apart) return rigid(a, amp, whole_turn_sign(a), 0, t, figure, figure.centre(), W, H);  // all pieces as one
  PlannedAction one = a;
  const double sign = k % 2 ? -1 : 1;
  one.direction = static_cast<int>(sign) * a.direction;
  return rigid(one, amp * (1 - 0.125 * static_cast<double>(k % 3)), sign, 0, t, box, {box.centre().x, box.y1}, W, H);
}

// A figure in pieces moved apart (figure_pieces.h): each piece's box, for its own motion, and in
// `piece_of` each part's piece; none when no action moves the figure apart.
std::vector<RigBox> piece_boxes(const Rig& rig, const MotionPlan& plan, std::vector<int>& piece_of) {
  std::vector<RigBox> out;
  if (std::none_of(plan.actions.begin(), plan.actions.end(), [](const PlannedAction& a) { return a.apart; })) return out;
  piece_of = figure_pieces(rig);
  out.resize(static_cast<size_t>(std::max(0, piece_count(piece_of))));
  for (size_t g = 0; g < rig.parts.size(); ++g)
    if (piece_of[g] >= 0) out[piece_of[g]].add(rig.parts[g].box);
  return out;
}

// The whole figure turning round to go (PlannedAction::turns_round) at t, with its travel: the
// outermost motion of the whole figure and of each of its pieces (made once a frame), so its bob,
// rock and bounce are its own, mirrored with it.
void turn_round(const MotionPlan& plan, const Rig& rig, double t, Affine& whole, std::vector<Affine>& whole_of) {
  const double W = std::max(rig.figure.w(), 1e-9), H = std::max(rig.figure.h(), 1e-9);
  Affine m;
  for (const PlannedAction& a : plan.actions)
    if (a.parts.empty() && a.turns_round) m = rigid(a, plan.amplitude(a), 1, 0, t, rig.figure, rig.figure.centre(), W, H) * m;
  whole = m * whole;
  for (Affine& w : whole_of) w = m * w;
}

// A rolling wheel's turn at t (PlannedAction::rolls), in degrees: the distance the figure's
// slide of the same words has gone, over the wheel's radius (rolling without slipping; going
// right turns it clockwise on the screen, and back again on the way back). Whole turns at a
// steady rate kept turning forwards while the car slid back. `radius`: the rolling radius of
// the wheel the part belongs to (rolling_radius).
double rolled_deg(const MotionPlan& plan, const PlannedAction& spin, double t, double radius, const RigBox& figure, double W,
                  double H) {
  for (const PlannedAction& b : plan.actions)
    if (b.primitive == Primitive::Slide && b.parts.empty() && b.verb == spin.verb && b.words == spin.words) {
      // (Turned round, the slide's map holds the mirror too: its travel alone.)
      const double x = b.turns_round ? 2 * b.direction * plan.amplitude(b) * W * turned_going_at(b.cycles * t).along
                                     : rigid(b, plan.amplitude(b), 1, 0, t, figure, figure.centre(), W, H).e;
      // Turned round (mirrored), the wheel's own turn shows mirrored: it turns the other way in
      // its own frame to roll the way the figure goes on the screen, and eases from one to the
      // other while the figure turns (a turn in place rolls its wheels), so no frame jumps.
      const double own = b.turns_round ? std::cos(kTau * turned_going_at(b.cycles * t).turns) : 1;
      return own * x / std::max(radius, 1e-9) * (180 / M_PI);
    }
  return 0;
}

// The radius a spun part rolls on: that of the widest part of the same spin about the same
// centre (within kConcentric of its width). A wheel's pieces (tyre, rim, hub, the lugs on the
// tyre) turn as one: each turned by the distance over its own radius, a tractor's rim turned
// faster than its tyre and its lugs were scrambled.
double rolling_radius(const Rig& rig, const PlannedAction& spin, int part) {
  const RigBox& b = rig.parts[part].box;
  double r = 0.5 * std::max(b.w(), b.h());
  for (int q : spin.parts) {
    const RigBox& o = rig.parts[q].box;
    const double ro = 0.5 * std::max(o.w(), o.h());
    const Vec2 d = o.centre() - b.centre();
    if (ro > r && std::hypot(d.x, d.y) <= kConcentric * 2 * ro) r = ro;
  }
  return r;
}

// Whether `a`, a motion of the whole figure, is the body's bounce or jitter on its wheels: a Bob
// or Shake of words that also spin wheels (a car driving, idling). The wheels stay on the ground
// and keep their centres; the body rides over them. Shaken with the body, a car's wheels hopped
// off the road with every jolt.
bool bounces_on_wheels(const MotionPlan& plan, const PlannedAction& a) {
  if (!a.parts.empty() || (a.primitive != Primitive::Bob && a.primitive != Primitive::Shake)) return false;
  for (const PlannedAction& s : plan.actions)
    if (s.primitive == Primitive::Spin && s.target == Target::Wheels && !s.parts.empty() && s.words == a.words) return true;
  return false;
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
  } else if (a.primitive == Primitive::Bend && a.anchored != 0) {
    // Held at one side (a stalk at its root, a banner at its pole): it bends from there, each
    // point displaced across the figure by the square of its distance from the held side (a
    // cantilever's curve), the far side as far as tan(angle) of the figure's length.
    // A plant rooted in a pot bends from the pot's mouth (sway_base.h); the pot holds.
    const bool across_x = a.anchored <= 2;
    const double len = std::max(across_x ? box.w() : a.rooted ? a.root.y - box.y0 : box.h(), 1e-9);
    const double f = across_x ? (q.x - box.x0) / len : (q.y - box.y0) / len;
    const double v = a.anchored % 2 == 1 ? f : a.rooted ? std::max(1 - f, 0.0) : 1 - f;
    const double e = std::tan(amp * M_PI / 180) * len * v * v * oscillation(a, a.cycles * t) * a.direction;
    return across_x ? Vec2{q.x, q.y + e} : Vec2{q.x + e, q.y};
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

}  // namespace

// The turn a region bend gives point q at t (motion_plan_internal.h).
RegionTurn motion_plan_internal::region_turn(const PlannedAction& a, double amp, double t, const RigBox& box, Vec2 q, int path) {
  const double W = std::max(box.w(), 1e-9), H = std::max(box.h(), 1e-9);
  const Vec2 c = box.centre();
  auto wave = [&](double phase) { return oscillation(a, a.cycles * t + phase); };
  // Limbs drawn in the part's outline, or read from its silhouette's skeleton: each bends about
  // the middle of its base, the turn growing from nothing at the base over half its width (the
  // outline stays in one piece).
  if (!a.lobes.empty()) {
    const int own = owner_lobe(a.lobes, path);
    for (const ArmLobe& l : a.lobes) {
      if ((a.region_side != 0 && l.side != a.region_side) || (own >= 0 && &l != &a.lobes[own])) continue;
      // A rigid part (one lobe, its own paths only: region_use) turns whole, every point of it.
      const double depth = own >= 0 ? lobe_owned_depth(l, q) : lobe_depth(l, q);
      if (depth <= 0 && !l.rigid) continue;
      // A located part that grows (petals opening, petal_rosette.h): its points spread from the
      // lobe's centre, as a pulse scales a part about its middle.
      if (a.primitive == Primitive::Pulse) return {l.pivot, 0, 1, amp * (0.5 - 0.5 * std::cos(kTau * a.cycles * t)), true};
      // A rotor's blades (rotor_blades.h): face on they turn whole about the hub, edge on their
      // length along their line follows |cos| of the turn (two blades in line: twice a turn).
      if (a.primitive == Primitive::Spin) return {l.pivot, 360.0 * amp * a.direction * t, 1};
      if (a.primitive == Primitive::Stretch) return {l.pivot, 0, 1, std::max(kEdgeOnMin, 1 - amp * (1 - std::fabs(std::cos(kTau * a.cycles * t)))) - 1, true};
      const double base = std::hypot(l.base1.x - l.base0.x, l.base1.y - l.base0.y);
      const double w = l.rigid ? 1 : smoothstep(depth / std::max(kLobeRamp * base, 1e-9));
      return {l.pivot, amp * (l.side < 0 ? 1 : -1) * wave(a.alternating && l.side > 0 ? 0.5 : 0), w};
    }
    return {};
  }
  switch (a.region) {
    case Region::Sides: {
      const double dx = q.x - c.x;
      const int side = dx < 0 ? -1 : 1;  // as the viewer sees it
      const double core = a.core_left > 0 ? (side < 0 ? a.core_left : a.core_right) : kCore * W;
      if (std::fabs(dx) <= core) return {};
      if (a.region_side != 0 && side != a.region_side) return {};
      const double w = smoothstep((std::fabs(dx) - core) / (kRamp * W));
      // Mirrored: both sides rise together; alternating: half a cycle apart.
      return {{c.x + side * core, c.y}, amp * (side < 0 ? 1 : -1) * wave(a.alternating && side > 0 ? 0.5 : 0), w};
    }
    case Region::Lower: {
      const double hip = box.y0 + kHip * H;
      if (q.y <= hip) return {};
      const int side = q.x < c.x ? -1 : 1;
      if (a.region_side != 0 && side != a.region_side) return {};
      const double w = smoothstep((q.y - hip) / (kRamp * H));
      return {{c.x + side * kCore * W, hip}, amp * wave(a.alternating && side > 0 ? 0.5 : 0) * (a.alternating ? 1 : (side < 0 ? 1 : -1)), w};
    }
    case Region::Top: {
      const double neck = box.y0 + kNeck * H;
      if (q.y >= neck) return {};
      return {{c.x, neck}, amp * wave(0), smoothstep((neck - q.y) / (kRamp * H))};
    }
    case Region::End: {
      const double start = a.direction > 0 ? box.x1 - kTailStart * W : box.x0 + kTailStart * W;
      const double beyond = a.direction * (q.x - start);
      if (beyond <= 0) return {};
      return {{start, c.y}, amp * wave(0), smoothstep(beyond / (kRamp * W))};
    }
    case Region::None: case Region::Located: break;
  }
  return {};
}

Vec2 motion_plan_internal::bend_region(const PlannedAction& a, double amp, double t, const RigBox& box, Vec2 q, int path) {
  // A blaze's tongues lick (flame_lick.h): not a turn about a pivot.
  for (const ArmLobe& l : a.lobes)
    if (l.kind == LobeKind::Blaze) return flame_lick(l, a, amp, t, q);
  const RegionTurn r = region_turn(a, amp, t, box, q, path);
  // A portrait's head nodding or shaking (head_turn.h): out of the picture's plane, not about the pivot in it.
  if (a.head_axis != HeadAxis::Plane && a.lobes.size() == 1) {
    if (r.weight <= 0) return q;
    RigBox head;
    for (Vec2 p : a.lobes[0].outline) head.add(p);
    const double degrees = amp * oscillation(a, a.cycles * t) * (a.head_axis == HeadAxis::Yaw ? a.direction : 1);
    HeadPath own;  // a point of no path of the head's (a part carried by it): the outline's
    if (auto it = std::lower_bound(a.lobe_paths.begin(), a.lobe_paths.end(), path); it != a.lobe_paths.end() && *it == path)
      if (static_cast<size_t>(it - a.lobe_paths.begin()) < a.head_paths.size()) own = a.head_paths[static_cast<size_t>(it - a.lobe_paths.begin())];
    return head_turn_point(head, a.lobes[0].pivot, a.head_axis, degrees, own, q);
  }
  if (r.pulse && a.primitive == Primitive::Stretch) {
    // Along the blade's line only (the lobe's pivot to its tip).
    for (const ArmLobe& l : a.lobes)
      if (l.pivot.x == r.pivot.x && l.pivot.y == r.pivot.y) {
        const Vec2 u = (1 / std::max(std::hypot(l.tip.x - l.pivot.x, l.tip.y - l.pivot.y), 1e-9)) * (l.tip - l.pivot), d = q - r.pivot;
        return q + (r.grow * (d.x * u.x + d.y * u.y)) * u;
      }
  }
  if (r.pulse) return r.pivot + (1 + r.grow) * (q - r.pivot);
  return r.weight > 0 ? rotate_about(q, r.pivot, r.angle * r.weight) : q;
}

namespace {

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
int motion_plan_internal::spin_symmetry(const Rig& rig, const std::vector<int>& parts) {
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

namespace {

// The motion of repeated element `e` (box `eb`) at time t: its falls and twinkles, one phase
// per element, so no two drops fall in step.
Affine element_motion(const Scene& scene, const MotionPlan& plan, int e, const RigBox& eb, double t, double W, double H) {
  const double CH = scene.height;
  Affine elem;
  for (const auto& a : plan.actions) {
    if (a.target != Target::Repeated) continue;
    const double phase = std::fmod(e * kPhaseSpacing + a.direction * 0.137, 1.0) + 1.0;
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
  return elem;
}

// Each part's transform at one frame: its parents' carried down the rig, the root's own turn
// kept off what stands on the ground, the head upright, and what rides on spinning wheels.
std::vector<Affine> world_transforms(const Rig& rig, const std::vector<Affine>& local, const Affine& root_turn,
                                     const std::vector<Affine>& spin, const std::vector<char>& planted, const WheelLoads& loads) {
  const int G = static_cast<int>(rig.parts.size());
  std::vector<Affine> world(G);
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
  return world;
}

// Per path: the plan moves it apart from the figure as a whole (detail_binding.h's `moves`): a
// located part's or a silhouette limb's own paths, or the paths of a part an action names and of
// what hangs from it. Whole-figure motions and a silhouette's bends of every path move nothing
// apart: they move every point by where it is.
std::vector<char> moved_apart(const Scene& scene, const Rig& rig, const MotionPlan& plan) {
  std::vector<char> moves(scene.paths.size(), 0);
  for (const auto& a : plan.actions) {
    if (a.target == Target::Repeated || a.parts.empty() || a.primitive == Primitive::Spin) continue;
    if (a.silhouette) {
      for (int p : a.lobe_paths) moves[static_cast<size_t>(p)] = 1;
      continue;
    }
    for (size_t pi = 0; pi < scene.paths.size() && pi < rig.part_of_path.size(); ++pi)
      for (int p : a.parts)
        if (rig.part_of_path[pi] >= 0 && part_under(rig, rig.part_of_path[pi], p)) moves[pi] = 1;
  }
  return moves;
}

// What each path's points ride on (detail_binding.h), but what a located part's finder says holds
// rides on none of it: the heart drawn over the lower half of a blaze took the blaze's bend as
// line art on its fill (twemoji 2764-fe0f-200d-1f525).
std::vector<std::vector<int>> hosts_of(const Scene& scene, const Rig& rig, const MotionPlan& plan, const std::vector<char>& fixed) {
  std::vector<std::vector<int>> rides_on = bind_to_hosts(scene, rig, moved_apart(scene, rig, plan), fixed);
  for (const PlannedAction& a : plan.actions)
    for (int p : a.held_paths) rides_on[static_cast<size_t>(p)].clear();
  return rides_on;
}

// How region action `a` moves the points of path `src` (of part `by`; `bg`: it stays): 1 bent
// with the region, 2 carried by the bend (carried_by_bend), 0 not at all. The part's own
// outlines and what hangs from it within its width and not below it (a hand at the end of a
// sleeve, also one raised above the sleeve's box) bend; what hangs below (legs under a waving
// torso) keeps its shape and follows the rig. A wheel (and what turns with it) keeps to its
// own frame: a pedalling leg's bend bent a sketched bicycle's wheels with it. Limbs of the
// whole silhouette: whatever lies in them bends with them (the outline drawn over a tail's
// fill), whichever part it belongs to.
int region_use(const Rig& rig, const PlannedAction& a, size_t src, int by, bool bg, const std::vector<char>& spinning,
               const WheelLoads& loads) {
  if (by >= 0 && by != a.parts[0] && (spinning[by] || loads.turns_with[by] >= 0)) return 0;
  const RigBox& hb = rig.parts[a.parts[0]].box;
  const Vec2 gc = by >= 0 ? rig.parts[by].box.centre() : Vec2{};
  if (a.silhouette)
    return !bg && (a.lobe_paths.empty() || std::binary_search(a.lobe_paths.begin(), a.lobe_paths.end(), static_cast<int>(src))) ? 1 : 0;
  const bool hangs = by >= 0 && part_under(rig, by, a.parts[0]);
  if (by == a.parts[0] || (hangs && gc.x >= hb.x0 && gc.x <= hb.x1 && gc.y <= hb.y1)) return 1;
  if (hangs && (gc.y <= hb.y1 || std::fabs(gc.x - hb.centre().x) > 0.25 * hb.w())) return 2;
  return 0;
}

// Each region action's mesh of the paths it bends (region_bend.h; null: the closed form), and
// `folds` sized for them.
template <class Stays>
std::vector<std::unique_ptr<RegionBend>> region_meshes(const Scene& scene, const Rig& rig, const MotionPlan& plan,
                                                       const std::vector<char>& spinning, const WheelLoads& loads, const Stays& stays,
                                                       std::vector<BendFold>* folds) {
  std::vector<std::unique_ptr<RegionBend>> mesh(plan.actions.size());
  for (size_t i = 0; i < plan.actions.size(); ++i) {
    const PlannedAction& a = plan.actions[i];
    if (a.region == Region::None || a.closed_form || a.target == Target::Repeated || a.parts.empty() || plan.amplitude(a) == 0)
      continue;
    // Rigid lobes turn in closed form: a rotation folds nothing.
    if (!a.lobes.empty() && std::all_of(a.lobes.begin(), a.lobes.end(), [](const ArmLobe& l) { return l.rigid; })) continue;
    std::vector<int> bent;
    for (size_t pi = 0; pi < scene.paths.size(); ++pi)
      if (region_use(rig, a, pi, rig.part_of_path[pi], stays(pi), spinning, loads) == 1) bent.push_back(static_cast<int>(pi));
    mesh[i] = std::make_unique<RegionBend>(scene, bent, a, rig.parts[a.parts[0]].box);
    if (mesh[i]->empty()) mesh[i].reset();
  }
  if (folds) {
    folds->assign(plan.actions.size(), BendFold{});
    for (size_t i = 0; i < mesh.size(); ++i) (*folds)[i].meshed = mesh[i] != nullptr;
  }
  return mesh;
}

// Per path, the diagonal of the part whose region bend moves it point by point (0: none does;
// carried_shapes.h).
template <class Stays>
std::vector<double> bend_sizes(const Scene& scene, const Rig& rig, const MotionPlan& plan, const std::vector<char>& spinning,
                               const WheelLoads& loads, const Stays& stays) {
  std::vector<double> size(scene.paths.size(), 0);
  for (const PlannedAction& a : plan.actions) {
    if (a.region == Region::None || a.target == Target::Repeated || a.parts.empty() || plan.amplitude(a) == 0) continue;
    if (!a.lobes.empty() && (a.primitive == Primitive::Spin || a.primitive == Primitive::Stretch)) continue;  // a rotor's own motion, whole
    const RigBox& hb = rig.parts[a.parts[0]].box;
    for (size_t pi = 0; pi < scene.paths.size(); ++pi)
      if (region_use(rig, a, pi, rig.part_of_path[pi], stays(pi), spinning, loads) == 1)
        size[pi] = std::max(size[pi], std::hypot(hb.w(), hb.h()));
  }
  return size;
}

// The region meshes at frame f (time t), their folds noted in `folds`.
std::vector<std::vector<Vec2>> solve_meshes(const std::vector<std::unique_ptr<RegionBend>>& mesh, const MotionPlan& plan, double t, int f,
                                            std::vector<BendFold>* folds) {
  std::vector<std::vector<Vec2>> bent(mesh.size());
  for (size_t i = 0; i < mesh.size(); ++i) {
    if (!mesh[i]) continue;
    bent[i] = mesh[i]->solve(plan.amplitude(plan.actions[i]), t);
    if (!folds) continue;
    const MeshQuality mq = mesh[i]->quality(bent[i]);
    BendFold& fd = (*folds)[i];
    if (mq.flipped > fd.flipped || (fd.flipped == 0 && mq.flipped == 0 && mq.min_area_ratio < fd.min_area_ratio)) fd.frame = f;
    fd.flipped = std::max(fd.flipped, mq.flipped);
    fd.min_area_ratio = std::min(fd.min_area_ratio, mq.min_area_ratio);
  }
  return bent;
}

// The tossed things' shifts at t: they fly apart from the rig's motions (tossed_things.h).
TossFrame toss_frame(const Scene& scene, const MotionPlan& plan, double t) {
  TossFrame toss = still_toss_frame(scene);
  for (const auto& a : plan.actions)
    if (a.primitive == Primitive::Toss) add_toss(a.tossed, a.arc, plan.amplitude(a), a.cycles * t, toss);
  return toss;
}

// Repeated elements: in `element_of`, per subpath of each path, the element it belongs to (an
// element may be some of the subpaths of one path), -1 for none; returns each element's box.
std::vector<RigBox> element_subpaths(const Scene& scene, const Rig& rig, std::vector<std::vector<int>>& element_of) {
  element_of.assign(scene.paths.size(), {});
  for (size_t pi = 0; pi < scene.paths.size(); ++pi) element_of[pi].assign(scene.paths[pi].subpaths.size(), -1);
  std::vector<RigBox> element_box(rig.repeated.size());
  for (size_t e = 0; e < rig.repeated.size(); ++e)
    for (const ElementPiece& piece : rig.repeated[e]) {
      const auto& subs = scene.paths[piece.path].subpaths;
      for (size_t si = 0; si < subs.size(); ++si) {
        if (piece.subpath >= 0 && static_cast<int>(si) != piece.subpath) continue;
        element_of[piece.path][si] = static_cast<int>(e);
        for (const Vec2& q : subs[si].points) element_box[e].add(q);
      }
    }
  return element_box;
}

// The parts a spin turns as themselves (a rotor's spin of a region turns its blades, not its part).
std::vector<char> spinning_parts(const MotionPlan& plan, int G) {
  std::vector<char> spinning(G, 0);
  for (const auto& a : plan.actions)
    if (a.primitive == Primitive::Spin && a.region == Region::None)
      for (int p : a.parts) spinning[p] = 1;
  return spinning;
}

}  // namespace

std::vector<Vec2> animate_plan(const Scene& scene, const Rig& rig, const MotionPlan& plan, int frames, std::vector<BendFold>* folds) {
  const int G = static_cast<int>(rig.parts.size());
  const double W = std::max(rig.figure.w(), 1e-9), H = std::max(rig.figure.h(), 1e-9);
  auto under = [&](int p, int a) { return part_under(rig, p, a); };
  // Repeated elements: which element each subpath belongs to; and whether they fly free.
  std::vector<std::vector<int>> element_of;
  const std::vector<RigBox> element_box = element_subpaths(scene, rig, element_of);
  const bool particles = std::any_of(plan.actions.begin(), plan.actions.end(), [](const auto& a) { return a.target == Target::Repeated && a.primitive == Primitive::Fall; });
  // Each part's box including what hangs from it (the extent a deformation spans).
  std::vector<RigBox> reach(G);
  for (int g = 0; g < G; ++g) reach[g] = chain_box(rig, g);
  // Parts the whole figure's motions leave where they are (fit_plan).
  std::vector<char> held(G, 0);
  for (int g = 0; g < G; ++g) held[g] = std::any_of(plan.held.begin(), plan.held.end(), [&](int h) { return under(g, h); });
  // The pole a wave runs from holds still (the wave's weight is small but not nothing across
  // its width: a flag's pole moved 0.8 px and the fitted one drifted out of the canvas).
  for (const auto& a : plan.actions)
    if ((a.primitive == Primitive::Undulate || a.primitive == Primitive::Bend) && a.anchored != 0)
      for (int p : pole_parts(rig, a.anchored, true)) held[p] = 1;
  // The ground the prompt says the figure moves on stays, or what it hangs from (support_band.h, hang_support.h).
  const HangSupport hang = plan.hang.empty() ? HangSupport{} : hang_support(scene, rig);
  const std::vector<char> ground = plan.ground.empty() ? hang.paths : support_paths(scene, rig, plan.ground);
  // What it sits in or on, when no ground band holds (seat_support.h): motions in place move the
  // sitter about its own box and leave the seat; what goes carries the seat too (`carried`).
  const SeatSupport seat = plan.seat.empty() || std::count(ground.begin(), ground.end(), 1) ? SeatSupport{} : seat_support(scene, rig);
  const RigBox& mover = seat.found ? seat.sitter : rig.figure;
  // Chains hanging from the root that reach the lowest kPlanted of the figure stand on the
  // ground (legs, feet): the root's own swing does not carry them.
  std::vector<char> planted(G, 0);
  for (int g = 0; g < G; ++g)
    planted[g] = rig.parts[g].parent == rig.root && rig.root >= 0 && !reach[g].empty() && reach[g].y1 >= rig.figure.y1 - kPlanted * rig.figure.h();
  std::vector<int> piece_of;
  const std::vector<RigBox> piece_box = piece_boxes(rig, plan, piece_of);
  const std::vector<char> spinning = spinning_parts(plan, G);
  const WheelLoads loads = wheel_loads(rig, spinning);
  // Line art moves as the fill it is drawn on, and a still fill as the moving line tracing it
  // (detail_binding.h): every motion below is applied to a point as its host path's. Parts
  // turning their own way (a wheel, what turns with it or rides on it) keep to themselves.
  std::vector<char> fixed(G, 0);
  for (int g = 0; g < G; ++g) fixed[g] = spinning[g] || loads.turns_with[g] >= 0 || loads.rides[g] >= 0;
  const std::vector<std::vector<int>> rides_on = seat_apart(seat, hosts_of(scene, rig, plan, fixed));

  // Whether path p stays where it is under the whole figure's motions: a background, a held part's, the ground's.
  auto stays = [&](size_t p) {
    const int g = rig.part_of_path[p];
    return (g >= 0 && (rig.parts[g].role == Role::Background || held[g])) || (p < ground.size() && ground[p]);
  };
  const std::vector<std::unique_ptr<RegionBend>> mesh = region_meshes(scene, rig, plan, spinning, loads, stays, folds);
  const std::vector<std::vector<size_t>> carried = carried_shapes(scene, bend_sizes(scene, rig, plan, spinning, loads, stays), rides_on);

  std::vector<Vec2> out;
  out.reserve(static_cast<size_t>(frames) * (scene.segment_count() * 3 + scene.paths.size() * 2));
  for (int f = 0; f < frames; ++f) {
    const double t = frames > 1 ? static_cast<double>(f) / (frames - 1) : 0;
    std::vector<Affine> local(G), spin(G);
    std::vector<char> spins(G, 0);
    Affine whole, root_turn, over_wheels, carried;
    std::vector<Affine> whole_of(piece_box.size());  // the whole figure's motion, per piece
    for (const auto& a : plan.actions) {
      const double amp = plan.amplitude(a);
      if (is_deformation(a) || a.target == Target::Repeated || a.primitive == Primitive::Toss) continue;
      if (a.parts.empty() && bounces_on_wheels(plan, a)) over_wheels = rigid(a, amp, 1, 0, t, rig.figure, rig.figure.centre(), W, H) * over_wheels;
      else if (a.parts.empty() && a.primitive == Primitive::Turn) {
        // Whole turns, never fewer; the plan's scale makes the turn shallower (turn_width).
        PlannedAction shallower = a;
        shallower.scale = a.scale * plan.scale;
        whole = rigid(shallower, amp, 1, 0, t, rig.figure, rig.figure.centre(), W, H) * whole;
        carried = rigid(shallower, amp, 1, 0, t, rig.figure, rig.figure.centre(), W, H) * carried;
      } else if (a.parts.empty() && !a.turns_round) {  // (turning round: turn_round, after)
        const bool swings = hang.found && a.primitive == Primitive::Rock;  // (hang_support.h)
        // (A rock goes its direction first, as a sway and a pendulum do: turn_agreement.h.)
        const Affine m = swings ? pendulum(a, amp, t, hang.grip) : rigid(a, amp, whole_turn_sign(a), 0, t, mover, mover.centre(), W, H);
        whole = compose_whole(whole, m, a);
        if (seat_goes(a)) carried = compose_whole(carried, m, a);
        for (size_t k = 0; k < whole_of.size(); ++k) whole_of[k] = compose_whole(whole_of[k], swings ? pendulum(a, amp, t, hang.grip) : piece_motion(a, amp, k, t, piece_box[k], rig.figure, W, H), a);
      }
      for (size_t i = 0; i < a.parts.size(); ++i) {
        const RigPart& P = rig.parts[a.parts[i]];
        Affine& into = a.primitive == Primitive::Spin ? spin[a.parts[i]]
                       : a.parts[i] == rig.root && a.primitive == Primitive::Swing ? root_turn : local[a.parts[i]];
        if (a.rolls) {
          const Vec2 c = P.box.centre();
          into = Affine::translate(c.x, c.y) * P.wheel_plane * Affine::rotate_deg(rolled_deg(plan, a, t, rolling_radius(rig, a, a.parts[i]), rig.figure, W, H)) *
                 P.wheel_plane.inverse() * Affine::translate(-c.x, -c.y) * into;
        } else
          into = rigid(a, amp, a.sign[i], a.phase[i], t, P.box, P.pivot, W, H, P.wheel_plane) * into;
        if (a.primitive == Primitive::Spin) spins[a.parts[i]] = 1;
      }
    }
    turn_round(plan, rig, t, whole, whole_of);
    std::vector<Affine> none;
    turn_round(plan, rig, t, carried, none);
    const std::vector<Affine> world = world_transforms(rig, local, root_turn, spin, planted, loads);
    const std::vector<std::vector<Vec2>> bent = solve_meshes(mesh, plan, t, f, folds);
    const TossFrame toss = toss_frame(scene, plan, t);
    for (size_t pi = 0; pi < scene.paths.size(); ++pi) {
      const bool background = stays(pi);
      size_t point = 0;  // the path's control point, counted over its subpaths (rides_on)
      for (size_t si = 0; si < scene.paths[pi].subpaths.size(); ++si) {
        const int e = element_of[pi][si];
        const bool free_particle = particles && e >= 0;
        // The element's own motion (falls, twinkles), one phase per element.
        const Affine elem = e >= 0 ? element_motion(scene, plan, e, element_box[e], t, W, H) : Affine();
        for (Vec2 q : scene.paths[pi].subpaths[si].points) {
          // The path whose motion the point takes: its own, or the one it is drawn on.
          const int rides = rides_on[pi].empty() ? -1 : rides_on[pi][point];
          const size_t src = rides >= 0 ? static_cast<size_t>(rides) : pi;
          const int by = rig.part_of_path[src];
          const bool bg = src == pi ? background : stays(src);
          const bool sat = seat.found && seat.seat[src];  // on the seat: only what goes moves it
          if (toss.on[pi][si] && (out.push_back(whole.apply(q + toss.shift[pi][si])), ++point)) continue;
          q = elem.apply(q);
          if (!free_particle) {
            for (size_t ai = 0; ai < plan.actions.size(); ++ai) {
              const PlannedAction& a = plan.actions[ai];
              if (!is_deformation(a)) continue;
              const double amp = plan.amplitude(a);
              if (a.region != Region::None) {
                const int use = region_use(rig, a, src, by, bg, spinning, loads);
                const RigBox& hb = rig.parts[a.parts[0]].box;
                // A head's feature turns as itself, not as the face it is drawn on (head_turn.h).
                if (use == 1) q = mesh[ai] ? mesh[ai]->apply(bent[ai], q) : bend_region(a, amp, t, hb, q, static_cast<int>(a.head_axis != HeadAxis::Plane ? pi : src));
                else if (use == 2)
                  q = mesh[ai] ? mesh[ai]->carry(bent[ai], rig.parts[by].pivot, q) : carried_by_bend(a, amp, t, hb, rig.parts[by].pivot, q);
              } else if (a.parts.empty()) {
                if (!bg && !sat && a.primitive == Primitive::Sway) q = hang.found ? pendulum(a, amp, t, hang.grip).apply(q) : sway_lean(a, amp, t, mover, q);
                else if (!bg && !sat) q = deform(a, amp, t, mover, q);
              } else {
                for (int p : a.parts)
                  if (by >= 0 && under(by, p)) q = deform(a, amp, t, reach[p], q);
              }
            }
            // A point on a fill that holds still (a pole, the ground) holds still with it.
            if (!(src != pi && by >= 0 && held[by])) {
              if (by >= 0) q = world[by].apply(q);
              if (!bg && !(by >= 0 && fixed[by])) q = over_wheels.apply(q);
              if (!bg) q = (sat ? carried : by >= 0 && !whole_of.empty() && piece_of[by] >= 0 ? whole_of[piece_of[by]] : whole).apply(q);
            }
          }
          ++point;
          out.push_back(q);
        }
      }
    }
  }
  keep_carried_rigid(scene, carried, frames, out);
  return out;
}

}  // namespace svgm
