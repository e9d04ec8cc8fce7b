// Elongated parts a prompt names that the rig has no part for (procedural/part_locator.h): a
// jellyfish's tentacles, a rose's head drooping on its stem, a mermaid's tail the skeleton
// labelled arms, an elephant's trunk the skeleton labelled a leg. The drawings (made for these
// tests, one group each) check that what was found moves and the body holds; the skeleton's
// limbs are given by hand where its labels are the point.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "svgmotion/svg_reader.h"
#include "procedural/motion_plan.h"
#include "procedural/motion_plan_internal.h"
#include "procedural/part_locator.h"

#include "motion_drawing.h"
using namespace svgm;
using svgm::test::Drawing;
using svgm::test::path_travel;

namespace {

// A skeleton limb from `pivot` to `tip`, its outline a band `half` wide either side of it.
ArmLobe limb(LobeKind kind, Vec2 pivot, Vec2 tip, double half) {
  ArmLobe l;
  l.kind = kind;
  l.pivot = pivot;
  l.tip = tip;
  const double len = std::hypot(tip.x - pivot.x, tip.y - pivot.y);
  const Vec2 n = {-(tip.y - pivot.y) / len * half, (tip.x - pivot.x) / len * half};
  l.base0 = pivot - n;
  l.base1 = pivot + n;
  l.outline = {pivot - n, tip - n, tip + n, pivot + n};
  l.side = tip.x < 100 ? -1 : 1;
  return l;
}

RigPart part(Role role, RigBox box, int parent) {
  RigPart P;
  P.role = role;
  P.box = box;
  P.parent = parent;
  P.name = role_name(role);
  P.words = {P.name};
  return P;
}

RigBox box(double x0, double y0, double x1, double y1) {
  RigBox b;
  b.add(Vec2{x0, y0});
  b.add(Vec2{x1, y1});
  return b;
}

// The plan of `words` said of the test rose (rose_stem.svg: one stem whose top is (100, 95), a
// leaf, a head and a petal drawn on it), checked to be one action on the located bloom, pivoted
// at the stem's top.
MotionPlan rose_bloom_plan(const Drawing& d, const std::string& words) {
  const ParsedPrompt prompt = parse_prompt(words);
  REQUIRE(prompt.clauses[0].figure == FigureClass::Plant);
  MotionPlan plan = plan_from_prompt(prompt, d.rig, 1);
  REQUIRE(plan.actions.size() == 1);
  const PlannedAction& a = plan.actions[0];
  CHECK(a.region == Region::Located);
  REQUIRE(a.lobes.size() == 1);
  CHECK(a.lobes[0].pivot.x == doctest::Approx(100));
  CHECK(a.lobes[0].pivot.y == doctest::Approx(95));
  return plan;
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("elongated parts: a jellyfish's tentacles wave about their ends under the bell; the bell and its highlight hold") {
  const Drawing d("jellyfish_strands.svg");
  REQUIRE(d.rig.parts.size() == 1);
  CHECK(part_shape_of("tentacles", FigureClass::None) == PartShape::Strands);
  const MotionPlan plan = plan_from_prompt(parse_prompt("the jellyfish's tentacles trail and wave"), d.rig, 1);
  REQUIRE(!plan.actions.empty());
  const PlannedAction& a = plan.actions[0];
  CHECK(a.region == Region::Located);
  CHECK(a.lobes.size() == 3);  // each colour stroke with the outline drawn along it
  CHECK(a.lobe_paths == std::vector<int>{2, 3, 4, 5, 6, 7});
  CHECK(a.why.find("the tentacles found as strands: 3 elongated elements hang below the body") != std::string::npos);
  for (const ArmLobe& l : a.lobes) {
    CHECK(l.pivot.y < 95);         // each turns about its top, at the bell
    CHECK(l.side == a.lobes[0].side);  // all the same way: mirrored, neighbours crossed
  }
  const auto t = d.travel(plan);
  CHECK(t[0] == 0.0);  // the bell
  CHECK(t[1] == 0.0);  // the highlight on it
  for (int p = 2; p < 8; ++p) CHECK(t[p] > 5.0);
  // A bell with a clapper has no strands.
  CHECK(locate_part(Drawing("bell_clapper.svg").rig, PartShape::Strands).lobes.empty());
}

TEST_CASE("elongated parts: a squid's arms hang from its head as well as from its mantle, and all of them wave") {
  // The head (a stout ellipse over the mantle's bottom) is joined to the body: the four arms
  // under it, 26 units below the mantle (past kStrandReach of it), hang from it. Measured from
  // the mantle alone, only the two outer arms were strands and moved.
  const Drawing d("squid_arms.svg");
  const MotionPlan plan = plan_from_prompt(parse_prompt("the squid waves its tentacles"), d.rig, 1);
  REQUIRE(!plan.actions.empty());
  const PlannedAction& a = plan.actions[0];
  CHECK(a.region == Region::Located);
  CHECK(a.lobes.size() == 6);
  CHECK(a.lobe_paths == std::vector<int>{2, 3, 4, 5, 6, 7});
  for (const ArmLobe& l : a.lobes) CHECK(l.pivot.y < 118);  // each about its top, at the mantle or the head
  const auto t = d.travel(plan);
  CHECK(t[0] == 0.0);  // the mantle
  CHECK(t[1] == 0.0);  // the head
  for (int p = 2; p < 8; ++p) CHECK(t[p] > 5.0);
}

TEST_CASE("elongated parts: a strand's own strokes turn with it where its neighbour's outline overlaps it") {
  // Two strands 8 apart, each a band 10 wide either side: the point (6, 60) lies in both. By
  // outline it takes the first (pivot (0, 0)); a point of path 3, which the second strand was
  // built from, takes the second, fully turned (60 beyond its base, past the ramp).
  PlannedAction a;
  a.region = Region::Located;
  a.primitive = Primitive::Swing;
  a.cycles = 1;
  a.lobes = {limb(LobeKind::Other, {0, 0}, {0, 100}, 10), limb(LobeKind::Other, {8, 0}, {8, 100}, 10)};
  a.lobes[1].paths = {3};
  const RigBox b = box(-10, 0, 18, 100);
  const auto by_outline = motion_plan_internal::region_turn(a, 30, 0.25, b, {6, 60});
  CHECK(by_outline.pivot.x == 0.0);
  const auto owned = motion_plan_internal::region_turn(a, 30, 0.25, b, {6, 60}, 3);
  CHECK(owned.pivot.x == 8.0);
  CHECK(owned.weight == 1.0);
  CHECK(owned.angle == by_outline.angle);
  // Path 2 belongs to no strand: by outline, as before.
  CHECK(motion_plan_internal::region_turn(a, 30, 0.25, b, {6, 60}, 2).pivot.x == 0.0);
  // The squid's strands each own the paths they were found on.
  const LocatedPart arms = locate_part(Drawing("squid_arms.svg").rig, PartShape::Strands);
  REQUIRE(arms.lobes.size() == 6);
  for (const ArmLobe& l : arms.lobes) CHECK(l.paths.size() == 1);
}

TEST_CASE("elongated parts: a rose droops at its neck, the top of its one stem; the stem and the leaf hold") {
  const Drawing d("rose_stem.svg");
  REQUIRE(d.rig.parts.size() == 1);
  const MotionPlan plan = rose_bloom_plan(d, "the rose droops on its stem");
  const PlannedAction& a = plan.actions[0];
  CHECK(a.lobe_paths == std::vector<int>{2, 3});
  CHECK(a.one_sided != 0);  // down and back, not up past the stem as well
  CHECK(a.why.find("found as bloom: 2 elements drawn above the top of the one stem (path 1)") != std::string::npos);
  const auto t = d.travel(plan);
  CHECK(t[0] == 0.0);  // the stem
  CHECK(t[1] == 0.0);  // the leaf
  CHECK(t[2] > 5.0);   // the head
  CHECK(t[3] > 5.0);   // the petal drawn on it
}

TEST_CASE("elongated parts: a plant that nods turns its bloom about the top of its stem, the stem and leaf still") {
  const Drawing d("rose_stem.svg");
  const MotionPlan plan = rose_bloom_plan(d, "the rose nods");
  const PlannedAction& a = plan.actions[0];
  // Two nods a loop: at t = 1/8 (frame 2 of 17) the first is at its full angle. The head turns
  // whole about (100, 95): its bottom (that point) stays, its top (100, 25), 70 above it,
  // moves the chord 2 * 70 * sin(angle / 2).
  const int F = 17;
  const std::vector<Vec2> pts = animate_plan(d.scene, d.rig, plan, F);
  const size_t per = pts.size() / F;
  size_t head = 0;
  for (int p = 0; p < 2; ++p)
    for (const auto& sp : d.scene.paths[p].subpaths) head += sp.points.size();
  const Vec2 bottom = pts[2 * per + head], top = pts[2 * per + head + 3];  // "M 100 95 C 60 95 60 25 100 25"
  CHECK(std::hypot(bottom.x - 100, bottom.y - 95) < 1e-6);
  const double angle = std::fabs(plan.amplitude(a)) * M_PI / 180;
  CHECK(std::hypot(top.x - 100, top.y - 25) == doctest::Approx(2 * 70 * std::sin(angle / 2)).epsilon(1e-3));
  const auto t = d.travel(plan);
  CHECK(t[0] == 0.0);  // the stem
  CHECK(t[1] == 0.0);  // the leaf
}

TEST_CASE("elongated parts: a sheaf of two stems has no one bloom: it bends from its base as before") {
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200"><g>
           <path d="M 80 190 C 82 160 78 130 80 95" fill="none" stroke="#262" stroke-width="5"/>
           <path d="M 120 190 C 122 160 118 130 120 95" fill="none" stroke="#262" stroke-width="5"/>
           <path d="M 100 95 C 50 95 50 25 100 25 C 150 25 150 95 100 95 Z" fill="#dc4"/></g></svg>)", "sheaf.svg");
  const Rig rig = build_rig(s, {});
  CHECK(locate_part(rig, PartShape::Bloom).lobes.empty());
  const ParsedPrompt prompt = parse_prompt("the wheat droops");
  REQUIRE(prompt.clauses[0].figure == FigureClass::Plant);
  const MotionPlan plan = plan_from_prompt(prompt, rig, 1);
  REQUIRE(plan.actions.size() == 1);
  CHECK(plan.actions[0].region == Region::None);
  CHECK(plan.actions[0].anchored == 4);  // held at its bottom
}

TEST_CASE("elongated parts: a tail the skeleton labelled arms is the limbs opposite the head, not the far end of the box") {
  // An upright figure (a mermaid): the head up left, an arm raised to the right near it, and
  // the tail's fin low on the right, two lobes leaving the body side by side.
  Rig rig;
  rig.canvas = box(0, 0, 200, 200);
  rig.figure = box(30, 10, 190, 190);
  rig.parts = {part(Role::Root, box(30, 60, 190, 190), -1), part(Role::Head, box(50, 10, 100, 60), 0)};
  rig.root = 0;
  rig.parts[1].chain_top = 1;
  const ArmLobe arm = limb(LobeKind::Arm, {110, 80}, {170, 40}, 8);
  const ArmLobe fin_up = limb(LobeKind::Arm, {150, 150}, {160, 110}, 10);
  const ArmLobe fin_out = limb(LobeKind::Arm, {158, 160}, {190, 140}, 10);
  rig.limbs = {arm, fin_up, fin_out};
  const auto tail = tail_limbs(rig);
  REQUIRE(tail.size() == 2);
  CHECK(tail[0].tip.x == doctest::Approx(190));  // the fin's lobe farthest from the head leads
  CHECK(tail[1].tip.y == doctest::Approx(110));  // its other lobe, beside its base, goes with it
  const MotionPlan plan = plan_from_prompt(parse_prompt("the mermaid flicks her tail"), rig, 1);
  REQUIRE(plan.actions.size() == 1);
  const PlannedAction& a = plan.actions[0];
  CHECK(a.region == Region::End);
  REQUIRE(a.lobes.size() == 2);  // not the box's far end, which held the raised hand too
  for (const ArmLobe& l : a.lobes) CHECK(l.tip.y > 100);
  // No head shows where the front is: nothing is taken for a tail.
  rig.parts.pop_back();
  CHECK(tail_limbs(rig).empty());
}

TEST_CASE("elongated parts: a trunk is the longest limb that does not stand on the ground, even one labelled a leg") {
  // An elephant whose stout legs are no limbs of the skeleton: its trunk hangs down beside
  // them (labelled a leg, as it points down) and stops short of the ground; one thin leg
  // stands on it.
  Rig rig;
  rig.canvas = box(0, 0, 200, 200);
  rig.figure = box(10, 30, 190, 190);
  rig.parts = {part(Role::Root, rig.figure, -1)};
  rig.root = 0;
  RigElement body;
  body.path = 0;
  body.box = rig.figure;
  body.points = {{10, 30}, {190, 30}, {190, 190}, {10, 190}};
  body.area = rig.figure.area();
  rig.elements = {body};
  const ArmLobe trunk = limb(LobeKind::Leg, {40, 80}, {25, 165}, 8);
  const ArmLobe leg = limb(LobeKind::Leg, {150, 140}, {150, 188}, 10);
  rig.limbs = {leg, trunk};
  const LocatedPart found = locate_part(rig, PartShape::Branch);
  REQUIRE(found.lobes.size() == 1);
  CHECK(found.lobes[0].tip.x == doctest::Approx(25));
  CHECK(found.why.find("does not stand on the ground") != std::string::npos);
  // A trunk reaching the ground is a leg: no branch.
  rig.limbs = {leg};
  CHECK(locate_part(rig, PartShape::Branch).lobes.empty());
}

}  // TEST_SUITE
