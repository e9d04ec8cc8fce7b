// A crawl on legs walks (procedural/legged_crawl.h): a creature with legs drawn (parts of their
// own, or legs of its silhouette's skeleton) told to crawl or creep moves its legs in turn and
// goes steadily the way it is sent, its body not stretched as a caterpillar's; a legless body
// still crawls by the caterpillar's steps.
#include <doctest/doctest.h>

#include <algorithm>

#include "procedural/legged_crawl.h"
#include "procedural/motion_plan.h"

#include "motion_drawing.h"
using namespace svgm;
using svgm::test::Drawing;
using svgm::test::eye_tail_animal;

namespace {

const PlannedAction* find_action(const MotionPlan& plan, Primitive p, Target t) {
  for (const auto& a : plan.actions)
    if (a.primitive == p && a.target == t) return &a;
  return nullptr;
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("legged crawl: six legs drawn as strokes of their own walk in turn as the beetle crawls right") {
  const Drawing d("six_legged_bug.svg");
  std::string why;
  CHECK(walkable_legs(d.rig, &why) == 6);
  CHECK(why == "6 legs drawn as parts");
  for (const char* prompt : {"the beetle crawls to the right", "the beetle creeps to the right"}) {
    CAPTURE(prompt);
    const MotionPlan plan = plan_from_prompt(parse_prompt(prompt), d.rig, 1);
    const PlannedAction* legs = find_action(plan, Primitive::Swing, Target::Legs);
    REQUIRE(legs);
    CHECK(legs->verb == "walk");
    REQUIRE(legs->parts.size() == 6);
    // In turn: neighbours half a cycle apart, three and three.
    CHECK(std::count(legs->phase.begin(), legs->phase.end(), 0.0) == 3);
    CHECK(std::count(legs->phase.begin(), legs->phase.end(), 0.5) == 3);
    // The body goes right steadily; no caterpillar's stretch.
    const PlannedAction* slide = find_action(plan, Primitive::Slide, Target::Whole);
    REQUIRE(slide);
    CHECK(slide->direction == 1);
    CHECK(slide->goes);
    CHECK_FALSE(slide->inches);
    CHECK(find_action(plan, Primitive::Stretch, Target::Whole) == nullptr);
  }
}

TEST_CASE("legged crawl: legs of the silhouette's skeleton (one path) bend as the animal creeps") {
  const Drawing d = eye_tail_animal();  // four legs in the body's one path
  CHECK(walkable_legs(d.rig, nullptr) >= 2);
  const MotionPlan plan = plan_from_prompt(parse_prompt("the lizard creeps along"), d.rig, 1);
  const PlannedAction* legs = find_action(plan, Primitive::Swing, Target::Legs);
  REQUIRE(legs);
  CHECK(legs->silhouette);
  CHECK(legs->lobes.size() >= 2);
  CHECK(find_action(plan, Primitive::Stretch, Target::Whole) == nullptr);
}

TEST_CASE("legged crawl: a legless grub crawls by its steps, a fish's crawl is not a walk") {
  const Drawing grub("legless_grub.svg");
  CHECK(walkable_legs(grub.rig, nullptr) == 0);
  const MotionPlan plan = plan_from_prompt(parse_prompt("the grub crawls to the right"), grub.rig, 1);
  CHECK(find_action(plan, Primitive::Swing, Target::Legs) == nullptr);
  const PlannedAction* stretch = find_action(plan, Primitive::Stretch, Target::Whole);
  REQUIRE(stretch);
  CHECK(stretch->inches);
  // A snake's crawl on a drawing with legs stays the creep (its class has none to walk on), and
  // so does a caterpillar's (the lexicon's object: its prolegs are no legs to stride on).
  const Drawing bug("six_legged_bug.svg");
  for (const char* prompt : {"the snake crawls to the right", "the caterpillar crawls to the right"}) {
    CAPTURE(prompt);
    const MotionPlan creep = plan_from_prompt(parse_prompt(prompt), bug.rig, 1);
    CHECK(find_action(creep, Primitive::Swing, Target::Legs) == nullptr);
  }
  // A move of a part the clause names is that part's, not a crawl: "lowers" is WordNet's move,
  // and the giraffe lowering its neck had walked (the suite's tw_giraffe_neck).
  const Clause lowers = parse_prompt("the beetle lowers its head").clauses.at(0);
  REQUIRE(lowers.verbs.size() == 1);
  CHECK(lowers.verbs[0]->name == "move");
  CHECK(legged_crawl(lowers.verbs[0], lowers, bug.rig)->name == "move");
  const Clause crawls = parse_prompt("the beetle crawls along").clauses.at(0);
  REQUIRE(crawls.verbs.size() == 1);
  CHECK(legged_crawl(crawls.verbs[0], crawls, bug.rig)->name == "walk");
}

}  // TEST_SUITE
