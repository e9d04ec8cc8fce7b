// A figure on wheels gets somewhere by its wheels (self_movers.h's wheeled_travel): a verb that
// carries a figure along by other means (the generic move WordNet reads "pulls away" and
// "trundles" as, a glide, a flight, a gait of legs) is its drive, its wheels rolling as the body
// slides; a bus and a train (WordNet's public transport) are wheeled. Before, "the taxi pulls
// away" slid and stretched the car with its wheels still, "the racing car zooms off" bent its
// lower part for legs and bobbed it as in flight, and the bus was an object. Needs WordNet for
// the readings of "pulls away", "trundles", "zooms" and "bus".
#include <doctest/doctest.h>

#include "motion/lexicon.h"
#include "procedural/motion_plan.h"
#include "procedural/self_movers.h"

#include "motion_drawing.h"
#include "wordnet_or_skip.h"

using namespace svgm;
using svgm::test::Drawing;

namespace {

// The plan's actions as "primitive:target" in order, and whether its wheel spin rolls.
std::string actions_of(const MotionPlan& plan, bool* rolls = nullptr) {
  std::string s;
  for (const auto& a : plan.actions) {
    s += (s.empty() ? "" : " ") + std::string(primitive_name(a.primitive)) + ":" + (a.target == Target::Whole ? "whole" : a.target == Target::Wheels ? "wheels" : "other");
    if (rolls && a.primitive == Primitive::Spin) *rolls = a.rolls;
  }
  return s;
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("a wheeled figure's move, glide, flight or gait is its drive: its wheels roll as it slides") {
  if (!wordnet_or_skip()) return;
  const Drawing car("car.svg");  // a body and two spoked wheels (tests/data/motion/car.svg)
  const MotionPlan drive = plan_from_prompt(parse_prompt("the car drives to the left"), car.rig, 1);
  bool rolls = false;
  REQUIRE(actions_of(drive, &rolls) == "shake:whole spin:wheels slide:whole");
  CHECK(rolls);
  for (const char* prompt : {"the taxi pulls away to the left", "the tractor trundles along to the left", "the car moves to the left",
                             "the racing car zooms off to the left", "the car glides to the left", "the car runs to the left"}) {
    CAPTURE(prompt);
    const MotionPlan plan = plan_from_prompt(parse_prompt(prompt), car.rig, 1);
    bool r = false;
    CHECK(actions_of(plan, &r) == actions_of(drive));
    CHECK(r);
    for (const auto& a : plan.actions)
      if (a.primitive == Primitive::Slide) CHECK(a.direction == -1);
  }
  // Verbs of its own stay: a hop, a spin of the wheels in place, a rock.
  CHECK(actions_of(plan_from_prompt(parse_prompt("the car's wheels spin"), car.rig, 1)) == "spin:wheels");
  CHECK(actions_of(plan_from_prompt(parse_prompt("the car rocks"), car.rig, 1)) == "rock:whole");
  // Said of a person, a move is a move (a slide and the stretch of a creep), not a drive.
  const Clause person = parse_prompt("the man moves to the left").clauses.at(0);
  REQUIRE(person.verbs.size() == 1);
  CHECK(wheeled_travel(person.verbs[0], person)->name == "move");
}

}  // TEST_SUITE
