// Splitting long segments before fitting: how many pieces each segment gets, that the pieces
// draw exactly the original curve (de Casteljau), that a closed outline stays closed on the
// same point, and that a plan made for another structure is refused.
#include <doctest/doctest.h>

#include <cmath>

#include "fit/plan/segment_split.h"
#include "svgmotion/error.h"

using namespace svgm;

namespace {

Vec2 cubic(const Vec2* p, double t) {
  const double u = 1 - t;
  return u * u * u * p[0] + 3 * u * u * t * p[1] + 3 * u * t * t * p[2] + t * t * t * p[3];
}

// A closed subpath of two cubics: a long curved one (control polygon 30 + 40 + 50 = 120) and a
// short one back (closing copy of the first point at the end).
Path two_segment_path() {
  Subpath sp;
  sp.closed = true;
  sp.points = {{0, 0}, {30, 0}, {30, 40}, {0.5, 10}, {0.4, 7}, {0.2, 3}, {0, 0}};
  Path p;
  p.id = "p";
  p.subpaths = {sp};
  return p;
}

}  // namespace

TEST_SUITE("fit") {

TEST_CASE("segment split: pieces by control-polygon length, exact curve, closed outline kept") {
  Scene s;
  s.width = s.height = 100;
  s.paths = {two_segment_path()};
  const Path& in = s.paths[0];
  const double poly = 30 + 40 + std::hypot(29.5, 30);
  // Longer than max_length: ceil(length / max_length) pieces, at most max_pieces; short: one.
  const SplitPlan plan = plan_segment_split(s, 30);
  REQUIRE(plan.size() == 1);
  REQUIRE(plan[0].size() == 1);
  CHECK(plan[0][0][0] == 4);  // ceil(99.9 / 30) = 4
  CHECK(plan[0][0][1] == 1);
  CHECK(plan_segment_split(s, 50)[0][0][0] == static_cast<int>(std::ceil(poly / 50)));
  CHECK(plan_segment_split(s, 10)[0][0][0] == 4);  // capped
  CHECK(plan_segment_split(s, 0)[0][0][0] == 1);   // off
  CHECK(plan_segment_split(s, 1e-300)[0][0][0] == 4);  // no int overflow: still capped
  CHECK(added_points(plan) == 9);

  const Path out = split_path(in, plan[0]);
  const Subpath& sp = out.subpaths[0];
  REQUIRE(sp.points.size() == 7 + 9);
  CHECK(sp.segment_count() == 5);
  // The closing copy is still exactly the first point, and the short segment is untouched.
  CHECK(sp.points.front().x == sp.points.back().x);
  CHECK(sp.points.front().y == sp.points.back().y);
  for (int j = 0; j < 3; ++j) {
    CHECK(sp.points[12 + j].x == in.subpaths[0].points[3 + j].x);
    CHECK(sp.points[12 + j].y == in.subpaths[0].points[3 + j].y);
  }
  // Piece k of 4 at parameter u is the original at (k + u) / 4.
  double worst = 0;
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i <= 20; ++i) {
      const double u = i / 20.0;
      const Vec2 a = cubic(&sp.points[3 * k], u), b = cubic(in.subpaths[0].points.data(), (k + u) / 4);
      worst = std::max(worst, std::hypot(a.x - b.x, a.y - b.y));
    }
  MESSAGE("largest distance between the pieces and the original curve: " << worst);
  CHECK(worst < 1e-12);

  // Applied to a scene, every path is split; a plan for another structure is refused.
  CHECK(split_scene(s, plan).paths[0].subpaths[0].points.size() == 16);
  CHECK_THROWS_AS(split_path(in, {{4}}), Error);
  CHECK_THROWS_AS(split_path(in, {{1, 1}, {1}}), Error);
}

}  // TEST_SUITE
