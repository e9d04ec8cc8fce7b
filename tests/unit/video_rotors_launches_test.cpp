// Rotors, plumes over a source that stays, and launches, on drawings made for these tests
// (issue 35): a wind turbine's blades (each a fill with its outline over it) spin about their hub
// as one, a side view's propeller seen edge on squeezes along its line as |cos| of its turn, a
// puff of smoke over a chimney rises while the chimney and the building hold, and a take-off
// climbs without dipping below where the figure stood.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "procedural/motion_plan.h"
#include "procedural/part_locator.h"
#include "procedural/rotor_blades.h"

#include "motion_drawing.h"
using namespace svgm;
using svgm::test::Drawing;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The points of path `p` at frame f of animate_plan's output `pts` (F frames).
std::vector<Vec2> points_at(const Scene& scene, const std::vector<Vec2>& pts, int F, size_t p, int f) {
  const size_t per = pts.size() / F;
  size_t first = 0, n = 0;
  for (size_t q = 0; q < p; ++q)
    for (const auto& sp : scene.paths[q].subpaths) first += sp.points.size();
  for (const auto& sp : scene.paths[p].subpaths) n += sp.points.size();
  return {pts.begin() + f * per + first, pts.begin() + f * per + first + n};
}

double dist(Vec2 a, Vec2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

}  // namespace

