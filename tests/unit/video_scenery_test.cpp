// The scenery of a scene (procedural/scenery.h): a carriage drawn on a meadow before a sky, the
// meadow grouped with the carriage, drives while the meadow and the sky stay.
#include <doctest/doctest.h>

#include <string>

#include "svgmotion/svg_reader.h"
#include "procedural/motion_plan.h"
#include "procedural/scenery.h"

#include "motion_drawing.h"

using namespace svgm;

namespace {

// A sky (a backdrop: most of the canvas, at its edges, painted first) and, in one group, a
// meadow from edge to edge, a carriage's body and its two wheels. `sky` false leaves it out.
std::string carriage_scene(bool sky) {
  return std::string(R"(<svg xmlns="http://www.w3.org/2000/svg" width="128" height="128">)") +
         (sky ? R"(<g><rect x="4" y="4" width="120" height="90" fill="#9cf"/></g>)" : "") +
         R"(<g><rect x="4" y="90" width="120" height="34" fill="#6a3"/>
               <rect x="30" y="50" width="70" height="40" fill="#fd5"/>
               <circle cx="45" cy="92" r="7" fill="#333"/><circle cx="85" cy="92" r="7" fill="#333"/></g></svg>)";
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("scenery: the meadow grouped with a carriage in a scene stays while the carriage drives; no sky, no scene") {
  const Scene s = read_svg_string(carriage_scene(true), "carriage.svg");
  CHECK(scenery_paths(s) == std::vector<char>{1, 1, 0, 0, 0});  // the sky, the meadow
  const Rig rig = build_rig(s, {});
  const int meadow = rig.part_of_path.at(1), body = rig.part_of_path.at(2);
  REQUIRE(meadow >= 0);
  REQUIRE(body >= 0);
  CHECK(meadow != body);
  CHECK(rig.parts[meadow].role == Role::Background);
  CHECK(rig.parts[body].role != Role::Background);
  const MotionPlan plan = plan_from_prompt(parse_prompt("the carriage rolls to the right"), rig, 1);
  const int F = 13;
  const std::vector<double> travel = test::path_travel(s, animate_plan(s, rig, plan, F), F);
  CHECK(travel[1] == 0);  // the meadow
  CHECK(travel[2] > 0);   // the carriage's body (the canvas leaves it little room)
  // Without the sky the drawing is no scene: nothing is scenery, the group stays one part.
  const Scene plain = read_svg_string(carriage_scene(false), "carriage.svg");
  CHECK(scenery_paths(plain) == std::vector<char>{0, 0, 0, 0});
}

}  // TEST_SUITE
