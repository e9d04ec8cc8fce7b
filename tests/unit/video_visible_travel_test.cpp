// The visible-travel floor of fit_plan (issue 35, item 4): a motion too small to see is raised
// to 8 % of the figure's diagonal when the canvas allows, whatever its primitive (a whole
// figure's bob, a part's swing whose chord grows slower than its angle), a clause the fitter's
// steps would cut below the floor is slowed instead, and a figure filling its canvas ends under
// the floor with a warning that names the canvas.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "svgmotion/svg_reader.h"
#include "procedural/motion_plan.h"

#include "motion_drawing.h"
using namespace svgm;

namespace {

constexpr int kFrames = 49;  // the default clip
constexpr int kKeyframes = 15;

double largest(const Scene& s, const Rig& rig, const MotionPlan& plan) {
  double m = 0;
  for (double v : test::path_travel(s, animate_plan(s, rig, plan, kFrames), kFrames)) m = std::max(m, v);
  return m;
}

double diagonal(const Rig& rig) { return std::hypot(rig.figure.w(), rig.figure.h()); }

bool has_line(const std::vector<std::string>& lines, const std::string& part) {
  return std::any_of(lines.begin(), lines.end(), [&](const std::string& l) { return l.find(part) != std::string::npos; });
}

// A round float (a ball) `h` units tall in the middle of a 200 x 200 canvas.
Scene ball(double h) {
  const double r = h / 2, top = 100 - r, bottom = 100 + r;
  char svg[400];
  std::snprintf(svg, sizeof svg,
                "<svg xmlns='http://www.w3.org/2000/svg' width='200' height='200'>"
                "<path fill='#d33' d='M100 %g A%g %g 0 1 1 100 %g A%g %g 0 1 1 100 %g Z'/></svg>",
                top, r, r, bottom, r, r, top);
  return read_svg_string(svg, "ball.svg");
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("a whole figure's bob of 3 % of its size is raised to at least 8 % when the canvas allows") {
  // A ball a third of its canvas: bobbing 0.04 of its height moves it 2.8 % of its diagonal.
  const Scene s = ball(60);
  const Rig rig = build_rig(s, {});
  MotionPlan plan = plan_from_prompt(parse_prompt("it bobs on the water"), rig, 1);
  REQUIRE(plan.actions.size() == 1);
  REQUIRE(plan.actions[0].primitive == Primitive::Bob);
  const double before = largest(s, rig, plan);
  REQUIRE(before < 0.04 * diagonal(rig));  // the drawing makes the test mean something
  fit_plan(s, rig, plan, kFrames, kKeyframes);
  // Raised, and kept raised: a whole-figure motion with no limbs beside it is no limb's accent
  // (set back to 100 % before, 2.8 % of the ball's size).
  CHECK(largest(s, rig, plan) >= 0.08 * diagonal(rig));
  CHECK(plan.actions[0].scale > 2);
  CHECK(plan.warnings.empty());
  CHECK(has_line(plan.notes, "bob raised to"));
}

TEST_CASE("a part's swing is raised to the floor, not short of it: its chord grows slower than its angle") {
  const test::Drawing d("stick_figure.svg");
  // A slight nod: the head turns by about 6 degrees about its neck; raised once by floor /
  // travel it reached about 99 % of the floor.
  MotionPlan plan = plan_from_prompt(parse_prompt("he nods his head slightly"), d.rig, 1);
  REQUIRE(plan.actions.size() == 1);
  REQUIRE(largest(d.scene, d.rig, plan) < 0.08 * diagonal(d.rig));
  fit_plan(d.scene, d.rig, plan, kFrames, kKeyframes);
  CHECK(largest(d.scene, d.rig, plan) >= 0.08 * diagonal(d.rig));
  CHECK(plan.actions[0].scale <= 4.0);
}

TEST_CASE("a figure filling its canvas stays under the floor, and a warning names the canvas") {
  // The ball is 180 of the canvas's 200 units tall: a bob of 8 % of its size would take it out
  // of the picture.
  const Scene s = ball(180);
  const Rig rig = build_rig(s, {});
  MotionPlan plan = plan_from_prompt(parse_prompt("it bobs on the water"), rig, 1);
  fit_plan(s, rig, plan, kFrames, kKeyframes);
  const double travel = largest(s, rig, plan);
  REQUIRE(travel < 0.08 * diagonal(rig));
  REQUIRE(travel > 0);
  char expected[120];
  std::snprintf(expected, sizeof expected, "bob held to %.1f %% of the figure's size by the canvas", 100 * travel / diagonal(rig));
  CHECK(has_line(plan.warnings, expected));
}

TEST_CASE("a clause the fitter's steps would cut under the floor is slowed, not cut") {
  const test::Drawing d("stick_figure.svg");
  // A nod, twice a loop, raised to the floor: between the 9 keyframes a short fit may take (5
  // given) the head turns too far to follow; cut to follow, it moved 6.4 % of the figure's size.
  // Once a loop, it keeps the floor.
  MotionPlan plan = plan_from_prompt(parse_prompt("he nods his head"), d.rig, 1);
  REQUIRE(plan.actions.size() == 1);
  const int cycles = plan.actions[0].cycles;
  REQUIRE(cycles == 2);
  fit_plan(d.scene, d.rig, plan, kFrames, 5);
  CHECK(plan.actions[0].cycles == 1);
  CHECK(has_line(plan.notes, "nod slowed to 1 cycles a loop instead of 2"));
  CHECK(largest(d.scene, d.rig, plan) >= 0.08 * diagonal(d.rig));
  CHECK(plan.warnings.empty());
}

TEST_CASE("a figure bobbing on a ground the prompt names rises from it, to the floor, and never sinks into it") {
  // A hull (30-70 x 55-66) whose bottom lies behind a sea band drawn after it (0-100 x 62-95),
  // and a sail: bobbing down by 8 % of the boat, its 7 units above the water went under.
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
           <path d="M 20 55 L 80 55 L 70 66 L 30 66 Z" fill="#a63"/>
           <path d="M 50 10 L 50 52 L 20 52 Z" fill="#ddd"/>
           <path d="M 0 62 L 100 62 L 100 95 L 0 95 Z" fill="#8cf"/></svg>)", "boat.svg");
  const Rig rig = build_rig(s, {});
  MotionPlan plan = plan_from_prompt(parse_prompt("the sailboat bobs on the waves"), rig, 1);
  REQUIRE(plan.ground == "on the waves");
  fit_plan(s, rig, plan, kFrames, kKeyframes);
  const std::vector<Vec2> pts = animate_plan(s, rig, plan, kFrames);
  const size_t per = pts.size() / kFrames;
  double lowest = 0, rise = 0;  // the hull's (path 0) largest move down and up from rest
  for (int f = 0; f < kFrames; ++f)
    for (size_t i = 0; i < s.paths[0].subpaths[0].points.size(); ++i) {
      lowest = std::max(lowest, pts[f * per + i].y - pts[i].y);
      rise = std::max(rise, pts[i].y - pts[f * per + i].y);
    }
  CHECK(lowest < 1e-9);
  const double boat = std::hypot(60.0, 56.0);  // the hull and sail: 20-80 x 10-66
  CHECK(rise >= 0.08 * boat);
  CHECK(has_line(plan.notes, "rises from the waves"));
}

TEST_CASE("a shake of 1 % of the figure's size is raised past four times to the floor") {
  // A ball a third of its canvas shaking 0.012 of its height: 0.85 % of its diagonal. Raised
  // at most four times (the limit before) it stayed at 3.4 %; the canvas and the fitter's
  // steps allow the floor.
  const Scene s = ball(60);
  const Rig rig = build_rig(s, {});
  MotionPlan plan = plan_from_prompt(parse_prompt("it shakes"), rig, 1);
  REQUIRE(plan.actions.size() == 1);
  REQUIRE(plan.actions[0].primitive == Primitive::Shake);
  const double before = largest(s, rig, plan);
  REQUIRE(before < 0.02 * diagonal(rig));  // the drawing makes the test mean something
  fit_plan(s, rig, plan, kFrames, kKeyframes);
  CHECK(plan.actions[0].scale > 4);
  CHECK(largest(s, rig, plan) >= 0.08 * diagonal(rig));
  CHECK(plan.warnings.empty());
}

TEST_CASE("a raised turn stops at a quarter turn, and a warning says the raise held it under the floor") {
  // A tall body (40 x 200) and a flat head on it (18 x 5), its neck about the middle of its
  // bottom: its corners lie about 10.3 units from there, and at 90 degrees they move about
  // 14.6 (the radius times the square root of 2), under the floor of 8 % of the figure's 208.9
  // units (16.7).
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="260">
           <g><path d="M 80 40 L 120 40 L 120 240 L 80 240 Z" fill="#a60"/></g>
           <g><path d="M 91 35 L 109 35 L 109 40 L 91 40 Z" fill="#fc9"/></g></svg>)", "tall.svg");
  const Rig rig = build_rig(s, {});
  MotionPlan plan = plan_from_prompt(parse_prompt("he nods his head"), rig, 1);
  REQUIRE(plan.actions.size() == 1);
  INFO(plan.actions[0].why);
  REQUIRE(plan.actions[0].parts.size() == 1);
  REQUIRE(rig.parts[plan.actions[0].parts[0]].role == Role::Head);
  const double asked = plan.amplitude(plan.actions[0]);
  REQUIRE(asked < 22.5);  // raised four times (the limit before) it would not reach 90 degrees,
  REQUIRE(12 * asked > 90);  // twelve times it would pass it
  // Keyframes enough for a quarter turn (at 15 the step between two of them cuts it to 72).
  const int F = 97;
  fit_plan(s, rig, plan, F, 49);
  CHECK(plan.amplitude(plan.actions[0]) == doctest::Approx(90));
  double travel = 0;
  for (double v : test::path_travel(s, animate_plan(s, rig, plan, F), F)) travel = std::max(travel, v);
  CHECK(travel < 0.08 * diagonal(rig));
  CHECK(travel > 0.8 * 0.08 * diagonal(rig));  // about the radius times the square root of 2
  CHECK(has_line(plan.warnings, "by the largest raise (12 times, turns to 90 degrees), under the 8 %"));
}

}  // TEST_SUITE
