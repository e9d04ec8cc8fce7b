// A plant sways from where it is held (procedural/sway_base.h): the mouth of its pot, or its
// stem's foot when nothing holds it, each point turning about there by the sway's angle times its
// height over the plant's. The drawings (tests/data/motion, made for these tests) are a sprout in
// a pot with a rim and a seedling standing alone; a figure that is no plant keeps the lean about
// its middle.
#include <doctest/doctest.h>

#include <cmath>

#include "procedural/motion_plan.h"
#include "procedural/motion_plan_internal.h"
#include "procedural/sway_base.h"

#include "motion_drawing.h"
using namespace svgm;
using svgm::test::Drawing;

namespace {

// The one action of `words` said of drawing `d`, checked to be a sway of the whole plant.
PlannedAction plant_sway(const Drawing& d, const char* words) {
  const ParsedPrompt prompt = parse_prompt(words);
  REQUIRE(prompt.clauses[0].figure == FigureClass::Plant);
  const MotionPlan plan = plan_from_prompt(prompt, d.rig, 1);
  REQUIRE(plan.actions.size() == 1);
  CHECK(plan.actions[0].primitive == Primitive::Sway);
  CHECK(plan.actions[0].target == Target::Whole);
  return plan.actions[0];
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("plant sway: a potted sprout sways from its pot's mouth (the rim's top middle); the pot holds") {
  const Drawing d("potted_sprout.svg");
  const PlantBase base = plant_base(d.rig);
  CHECK(base.held);
  CHECK(base.root.x == doctest::Approx(100));
  CHECK(base.root.y == doctest::Approx(130).epsilon(0.01));
  const PlannedAction a = plant_sway(d, "the tulip sways in the breeze");
  CHECK(a.rooted);
  CHECK(a.root.y == doctest::Approx(130).epsilon(0.01));
  MotionPlan plan;
  plan.actions = {a};
  const std::vector<double> t = d.travel(plan);
  CHECK(t[0] == 0.0);  // the pot's body
  CHECK(t[1] == 0.0);  // its rim
  CHECK(t[3] > 3.0);   // the leaf at the top
}

TEST_CASE("plant sway: a seedling held by nothing sways from its stem's foot, its lower stem bending too") {
  const Drawing d("seedling_stem.svg");
  const PlantBase base = plant_base(d.rig);
  CHECK_FALSE(base.held);
  CHECK(base.root.x == doctest::Approx(100));
  CHECK(base.root.y == doctest::Approx(190).epsilon(0.01));
  const PlannedAction a = plant_sway(d, "the seedling sways gently");
  CHECK(a.rooted);
  CHECK(a.root.y == doctest::Approx(190).epsilon(0.01));
}

TEST_CASE("plant sway: each point turns about the root by the angle times its height over the plant's") {
  PlannedAction a;
  a.primitive = Primitive::Sway;
  a.rooted = true;
  a.root = {100, 190};
  a.direction = 1;
  a.cycles = 1;
  RigBox box;
  box.add(Vec2{60, 20});
  box.add(Vec2{140, 190});
  // At t = 0.25 the sway is at its peak (sin 90 degrees): the whole 10 degrees at the top.
  const double r = M_PI / 180;
  const Vec2 mid = sway_lean(a, 10, 0.25, box, {100, 105});  // half way up: 5 degrees
  CHECK(mid.x == doctest::Approx(100 + 85 * std::sin(5 * r)));
  CHECK(mid.y == doctest::Approx(190 - 85 * std::cos(5 * r)));
  const Vec2 top = sway_lean(a, 10, 0.25, box, {100, 20});  // the top: 10 degrees
  CHECK(top.x == doctest::Approx(100 + 170 * std::sin(10 * r)));
  const Vec2 below = sway_lean(a, 10, 0.25, box, {120, 195});  // below the root: holds
  CHECK(below.x == 120.0);
  CHECK(below.y == 195.0);
}

TEST_CASE("plant sway: a figure that is no plant still leans its top about its middle") {
  const Drawing d("seedling_stem.svg");
  const MotionPlan plan = plan_from_prompt(parse_prompt("the bottle sways"), d.rig, 1);
  REQUIRE(plan.actions.size() == 1);
  CHECK(plan.actions[0].primitive == Primitive::Sway);
  CHECK_FALSE(plan.actions[0].rooted);
}

}  // TEST_SUITE
