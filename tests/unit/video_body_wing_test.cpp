// A bird's wing drawn over its body (procedural/body_wing.h): with no wing part in the rig and
// no arm in the silhouette, "flaps its wings" turns the shape folded on the flank about its
// shoulder (its point nearest the eye), where the body's sides used to bend (its head and its
// back swung, the wing held still).
#include <doctest/doctest.h>

#include <cmath>

#include "procedural/body_wing.h"
#include "procedural/eye_cue.h"
#include "procedural/motion_plan.h"

#include "motion_drawing.h"
using namespace svgm;
using svgm::test::Drawing;
using svgm::test::path_travel;

TEST_SUITE("video") {

TEST_CASE("body wing: a side-view bird's wing drawn inside its body turns about its shoulder; the body and the eye hold") {
  const Drawing d("bird_wing_on_body.svg");
  REQUIRE(d.rig.parts.size() == 1);  // one group: no wing part in the rig
  Rig rig = d.rig;
  REQUIRE(apply_eye_cue(rig, d.scene, d.scene).side == -1);  // the head at the left
  // Paths: 0 the body, 1 the eye, 2 the wing, 3 the feather line on it.
  const LocatedPart w = wing_on_body(rig);
  REQUIRE(w.lobes.size() == 1);
  CHECK(w.paths == std::vector<int>{2, 3});
  // The shoulder: the wing's corner nearest the eye (55, 75) is (80, 90).
  CHECK(w.lobes[0].pivot.x == doctest::Approx(80));
  CHECK(w.lobes[0].pivot.y == doctest::Approx(90));
  CHECK(w.lobes[0].rigid);  // paths of its own: they turn whole
  const MotionPlan plan = plan_from_prompt(parse_prompt("the bird flaps its wings"), rig, 1);
  REQUIRE(plan.actions.size() >= 1);
  const PlannedAction& a = plan.actions[0];
  CHECK(a.primitive == Primitive::Swing);
  CHECK(a.region == Region::Located);
  CHECK(a.lobe_paths == std::vector<int>{2, 3});
  CHECK(a.why.find("no separate wings: the wing drawn over the body turns") != std::string::npos);
  const auto t = path_travel(d.scene, animate_plan(d.scene, rig, plan, 13), 13);
  CHECK(t[0] == 0.0);  // the body
  CHECK(t[1] == 0.0);  // the eye
  CHECK(t[2] > 10.0);  // the wing's tip, 70 units from the shoulder, turns by its swing
  CHECK(t[3] > 5.0);   // the feather line goes with it
}

TEST_CASE("body wing: a shape holding the eye (a cheek patch) is the head's, no wing; none is found on a figure without one") {
  const Drawing d("bird_wing_on_body.svg");
  Rig rig = d.rig;
  // The eye moved into the wing: the wing now holds it and is taken for the head's.
  rig.eye_side = -1;
  rig.eye = {100, 100};
  CHECK(wing_on_body(rig).lobes.empty());
}

}  // TEST_SUITE
