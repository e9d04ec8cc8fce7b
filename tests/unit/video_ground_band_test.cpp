// The ground a vehicle goes on (procedural/support_band.h): a thing sent a way told ("the boat
// sails away to the left") leaves its sea where it is, as a leaving untold does; a tall sea the
// boat stands on is ground though it starts high in the drawing; two wheels drawn as one path
// are not ground (a scooter's wheels stayed while its body crept off), nor is a vehicle's body
// that reaches its bottom with its windows within, nor a hull drawn down past its sea.
#include <doctest/doctest.h>

#include "procedural/motion_plan.h"
#include "procedural/support_band.h"

#include "motion_drawing.h"
#include "wordnet_or_skip.h"

using namespace svgm;
using svgm::test::Drawing;

TEST_SUITE("video") {

TEST_CASE("ground band: a boat sent a way told leaves its sea where it is; a creature's told gait keeps its band") {
  if (!wordnet_or_skip()) return;
  const Drawing d("boat_on_sea.svg");
  for (const char* prompt : {"the boat sails away to the left", "the boat sails to the right", "the boat glides to the left"}) {
    CAPTURE(prompt);
    MotionPlan plan = plan_from_prompt(parse_prompt(prompt), d.rig, 1);
    CHECK(plan.ground == "along the ground");
    const int F = 13;
    fit_plan(d.scene, d.rig, plan, F, 9);
    const std::vector<double> moved = d.travel(plan, F);
    CAPTURE(moved[0]);
    CAPTURE(moved[1]);
    CHECK(moved[0] < 0.5);  // the sea (path 0) stays
    CHECK(moved[1] > 3);    // the hull goes
  }
  // Rocking on the spot is no travel: the prompt names no ground, none is read.
  CHECK(plan_from_prompt(parse_prompt("the boat rocks"), d.rig, 1).ground.empty());
  // A creature's gait told a way goes with what is drawn under it (a board, skis).
  CHECK(plan_from_prompt(parse_prompt("the dog walks to the left"), d.rig, 1).ground.empty());
}

TEST_CASE("ground band: a hull drawn down past its sea is not the ground of a ship sent a way told: the hull goes") {
  if (!wordnet_or_skip()) return;
  const Drawing d("ship_hull_below_sea.svg");
  REQUIRE(d.scene.paths.size() == 4);
  MotionPlan plan = plan_from_prompt(parse_prompt("the ship sails to the left"), d.rig, 1);
  REQUIRE(plan.ground == kAlongGround);
  // The stripe lies within the hull, the cabin and the sea do not: the rest does not stand on it.
  CHECK(support_paths(d.scene, d.rig, plan.ground) == std::vector<char>{0, 0, 0, 0});
  const int F = 13;
  fit_plan(d.scene, d.rig, plan, F, 9);
  const std::vector<double> moved = d.travel(plan, F);
  CAPTURE(moved[0]);
  CHECK(moved[0] > 3);  // the hull (path 0) goes with its cabin
  CHECK(moved[2] > 3);
}

TEST_CASE("ground band: a sea taller than the drawing's lower 60 % is ground when the boat stands on it") {
  const Drawing d("boat_tall_sea.svg");
  // Sea 0-100 x 28-60 (its top 18 units below the figure's top at 10: 0.36 of the height 50),
  // the wave line within it; the hull dips 8 units into it, the cabin above.
  REQUIRE(d.scene.paths.size() == 4);
  CHECK(support_paths(d.scene, d.rig) == std::vector<char>{1, 1, 0, 0});
  CHECK(support_paths(d.rig) == std::vector<char>{1, 1, 0, 0});
}

TEST_CASE("ground band: two wheels drawn as one path span the bottom in two pieces: no ground") {
  const Drawing d("scooter_wheels_path.svg");
  REQUIRE(d.scene.paths.size() == 3);
  CHECK(support_paths(d.scene, d.rig) == std::vector<char>{0, 0, 0});
  CHECK(support_paths(d.rig) == std::vector<char>{0, 0, 0});
}

TEST_CASE("ground band: a bus body reaching its bottom, its windows within, is no ground") {
  const Drawing d("bus_body_low.svg");
  REQUIRE(d.scene.paths.size() == 4);
  CHECK(support_paths(d.scene, d.rig) == std::vector<char>{0, 0, 0, 0});
}

}  // TEST_SUITE
