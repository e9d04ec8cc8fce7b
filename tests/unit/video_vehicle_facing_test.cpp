// Which way a vehicle faces (procedural/shape_facing.h): the low end of its outline (its bonnet)
// is its front, its tall square end (its box) the rear; a vehicle told to go the other way turns
// round (gait_travel.h's goes_against_facing). On a van drawn for the test (van_side.svg: a
// bonnet 25 units lower than its box, facing left) and its mirror image (van_side_right.svg).
// And the eye cue's bound for a long-tailed fish's eye, which a person's eye does not meet.
#include <doctest/doctest.h>

#include <string>

#include "procedural/eye_cue.h"
#include "procedural/gait_travel.h"
#include "procedural/limb_qualifiers.h"
#include "procedural/motion_plan.h"
#include "procedural/shape_facing.h"

#include "motion_drawing.h"
using namespace svgm;
using svgm::test::Drawing;

namespace {

// How many of the plan's travels (the whole figure's slide going somewhere) turn round.
int turning_slides(const MotionPlan& plan) {
  int n = 0;
  for (const auto& a : plan.actions) n += a.primitive == Primitive::Slide && a.parts.empty() && a.goes && a.turns_round;
  return n;
}

int going_slides(const MotionPlan& plan) {
  int n = 0;
  for (const auto& a : plan.actions) n += a.primitive == Primitive::Slide && a.parts.empty() && a.goes;
  return n;
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("vehicle facing: the van's ends read from its outline; its low bonnet is its front, mirrored the other way") {
  const Drawing van("van_side.svg");
  // The figure from y 10 (the box's top) to 70 (the wheels' bottom): 60 tall. The left end's top
  // is the bonnet's at 35, (35 - 10) / 60 of the height; the right end's the box's at 10.
  const SideProfile p = side_profile(van.rig);
  REQUIRE_FALSE(p.empty);
  CHECK(p.left.top == doctest::Approx(25.0 / 60));
  CHECK(p.right.top == doctest::Approx(0.0));
  std::string why;
  CHECK(shape_facing(van.rig, FigureClass::Wheeled, &why) == -1);
  CHECK(why == "its shape: the left end low (its top at 0.42 of its height), the other tall and square (0.00)");
  // Only a vehicle is read so: a creature's higher end is not its head often enough.
  CHECK(shape_facing(van.rig, FigureClass::Quadruped, nullptr) == 0);
  CHECK(shape_facing(van.rig, FigureClass::None, nullptr) == 0);
  // facing_side for a vehicle: its outline, never its "head" part (the part above its body).
  CHECK(facing_side(van.rig, FigureClass::Wheeled, &why) == -1);
  CHECK(why.rfind("its shape", 0) == 0);
  const Drawing mirrored("van_side_right.svg");
  CHECK(shape_facing(mirrored.rig, FigureClass::Wheeled, nullptr) == 1);
  CHECK(side_profile(mirrored.rig).right.top == doctest::Approx(25.0 / 60));
}

TEST_CASE("vehicle facing: the van told to drive off the other way turns round; told its own way, it does not") {
  const Drawing van("van_side.svg");
  const MotionPlan right = plan_from_prompt(parse_prompt("the van drives off to the right"), van.rig, 1);
  CHECK(going_slides(right) == 1);
  CHECK(turning_slides(right) == 1);
  const MotionPlan left = plan_from_prompt(parse_prompt("the van drives off to the left"), van.rig, 1);
  CHECK(going_slides(left) == 1);
  CHECK(turning_slides(left) == 0);
  const Drawing mirrored("van_side_right.svg");
  CHECK(turning_slides(plan_from_prompt(parse_prompt("the van drives off to the left"), mirrored.rig, 1)) == 1);
  CHECK(turning_slides(plan_from_prompt(parse_prompt("the van drives off to the right"), mirrored.rig, 1)) == 0);
  std::string why;
  CHECK(goes_against_facing(van.rig, FigureClass::Wheeled, 1, &why));
  CHECK(why.rfind("it faces left (its shape: the left end low", 0) == 0);
}

TEST_CASE("eye cue: an eye an eighth of the width off the middle (a long tail behind it) shows the head, not a person's") {
  // A figure 200 x 100; a dark dot at x 71-79 (middle 75, 0.125 of the width left of the middle):
  // a shark's or a dolphin's eye, its long tail putting the figure's middle behind it.
  Rig rig;
  rig.figure.add(Vec2{0, 0});
  rig.figure.add(Vec2{200, 100});
  RigElement body, eye;
  for (Vec2 q : {Vec2{0, 0}, Vec2{200, 0}, Vec2{200, 100}, Vec2{0, 100}}) body.box.add(q), body.points.push_back(q);
  body.area = 200 * 100, body.lightness = 0.8;
  for (Vec2 q : {Vec2{71, 20}, Vec2{79, 20}, Vec2{79, 28}, Vec2{71, 28}}) eye.box.add(q), eye.points.push_back(q);
  eye.area = 64, eye.lightness = 0.1;
  rig.elements = {body, eye};
  const EyeCue cue = find_eye(rig);
  CHECK(cue.side == -1);
  rig.eye_side = cue.side, rig.eye = cue.at;
  CHECK(facing_side(rig, FigureClass::FishOrSnake, nullptr) == -1);
  // A person's dot that near the middle shows no facing: a person drawn from the front stays.
  CHECK(facing_side(rig, FigureClass::Biped, nullptr) == 0);
}

}  // TEST_SUITE
