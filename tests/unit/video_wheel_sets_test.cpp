// Small wheels found as a set (procedural/wheel_sets.h) on drawings made here: a car drawn as
// openmoji draws one (the body and two hub discs in one group, the tyres' outlines with the body's
// outline in another) gets its four round paths as wheels, which turn about their own centres;
// plain discs look the same turned, so the body bounces on them (invisible_spin.h); driven, the
// car's wheels roll, hub and tyre by one angle; a standing figure with two round shoes has no
// wheels.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "svgmotion/svg_reader.h"
#include "procedural/motion_plan.h"
#include "procedural/wheel_sets.h"

using namespace svgm;

namespace {

// On a 72 x 72 canvas: a car body 10..62 x 30..52, hubs r 4 and tyres r 5 at (20, 51), (52, 51).
const char* kCar = R"(<svg xmlns="http://www.w3.org/2000/svg" width="72" height="72">
  <g id="color"><path fill="#e54" d="M 10 40 L 25 30 L 50 30 L 62 40 L 62 52 L 10 52 Z"/>
    <circle cx="20" cy="51" r="4" fill="#999"/><circle cx="52" cy="51" r="4" fill="#999"/></g>
  <g id="line"><path fill="none" stroke="#000" stroke-width="2" d="M 10 40 L 25 30 L 50 30 L 62 40 L 62 52 L 10 52 Z"/>
    <circle cx="20" cy="51" r="5" fill="none" stroke="#000" stroke-width="2"/>
    <circle cx="52" cy="51" r="5" fill="none" stroke="#000" stroke-width="2"/></g>
</svg>)";

}  // namespace

