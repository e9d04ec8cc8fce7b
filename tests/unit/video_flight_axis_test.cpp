// Launches along the figure's own axis (flight_axis.h, issue 35): a rocket drawn on a slant
// (tests/data/motion/rocket_slant.svg, its nose up and right at 45 degrees) told it launches
// goes off towards its nose, not straight up shrinking towards its top; mirrored, it goes up and
// left; a landing comes in along a nose that points down and stays; a flying saucer (no nose:
// its ends alike) still climbs straight up.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "procedural/flight_axis.h"
#include "procedural/motion_plan.h"
#include "procedural/travel_profile.h"
#include "procedural/travel_words.h"

#include "motion_drawing.h"
#include "wordnet_or_skip.h"

using namespace svgm;
using svgm::test::Drawing;
using svgm::test::mirrored_drawing;

namespace {


// The drawing turned upside down (y -> height - y), its rig rebuilt: the nose points down.
Drawing flipped(const char* name) {
  Drawing d(name);
  for (Path& p : d.scene.paths)
    for (auto& sp : p.subpaths)
      for (Vec2& q : sp.points) q.y = d.scene.height - q.y;
  d.rig = build_rig(d.scene, {});
  return d;
}

// The mean of every point of the scene at frame f of animate_plan's output (F frames).
Vec2 mean_at(const std::vector<Vec2>& pts, int F, int f) {
  const size_t per = pts.size() / F;
  Vec2 m{0, 0};
  for (size_t i = 0; i < per; ++i) m = m + pts[f * per + i];
  return (1.0 / static_cast<double>(per)) * m;
}

std::string actions_of(const MotionPlan& plan) {
  std::string s;
  for (const auto& a : plan.actions) s += (s.empty() ? "" : " ") + std::string(primitive_name(a.primitive));
  return s;
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("flight axis: a rocket on a slant is mirrored about its length, its nose the narrow end up and to the right") {
  const Drawing d("rocket_slant.svg");
  const FlightAxis a = flight_axis(d.rig);
  CAPTURE(a.why);
  REQUIRE(a.found);
  // Drawn along (cos 45, -sin 45): within the 3 degree steps of the mirror search.
  CHECK(a.nose.x == doctest::Approx(std::sqrt(0.5)).epsilon(0.04));
  CHECK(a.nose.y == doctest::Approx(-std::sqrt(0.5)).epsilon(0.04));
  const FlightAxis m = flight_axis(mirrored_drawing("rocket_slant.svg").rig);
  REQUIRE(m.found);
  CHECK(m.nose.x == doctest::Approx(-std::sqrt(0.5)).epsilon(0.04));
  CHECK(m.nose.y == doctest::Approx(-std::sqrt(0.5)).epsilon(0.04));
  // Upside down, its nose points down and to the right.
  const FlightAxis f = flight_axis(flipped("rocket_slant.svg").rig);
  REQUIRE(f.found);
  CHECK(f.nose.x == doctest::Approx(std::sqrt(0.5)).epsilon(0.04));
  CHECK(f.nose.y == doctest::Approx(std::sqrt(0.5)).epsilon(0.04));
}

TEST_CASE("launches: the rocket on a slant goes off towards its nose, speeding up, and settles back; no shrink, no sideways slide") {
  const Drawing d("rocket_slant.svg");
  for (const char* prompt : {"the rocket launches", "the spaceship blasts off into space", "the rocket takes off"}) {
    CAPTURE(prompt);
    MotionPlan plan = plan_from_prompt(parse_prompt(prompt), d.rig, 1);
    CHECK(actions_of(plan) == "bob shake");
    CHECK(plan.actions.at(0).heading.x == doctest::Approx(std::sqrt(0.5)).epsilon(0.04));
    CHECK(plan.actions.at(0).heading.y == doctest::Approx(-std::sqrt(0.5)).epsilon(0.04));
  }
  // The way without the rumble (a small sideways shake).
  MotionPlan plan = plan_from_prompt(parse_prompt("the rocket launches"), d.rig, 1);
  plan.actions.resize(1);
  const int F = 41;  // frame f at loop time f / 40
  const std::vector<Vec2> pts = animate_plan(d.scene, d.rig, plan, F);
  const Vec2 rest = mean_at(pts, F, 0);
  // Still through the ignition, farthest out at kLaunchOut.
  const Vec2 ignited = mean_at(pts, F, 4);  // t = 0.1 < kIgnitionShare
  CHECK(std::hypot(ignited.x - rest.x, ignited.y - rest.y) < 1e-9);
  const int far = static_cast<int>(std::lround(kLaunchOut * 40));
  const Vec2 out = mean_at(pts, F, far) - rest;
  const double reach = plan.actions[0].amp * (std::sqrt(0.5) * d.rig.figure.w() + std::sqrt(0.5) * d.rig.figure.h());
  CHECK(std::hypot(out.x, out.y) == doctest::Approx(reach).epsilon(0.02));
  CHECK(out.x > 0);
  CHECK(out.y < 0);
  CHECK(std::fabs(out.x + out.y) < 1e-6 * reach);  // along the diagonal: as far right as up
  // Speeding up: the second half of the way out goes farther than the first.
  const int mid = static_cast<int>(std::lround((kIgnitionShare + kLaunchOut) / 2 * 40));
  const Vec2 half = mean_at(pts, F, mid) - rest;
  CHECK(std::hypot(half.x, half.y) < 0.5 * std::hypot(out.x, out.y));
  // Every frame the same size: the rocket never shrinks (a launch, not a going away).
  for (int f = 0; f < F; ++f) {
    RigBox b;
    const size_t per = pts.size() / F;
    for (size_t i = 0; i < per; ++i) b.add(pts[f * per + i]);
    RigBox r;
    for (size_t i = 0; i < per; ++i) r.add(pts[i]);
    CHECK(b.w() == doctest::Approx(r.w()).epsilon(1e-9));
  }
}

TEST_CASE("launches: a rocket mirrored goes up and to the left; one pointing down climbs straight up as before") {
  const MotionPlan left = plan_from_prompt(parse_prompt("the rocket launches"), mirrored_drawing("rocket_slant.svg").rig, 1);
  REQUIRE(actions_of(left) == "bob shake");
  CHECK(left.actions[0].heading.x < -0.6);
  CHECK(left.actions[0].heading.y < -0.6);
  // Upside down its nose points down and to the right: a launch never goes down.
  const MotionPlan down = plan_from_prompt(parse_prompt("the rocket launches"), flipped("rocket_slant.svg").rig, 1);
  CHECK(actions_of(down) == "bob slide pulse shake");
  for (const auto& a : down.actions) CHECK(a.heading == Vec2{0, 0});
}

TEST_CASE("lands: a rocket pointing down comes in along its nose and stays down; pointing up, it comes straight down") {
  if (!wordnet_or_skip()) return;  // "lands" is WordNet's land (lexicon_anchors.cpp)
  const Drawing down = flipped("rocket_slant.svg");
  MotionPlan plan = plan_from_prompt(parse_prompt("the rocket lands"), down.rig, 1);
  REQUIRE(actions_of(plan) == "bob");
  const PlannedAction& a = plan.actions[0];
  CHECK(a.vertical == -1);
  CHECK(a.heading.x == doctest::Approx(std::sqrt(0.5)).epsilon(0.04));
  CHECK(a.heading.y == doctest::Approx(std::sqrt(0.5)).epsilon(0.04));
  const int F = 41;
  const std::vector<Vec2> pts = animate_plan(down.scene, down.rig, plan, F);
  const Vec2 rest = mean_at(pts, F, 0);
  // Farthest back (up and to the left, behind its nose) at kLandBack, down again from kLandDown.
  const Vec2 back = mean_at(pts, F, static_cast<int>(std::lround(kLandBack * 40))) - rest;
  CHECK(back.x < 0);
  CHECK(back.y < 0);
  for (int f = static_cast<int>(std::ceil(kLandDown * 40)); f < F; ++f) {
    const Vec2 m = mean_at(pts, F, f) - rest;
    CHECK(std::hypot(m.x, m.y) < 1e-9);
  }
  const MotionPlan up = plan_from_prompt(parse_prompt("the rocket lands"), Drawing("rocket_slant.svg").rig, 1);
  REQUIRE(actions_of(up) == "bob");
  CHECK(up.actions[0].heading == Vec2{0, 1});
  // Both get the room of a trip one way (pipeline/canvas_room.h); a hover does not.
  CHECK(launches_figure(parse_prompt("the plane lands")));
  CHECK(launches_figure(parse_prompt("the rocket blasts off")));
  CHECK_FALSE(launches_figure(parse_prompt("the plane hovers")));
}

}  // TEST_SUITE
