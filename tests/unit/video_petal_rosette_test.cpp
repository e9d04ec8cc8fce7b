// The petals a prompt names (procedural/petal_rosette.h) on a daisy made for this test, drawn in
// one group so the rig has no part for its petals: the head of petals and its heart spread from
// the flower's centre, the stem and the leaf hold still.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "svgmotion/svg_reader.h"
#include "procedural/motion_plan.h"
#include "procedural/part_locator.h"
#include "procedural/petal_rosette.h"

#include "motion_drawing.h"
using namespace svgm;
using svgm::test::Drawing;
using svgm::test::path_travel;

namespace {

std::string data(const char* name) { return test::motion_data(name); }

// Largest displacement from frame 0 of the points of each scene path over `plan`'s frames.
std::vector<double> travel(const Scene& scene, const Rig& rig, const MotionPlan& plan, int F = 13) {
  return path_travel(scene, animate_plan(scene, rig, plan, F), F);
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("petals: a daisy's petals open, spreading from its centre; the stem and the leaf hold") {
  const Scene scene = read_svg_file(data("daisy_petals.svg"));
  const Rig rig = build_rig(scene, read_source_names(data("daisy_petals.svg")));
  CHECK(part_shape_of("petals", FigureClass::Plant) == PartShape::Petals);
  const MotionPlan plan = plan_from_prompt(parse_prompt("the petals open"), rig, 1);
  REQUIRE(plan.actions.size() == 1);
  const PlannedAction& a = plan.actions[0];
  CHECK(a.region == Region::Located);
  CHECK(a.primitive == Primitive::Pulse);
  CHECK(a.lobe_paths == std::vector<int>{2, 3});  // the petals and their heart
  REQUIRE(a.lobes.size() == 1);
  CHECK(a.lobes[0].pivot.x == doctest::Approx(120).epsilon(0.01));
  CHECK(a.lobes[0].pivot.y == doctest::Approx(70).epsilon(0.01));
  CHECK(a.why.find("the petals found as petals: an outline of 6 petals round its middle (path 3 at") != std::string::npos);
  const auto t = travel(scene, rig, plan);
  CHECK(t[0] == 0.0);  // the stem
  CHECK(t[1] == 0.0);  // the leaf
  CHECK(t[2] > 3.0);   // the petals' tips, 40 px from the centre
  CHECK(t[3] < t[2]);  // the heart, nearer the centre, spreads less
}

TEST_CASE("petals: an elephant and a bell have none; no petals are invented") {
  const Scene scene = read_svg_file(data("elephant_ear.svg"));
  const Rig rig = build_rig(scene, read_source_names(data("elephant_ear.svg")));
  CHECK(find_petals(rig).lobes.empty());
  const Scene bell = read_svg_file(data("bell_clapper.svg"));
  CHECK(find_petals(build_rig(bell, read_source_names(data("bell_clapper.svg")))).lobes.empty());
}

}  // TEST_SUITE
