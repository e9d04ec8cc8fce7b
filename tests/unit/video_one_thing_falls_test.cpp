// One thing drawn in similar pieces falls whole (procedural/self_movers.h's
// repeated_are_the_figure): a snowflake drawn as eight small pieces round its middle tumbles as
// one, where its pieces had dropped apart from each other as rain; drops under an umbrella still
// fall one by one.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "procedural/motion_plan.h"
#include "procedural/self_movers.h"
#include "svgmotion/svg_reader.h"

#include "motion_drawing.h"
using namespace svgm;
using svgm::test::Drawing;

TEST_SUITE("video") {

TEST_CASE("one thing falls: eight small pieces round a middle are one flake that tumbles whole") {
  // Eight 12 x 12 squares on a ring of radius 50 about (100, 100).
  std::string svg = R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">)";
  for (int k = 0; k < 8; ++k) {
    const double a = k * M_PI / 4, x = 100 + 50 * std::cos(a), y = 100 + 50 * std::sin(a);
    svg += "<g><rect x=\"" + std::to_string(x - 6) + "\" y=\"" + std::to_string(y - 6) + "\" width=\"12\" height=\"12\" fill=\"#46c\"/></g>";
  }
  svg += "</svg>";
  const Scene s = read_svg_string(svg, "flake.svg");
  const Rig rig = build_rig(s, {});
  REQUIRE(rig.repeated.size() == 8);
  CHECK(repeated_are_the_figure(rig));
  const MotionPlan plan = plan_from_prompt(parse_prompt("the snowflake falls"), rig, 1);
  REQUIRE(!plan.actions.empty());
  for (const PlannedAction& a : plan.actions) {
    CHECK(a.verb == "tumble");
    CHECK(a.target == Target::Whole);
    CHECK(a.primitive != Primitive::Fall);
  }
}

TEST_CASE("one thing falls: drops under an umbrella are not the figure; they fall one by one") {
  const Drawing d("rain_scene.svg");
  REQUIRE(d.rig.repeated.size() >= 3);
  CHECK(!repeated_are_the_figure(d.rig));
  const MotionPlan plan = plan_from_prompt(parse_prompt("rain falls on the umbrella"), d.rig, 1);
  REQUIRE(!plan.actions.empty());
  CHECK(plan.actions[0].primitive == Primitive::Fall);
  CHECK(plan.actions[0].target == Target::Repeated);
}

}  // TEST_SUITE
