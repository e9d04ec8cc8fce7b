// A figure told it leaves ("sails away", "drives away", "flies off": procedural/leave_way.h) goes
// steadily the way it faces or its nose points, a travel's distance, and glides back; "away" was
// read as a depth nothing drew (the van slid its drive's 10 % both ways, the rocket only bobbed).
// "off the table" says where from, not that it leaves.
#include <doctest/doctest.h>

#include <cmath>

#include "procedural/gait_travel.h"
#include "procedural/leave_way.h"
#include "procedural/motion_plan.h"
#include "procedural/travel_words.h"

#include "motion_drawing.h"
#include "wordnet_or_skip.h"

using namespace svgm;
using svgm::test::Drawing;
using svgm::test::mirrored_drawing;

namespace {

// The whole figure's slides that go somewhere (PlannedAction::goes), as their directions.
std::vector<int> going_ways(const MotionPlan& plan) {
  std::vector<int> out;
  for (const auto& a : plan.actions)
    if (a.primitive == Primitive::Slide && a.parts.empty() && a.goes && a.amp >= kTravelReach) out.push_back(a.direction);
  return out;
}


bool leaves(const char* prompt) {
  const ParsedPrompt p = parse_prompt(prompt);
  for (const Clause& c : p.clauses)
    if (says_leaving(c)) return true;
  return false;
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("leave way: 'away' and 'off' after a verb that gets somewhere say the figure leaves; 'off the table' does not") {
  CHECK(leaves("the ship sails away"));
  CHECK(leaves("the van drives off"));
  CHECK(leaves("the plane flies off into the sky"));
  CHECK_FALSE(leaves("the ship rocks on the waves"));
  CHECK_FALSE(leaves("the cat jumps off the table"));
  CHECK_FALSE(leaves("the flag waves"));
  // A launch's own "off" is the launch's (flight_aim.h), not a leaving.
  CHECK_FALSE(leaves("the flying saucer blasts off"));
  CHECK_FALSE(leaves("the jet takes off into the sky"));
  // It travels across: the pipeline gives it room (travel_words.h).
  CHECK(sends_figure_across(parse_prompt("the ship sails away")));
}

TEST_CASE("leave way: a van facing left drives away to the left, facing right to the right, a travel's distance") {
  for (const char* prompt : {"the van drives away", "the van speeds away"}) {
    CAPTURE(prompt);
    const Drawing left("van_side.svg"), right("van_side_right.svg");
    CHECK(going_ways(plan_from_prompt(parse_prompt(prompt), left.rig, 1)) == std::vector<int>{-1});
    CHECK(going_ways(plan_from_prompt(parse_prompt(prompt), right.rig, 1)) == std::vector<int>{1});
  }
  // Kept where it is, it does not leave.
  const Drawing left("van_side.svg");
  CHECK(going_ways(plan_from_prompt(parse_prompt("the van drives away on the spot"), left.rig, 1)).empty());
}

TEST_CASE("leave way: a rocket with no facing flies off nose first: up and right goes right, mirrored goes left") {
  if (!wordnet_or_skip()) return;
  const Drawing d("rocket_slant.svg");
  std::string why;
  const ParsedPrompt p = parse_prompt("the rocket flies off");
  REQUIRE(!p.clauses.empty());
  CHECK(leaving_side(p, p.clauses[0], d.rig, &why) == 1);
  CAPTURE(why);
  CHECK(going_ways(plan_from_prompt(p, d.rig, 1)) == std::vector<int>{1});
  const Drawing m = mirrored_drawing("rocket_slant.svg");
  CHECK(leaving_side(p, p.clauses[0], m.rig, &why) == -1);
  CHECK(going_ways(plan_from_prompt(p, m.rig, 1)) == std::vector<int>{-1});
}

TEST_CASE("leave way: a boat sailing away leaves its sea where it is, as a launch leaves its ground") {
  if (!wordnet_or_skip()) return;
  const Drawing d("boat_on_sea.svg");
  const ParsedPrompt p = parse_prompt("the boat sails away");
  MotionPlan plan = plan_from_prompt(p, d.rig, 1);
  CHECK(going_ways(plan).size() == 1);
  const int F = 13;
  fit_plan(d.scene, d.rig, plan, F, 9);
  const std::vector<double> moved = d.travel(plan, F);
  CAPTURE(moved[0]);
  CAPTURE(moved[1]);
  CHECK(moved[0] < 0.5);  // the sea (path 0) stays
  CHECK(moved[1] > 3);    // the hull goes (a travel of 15 % of the figure's 100 units, less what the canvas keeps)
}

}  // TEST_SUITE
