// The motion plan: which parts of the rig (part_rig.h) move, by which verb (motion_verbs.h),
// about which pivot, how far and how often, and why; built from a prompt (prompt_parse.h) or
// from an explicit plan the user wrote (stages.video.options.motion: "flap:wing*, bob:root").
// Then the frames: every control point of the scene at every frame of one seamless loop.
//
// Frames are built part by part down the rig (a limb's segments follow it), in this order for
// each control point: its repeated element's own motion (a falling drop), deformations of the
// shape (a swimming wave, a bend), the rig's rotations about the pivots, then the motion of the
// whole figure (a hop, a bob, a rock about its base). A swing of the root itself (a boxer's
// body turning into a punch, an upper body swaying) leaves the chains hanging from the root
// that reach the figure's feet where they are, and carries the head upright (it follows its
// neck without the turn). The background stays still unless a plan
// names it. The first and the last frame are the rest pose (the loop closes), except for
// repeated elements, which each keep their own phase.
//
// Three limits keep the target followable (fit_plan): no control point leaves the canvas (less a
// margin of kFrameMargin; a point already outside it at rest, a line drawing's handle, or a
// point of a spinning part, may move while the curves it shapes stay in), no point travels farther than kMaxStep of the
// canvas diagonal between two keyframes, and no swinging part (a part of its own, not a
// region of one shape bending) turns by more than kMaxTurn degrees between two keyframes. When any fails
// the amplitudes are scaled down (spins keep whole turns; falls are shortened per element).
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "motion/motion_verbs.h"
#include "procedural/head_turn.h"
#include "procedural/part_rig.h"
#include "procedural/prompt_parse.h"
#include "procedural/tossed_things.h"

