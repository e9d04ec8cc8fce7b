// The scenery of a scene (procedural/scenery.h) and the backdrop rule it starts from
// (scene/backdrop.h): a carriage drawn on a meadow before a sky, the meadow grouped with the
// carriage, drives while the meadow and the sky stay; a climber drawn in one group with the rock
// face behind her climbs while the rock stays; a fairy whose wings fill her canvas (painted
// first, reaching three of its edges) keeps every part, as the pipeline reads her (with room).
#include <doctest/doctest.h>

#include <string>

#include "svgmotion/svg_reader.h"
#include "pipeline/canvas_room.h"
#include "procedural/motion_plan.h"
#include "procedural/scenery.h"
#include "scene/backdrop.h"

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

// A climber on a 36-unit canvas before a rock face: the rock (path 0) a quadrilateral along the
// left edge, the whole top-left and bottom-left, painted first; the climber on its right edge,
// every piece drawn in one group with the rock (as a grouper may leave them).
constexpr const char* kClimber = R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 36 36"><g>
  <path d="M0 0H20L24 36H0Z" fill="#99aab5"/>
  <rect x="24" y="9" width="6" height="14" fill="#fa743e"/><circle cx="27" cy="6" r="3.5" fill="#ffdc5d"/>
  <rect x="24" y="22" width="2" height="11" fill="#292f33"/><rect x="28" y="22" width="2" height="11" fill="#292f33"/>
  <path d="M24 12L20 6L21 5L25 11Z" fill="#ffdc5d"/></g></svg>)";

// A fairy on a 36-unit canvas whose wings fill it: the two wings (one group, painted first)
// reach the left, right and bottom edges with their tips; her body and head in front.
constexpr const char* kFairy = R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 36 36">
  <g><path d="M18 20L1 11L4 30L17 35Z" fill="#abdfff"/><path d="M18 20L35 11L32 30L19 35Z" fill="#abdfff"/></g>
  <g><rect x="14" y="14" width="8" height="16" fill="#fa743e"/></g>
  <g><circle cx="18" cy="8" r="5" fill="#ffdc5d"/></g></svg>)";

