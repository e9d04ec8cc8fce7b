// A gait with no direction said goes the way the figure faces (procedural/gait_travel.h): an
// animal with its eye at the left walks or crawls to the left, a visible distance; "on the spot"
// anywhere in the prompt, a direction said, a clause naming the striding legs, or a figure whose
// facing is not known keeps the old in-place gait; a flight is no gait.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "procedural/eye_cue.h"
#include "procedural/gait_travel.h"
#include "procedural/motion_plan.h"
#include "procedural/motion_plan_internal.h"

#include "motion_drawing.h"
using namespace svgm;
using svgm::test::Drawing;
using svgm::test::eye_tail_animal;

namespace {

// The whole figure's slides of a plan, as their directions.
std::vector<int> slide_ways(const MotionPlan& plan) {
  std::vector<int> out;
  for (const auto& a : plan.actions)
    if (a.primitive == Primitive::Slide && a.parts.empty()) out.push_back(a.direction);
  return out;
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("gait travel: an animal facing left (its eye) walks and crawls to the left with no direction said") {
  Drawing d = eye_tail_animal();  // a four-legged animal, its eye on the snout at the left
  REQUIRE(d.rig.eye_side == -1);
  for (const char* prompt : {"the animal walks", "the dog trots", "the caterpillar crawls"}) {
    CAPTURE(prompt);
    MotionPlan plan = plan_from_prompt(parse_prompt(prompt), d.rig, 1);
    CHECK(slide_ways(plan) == std::vector<int>{-1});
    // A travel's amplitude: at least kTravelReach of the figure's width (a crawl's own creep raised
    // to it; a walk's added slide not cut by Builder::add's jitter).
    for (const auto& a : plan.actions)
      if (a.primitive == Primitive::Slide) CHECK(a.amp >= kTravelReach);
    const int F = 25;
    fit_plan(d.scene, d.rig, plan, F, 9);
    const std::vector<Vec2> pts = animate_plan(d.scene, d.rig, plan, F);
    // A quarter of the loop in (most of the way to its far end, travel_profile.h), the eye (path 1, its points after path 0's)
    // is to the left of where it stood, by 4 % of the figure's width or, as here, most of the
    // room the canvas leaves at the left (the snout is 8 units from its edge).
    size_t eye = 0;
    for (const auto& sp : d.scene.paths[0].subpaths) eye += sp.points.size();
    const size_t per = pts.size() / F;
    const double room = std::min(0.04 * d.rig.figure.w(), d.rig.figure.x0);
    CHECK(pts[eye].x - pts[F / 4 * per + eye].x >= 0.25 * room);  // (a crawl's stretch shares the room)
  }
}

TEST_CASE("gait travel: a direction said, 'on the spot', the striding legs named or a flight keep the old plan") {
  Drawing d = eye_tail_animal();
  CHECK(slide_ways(plan_from_prompt(parse_prompt("the animal walks to the right"), d.rig, 1)) == std::vector<int>{1});
  CHECK(slide_ways(plan_from_prompt(parse_prompt("the animal walks on the spot"), d.rig, 1)).empty());
  CHECK(slide_ways(plan_from_prompt(parse_prompt("the animal runs on the spot, legs striding"), d.rig, 1)).empty());
  CHECK(slide_ways(plan_from_prompt(parse_prompt("the bird flies"), d.rig, 1)).empty());
  // No facing known (a stick figure seen from the front): the gait stays in place, as before.
  const Drawing man("stick_figure.svg");
  CHECK(slide_ways(plan_from_prompt(parse_prompt("the man walks"), man.rig, 1)).empty());
}

TEST_CASE("gait travel: an animal filling its canvas, its travel held there, steps visibly on its body") {
  Drawing d = eye_tail_animal();  // 8 units of room each side of a 204-unit figure
  MotionPlan plan = plan_from_prompt(parse_prompt("the animal walks"), d.rig, 1);
  const int F = 25;
  fit_plan(d.scene, d.rig, plan, F, 9);
  // Its gait without the travel: the legs' steps and the bob alone.
  MotionPlan body = plan;
  int travels = 0;
  for (auto& a : body.actions)
    if (a.goes) a.amp = 0, ++travels;
  REQUIRE(travels == 1);
  double farthest = 0;
  for (double t : svgm::test::path_travel(d.scene, animate_plan(d.scene, d.rig, body, F), F)) farthest = std::max(farthest, t);
  const double diagonal = std::hypot(d.rig.figure.w(), d.rig.figure.h());
  CHECK(farthest >= 0.999 * motion_plan_internal::kVisibleTravel * diagonal);
  bool noted = false;
  for (const auto& n : plan.notes) noted = noted || n.find("gait on the body raised") != std::string::npos;
  CHECK(noted);
}

}  // TEST_SUITE