TEST_SUITE("video") {

TEST_CASE("a car's small wheels are found as a set and spin about their own centres; plain discs: the body bounces on them") {
  const Scene s = read_svg_string(kCar, "car.svg");
  CHECK(wheel_set_paths(s) == std::set<int>{1, 2, 4, 5});
  const Rig rig = build_rig(s, {});
  std::vector<int> round;
  for (size_t i = 0; i < rig.parts.size(); ++i)
    if (rig.parts[i].round) round.push_back(static_cast<int>(i));
  CHECK(round.size() == 4);
  MotionPlan plan = plan_from_prompt(parse_prompt("the car's wheels spin"), rig, 1);
  REQUIRE(!plan.actions.empty());
  CHECK(plan.actions[0].primitive == Primitive::Spin);
  // The wheels turn (a hub may turn as the load of its tyre: part_rig_units.cpp).
  REQUIRE(!plan.actions[0].parts.empty());
  for (int p : plan.actions[0].parts) CHECK(std::find(round.begin(), round.end(), p) != round.end());
  const int F = 13;
  fit_plan(s, rig, plan, F, 7);
  const auto pts = animate_plan(s, rig, plan, F);
  const size_t per = pts.size() / F;
  // The wheels are plain discs sent nowhere: they spin in place and the body bounces on them.
  CHECK(!plan.actions[0].rolls);
  REQUIRE(plan.actions.size() == 2);
  CHECK(plan.actions[1].primitive == Primitive::Bob);
  // Per path: the largest travel of its points, and the largest change of the distance of its
  // points from their wheel's resting centre (a turn about the centre keeps them on their circle).
  size_t i = 0;
  for (size_t p = 0; p < s.paths.size(); ++p) {
    double travel = 0, radial = 0;
    const Vec2 c{p == 1 || p == 4 ? 20.0 : 52.0, 51.0};
    for (const auto& sp : s.paths[p].subpaths)
      for (size_t q = 0; q < sp.points.size(); ++q, ++i)
        for (int f = 1; f < F; ++f) {
          const Vec2 a = pts[i], b = pts[f * per + i];
          travel = std::max(travel, std::hypot(b.x - a.x, b.y - a.y));
          radial = std::max(radial, std::fabs(std::hypot(b.x - c.x, b.y - c.y) - std::hypot(a.x - c.x, a.y - c.y)));
        }
    if (p == 0 || p == 3) {
      // The body bounces: a little, well under what the wheels' points go round.
      CHECK(travel > 0.1);
      CHECK(travel < 0.05 * 22 + 1e-9);
    } else {
      CHECK(travel > 3.0);     // a wheel's points go round
      CHECK(radial < 1e-6);    // about its own centre, which stays on the ground
    }
  }
}

TEST_CASE("wheels roll without slipping: a wheel's pieces turn as one by the distance over the outer radius") {
  // The same car driven to the right: the car slides, its wheels roll. The hub (r 4) and the
  // tyre (r 5) of a wheel turn by the same angle, the distance over the tyre's radius (5): each
  // by its own radius, a rim turned faster than its tyre (a tractor's lugs were scrambled).
  const Scene s = read_svg_string(kCar, "car.svg");
  const Rig rig = build_rig(s, {});
  MotionPlan plan = plan_from_prompt(parse_prompt("the car drives to the right"), rig, 1);
  const int F = 13;
  fit_plan(s, rig, plan, F, 7);
  int spin = -1;
  for (size_t k = 0; k < plan.actions.size(); ++k)
    if (plan.actions[k].primitive == Primitive::Spin) spin = static_cast<int>(k);
  REQUIRE(spin >= 0);
  CHECK(plan.actions[spin].rolls);
  for (auto& a : plan.actions)  // the engine's jitter aside: the body's x is the slide's
    if (a.primitive == Primitive::Shake) a.amp = 0;
  const auto pts = animate_plan(s, rig, plan, F);
  const size_t per = pts.size() / F;
  // First points: body 0, hub 1 (at (20, 47): M cx, cy - r), tyre 4 (at (20, 46)).
  auto first = [&](int path) {
    size_t n = 0;
    for (int p = 0; p < path; ++p)
      for (const auto& sp : s.paths[p].subpaths) n += sp.points.size();
    return n;
  };
  const Vec2 hub0 = pts[first(1)], tyre0 = pts[first(4)];
  double farthest = 0;
  for (int f = 1; f < F; ++f) {
    // The wheel's centre goes with the slide (the body's x).
    const double x = pts[f * per + first(0)].x - pts[first(0)].x;
    const Vec2 c{20 + x, 51};
    const Vec2 h = pts[f * per + first(1)], t = pts[f * per + first(4)];
    const double ah = std::atan2(h.y - c.y, h.x - c.x) - std::atan2(hub0.y - 51, hub0.x - 20);
    const double at = std::atan2(t.y - c.y, t.x - c.x) - std::atan2(tyre0.y - 51, tyre0.x - 20);
    CHECK(std::remainder(ah - at, 2 * M_PI) == doctest::Approx(0).epsilon(1e-6));
    CHECK(std::remainder(at - x / 5, 2 * M_PI) == doctest::Approx(0).epsilon(1e-6));
    farthest = std::max(farthest, std::fabs(x));
  }
  CHECK(farthest > 1.0);
}

TEST_CASE("a tractor's small front wheel on the ground with its large back wheel is a wheel; a round lamp up front is not") {
  // On a 72 x 72 canvas: a body 8..62 x 20..50, a back wheel r 14 at (46, 50) (tyre and hub), a
  // front wheel r 6 at (16, 58) (0.43 of the back one's width, its bottom on the same ground), a
  // round lamp r 6 at (12, 32).
  const Scene s = read_svg_string(R"(<svg xmlns="http://www.w3.org/2000/svg" width="72" height="72">
    <g><path fill="#7b5" d="M 8 24 L 30 24 L 36 10 L 62 10 L 62 50 L 8 50 Z"/>
    <circle cx="46" cy="50" r="14" fill="#333"/><circle cx="46" cy="50" r="7" fill="#fc4"/>
    <circle cx="16" cy="58" r="6" fill="#333"/><circle cx="16" cy="58" r="3" fill="#fc4"/>
    <circle cx="12" cy="32" r="6" fill="#ff8"/></g></svg>)", "tractor.svg");
  const Rig rig = build_rig(s, {});
  MotionPlan plan = plan_from_prompt(parse_prompt("the tractor's wheels turn"), rig, 1);
  REQUIRE(!plan.actions.empty());
  CHECK(plan.actions[0].primitive == Primitive::Spin);
  std::set<int> spun;
  for (int p : plan.actions[0].parts)
    for (size_t pi = 0; pi < s.paths.size(); ++pi)
      if (rig.part_of_path[pi] == p) spun.insert(static_cast<int>(pi));
  CHECK(spun.count(1));   // the back tyre
  CHECK(spun.count(3));   // the front tyre
  CHECK(!spun.count(5));  // the lamp
  CHECK(!spun.count(0));  // the body
}

TEST_CASE("no wheel set: round shoes under a standing figure, round eyes up in a wide one") {
  // Taller than wide: a figure standing on two round shoes.
  const Scene standing = read_svg_string(R"(<svg xmlns="http://www.w3.org/2000/svg" width="72" height="72">
    <g><rect x="26" y="6" width="20" height="50" fill="#48c"/>
    <circle cx="28" cy="60" r="5" fill="#333"/><circle cx="44" cy="60" r="5" fill="#333"/></g></svg>)", "standing.svg");
  CHECK(wheel_set_paths(standing).empty());
  // Wider than tall, the round paths in its upper part: eyes of a fish.
  const Scene fish = read_svg_string(R"(<svg xmlns="http://www.w3.org/2000/svg" width="72" height="72">
    <g><rect x="6" y="26" width="60" height="24" fill="#48c"/>
    <circle cx="14" cy="31" r="3" fill="#333"/><circle cx="58" cy="31" r="3" fill="#333"/></g></svg>)", "fish.svg");
  CHECK(wheel_set_paths(fish).empty());
}

}  // TEST_SUITE
