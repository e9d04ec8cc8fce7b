// motion.json's per-path motion (procedural/motion_plan.h's path_motion_json): every control
// point's rest position lies in its path's rest box as written (both rounded alike), so a
// reader's region ending at the drawing's edge holds the points on that edge.
#include <doctest/doctest.h>

#include "svgmotion/svg_reader.h"
#include "procedural/motion_plan.h"

using namespace svgm;

TEST_SUITE("video") {

TEST_CASE("motion.json: the rest positions of a path's points lie in its rest box as written") {
  // A square whose left edge is at 9.916 and right edge at 30.254: rounded to 0.1 they were 9.9
  // and 30.3, outside the box [9.92, 30.25].
  const Scene s = read_svg_string(R"(<svg xmlns="http://www.w3.org/2000/svg" width="72" height="72">
    <path d="M 9.916 41.834 L 30.254 41.834 L 30.254 62.166 L 9.916 62.166 Z"/></svg>)", "edge.svg");
  const int F = 3;
  std::vector<Vec2> pts;
  for (int f = 0; f < F; ++f)
    for (const auto& sp : s.paths[0].subpaths)
      for (const Vec2& q : sp.points) pts.push_back(q + Vec2{0, 1.0 * f});
  const auto j = path_motion_json(s, path_motion(s, pts, F));
  REQUIRE(j.size() == 1);
  const auto& rest = j[0]["rest"];
  const auto& pt = j[0]["point_travel"];
  REQUIRE(pt.size() == 3 * 13);
  for (size_t k = 0; k < pt.size(); k += 3) {
    CHECK(pt[k].get<double>() >= rest[0].get<double>());
    CHECK(pt[k + 1].get<double>() >= rest[1].get<double>());
    CHECK(pt[k].get<double>() <= rest[2].get<double>());
    CHECK(pt[k + 1].get<double>() <= rest[3].get<double>());
  }
  CHECK(pt[0].get<double>() == rest[0].get<double>());
  CHECK(pt[2].get<double>() == 2.0);
}

TEST_CASE("motion.json: a point's travel is written to 0.01, not 0.1") {
  // A square moving 4.06 units down over 3 frames on a 47-unit canvas (a twemoji's size): 8 % of
  // a figure there is about 4 units, and to 0.1 its travel read 4.1 (1 % over), a travel of 4.04
  // 4.0 (1 % under the floor it was raised to).
  const Scene s = read_svg_string(R"(<svg xmlns="http://www.w3.org/2000/svg" width="47" height="47">
    <path d="M 10 10 L 30 10 L 30 30 L 10 30 Z"/></svg>)", "move.svg");
  const int F = 3;
  std::vector<Vec2> pts;
  for (int f = 0; f < F; ++f)
    for (const auto& sp : s.paths[0].subpaths)
      for (const Vec2& q : sp.points) pts.push_back(q + Vec2{0, 2.02 * f});
  const auto j = path_motion_json(s, path_motion(s, pts, F));
  REQUIRE(j.size() == 1);
  CHECK(j[0]["point_travel"][2].get<double>() == doctest::Approx(4.04).epsilon(1e-9));
}

}  // TEST_SUITE
