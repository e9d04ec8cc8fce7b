// The part locator (procedural/part_locator.h) on drawings made for these tests, each drawn in
// one group so the rig has no part for what the prompt names: a hare's ears, a bell's clapper,
// a clock's hands. The plan moves what was found (and the details drawn on it), the rest of the
// figure holds still, and the action says why those paths were chosen.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "svgmotion/svg_reader.h"
#include "procedural/motion_plan.h"
#include "procedural/part_locator.h"

#include "motion_drawing.h"
using namespace svgm;
using svgm::test::Drawing;
using svgm::test::path_travel;

TEST_SUITE("video") {

TEST_CASE("part locator: nouns name kinds of part; a trunk is a branch only on a creature, hands a dial's only on an object") {
  using C = FigureClass;
  CHECK(part_shape_of("ears", C::Quadruped) == PartShape::Ears);
  CHECK(part_shape_of("clapper", C::Object) == PartShape::Clapper);
  CHECK(part_shape_of("spouts", C::FishOrSnake) == PartShape::Jet);
  CHECK(part_shape_of("claws", C::None) == PartShape::SidePair);
  CHECK(part_shape_of("trunk", C::Quadruped) == PartShape::Branch);
  CHECK(part_shape_of("trunk", C::Plant) == PartShape::None);
  CHECK(part_shape_of("hands", C::Object) == PartShape::Hands);
  CHECK(part_shape_of("hands", C::Biped) == PartShape::None);
  CHECK(part_shape_of("hands", C::None) == PartShape::None);  // "he raises his hand"
  CHECK(part_shape_of("wings", C::Bird) == PartShape::None);
  CHECK(parse_prompt("the clock's hands go round").clauses[0].figure == C::Object);
}

TEST_CASE("part locator: the notes name each bending limb by its skeleton label and its box in shares of the figure's") {
  // A figure 200 x 100 from (100, 50); a tail lobe over x 260-300, y 100-150 and an arm lobe
  // over x 100-150, y 50-75: in shares, 0.80-1.00 by 0.50-1.00 and 0.00-0.25 by 0.00-0.25.
  Rig rig;
  rig.figure.add(Vec2{100, 50});
  rig.figure.add(Vec2{300, 150});
  ArmLobe tail, arm;
  tail.kind = LobeKind::Tail;
  tail.outline = {{260, 100}, {300, 100}, {300, 150}, {260, 150}};
  arm.kind = LobeKind::Arm;
  arm.outline = {{100, 50}, {150, 60}, {120, 75}};
  CHECK(fmt_lobes(rig, {tail}) == "tail 0.80,0.50-1.00,1.00");
  CHECK(fmt_lobes(rig, {tail, arm}) == "tail 0.80,0.50-1.00,1.00, arm 0.00,0.00-0.25,0.25");
  CHECK(fmt_lobes(rig, {}).empty());
}

TEST_CASE("part locator: a hare's ears drawn in its body's group twitch; the body and the eye hold") {
  const Drawing d("ears_one_group.svg");
  REQUIRE(d.rig.parts.size() == 1);  // one group: no ear part in the rig
  const MotionPlan plan = plan_from_prompt(parse_prompt("the hare twitches its ears"), d.rig, 1);
  REQUIRE(plan.actions.size() >= 1);
  const PlannedAction& a = plan.actions[0];
  CHECK(a.region == Region::Located);
  CHECK(a.primitive == Primitive::Swing);
  CHECK(a.lobes.size() == 2);
  CHECK(a.lobe_paths == std::vector<int>{1, 2, 3});  // both ears and the inner colour of one
  CHECK(a.why.rfind("'the hare twitches its ears': ", 0) == 0);
  CHECK(a.why.find("moves the part the prompt names; the ears found as ears: 2 elements stick out at the figure's top") != std::string::npos);
  const auto t = d.travel(plan);
  CHECK(t[0] == 0.0);  // the body
  CHECK(t[4] == 0.0);  // the eye
  CHECK(t[1] > 10.0);
  CHECK(t[2] > 5.0);   // the inner colour goes with its ear
  CHECK(t[3] > 10.0);
  // The report names the paths found.
  const auto j = motion_report(d.scene, d.rig, plan);
  CHECK(j["plan"][0]["region"] == "located part");
  CHECK(j["plan"][0]["located_paths"].size() == 3);
}

TEST_CASE("part locator: an elephant's ear, larger than a usual part (38 % of the figure's box), flaps; the body and the eye hold") {
  const Drawing d("elephant_ear.svg");
  REQUIRE(d.rig.parts.size() == 1);
  const MotionPlan plan = plan_from_prompt(parse_prompt("the elephant flaps its ears"), d.rig, 1);
  REQUIRE(plan.actions.size() >= 1);
  const PlannedAction& a = plan.actions[0];
  CHECK(a.region == Region::Located);
  CHECK(a.lobes.size() == 1);
  CHECK(a.lobe_paths == std::vector<int>{1});
  CHECK(a.why.find("the ears found as ears: 1 element sticks out at the figure's top (path 2 at") != std::string::npos);
  const auto t = d.travel(plan);
  CHECK(t[0] == 0.0);
  CHECK(t[1] > 10.0);
  CHECK(t[2] == 0.0);
}

TEST_CASE("part locator: an ear drawn in one stroke with the head and trunk is its stretch above the figure's middle") {
  // The stroke's box (x 30-100, y 30-150) reaches 0.8 of the figure's height (y 30-180): no
  // ear hangs that low, so the lobe holds only its points above the middle (y 105); the trunk's
  // tip (30, 150) stays out of it, the ear's top (75, 32) is in it.
  const Drawing d("elephant_head_outline.svg");
  const MotionPlan plan = plan_from_prompt(parse_prompt("the elephant flaps its ears"), d.rig, 1);
  REQUIRE(plan.actions.size() >= 1);
  const PlannedAction& a = plan.actions[0];
  CHECK(a.region == Region::Located);
  REQUIRE(a.lobes.size() == 1);
  CHECK(a.lobe_paths == std::vector<int>{1});
  CHECK(a.why.find("of one reaching the figure's lower quarter (a head drawn with its ear) only its stretch above the middle") != std::string::npos);
  double lowest = 0;
  for (Vec2 q : a.lobes[0].outline) lowest = std::max(lowest, q.y);
  CHECK(lowest < 110);  // the hull of points at y <= 105, grown by 6 % about its middle
  CHECK(lobe_depth(a.lobes[0], {30, 150}) == 0.0);
  CHECK(lobe_depth(a.lobes[0], {75, 33}) > 0.0);
  const auto t = d.travel(plan);
  CHECK(t[0] == 0.0);  // the body
  CHECK(t[1] > 5.0);
}

TEST_CASE("part locator: a bell's clapper under the rim swings from the rim's middle, its fill with its outline; the bell holds") {
  const Drawing d("bell_clapper.svg");
  const MotionPlan plan = plan_from_prompt(parse_prompt("the bell's clapper swings"), d.rig, 1);
  REQUIRE(plan.actions.size() == 1);
  const PlannedAction& a = plan.actions[0];
  CHECK(a.region == Region::Located);
  REQUIRE(a.lobes.size() == 1);
  CHECK(a.lobes[0].rigid);
  // Drawn wholly below the rim (y 155; its fill starts at 156, its outline's arc at 160), it
  // hangs from the rim's middle.
  CHECK(a.lobes[0].pivot.x == doctest::Approx(100));
  CHECK(a.lobes[0].pivot.y == doctest::Approx(155));
  // The outline's arc is lowest; the fill it is drawn over goes with it.
  CHECK(a.why.find("the lowest small element centred under the body, with what overlaps it (path 3+4") != std::string::npos);
  const auto t = d.travel(plan);
  CHECK(t[0] == 0.0);
  CHECK(t[1] == 0.0);
  CHECK(t[2] > 3.0);
  CHECK(t[3] > 3.0);
}

TEST_CASE("part locator: a clapper hanging inside its bell's outline swings whole: its shape unchanged, its top still") {
  // The clapper's disc starts inside the bell (its top at y 140, the rim at 155) and hangs below
  // it, its outline's arc over its lower half: the two swing as one rigid piece about the disc's top.
  const Scene s = read_svg_string(R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">
        <g><circle cx="100" cy="152" r="12" fill="#a70"/>
           <path d="M 100 30 C 60 30 55 80 50 140 L 40 155 L 160 155 L 150 140 C 145 80 140 30 100 30 Z" fill="#fc2"/>
           <path d="M 89 156 C 91 168 109 168 111 156" fill="none" stroke="#000" stroke-width="2"/></g></svg>)", "bell.svg");
  const Rig rig = build_rig(s, {});
  const MotionPlan plan = plan_from_prompt(parse_prompt("the bell's clapper swings"), rig, 1);
  REQUIRE(plan.actions.size() == 1);
  const PlannedAction& a = plan.actions[0];
  REQUIRE(a.lobes.size() == 1);
  CHECK(a.lobes[0].rigid);
  CHECK(a.lobe_paths == std::vector<int>{0, 2});
  const Vec2 top = a.lobes[0].pivot;
  CHECK(top.x == doctest::Approx(100));
  CHECK(top.y == doctest::Approx(140));
  const int F = 13;
  const std::vector<Vec2> pts = animate_plan(s, rig, plan, F);
  const size_t per = pts.size() / F;
  // The clapper's points (the disc's, then the arc's after the bell's) and the bell's.
  std::vector<size_t> clapper, bell;
  size_t i = 0;
  for (size_t p = 0; p < s.paths.size(); ++p)
    for (const auto& sp : s.paths[p].subpaths)
      for (size_t q = 0; q < sp.points.size(); ++q, ++i) (p == 1 ? bell : clapper).push_back(i);
  double turned = 0;
  for (int f = 1; f < F; ++f) {
    const Vec2* P = &pts[f * per];
    // Rigid: every distance between two of its points is as at rest, and so is each point's
    // distance from the top it hangs by.
    for (size_t u : clapper) {
      CHECK(std::hypot(P[u].x - top.x, P[u].y - top.y) == doctest::Approx(std::hypot(pts[u].x - top.x, pts[u].y - top.y)).epsilon(1e-6));
      for (size_t v : clapper)
        CHECK(std::hypot(P[u].x - P[v].x, P[u].y - P[v].y) == doctest::Approx(std::hypot(pts[u].x - pts[v].x, pts[u].y - pts[v].y)).epsilon(1e-6));
      turned = std::max(turned, std::hypot(P[u].x - pts[u].x, P[u].y - pts[u].y));
    }
    for (size_t u : bell) CHECK(std::hypot(P[u].x - pts[u].x, P[u].y - pts[u].y) == 0.0);
  }
  CHECK(turned > 3.0);  // it does swing
}

TEST_CASE("part locator: a clock's hands turn about the face's middle, not as arms of its case; the tick mark holds") {
  const Drawing d("clock_hands.svg");
  const MotionPlan plan = plan_from_prompt(parse_prompt("the clock's hands go round"), d.rig, 1);
  REQUIRE(!plan.actions.empty());
  const PlannedAction& a = plan.actions[0];
  CHECK(a.region == Region::Located);
  REQUIRE(a.lobes.size() == 2);
  for (const ArmLobe& l : a.lobes) {
    CHECK(l.pivot.x == doctest::Approx(100));
    CHECK(l.pivot.y == doctest::Approx(105));
  }
  CHECK(a.why.find("2 thin elements (path 3+4) inside path 2 meet at one end") != std::string::npos);
  const auto t = d.travel(plan);
  CHECK(t[0] == 0.0);  // the case
  CHECK(t[1] == 0.0);  // the face
  CHECK(t[2] > 5.0);
  CHECK(t[3] > 5.0);
  CHECK(t[4] == 0.0);  // the tick mark
}

TEST_CASE("part locator: a part the figure does not show is not invented") {
  const Drawing d("bell_clapper.svg");
  CHECK(locate_part(d.rig, PartShape::Hands).lobes.empty());
  CHECK(locate_part(d.rig, PartShape::SidePair).lobes.empty());
}

}  // TEST_SUITE