TEST_SUITE("video") {

TEST_CASE("rotors: 'propeller', 'rotor', 'blade' and 'vane' name a rotor") {
  for (const char* w : {"propeller", "rotors", "blades", "vanes"}) CHECK(part_shape_of(w, FigureClass::None) == PartShape::Rotor);
  CHECK(std::string(part_shape_name(PartShape::Rotor)) == "rotor");
}

TEST_CASE("rotors: a turbine's three blades are found about the hub disc, each with its outline; the tower is no blade") {
  const Drawing d("rotor_turbine.svg");
  const LocatedPart r = locate_part(d.rig, PartShape::Rotor);
  REQUIRE(r.lobes.size() == 3);
  CHECK_FALSE(rotor_edge_on(d.rig, r));
  CHECK(r.paths == std::vector<int>{1, 2, 3, 4, 5, 6});  // the blades' fills and outlines
  for (const ArmLobe& l : r.lobes) {
    CHECK(l.pivot.x == doctest::Approx(100));  // the hub disc's middle
    CHECK(l.pivot.y == doctest::Approx(80));
  }
}

TEST_CASE("rotors: the blades turn in the breeze: whole turns about the hub, fill and outline as one; the tower holds") {
  const Drawing d("rotor_turbine.svg");
  const MotionPlan plan = plan_from_prompt(parse_prompt("the turbine's blades turn in the breeze"), d.rig, 1);
  REQUIRE(plan.actions.size() == 1);
  const PlannedAction& a = plan.actions[0];
  CHECK(a.primitive == Primitive::Spin);
  CHECK(a.region == Region::Located);
  CHECK(a.why.find("a rotor's blades spin about their hub") != std::string::npos);
  const int F = 13;  // frame 3 of 12 intervals: a quarter turn
  const std::vector<Vec2> pts = animate_plan(d.scene, d.rig, plan, F);
  const Vec2 hub{100, 80};
  for (size_t p = 1; p <= 6; ++p) {
    const std::vector<Vec2> rest = points_at(d.scene, pts, F, p, 0), q = points_at(d.scene, pts, F, p, 3);
    for (size_t i = 0; i < rest.size(); ++i) {
      CHECK(dist(q[i], hub) == doctest::Approx(dist(rest[i], hub)).epsilon(1e-9));  // turned about the hub
      const double turned = std::atan2(q[i].y - hub.y, q[i].x - hub.x) - std::atan2(rest[i].y - hub.y, rest[i].x - hub.x);
      CHECK(std::fabs(std::cos(turned)) < 1e-9);  // by a quarter turn
    }
  }
  // The fill and its outline (paths 1 and 2, the same points) stay one on the other.
  for (int f = 0; f < F; ++f) {
    const std::vector<Vec2> fill = points_at(d.scene, pts, F, 1, f), line = points_at(d.scene, pts, F, 2, f);
    REQUIRE(fill.size() == line.size());
    for (size_t i = 0; i < fill.size(); ++i) CHECK(dist(fill[i], line[i]) < 1e-9);
  }
  const auto t = d.travel(plan);
  CHECK(t[0] == 0.0);  // the tower
  CHECK(t[1] > 0.08 * 178);  // a blade's tip, past the 8 % of the figure's height
}

TEST_CASE("rotors: a propeller seen edge on squeezes along its line as |cos| of its turn about the hub; the plane holds") {
  const Drawing d("rotor_edge_on.svg");
  const LocatedPart r = locate_part(d.rig, PartShape::Rotor);
  REQUIRE(r.lobes.size() == 2);
  CHECK(rotor_edge_on(d.rig, r));
  const MotionPlan plan = plan_from_prompt(parse_prompt("the propeller spins"), d.rig, 1);
  REQUIRE(plan.actions.size() == 1);
  const PlannedAction& a = plan.actions[0];
  CHECK(a.primitive == Primitive::Stretch);
  const double amp = plan.amplitude(a), hub = r.lobes[0].pivot.y;
  CHECK(hub == doctest::Approx(100));
  const int F = 17;
  const std::vector<Vec2> pts = animate_plan(d.scene, d.rig, plan, F);
  for (int f = 0; f < F; ++f) {
    const double t = static_cast<double>(f) / (F - 1);
    const double want = std::max(kEdgeOnMin, 1 - amp * (1 - std::fabs(std::cos(2 * kPi * a.cycles * t))));
    const std::vector<Vec2> rest = points_at(d.scene, pts, F, 2, 0), q = points_at(d.scene, pts, F, 2, f);
    double x0 = 1e9, x1 = -1e9, r0 = 1e9, r1 = -1e9;
    for (size_t i = 0; i < rest.size(); ++i) {
      // Along the blades' line (vertical) about the hub, within 0.2 px (half a percent of a blade).
      CHECK(std::fabs((q[i].y - hub) - want * (rest[i].y - hub)) < 0.2);
      x0 = std::min(x0, q[i].x), x1 = std::max(x1, q[i].x), r0 = std::min(r0, rest[i].x), r1 = std::max(r1, rest[i].x);
    }
    CHECK(x1 - x0 == doctest::Approx(r1 - r0).epsilon(0.02));  // its width across the line stays
  }
  const auto t = d.travel(plan);
  CHECK(t[0] == 0.0);  // the fuselage
  CHECK(t[1] == 0.0);  // the wing
  CHECK(t[2] >= 0.08 * 153);
}

TEST_CASE("rotors: a propeller drawn as two strokes crossing at its hub spins whole about it; a lone stroke is no rotor") {
  const Drawing d("rotor_crossed.svg");
  const LocatedPart r = locate_part(d.rig, PartShape::Rotor);
  INFO(r.why);
  // Both strokes, each across the hub (170,100): two lobes, not in one line; not the aerial
  // (path 2, one stroke), nor the fuselage that crosses the wing at its middle.
  CHECK(r.paths == std::vector<int>{3, 4});
  REQUIRE(r.lobes.size() == 2);
  CHECK_FALSE(rotor_edge_on(d.rig, r));
  for (const ArmLobe& l : r.lobes) {
    CHECK(l.pivot.x == doctest::Approx(170).epsilon(0.01));
    CHECK(l.pivot.y == doctest::Approx(100).epsilon(0.01));
  }
  const MotionPlan plan = plan_from_prompt(parse_prompt("the propeller spins"), d.rig, 1);
  REQUIRE(plan.actions.size() == 1);
  CHECK(plan.actions[0].primitive == Primitive::Spin);
  const auto t = d.travel(plan);
  CHECK(t[0] == 0.0);  // the fuselage
  CHECK(t[1] == 0.0);  // the wing
  CHECK(t[2] == 0.0);  // the aerial
  CHECK(t[3] > 40.0);  // each stroke turns whole: its ends (28 px from the hub) go round
  CHECK(t[4] > 30.0);
}

TEST_CASE("rotors: a helicopter's main rotor, one bar on a mast, is seen edge on: it squeezes about its hub, never over the cabin") {
  const Drawing d("rotor_helicopter.svg");
  const LocatedPart r = locate_part(d.rig, PartShape::Rotor);
  INFO(r.why);
  // The bar (path 3), not the mast (path 2) nor the tail rotor (paths 4, 5: shorter blades).
  CHECK(r.paths == std::vector<int>{3});
  REQUIRE(!r.lobes.empty());
  CHECK(r.lobes[0].pivot.x == doctest::Approx(90));  // the bar's middle, on the mast
  CHECK(r.lobes[0].pivot.y == doctest::Approx(40).epsilon(0.01));
  CHECK(rotor_edge_on(d.rig, r));
  const MotionPlan plan = plan_from_prompt(parse_prompt("the helicopter hovers, its rotor spinning"), d.rig, 1);
  const PlannedAction* spin = nullptr;
  for (const PlannedAction& a : plan.actions)
    if (a.region == Region::Located) spin = &a;
  REQUIRE(spin);
  CHECK(spin->primitive == Primitive::Stretch);
  const int F = 17;
  const std::vector<Vec2> pts = animate_plan(d.scene, d.rig, plan, F);
  double shortest = 1e9, longest = 0;
  for (int f = 0; f < F; ++f) {
    const std::vector<Vec2> q = points_at(d.scene, pts, F, 3, f);
    // The hover bobs the whole helicopter (carried_flight.h): the rotor is seen on the cabin.
    const double bob = points_at(d.scene, pts, F, 0, f)[0].y - points_at(d.scene, pts, F, 0, 0)[0].y;
    double x0 = 1e9, x1 = -1e9, y1 = -1e9;
    for (const Vec2& p : q) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y - bob);
    shortest = std::min(shortest, x1 - x0), longest = std::max(longest, x1 - x0);
    CHECK(0.5 * (x0 + x1) == doctest::Approx(90).epsilon(0.01));  // its middle stays on the hub
    CHECK(y1 <= 43 + 0.5);  // never down over the cabin (its top at 70) or the window
  }
  CHECK(longest == doctest::Approx(140).epsilon(0.01));  // drawn width shrinks and grows back
  CHECK(shortest < 0.5 * 140);
}