// The document as the pipeline reads it: a drawing filling its canvas is given room to move
// (pipeline/canvas_room.h), so the backdrop is judged on the middle of a larger canvas.
Scene with_room(const char* doc) {
  return read_svg_string(give_canvas_room(doc, "t.svg", read_svg_string(doc, "t.svg"), kAutoRoom), "t.svg");
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

TEST_CASE("scenery: a landscape in layers is cut by the frame as a whole: mountains and a meadow along the sides") {
  // The sky with its mountains (path 0) runs along the left side from y 30 to 94 (0.5 of it)
  // and the right from 40 (0.42): alone, the frame does not cut it enough for a backdrop
  // (kBackdropCut). With the meadow painted under it at the same edges (y 90 to 124) the
  // landscape runs along 0.73 of the left side: a scene, whose meadow and rails stay.
  auto doc = [](bool meadow_at_edges) {
    return std::string(R"(<svg xmlns="http://www.w3.org/2000/svg" width="128" height="128">
      <g><path d="M4 30L40 10L80 30L124 40L124 94L4 94Z" fill="#9cf"/></g><g>)") +
           (meadow_at_edges ? R"(<rect x="4" y="90" width="120" height="34" fill="#6a3"/>)" : R"(<rect x="20" y="96" width="88" height="20" fill="#6a3"/>)") +
           R"(<rect x="30" y="50" width="70" height="40" fill="#fd5"/>
              <circle cx="45" cy="92" r="7" fill="#333"/><circle cx="85" cy="92" r="7" fill="#333"/></g>
              <g><rect x="4" y="118" width="120" height="3" fill="#555"/></g></svg>)";
  };
  const Scene s = read_svg_string(doc(true), "landscape.svg");
  CHECK(frame_cut(s, {0}) < kBackdropCut);
  CHECK(frame_cut(s, {0, 1}) >= kBackdropCut);
  CHECK(scenery_paths(s) == std::vector<char>{1, 1, 0, 0, 0, 1});
  // The rails from edge to edge, a part of their own, stay with the background; the carriage drives.
  const Rig rig = build_rig(s, {});
  REQUIRE(rig.part_of_path.at(5) >= 0);
  CHECK(rig.parts[rig.part_of_path.at(5)].role == Role::Background);
  const MotionPlan plan = plan_from_prompt(parse_prompt("the carriage rolls to the right"), rig, 1);
  const std::vector<double> travel = test::path_travel(s, animate_plan(s, rig, plan, 13), 13);
  CHECK(travel[5] == 0);
  CHECK(travel[1] == 0);
  CHECK(travel[2] > 0);
  // A mat under the carriage that reaches no edge adds nothing the frame cuts: no scene.
  const Scene mat = read_svg_string(doc(false), "landscape.svg");
  CHECK(scenery_paths(mat) == std::vector<char>{0, 0, 0, 0, 0, 0});
}

TEST_CASE("scenery: the frame cuts a rock face along its sides; the climber grouped with it climbs, the rock stays") {
  const Scene s = with_room(kClimber);
  REQUIRE(s.room == doctest::Approx(kAutoRoom));
  // The rock's outline runs along the whole left side (the top from 0 to 20, the bottom from 0
  // to 24) of the drawing's own 36-unit canvas.
  CHECK(frame_cut(s, {0}) == doctest::Approx(1).epsilon(0.01));
  CHECK(frame_cut(s, {1}) == 0);  // the climber's body
  CHECK(scenery_paths(s) == std::vector<char>{1, 0, 0, 0, 0, 0});
  const Rig rig = build_rig(s, {});
  const int rock = rig.part_of_path.at(0), body = rig.part_of_path.at(1);
  REQUIRE(rock >= 0);
  REQUIRE(body >= 0);
  CHECK(rock != body);
  CHECK(rig.parts[rock].role == Role::Background);
  CHECK(rig.parts[body].role != Role::Background);
  const MotionPlan plan = plan_from_prompt(parse_prompt("she climbs up the rock face"), rig, 1);
  const int F = 13;
  const std::vector<double> travel = test::path_travel(s, animate_plan(s, rig, plan, F), F);
  CHECK(travel[0] == 0);  // the rock
  CHECK(travel[1] > 0);   // the climber's body
}

TEST_CASE("scenery: wings filling the canvas at their tips are the figure's, not its backdrop") {
  const Scene s = with_room(kFairy);
  REQUIRE(s.room == doctest::Approx(kAutoRoom));
  // The box rule alone takes the wings for a backdrop: together 34 x 24 of the 36 x 36 canvas
  // (63 %), reaching the left, right and bottom edges, painted first.
  CHECK(is_backdrop(1, 11, 35, 35, 0.125, 36, 36));
  // The frame touches them only at their tips (2.4 units of the left and of the right side,
  // with the outline sampled at eighths of its segments): no backdrop.
  CHECK(frame_cut(s, {0, 1}) < kBackdropCut);
  const double o = kAutoRoom * 36;  // the drawing's canvas starts here on the larger one
  CHECK_FALSE(is_backdrop(s, {0, 1}, 1 + o, 11 + o, 35 + o, 35 + o, 0.125));
  CHECK(scenery_paths(s) == std::vector<char>{0, 0, 0, 0});
  const Rig rig = build_rig(s, {});
  for (const RigPart& P : rig.parts) CHECK_MESSAGE(P.role != Role::Background, P.name);
  // Floating up, the whole figure moves: the wings too (as a backdrop they stayed behind).
  const MotionPlan plan = plan_from_prompt(parse_prompt("the fairy floats up"), rig, 1);
  const int F = 13;
  const std::vector<double> travel = test::path_travel(s, animate_plan(s, rig, plan, F), F);
  CHECK(travel[0] > 0);  // both wings
  CHECK(travel[1] > 0);
}

TEST_CASE("scenery: a long thin figure spanning its canvas, with only its eye and tongue besides, is the figure") {
  // A snake's body arching over the canvas (painted first, 90 % of the canvas by its box, its
  // back along the left and the right edges for nine tenths of them), its tongue and its eye:
  // 43 units of area beside its 3750.
  auto scene = [](const char* more) {
    return read_svg_string(std::string(R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
        <g><path d="M 0 100 L 0 10 L 100 10 L 100 100 L 85 100 L 85 25 L 15 25 L 15 100 Z" fill="#7b5"/></g>
        <g><path d="M 20 2 L 30 5 L 20 8 Z" fill="#d24"/></g>
        <g><circle cx="10" cy="17" r="2" fill="#000"/></g>)") + more + "</svg>", "snake.svg");
  };
  const Scene s = scene("");
  REQUIRE(is_backdrop(s, {0}, 0, 10, 100, 100, 0.0));  // the backdrop rule alone takes it
  const Rig rig = build_rig(s, {});
  for (const RigPart& P : rig.parts) CHECK_MESSAGE(P.role != Role::Background, P.name);
  CHECK(rig.figure.x0 == doctest::Approx(0));
  CHECK(rig.figure.y1 == doctest::Approx(100));
  // A figure of its own before the same shape (a third of its area): the shape is its backdrop.
  const Scene f = scene(R"(<g><rect x="35" y="40" width="30" height="40" fill="#c33"/></g>)");
  const Rig frig = build_rig(f, {});
  REQUIRE(frig.parts.size() == 4);
  CHECK(frig.parts[0].role == Role::Background);
  CHECK(frig.parts[3].role != Role::Background);
}

}  // TEST_SUITE
