// Where the prompt sends a figure that gets somewhere by itself ("walks to the left", "hops to
// the right"): the whole figure slides that way first and back, its gait going on; a verb that
// does not take the figure anywhere ("waves to the right") and a verb with a travel of its own
// ("drives") get no second slide. Before, the direction was read and ignored: the figure walked
// on the spot. "across" with no way said is a travel told too (gait_travel.h's travel_across).
#include <doctest/doctest.h>

#include <cmath>

#include "procedural/motion_plan.h"

#include "motion_drawing.h"
using namespace svgm;
using svgm::test::Drawing;

namespace {

int slides(const MotionPlan& plan) {
  int n = 0;
  for (const auto& a : plan.actions) n += a.primitive == Primitive::Slide && a.parts.empty();
  return n;
}

// The mean x of the torso's four corners (path 0, the root: only the whole figure's motions
// move it) at frame f of animate_plan's `pts` (F frames).
double torso_x(const std::vector<Vec2>& pts, int F, int f) {
  const size_t per = pts.size() / F;
  double s = 0;
  for (size_t i = 0; i < 4; ++i) s += pts[f * per + i].x;
  return s / 4;
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("a figure told where it walks travels there first, a visible distance, and comes back") {
  const Drawing fx("stick_figure.svg");  // the figure spans x 45-155 of a 200-wide canvas
  for (const char* prompt : {"the man walks to the left", "the man hops to the right", "the man runs left"}) {
    CAPTURE(prompt);
    MotionPlan plan = plan_from_prompt(parse_prompt(prompt), fx.rig, 1);
    REQUIRE(slides(plan) == 1);
    const int dir = std::string(prompt).find("left") != std::string::npos ? -1 : 1;
    const int F = 49;
    fit_plan(fx.scene, fx.rig, plan, F, 15);
    const auto pts = animate_plan(fx.scene, fx.rig, plan, F);
    const double rest = torso_x(pts, F, 0);
    // A quarter of the loop in (the slide's one cycle at its far end), the body is on the side
    // it was sent to, by at least 4 % of the figure's width (110 * 0.04 = 4.4 units; the slide is
    // 8 %, give or take its 15 % of randomness and the fitter's step limit); at rest at the end.
    CHECK(dir * (torso_x(pts, F, F / 4) - rest) > 4.4);
    CHECK(std::fabs(torso_x(pts, F, F - 1) - rest) < 1e-6);
  }
}

TEST_CASE("no direction, a verb that goes nowhere, or a verb with its own travel: no added slide") {
  const Drawing fx("stick_figure.svg");
  CHECK(slides(plan_from_prompt(parse_prompt("the man walks"), fx.rig, 1)) == 0);
  CHECK(slides(plan_from_prompt(parse_prompt("the man waves to the right"), fx.rig, 1)) == 0);
  const Drawing car("car.svg");
  const MotionPlan drive = plan_from_prompt(parse_prompt("the car drives to the right"), car.rig, 1);
  CHECK(slides(drive) == 1);
}

TEST_CASE("'across' with no way said sends any figure that gets somewhere across: the way it faces, else right") {
  const Drawing fx("stick_figure.svg");
  // A bounce is no gait: said with no way it stays; "across" is a travel told.
  CHECK(slides(plan_from_prompt(parse_prompt("the man bounces"), fx.rig, 1)) == 0);
  for (const char* prompt : {"the man bounces across the screen", "the man floats across"}) {
    CAPTURE(prompt);
    MotionPlan plan = plan_from_prompt(parse_prompt(prompt), fx.rig, 1);
    REQUIRE(slides(plan) == 1);
    int dir = 0;
    for (const auto& a : plan.actions)
      if (a.primitive == Primitive::Slide && a.parts.empty()) dir = a.travel;
    // The stick figure shows no facing (no eye, its head above its middle): to the right.
    CHECK(dir == 1);
    const int F = 49;
    fit_plan(fx.scene, fx.rig, plan, F, 15);
    const auto pts = animate_plan(fx.scene, fx.rig, plan, F);
    CHECK(torso_x(pts, F, F / 4) - torso_x(pts, F, 0) > 4.4);
  }
  // A vehicle's own drive goes that way too.
  const Drawing car("car.svg");
  for (const auto& a : plan_from_prompt(parse_prompt("the car rolls across the road"), car.rig, 1).actions)
    if (a.primitive == Primitive::Slide && a.parts.empty()) CHECK(a.travel != 0);
}

}  // TEST_SUITE

TEST_SUITE("video") {

TEST_CASE("a gait on a figure the prompt calls an animal swings no arms: only a person's gait has them") {
  const Drawing fx("stick_figure.svg");
  auto arms = [&](const char* prompt) {
    int n = 0;
    for (const auto& a : plan_from_prompt(parse_prompt(prompt), fx.rig, 1).actions) n += a.target == Target::Arms;
    return n;
  };
  CHECK(arms("the man runs") == 1);
  CHECK(arms("the dog runs") == 0);
  CHECK(arms("the horse walks") == 0);
}

}  // TEST_SUITE
