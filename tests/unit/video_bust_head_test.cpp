// The head of a portrait (procedural/bust_head.h): on a bust whose hair the rig takes for the
// body, and on a head drawn alone whose hair the rig takes for the head, a turn of the head
// turns everything drawn above the shoulders (or the whole figure) whole about the neck, and
// the shoulders hold. The drawings were made for these tests (tests/data/motion).
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "procedural/bust_head.h"
#include "procedural/motion_plan.h"
#include "procedural/prompt_parse.h"

#include "motion_drawing.h"
using namespace svgm;
using svgm::test::Drawing;

TEST_SUITE("video") {

TEST_CASE("bust head: on a bust the head above the shoulders turns about the middle of their top; the shoulders hold") {
  const Drawing d("bust_portrait.svg");
  const LocatedPart head = bust_head(d.rig);
  REQUIRE(head.lobes.size() == 1);
  CHECK(head.lobes[0].rigid);
  CHECK(head.lobes[0].pivot.x == doctest::Approx(100));  // the middle of the head's box (42 .. 158)
  CHECK(head.lobes[0].pivot.y == doctest::Approx(140));  // the shoulders' top
  CHECK(head.paths == std::vector<int>{0, 1, 2, 3});     // hair, face, two eyes; not the shoulders (4)
  // A tilt turns it in the picture's plane (a nod or a shake turns it out of it: head_turn_test).
  for (const char* prompt : {"she tilts her head", "he tips his head"}) {
    CAPTURE(prompt);
    const MotionPlan plan = plan_from_prompt(parse_prompt(prompt), d.rig, 1);
    REQUIRE(plan.actions.size() == 1);
    CHECK(plan.actions[0].region == Region::Located);
    CHECK(plan.actions[0].primitive == Primitive::Swing);
    // 25 frames: a quarter cycle apart for the shake's 6 cycles (13 frames fall on its zeros).
    const auto t = d.travel(plan, 25);
    REQUIRE(t.size() == 5);
    CHECK(t[4] == 0.0);  // the shoulders
    // The face turns whole with the hair: its top (100, 40), 100 above the pivot, moves the
    // chord of the swing's angle, not a share of it as a bend's ramp would give.
    const double angle = std::fabs(plan.amplitude(plan.actions[0])) * M_PI / 180;
    CHECK(t[1] > 0.8 * 2 * 100 * std::sin(angle / 2));
  }
}

TEST_CASE("bust head: a head drawn alone is the whole figure, turning about the middle of its bottom") {
  const Drawing d("head_alone.svg");
  const LocatedPart head = bust_head(d.rig);
  REQUIRE(head.lobes.size() == 1);
  CHECK(head.lobes[0].pivot.x == doctest::Approx(100));
  CHECK(head.lobes[0].pivot.y == doctest::Approx(180));  // the face's bottom, 110 + 70
  CHECK(head.paths == std::vector<int>{0, 1, 2, 3});
  const MotionPlan plan = plan_from_prompt(parse_prompt("he shakes his head"), d.rig, 1);
  REQUIRE(plan.actions.size() == 1);
  CHECK(plan.actions[0].region == Region::Located);
  const auto t = d.travel(plan, 25);
  CHECK(t[0] > 1.0);  // the face turns with the hair (before, the hair alone turned on it)
  CHECK(t[1] > 1.0);
}

TEST_CASE("bust head: only a head said of no animal: 'he shakes his head no' turns it, 'the owl turns its head' does not") {
  const Drawing d("head_alone.svg");
  // "no" reads as an object, the clause's figure: still no animal, the head alone turns.
  CHECK(plan_from_prompt(parse_prompt("he shakes his head no"), d.rig, 1).actions[0].region == Region::Located);
  // An owl is compact and limbless too, and no portrait: its rig's head turns as before.
  const MotionPlan owl = plan_from_prompt(parse_prompt("the owl nods its head"), d.rig, 1);
  REQUIRE_FALSE(owl.actions.empty());
  CHECK(owl.actions[0].region != Region::Located);
}

TEST_CASE("bust head: a figure with arms has no bust head (the stick figure's head is its rig's)") {
  const Drawing d("stick_figure.svg");
  CHECK(bust_head(d.rig).lobes.empty());
}

}  // TEST_SUITE
