// Which way an eyeless animal faces, from its silhouette (procedural/body_facing.h): its head
// held out beyond its feet and slimmer than its rump is its front. On an animal drawn for the
// test (beast_side.svg: no eye, its head and neck held out left of its front legs, a thin tail
// line behind its hind legs) and its mirror image (beast_side_right.svg). Told to go the other
// way it turns round first (gait_travel.h); a person drawn so is never read by its shape.
#include <doctest/doctest.h>

#include <string>

#include "procedural/body_facing.h"
#include "procedural/gait_travel.h"
#include "procedural/limb_qualifiers.h"
#include "procedural/motion_plan.h"

#include "motion_drawing.h"
using namespace svgm;
using svgm::test::Drawing;

namespace {

int turning_slides(const MotionPlan& plan) {
  int n = 0;
  for (const auto& a : plan.actions) n += a.primitive == Primitive::Slide && a.parts.empty() && a.goes && a.turns_round;
  return n;
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("body facing: an eyeless animal's head end is the one held out beyond its feet and slimmer; mirrored, the other") {
  const Drawing beast("beast_side.svg");
  REQUIRE(beast.rig.eye_side == 0);  // no eye to read: the silhouette must say it
  const BodyEnds e = body_ends(beast.rig);
  REQUIRE_FALSE(e.empty);
  // The head (x 2..30) lies wholly left of the front legs (x 32..), the tail line (x 90..98)
  // right of the hind legs (.. x 89): the left end overhangs more; the head's outer columns
  // hold only its height, the right end's the body, a leg and the tail.
  CHECK(e.overhang_left > e.overhang_right + kBodyStep);
  CHECK(e.fill_right > e.fill_left + kBodyStep);
  std::string why;
  CHECK(body_facing(beast.rig, FigureClass::Quadruped, &why) == -1);
  CHECK(why.rfind("its shape: the left end held out beyond its feet", 0) == 0);
  CHECK(facing_side(beast.rig, FigureClass::Quadruped, nullptr) == -1);
  // A person, an insect, a fish (no feet) are not read by their silhouette.
  CHECK(body_facing(beast.rig, FigureClass::Biped, nullptr) == 0);
  CHECK(body_facing(beast.rig, FigureClass::Insect, nullptr) == 0);
  CHECK(body_facing(beast.rig, FigureClass::FishOrSnake, nullptr) == 0);
  const Drawing mirrored("beast_side_right.svg");
  CHECK(body_facing(mirrored.rig, FigureClass::Quadruped, nullptr) == 1);
  CHECK(facing_side(mirrored.rig, FigureClass::Quadruped, nullptr) == 1);
}

TEST_CASE("body facing: the eyeless animal told to go the other way turns round; told its own way, it does not") {
  const Drawing beast("beast_side.svg");
  CHECK(turning_slides(plan_from_prompt(parse_prompt("the ox walks to the right"), beast.rig, 1)) == 1);
  CHECK(turning_slides(plan_from_prompt(parse_prompt("the ox walks to the left"), beast.rig, 1)) == 0);
  const Drawing mirrored("beast_side_right.svg");
  CHECK(turning_slides(plan_from_prompt(parse_prompt("the ox walks to the left"), mirrored.rig, 1)) == 1);
  CHECK(turning_slides(plan_from_prompt(parse_prompt("the ox walks to the right"), mirrored.rig, 1)) == 0);
  std::string why;
  CHECK(goes_against_facing(beast.rig, FigureClass::Quadruped, 1, &why));
  CHECK(why.rfind("it faces left (its shape: the left end held out", 0) == 0);
}

}  // TEST_SUITE
