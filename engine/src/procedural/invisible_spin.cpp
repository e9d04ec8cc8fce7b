// Wheels whose spin cannot be seen roll instead (invisible_spin.h).
#include "procedural/invisible_spin.h"

#include <algorithm>
#include <cmath>

#include "geometry/curve_samples.h"
#include "motion/motion_verbs.h"
#include "procedural/motion_plan_internal.h"

namespace svgm {

bool looks_same_turned(const Scene& scene, const Rig& rig, const std::vector<int>& parts) {
  if (parts.empty()) return false;
  for (int p : parts) {
    const RigPart& P = rig.parts[p];
    const Vec2 c = P.box.centre();
    const double R = 0.5 * std::max(P.box.w(), P.box.h());
    if (R <= 0) return false;
    const Affine to_plane = P.wheel_plane.inverse();
    bool any = false;
    for (size_t pi = 0; pi < scene.paths.size(); ++pi) {
      if (!motion_plan_internal::part_under(rig, rig.part_of_path[pi], p)) continue;
      // What hangs from the wheel but reaches out of it (a scooter's fork and handlebar, hung
      // from its front wheel) does not turn with it: the wheel looks the same turned without it.
      const RigBox& b = rig.parts[rig.part_of_path[pi]].box;
      const double ox = std::min(b.x1, P.box.x1) - std::max(b.x0, P.box.x0), oy = std::min(b.y1, P.box.y1) - std::max(b.y0, P.box.y0);
      if (rig.part_of_path[pi] != p && (ox <= 0 || oy <= 0 || ox * oy < kInsideWheel * b.area())) continue;
      const Path& path = scene.paths[pi];
      if (path.fill_gradient >= 0 || path.stroke_gradient >= 0 || (path.has_stroke && !path.stroke.dashes.empty())) return false;
      for (const Subpath& sp : path.subpaths) {
        if (sp.points.empty()) continue;
        // An arc that does not close (a sketched wheel's stroke winding most of the way round)
        // shows its gap turning.
        if (!sp.closed && std::hypot(sp.points.back().x - sp.points[0].x, sp.points.back().y - sp.points[0].y) > kRoundTolerance * R)
          return false;
        double lo = 1e300, hi = 0;
        std::vector<Vec2> samples;
        append_curve_samples(sp, 4, true, samples);
        for (const Vec2& q : samples) {
          const Vec2 v = to_plane.apply(q - c);
          lo = std::min(lo, std::hypot(v.x, v.y));
          hi = std::max(hi, std::hypot(v.x, v.y));
        }
        if (hi - lo > kRoundTolerance * R) return false;
        any = true;
      }
    }
    if (!any) return false;
  }
  return true;
}

void roll_wheels_with_slides(MotionPlan& plan) {
  for (PlannedAction& a : plan.actions)
    if (a.primitive == Primitive::Spin && a.target == Target::Wheels)
      for (const PlannedAction& s : plan.actions)
        if (s.primitive == Primitive::Slide && s.parts.empty() && s.verb == a.verb && s.words == a.words) a.rolls = true;
}

void roll_invisible_spins(const Scene& scene, const Rig& rig, MotionPlan& plan) {
  const Verb* drive = find_verb_by_name("drive");
  if (!drive) return;
  const Action* slide = nullptr;
  for (const Action& act : drive->actions)
    if (act.primitive == Primitive::Slide && act.target == Target::Whole) slide = &act;
  if (!slide) return;
  const size_t n = plan.actions.size();
  for (size_t i = 0; i < n; ++i) {
    PlannedAction& a = plan.actions[i];
    if (a.primitive != Primitive::Spin || a.target != Target::Wheels || a.rolls) continue;
    // Only when the spin is all its words show (a pedalling leg shows the motion by itself).
    bool alone = true;
    for (const PlannedAction& s : plan.actions) alone = alone && (&s == &a || s.words != a.words);
    if (!alone || !looks_same_turned(scene, rig, a.parts)) continue;
    std::string names;
    for (int p : a.parts) names += (names.empty() ? "" : ", ") + rig.parts[p].name;
    PlannedAction body;
    body.verb = a.verb;
    body.words = a.words;
    body.target = Target::Whole;
    body.direction = a.travel != 0 ? a.travel : a.direction;
    body.travel = a.travel;
    if (a.travel != 0) {
      // Sent somewhere ("the wheels spin to the right"): the figure rolls there on them.
      body.primitive = Primitive::Slide;
      body.amp = slide->amp;
      body.cycles = slide->cycles;
      body.why = "'" + a.words + "': the wheels look the same turned, so the figure rolls with them";
      a.rolls = true;
      plan.warnings.push_back("the wheels (" + names + ") look the same at every angle: spun in place they would not show, so the figure rolls with them");
    } else {
      // Sent nowhere ("the car's wheels spin"): they spin in place and the body bounces on them
      // (motion_frames.cpp: a bounce of the same words leaves the wheels on the ground). Rolled
      // out and back instead, a car filling its canvas slid 4 % of its size, its roof moving as
      // much as its wheels.
      body.primitive = Primitive::Bob;
      body.amp = kIdleBounce;
      body.cycles = kIdleBounces;
      body.why = "'" + a.words + "': the wheels look the same turned, so the body bounces on them as they spin";
      plan.warnings.push_back("the wheels (" + names + ") look the same at every angle: spun in place they would not show, so the body bounces on them");
    }
    plan.actions.push_back(std::move(body));
  }
}

}  // namespace svgm