namespace svgm {

// A limb that is not a part of its own (a bat drawn as one silhouette): a region of the part's
// own outlines (not what hangs from it) bends about a pivot line, each point turning by the action's angle times a weight that
// grows smoothly from 0 at the pivot line (so the shape stays in one piece).
// Located: a part the prompt names that the rig has no part for, found by part_locator.h; its
// lobes turn and only the paths it found move.
enum class Region { None, Sides, Lower, Top, End, Located };

struct PlannedAction {
  std::string verb;
  std::string words;            // the prompt's words (or the plan item) it came from
  Primitive primitive = Primitive::Swing;
  Target target = Target::Whole;
  std::vector<int> parts;       // rig parts (for Whole: none, the whole figure)
  std::vector<double> sign;     // per part: +1 / -1 (mirrored or alternating pairs)
  std::vector<double> phase;    // per part, in cycles (alternating pairs: 0 and 0.5)
  double amp = 0;               // in the primitive's unit (motion_verbs.h)
  int cycles = 1;
  int vertical = 0;             // Bob: +1 only up, -1 only down
  int direction = 1;            // Spin, Slide, Rock one-sided: which way first
  int travel = 0;               // where the prompt sends the figure: -1 left, +1 right, 0 nowhere
  int anchored = 0;             // Undulate or Bend of the whole figure: the side a pole holds it
                                // at (a flag), or a Bend's base (a stalk): 1 left, 2 right, 3 top,
                                // 4 bottom; 0 free (a fish)
  bool rooted = false;          // Sway of a plant, or its Bend from its base (anchored 4): it
  Vec2 root{0, 0};              // turns from `root`, where its pot or the ground holds it
                                // (sway_base.h), not about its middle or its box's bottom
  Region region = Region::None; // a Swing of a region of parts[0] instead of whole parts
  int region_side = 0;          // Sides/Lower: -1 only the viewer's left, +1 only the right
  bool alternating = false;     // Sides/Lower: the two sides half a cycle apart
  double core_left = 0, core_right = 0;  // Sides: the still core's half-widths left and right
                                         // of the box centre (0: kCore of the box width)
  std::vector<ArmLobe> lobes;   // the limbs that bend, each about its base, when known: arms
                                // drawn in the part's outline (part_rig.h), or limbs of the
                                // figure's silhouette (Rig::limbs)
  bool silhouette = false;      // lobes are Rig::limbs: the points of every part within them bend
  std::vector<int> lobe_paths;  // when not empty, only these scene paths' points bend (sorted)
  std::vector<int> held_paths;  // scene paths that ride on none of lobe_paths (LocatedPart::holds)
  HeadAxis head_axis = HeadAxis::Plane;  // a portrait's head (bust_head.h) nodding (Pitch) or
                                         // shaking (Yaw) out of the picture's plane (head_turn.h)
  std::vector<HeadPath> head_paths;      // its paths' features and outline, as lobe_paths
  double scale = 1;             // this action's own amplitude factor (fit_plan), times plan.scale
  int one_sided = 0;            // Swing, Rock, Bend, Sway, region bends: 0 back and forth about
                                // rest; +1 / -1 out to one side only and back (fit_plan: the
                                // other side would leave the canvas)
  bool goes = false;            // Slide of the whole figure going somewhere on its own (a gait,
                                // a swim, a flight): forward steadily, then back (travel_profile.h)
  bool turns_round = false;     // Slide that goes (goes): the figure faces the other way, so it
                                // turns round about its vertical axis to go, and back to come
                                // home (travel_profile.h's turned_going_at; the mirror is the
                                // whole figure's outermost motion, animate_plan)
  bool inches = false;          // Slide and Stretch of the whole figure sent crawling somewhere:
                                // its steps, the ends planted in turn (travel_profile.h)
  bool rolls = false;           // Spin of wheels: they roll with the figure's Slide of the same
                                // words (the turn follows the distance, both ways), instead of
                                // whole turns
  Vec2 vanish{0, 0};            // Pulse of the whole figure that goes (goes): the point on its
                                // horizon it shrinks towards, going away (direction -1), or grows
                                // from, coming nearer (+1) (depth_travel.h)
  Vec2 heading{0, 0};           // Bob of the whole figure (a launch's climb, a landing): the
                                // unit way it goes, towards its nose (flight_axis.h), instead of
                                // straight up or down; {0, 0}: none
  bool apart = false;           // Whole: each separate piece of the figure (figure_pieces.h)
                                // moves its own way (a tumble of two leaves)
  bool closed_form = false;     // region bends: the closed-form bend, not the mesh (region_bend.h:
                                // fit_plan's choice when unfolding the mesh would hide the motion)
  std::vector<TossedThing> tossed;  // Toss: the things it tosses, each with its phase
  TossArc arc;                  // Toss: the cascade they fly (tossed_things.h)
  std::string why;
};

struct MotionPlan {
  std::string source;           // "prompt" or "stages.video.options.motion"
  std::vector<PlannedAction> actions;
  std::vector<std::string> not_understood;  // prompt words that named no motion, part or modifier
  std::vector<std::string> warnings;        // one line each
  std::vector<std::string> notes;           // informational lines (an amplitude scaled to fit)
  std::vector<std::string> readings;        // words the lexicon read ("'shuffles' read as walk")
  double scale = 1;             // amplitude factor of every action fit_plan chose (1: as planned)
  int keyframes = 0;            // keyframes the fitter needs to follow the motion (fit_plan: at
                                // least the fitter's own count; 0 before fit_plan)
  std::vector<int> held;        // parts (with what hangs from them) the whole figure's motions
                                // leave where they are, as the background (fit_plan: small parts
                                // at the canvas's edge when the figure could not move otherwise)
  std::string ground;           // the prompt's words naming a ground the figure moves on ("on
                                // the waves"): the band drawn there stays (support_band.h)
  std::string hang;             // the prompt's words naming what the figure hangs from ("from
                                // the branch"): it stays, the figure swings about its grip
                                // (hang_support.h)
  std::string seat;             // the prompt's words naming what the figure sits in or on ("in
                                // the bathtub"): it stays under motions in place (seat_support.h)
  // The amplitude `a` moves with: its own, times its scale and the plan's (the whole turns of a
  // spin or a turn are never scaled).
  double amplitude(const PlannedAction& a) const {
    return a.primitive == Primitive::Spin || a.primitive == Primitive::Turn || a.primitive == Primitive::Windmill ? a.amp : a.amp * a.scale * scale;
  }
  std::string summary() const;  // one line: "flap wing_left+wing_right 30 deg x3; bob whole"
};

// From a prompt. `seed` picks an arm when a one-sided verb names no side, and varies the
// amplitudes by up to 15 %. A prompt with no motion word gets a gentle sway of the figure and a
// warning naming the words that were not understood.
MotionPlan plan_from_prompt(const ParsedPrompt& prompt, const Rig& rig, uint32_t seed);

// From an explicit plan (parse_explicit_plan). Throws svgm::Error naming the pattern when a
// pattern matches no part (listing the parts' names).
MotionPlan plan_from_steps(const std::vector<ExplicitStep>& steps, const Rig& rig, uint32_t seed);

// Control points of every frame: frames * (the scene's path points) canvas points, in scene
// order (paths, subpaths, points), for t = f / (frames - 1).
// Region bends move their points through an as-rigid-as-possible mesh (region_bend.h); when
// `folds` is given, it gets one entry per action: the worst frame of that action's mesh.
struct BendFold {
  int flipped = 0;            // the most flipped triangles in one frame (folds)
  double min_area_ratio = 1;  // the smallest deformed / rest triangle area over the frames
  int frame = -1;             // the frame with the most folds (or the thinnest triangle)
  bool meshed = false;        // the action bent its region through a mesh
};
std::vector<Vec2> animate_plan(const Scene& scene, const Rig& rig, const MotionPlan& plan, int frames,
                               std::vector<BendFold>* folds = nullptr);

// Scales the plan's amplitudes until every frame keeps every control point inside the canvas,
// no point moves farther than kMaxStep of the diagonal and no swinging part turns farther than
// kMaxTurn between keyframes (`keyframes` spread over `frames`): first each action alone (its own scale: a sway that would push a
// canvas-filling drawing out is made smaller without shrinking the rain falling beside it),
// then all together (plan.scale). A point already within the margin at rest may move up to
// 0.9 of the margin from the edge, never beyond it. A point outside the canvas at rest is held
// by the cubics it shapes instead (sampled at quarters): their points inside stay inside, those
// outside go at most 0.9 of the margin farther. A note says each scaling; a warning says when
// even the smallest scale fails. When a motion of the whole figure fails so, the figure's small
// parts at the canvas's edge (each with what hangs from it within kHeldMaxShare of the figure's
// box) are held (MotionPlan::held) and the plan is fitted again, kept when that fits.
void fit_plan(const Scene& scene, const Rig& rig, MotionPlan& plan, int frames, int keyframes);

// The report written to motion.json: the parts found and the plan.
nlohmann::json motion_report(const Scene& scene, const Rig& rig, const MotionPlan& plan);

// How far each path's control points travel from their rest positions over the frames
// (animate_plan's points): the largest and the mean (over points) of each point's largest
// distance, and the box the path sweeps; in the JSON also each control point's rest position and
// travel ("point_travel": [x, y, travel, ...], the rest position rounded to 0.01 as the boxes
// are, the travel to 0.1), so a reader can check what moved
// where (tests/bench/motion_score.py). The swept box is that of the path's curves (each cubic
// at quarters), not of its handles. "body" numbers the rigid bodies: paths one affine map moves
// in every frame (geometry/rigid_bodies.h; -1: a path no single map moves).
struct PathMotion {
  double max_travel = 0, mean_travel = 0;
  int points = 0;
  RigBox rest, swept;
  std::vector<float> travel;  // each control point's largest distance from rest, in order
  int body = -1;  // its rigid body (geometry/rigid_bodies.h: the paths one affine map moves), -1: none
};
// `body_maps` (may be null): each rigid body's map from rest in every frame.
std::vector<PathMotion> path_motion(const Scene& scene, const std::vector<Vec2>& points, int frames,
                                    std::vector<std::vector<Affine>>* body_maps = nullptr);
nlohmann::json path_motion_json(const Scene& scene, const std::vector<PathMotion>& motion);
// motion.json's "bodies": per body, per frame, its map [a, b, c, d, e, f] (SVG's matrix order;
// canvas units).
nlohmann::json body_maps_json(const std::vector<std::vector<Affine>>& maps);

constexpr double kFrameMargin = 0.01;  // of the canvas size: control points stay this far inside
constexpr double kMaxStep = 0.08;      // of the canvas diagonal between keyframes (about 29 px
                                       // at the fitter's 256 px: what flow warm starts follow)
constexpr double kMaxTurn = 20;        // degrees a swinging part turns between
                                       // keyframes: a boxer's arm drawn behind his body turned
                                       // 33 degrees per keyframe (26.7 x 3 punches), its visible
                                       // area fell from 39 to 12 px from one keyframe to the next
                                       // and the ranker stopped it (continuity); at 23 degrees it
                                       // still fell 56 %, at 17 it kept its area

}  // namespace svgm
