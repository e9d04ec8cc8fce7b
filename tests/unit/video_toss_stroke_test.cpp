// Juggling and swimming strokes (toss_and_stroke.h, tossed_things.h) on drawings made for these
// tests: a juggler's three balls (and nothing else: not his eyes, not his head) fly a cascade,
// all on its one curve half way through the loop and back to where they were drawn, a third of
// a cycle apart; "tosses the balls" reads so, fronds tossing do not; a swimmer's arms
// turn over in whole turns about the shoulders while the water stays.
#include <doctest/doctest.h>

#include <cmath>

#include "procedural/motion_plan.h"
#include "procedural/toss_and_stroke.h"
#include "procedural/tossed_things.h"

#include "motion_drawing.h"
using namespace svgm;
using svgm::test::Drawing;

namespace {

// The index of the path whose first point is `p` (the drawings start each path at a known point).
int path_at(const Scene& scene, Vec2 p) {
  for (size_t i = 0; i < scene.paths.size(); ++i) {
    const Vec2 q = scene.paths[i].subpaths[0].points[0];
    if (std::hypot(q.x - p.x, q.y - p.y) < 1e-6) return static_cast<int>(i);
  }
  return -1;
}

size_t first_point(const Scene& scene, int path) {
  size_t i = 0;
  for (int p = 0; p < path; ++p)
    for (const auto& sp : scene.paths[p].subpaths) i += sp.points.size();
  return i;
}

}  // namespace

