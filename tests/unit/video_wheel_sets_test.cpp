// Small wheels found as a set (procedural/wheel_sets.h) on drawings made here: a car drawn as
// openmoji draws one (the body and two hub discs in one group, the tyres' outlines with the body's
// outline in another) gets its four round paths as wheels, which turn about their own centres;
// plain discs look the same turned, so the car rolls with them (invisible_spin.h); a standing
// figure with two round shoes has no wheels.
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

TEST_CASE("a car's small wheels are found as a set and turn about their own centres; plain discs roll the car") {
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
  // The wheels are plain discs: the car rolls with them (a slide of the whole figure).
  CHECK(plan.actions[0].rolls);
  // Per path: the largest travel of its points, and the largest change of the distance of its
  // points from their wheel's centre, which goes with the body (a turn about the centre keeps
  // them on their circle).
  size_t i = 0;
  for (size_t p = 0; p < s.paths.size(); ++p) {
    double travel = 0, radial = 0;
    const Vec2 c{p == 1 || p == 4 ? 20.0 : 52.0, 51.0};
    for (const auto& sp : s.paths[p].subpaths)
      for (size_t q = 0; q < sp.points.size(); ++q, ++i)
        for (int f = 1; f < F; ++f) {
          const Vec2 a = pts[i], b = pts[f * per + i], body = pts[f * per] - pts[0];
          travel = std::max(travel, std::hypot(b.x - a.x, b.y - a.y));
          radial = std::max(radial, std::fabs(std::hypot(b.x - c.x - body.x, b.y - c.y - body.y) - std::hypot(a.x - c.x, a.y - c.y)));
        }
    CHECK(travel > 3.0);    // the body rolls, a wheel's points go round
    if (p != 0 && p != 3) CHECK(radial < 0.5);   // about its own centre
  }
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