TEST_CASE("rotors: a tail rotor, two blades in a slanting line with nothing across them, is seen face on: it spins") {
  // The boom the tail rotor sits on runs 45 degrees from its blades' line, not square to it.
  const Drawing d("rotor_tail.svg");
  const LocatedPart r = locate_part(d.rig, PartShape::Rotor);
  INFO(r.why);
  REQUIRE(r.lobes.size() == 2);
  CHECK_FALSE(rotor_edge_on(d.rig, r));
  for (const ArmLobe& l : r.lobes) {
    CHECK(l.pivot.x == doctest::Approx(130));
    CHECK(l.pivot.y == doctest::Approx(100));
  }
  const MotionPlan plan = plan_from_prompt(parse_prompt("the rotor spins"), d.rig, 1);
  REQUIRE(plan.actions.size() == 1);
  CHECK(plan.actions[0].primitive == Primitive::Spin);
}

TEST_CASE("plumes: a cloud of smoke over a chimney rises; the chimney standing on the building holds") {
  const Drawing d("smoke_factory.svg");
  const LocatedPart j = locate_part(d.rig, PartShape::Jet);
  CHECK(j.paths == std::vector<int>{2});  // the puff, not the chimney under it
  const MotionPlan plan = plan_from_prompt(parse_prompt("a cloud of smoke rises from the chimney"), d.rig, 1);
  REQUIRE(plan.actions.size() == 1);
  CHECK(plan.actions[0].primitive == Primitive::Pulse);
  CHECK(plan.actions[0].why.find("a plume rises") != std::string::npos);
  const int F = 13;
  const std::vector<Vec2> pts = animate_plan(d.scene, d.rig, plan, F);
  double top = 1e9;
  for (int f = 0; f < F; ++f)
    for (Vec2 q : points_at(d.scene, pts, F, 2, f)) top = std::min(top, q.y);
  CHECK(12 - top >= 0.08 * 178);  // its top (y 12) goes up past the 8 %
  const auto t = d.travel(plan);
  CHECK(t[0] == 0.0);
  CHECK(t[1] == 0.0);
}

TEST_CASE("launches: a plane that takes off climbs a quarter of its height and never dips below where it stood") {
  const Drawing d("rotor_edge_on.svg");
  const MotionPlan plan = plan_from_prompt(parse_prompt("the plane takes off"), d.rig, 1);
  REQUIRE(!plan.actions.empty());
  const PlannedAction& a = plan.actions[0];
  CHECK(a.verb == "takeoff");
  CHECK(a.primitive == Primitive::Bob);
  CHECK(a.vertical == 1);
  const int F = 13;
  const std::vector<Vec2> pts = animate_plan(d.scene, d.rig, plan, F);
  const size_t per = pts.size() / F;
  double rise = 0;
  for (int f = 1; f < F; ++f)
    for (size_t i = 0; i < per; ++i) {
      CHECK(pts[f * per + i].y <= pts[i].y + 1e-9);
      rise = std::max(rise, pts[i].y - pts[f * per + i].y);
    }
  const double H = d.rig.figure.h();
  CHECK(rise >= 0.2 * H);
}

}  // TEST_SUITE
