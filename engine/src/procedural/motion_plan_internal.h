// What the files of the motion plan share (motion_plan.cpp plans, motion_frames.cpp draws the
// frames, motion_fit.cpp keeps them inside the canvas and visible, motion_report.cpp writes
// motion.json): the plan's constants and the helpers more than one of them calls. Not part of
// the engine's interface: include it only from those files.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "procedural/motion_plan.h"
#include "procedural/part_locator.h"
#include "rank/pixel_ranker.h"

namespace svgm::motion_plan_internal {

inline constexpr double kTau = 2 * M_PI;
// Golden-ratio spacing of the phases of repeated elements: no two drops fall in step.
inline constexpr double kPhaseSpacing = 0.6180339887498949;
// A prompt with no motion word: the figure's top leans this many degrees (a Sway), once.
inline constexpr double kFallbackSwayDeg = 6;
// fit_plan: a point in the canvas margin at rest may come this close to the edge (share of the
// margin); and it gives up after this many steps of 0.8 (7 % of the size).
inline constexpr double kMarginUse = 0.9;
inline constexpr int kScaleAttempts = 12;
// A region bend is made smaller until its mesh stops folding down to this share of its size;
// below it the fold is taken for parts overlapping, and the bend keeps its size in closed form.
inline constexpr double kMinUnfoldScale = 0.5;
// fit_plan: a clause whose largest motion is under this share of the figure's diagonal is
// raised to it (a viewer must see the motion the prompt asked for; the pixel ranker calls a video
// where under 0.5 % of the foreground changes 'no motion'), by at most kMaxBoost, and no turn
// of it (a swing, rock, sway or bend, in degrees) raised past kMaxRaisedTurn, a quarter turn
// each way (past it a swinging part turns upside down): the canvas and the fitter's steps scale
// it back afterwards. At 4 times a tiger's lashing tail (a bend of 4.5 degrees, 0.7 % of its
// size) and an alarm clock's shake (1 %) stayed at 2.8 and 4 %, too little to see; at 60
// degrees a whale's spout (75 degrees to reach the floor) stayed at 6.6 %.
inline constexpr double kVisibleTravel = 0.08;  // of the figure's diagonal (the floor)
// A flight that carries the whole figure (carried_flight.h: a hover's bob, a buzz's dart) is a
// light thing going about in the air: its body's motion is the motion, and at the floor a
// hovering helicopter's bob and a ladybug's dart (8.6 % of its size) read as a nudge, not as
// flight. Raised to this instead; the canvas scales it back (to the room it leaves, as a travel:
// motion_fit.cpp).
inline constexpr double kCarriedTravel = 0.14;
inline constexpr double kMaxBoost = 12;
inline constexpr double kMaxRaisedTurn = 90;  // degrees
// The raise is measured again up to this many times (a swing's chord grows slower than its
// angle), aiming this share over the floor: motion.json rounds travels to 0.1 px, 0.9 % of the
// floor on a 72 px emoji, and a clause raised to exactly 8 % read as 7.9 there; the travel is
// read at the fitter's keyframes, between which a bob's peak may fall (a hovering saucer
// raised to 8.1 % read as 7.7).
inline constexpr int kRaiseRounds = 4;
inline constexpr double kRaiseAim = 1.08;
// region_host: a part carries the arms when its middle is above this share of the figure's
// height, it is at least this share of the figure tall, and this much wider than the root.
inline constexpr double kArmHostTop = 0.6;
inline constexpr double kArmHostMinHeight = 0.2;
inline constexpr double kArmHostWider = 1.15;
// Wheels: round parts at least this share of the widest one's width; and parts whose centre is
// within this share of a wheel's width from its centre turn with it.
inline constexpr double kWheelShare = 0.5;
inline constexpr double kConcentric = 0.1;
// A round part at least kSmallWheelShare of the widest wheel's width whose bottom is within
// kWheelGround of that width of the lowest large wheel's bottom stands on the same ground: a
// wheel (a tractor's front wheel is 0.45 of its back one).
inline constexpr double kSmallWheelShare = 0.25, kWheelGround = 0.1;
// A part hanging from a spinning part turns with it when this share of its box is inside (a
// stand reaching into the wheel's box is not carried).
inline constexpr double kSpinInsideShare = 0.9;
// A Sides bend's still core, each side, in shares of the bending part's width (side_core): at
// least the middle quarter of it (kCore below), at most 70 % of it (the outer 15 % each side
// still bends: a ghost's stubby arms).
inline constexpr double kCoreMin = 0.12, kCoreMax = 0.35;

// The usual amplitude of each primitive on one part, in its unit (motion_verbs.h), in the order
// of Primitive: for a whole-figure verb a prompt aims at a part ("his legs squatting").
inline constexpr double kPartAmplitude[] = {20, 1, 0.07, 0.04, 0.04, 6, 0.05, 15, 0.01, 0.08, 0.08, 0.08, 0.12, 6, 1, 1, 1};
static_assert(sizeof kPartAmplitude / sizeof kPartAmplitude[0] == static_cast<size_t>(Primitive::Windmill) + 1);
// A Sway's hinge, in shares of the figure's height from its top: the lower 45 % stays planted
// (a wine glass's stem and foot, a saxophonist's legs); above it the lean grows over kRamp of
// the height (bend_region's ramp) to the full angle.
inline constexpr double kSwayHinge = 0.55;
// A whole-figure wave is anchored at a side of the figure where thin parts (at most kPoleWidth
// of the figure's extent across that side) lying within kPoleEnd of it together span kPoleSpan
// of the figure along it: a flag's pole. The wave then runs away from that side.
inline constexpr double kPoleWidth = 0.05, kPoleEnd = 0.1, kPoleSpan = 0.7;
// ... or a part starting at that side at most kPoleWidthMax of the extent thick and at least
// kPoleAspect times as long as it is thick (a flagpole drawn as a bar).
inline constexpr double kPoleWidthMax = 0.2, kPoleAspect = 4;
// A figure at least this many times as tall as it is wide stands upright: bent as a whole, its
// base holds (bend_anchor).
inline constexpr double kUpright = 0.8;
// A figure whose longer side is less than this many times its shorter one is compact: it swims
// with its lower limbs, not by a wave along its body (Builder::add).
inline constexpr double kElongated = 1.6;
// A Turn (a pirouette) narrows the figure from its width facing the viewer to this share of it
// edge on, never less: a flat drawing seen edge on has no width, and a part of it narrower than
// a pixel is a colour vanishing from the video, which the pixel ranker calls a continuity break
// (kRankVanishRatio). Past the edge-on moment the figure is mirrored (its back).
inline constexpr double kTurnEdgeWidth = kRankVanishRatio;
// The width factor of a Turn at `turns` whole turns: signed (negative: mirrored), its size
// from 1 (facing) down to kTurnEdgeWidth (edge on) as the squared cosine, which eases into the
// edge-on moment. As the cosine itself the width fell fastest there, where the outlines crowd
// together: a dancer's black outline fell from 360 px to 147 px between two of the ranker's
// frames (a 'continuity' defect). `depth` (the action's scale, at most 1) makes the turn
// shallower: edge on, the width is 1 - depth * (1 - kTurnEdgeWidth). Outlines keep their width
// as the figure narrows: a dancer's thick outlines covered her black dress edge on (914 px
// down to 84 px), and the procedural video's self-check asks for a shallower turn.
inline double turn_width(double turns, double depth = 1) {
  const double c = std::cos(kTau * turns);
  return (c < 0 ? -1 : 1) * (1 - std::clamp(depth, 0.0, 1.0) * (1 - kTurnEdgeWidth) * (1 - c * c));
}
// A chain hanging from the root that reaches the lowest this share of the figure stands on the
// ground (animate_plan): a saxophonist's legs stay while his upper body sways about the hips.
inline constexpr double kPlanted = 0.15;


// A region bend (PlannedAction::region) at point q and time t: a turn about `pivot` by `angle`
// degrees (the action's whole turn at t) times `weight`, which is 0 where the region holds and
// grows smoothly to 1 over the ramp beyond the pivot line; or, for a located part that grows
// (pulse), a scaling by 1 + grow about `pivot`. The weight depends on q only, never on t or the
// amplitude: region_bend.h reads from it which mesh vertices hold, which turn, which bend.
struct RegionTurn {
  Vec2 pivot;
  double angle = 0, weight = 0, grow = 0;
  bool pulse = false;
};
// `path`: the scene path q belongs to (-1: unknown), for lobes that own their paths (owner_lobe).
RegionTurn region_turn(const PlannedAction& a, double amp, double t, const RigBox& box, Vec2 q, int path = -1);
// The closed-form bend: q turned by region_turn's angle times its weight (or grown).
Vec2 bend_region(const PlannedAction& a, double amp, double t, const RigBox& box, Vec2 q, int path = -1);
// fit_plan: a region bend's mesh may thin no triangle below this share of its rest area (a
// pinch); below, or with a triangle flipped (a fold), its amplitude is scaled down. The inside
// of a sharp bend compresses: the test sweater's armpit, at 35 degrees, to 11 % with the closed
// form's band alone.
inline constexpr double kPinchArea = 0.05;

// Arms: an upper limb whose box is less than this share of the largest one's is left out.
inline constexpr double kArmMinShare = 0.2;

// A one-sided verb with no side named moves the limb reaching this many times farther from the
// body than the others (reaching_out): a boxer's extended arm reaches 1.4 times as far as the
// arm he keeps in guard.
inline constexpr double kReachLead = 1.2;

// fit_plan: a part at the canvas's edge holds still when the whole figure cannot move otherwise,
// if it and what hangs from it cover at most this share of the figure's box (a splash, not the
// body).
inline constexpr double kHeldMaxShare = 0.1;

// A rock aimed at a part turns it by at most this many times the rock's angle (Builder::add).
inline constexpr double kRockToPartMax = 4;
// head_side: the head shows a tail's end when its middle is this share of the body's width off
// the body's middle.
inline constexpr double kHeadOffCentre = 0.1;

// A portrait's head (bust_head.h: one rigid head lobe) nodding or shaking out of the picture's
// plane (head_turn.h) for verb `verb`: sets `a`'s head axis, its paths' features, at least
// kHeadTurnDeg (times `size`) and a nod's one-sided dip; returns the note's addition ("; it
// dips forward (a pitch)"), empty when the head turns in the plane.
std::string plan_head_turn(const Rig& rig, const LocatedPart& located, const std::string& verb, double size, PlannedAction& a);

// The unit of a primitive's amplitude (motion_verbs.h), as motion.json names it.
const char* unit_of(Primitive p);
std::string join(const std::vector<std::string>& v, const char* sep);
bool is_limb_target(Target t);
// A target naming a part of the figure (a limb, the head, the body, the wheels): not the whole
// figure, a word matched to part names, the repeated elements or the backdrop.
bool is_part_target(Target t);
// Keeps only the parts whose ancestors are not also in the set (a limb's segments follow it).
std::vector<int> topmost(const Rig& rig, std::vector<int> parts);
// Whether part p is at or under part a (a descendant through the parents).
bool part_under(const Rig& rig, int p, int a);
// The box of part a with everything that hangs from it.
RigBox chain_box(const Rig& rig, int a);
// The pole's parts at `side` of the figure (1 left, 2 right, 3 top, 4 bottom); `thick`: also
// upright bars drawn thick.
std::vector<int> pole_parts(const Rig& rig, int side, bool thick);
// The side a pole holds the figure at (1 left, 2 right, 3 top, 4 bottom), 0 for none
// (motion_anchors.cpp); `thick` as for pole_parts.
int anchored_side(const Rig& rig, bool thick);
// Where a bend of the whole figure is held: a pole's side, the base (4) of an upright figure or a
// plant, 0 when it bends free (a fish, a bird, an insect).
int bend_anchor(const Rig& rig, FigureClass figure);
// Of several limbs, the one whose chain reaches kReachLead farther from the root's middle than
// every other; -1 when none does (rig_queries.cpp).
int reaching_out(const Rig& rig, const std::vector<int>& limbs);
// Which limbs of a silhouette's skeleton a limb role bends (rig_queries.cpp).
bool lobe_serves(LobeKind k, Target t);
// The riders evenly spaced round the spinning `parts` (motion_frames.cpp, with the wheel loads).
int spin_symmetry(const Rig& rig, const std::vector<int>& parts);
// The parts target `t` (or, for Target::Named, `noun`) means, with a note when a fallback had
// to stand in (plan_targets.cpp).
std::vector<int> parts_for(const Rig& rig, Target t, const std::string& noun, std::string* note);
// The bloom on one stem (part_locator.h) a plant's `primitive` aimed at `target` turns instead
// (plan_targets.cpp); no lobes when none does.
LocatedPart plant_bloom(const Rig& rig, Primitive primitive, Target target, FigureClass figure, const std::string& noun);
// That bloom, else for a turn of a head said of no animal (a person or no figure named: "she
// nods"; an owl or a coiled snake is no bust) the head of a bust or of a head alone (bust_head.h).
LocatedPart bloom_or_bust_head(const Rig& rig, Primitive primitive, Target target, FigureClass figure, const std::string& noun);
// The oscillation of a back-and-forth action at phase u (in cycles) (motion_frames.cpp).
double oscillation(const PlannedAction& a, double u);
// The rigid motion of one action at time t on a part (or the figure) with box `box` and
// attachment `pivot`; `H`, `W` the figure's size (units of the translations); `plane` a wheel's
// plane a spin turns in (rigid_motion.cpp).
Affine rigid(const PlannedAction& a, double amp, double sign, double phase, double t, const RigBox& box, Vec2 pivot, double W, double H,
             const Affine& plane = {});

}  // namespace svgm::motion_plan_internal