TEST_SUITE("motion") {

TEST_CASE("juggling: the three balls, not the eyes or the head, are the tossed things; the cascade is closed") {
  const Drawing d("juggler.svg");
  const std::vector<TossedThing> things = find_tossed_things(d.rig);
  REQUIRE(things.size() == 3);
  // Left to right: the red ball (42..58), the green one (92..108), the yellow one (142..158),
  // each with its highlight (two pieces).
  CHECK(things[0].box.x0 == doctest::Approx(42));
  CHECK(things[1].box.y0 == doctest::Approx(14));
  CHECK(things[2].box.x1 == doctest::Approx(158));
  for (const auto& t : things) CHECK(t.pieces.size() == 2);
  std::vector<TossedThing> phased = things;
  const TossArc arc = cascade_arc(d.rig, phased);
  // The hands at the arms' ends (50,112) and (150,112), the arcs rising to the highest ball
  // (y 22): 90 px; spread about x 100.
  CHECK(arc.hand == doctest::Approx(112));
  CHECK(arc.rise == doctest::Approx(90));
  CHECK(arc.centre == doctest::Approx(100));
  CHECK(arc.outer == doctest::Approx(50));
  // The apex of the first throw: half way through its flight, `rise` over the hands, half way
  // from the left inner point (100 - 20) to the right outer point (150).
  const Vec2 top = cascade_point(arc, 0.5 * kTossAir * 0.5);
  CHECK(top.y == doctest::Approx(112 - 90));
  CHECK(top.x == doctest::Approx(115));
  // Closed: a cycle later it is where it was; the second throw goes the other way.
  CHECK(cascade_point(arc, 1.1).x == doctest::Approx(cascade_point(arc, 0.1).x));
  CHECK(cascade_point(arc, 0.5 + 0.5 * kTossAir * 0.5).x == doctest::Approx(85));
  // Three balls a third of a cycle apart.
  std::vector<double> ph;
  for (const auto& t : phased) ph.push_back(t.phase - std::floor(t.phase));
  std::sort(ph.begin(), ph.end());
  CHECK(ph[1] - ph[0] == doctest::Approx(1.0 / 3));
  CHECK(ph[2] - ph[1] == doctest::Approx(1.0 / 3));
}

TEST_CASE("juggling: 'tosses the balls' flies each ball onto the cascade and back to where it was drawn") {
  const Drawing d("juggler.svg");
  for (const char* prompt : {"the juggler juggles", "the juggler tosses the balls", "he keeps the balls in the air"}) {
    CAPTURE(prompt);
    const MotionPlan plan = plan_from_prompt(parse_prompt(prompt), d.rig, 1);
    REQUIRE(!plan.actions.empty());
    CHECK(plan.actions[0].verb == "juggle");
    REQUIRE(plan.actions[0].primitive == Primitive::Toss);
    REQUIRE(plan.actions[0].tossed.size() == 3);
    const int F = 61;
    const auto pts = animate_plan(d.scene, d.rig, plan, F);
    const size_t per = pts.size() / F;
    const TossArc& arc = plan.actions[0].arc;
    for (Vec2 start : {Vec2{50, 62}, Vec2{100, 14}, Vec2{150, 62}}) {
      const int p = path_at(d.scene, start);
      REQUIRE(p >= 0);
      const TossedThing* th = nullptr;
      for (const auto& t : plan.actions[0].tossed)
        if (t.box.x0 <= start.x && start.x <= t.box.x1 && t.box.y0 <= start.y + 1 && start.y <= t.box.y1) th = &t;
      REQUIRE(th);
      // The ball's top point (its centre 8 px over): half way through the loop every ball is on
      // the one cascade curve, at its phase plus half a cycle.
      const Vec2 mid = pts[(F / 2) * per + first_point(d.scene, p)], on = cascade_point(arc, th->phase + 0.5);
      CHECK(mid.x == doctest::Approx(on.x));
      CHECK(mid.y + 8 == doctest::Approx(on.y));
      // It rises and falls through at least half the arcs' rise.
      double lo = 1e9, hi = -1e9;
      for (int f = 0; f < F; ++f) lo = std::min(lo, pts[f * per + first_point(d.scene, p)].y), hi = std::max(hi, pts[f * per + first_point(d.scene, p)].y);
      CHECK(hi - lo >= 0.5 * arc.rise);
      // Back where it was drawn at the loop's end.
      const Vec2 end = pts[(F - 1) * per + first_point(d.scene, p)];
      CHECK(std::hypot(end.x - start.x, end.y - start.y) < 1e-6);
    }
    // The legs stay.
    const std::vector<double> moved = d.travel(plan);
    CHECK(moved[static_cast<size_t>(path_at(d.scene, {84, 140}))] < 1e-9);
  }
}

TEST_CASE("juggling is read only with several things tossed and drawn: fronds toss, a boxer has no balls") {
  const Drawing juggler("juggler.svg"), boxer("boxer.svg");
  for (const char* prompt : {"the palm fronds toss in the wind", "the player throws the ball"}) {
    CAPTURE(prompt);
    CHECK_FALSE(reads_as_juggling(parse_prompt(prompt).clauses[0], juggler.rig));
  }
  CHECK(reads_as_juggling(parse_prompt("the juggler tosses the balls").clauses[0], juggler.rig));
  CHECK_FALSE(reads_as_juggling(parse_prompt("the juggler tosses the balls").clauses[0], boxer.rig));
  CHECK(find_tossed_things(boxer.rig).empty());
}

TEST_CASE("front crawl: the arms turn over about the shoulders, whole turns; the water stays") {
  const Drawing d("swimmer.svg");
  const MotionPlan plan = plan_from_prompt(parse_prompt("the swimmer swims the front crawl"), d.rig, 1);
  REQUIRE(!plan.actions.empty());
  const PlannedAction& a = plan.actions[0];
  CHECK(a.verb == "stroke");
  REQUIRE(a.primitive == Primitive::Windmill);
  REQUIRE(a.parts.size() == 2);
  // Facing right (the head and its eye at the right): over the top clockwise on the screen.
  CHECK(a.direction == 1);
  const int F = 73;
  const auto pts = animate_plan(d.scene, d.rig, plan, F);
  const size_t per = pts.size() / F;
  // The forward arm's hand (190,52) turns about its shoulder through a whole turn: its angle,
  // unwrapped over the loop, goes through at least 270 degrees one way.
  const int arm = path_at(d.scene, {150, 88});
  REQUIRE(arm >= 0);
  const Vec2 pivot = d.rig.parts[static_cast<size_t>(d.rig.part_of_path[static_cast<size_t>(arm)])].pivot;
  const size_t hand = first_point(d.scene, arm) + 1;
  double turned = 0, prev = std::atan2(pts[hand].y - pivot.y, pts[hand].x - pivot.x);
  for (int f = 1; f < F; ++f) {
    const double ang = std::atan2(pts[f * per + hand].y - pivot.y, pts[f * per + hand].x - pivot.x);
    turned += std::remainder(ang - prev, 2 * M_PI);
    prev = ang;
  }
  CHECK(turned * 180 / M_PI >= 270);
  // The water stays.
  const std::vector<double> moved = d.travel(plan);
  CHECK(moved[static_cast<size_t>(path_at(d.scene, {0, 100}))] < 1e-9);
}

TEST_CASE("strokes are read of swimmers only: a baby crawls, a snail creeps") {
  CHECK(stroke_reading(parse_prompt("the swimmer swims the front crawl").clauses[0])->name == "stroke");
  CHECK(stroke_reading(parse_prompt("she swims freestyle").clauses[0])->name == "stroke");
  CHECK(stroke_reading(parse_prompt("he swims the backstroke").clauses[0])->name == "backstroke");
  CHECK(stroke_reading(parse_prompt("the swimmer swims butterfly").clauses[0])->name == "butterfly");
  CHECK(stroke_reading(parse_prompt("the baby crawls to the left").clauses[0]) == nullptr);
  CHECK(stroke_reading(parse_prompt("the snail crawls").clauses[0]) == nullptr);
  CHECK(stroke_reading(parse_prompt("the fish swims").clauses[0]) == nullptr);
}

}  // TEST_SUITE
