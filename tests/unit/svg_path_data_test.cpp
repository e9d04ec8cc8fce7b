// Path data grammar: commands, implicit repeats, compact numbers, reflections, arcs, errors.
#include <doctest/doctest.h>

#include <cmath>

#include "svg/path_data.h"

using namespace svgm;
using svgm::svg::parse_path_data;

namespace {

std::vector<Subpath> parse(std::string_view d, svg::PathDataResult* r = nullptr) {
  std::vector<Subpath> out;
  const auto res = parse_path_data(d, out);
  if (r) *r = res;
  return out;
}

bool near(Vec2 a, Vec2 b, double eps = 1e-9) { return std::fabs(a.x - b.x) < eps && std::fabs(a.y - b.y) < eps; }

}  // namespace

TEST_SUITE("svg") {

TEST_CASE("lines become cubics with control points at thirds; H, V and implicit L") {
  const auto s = parse("M 0 0 L 30 0 H 60 V 30 90 L 90 90 60 120");
  REQUIRE(s.size() == 1);
  REQUIRE(s[0].segment_count() == 6);  // L, H, V, V (implicit), L, L (implicit)
  CHECK(near(s[0].points[1], {10, 0}));
  CHECK(near(s[0].points[2], {20, 0}));
  CHECK(near(s[0].points[6], {60, 0}));
  CHECK(near(s[0].points[9], {60, 30}));
  CHECK(near(s[0].points[12], {60, 90}));
  CHECK(near(s[0].points[15], {90, 90}));
  CHECK(near(s[0].points[18], {60, 120}));
}

TEST_CASE("compact numbers: 1.5.5, -1e-2, signs as separators") {
  const auto s = parse("M1.5.5L-1e-2-2");
  REQUIRE(s.size() == 1);
  CHECK(near(s[0].points[0], {1.5, 0.5}));
  CHECK(near(s[0].points[3], {-0.01, -2}));
}

TEST_CASE("relative commands, implicit lineto after moveto, close returns to start") {
  const auto s = parse("m 10 10 20 0 0 20 z l 5 5");
  REQUIRE(s.size() == 2);
  CHECK(s[0].closed);
  CHECK(near(s[0].points.back(), {10, 10}));  // Z added the closing line
  CHECK(s[0].segment_count() == 3);
  CHECK(near(s[1].points[0], {10, 10}));      // after Z, l starts at the subpath's start
  CHECK(near(s[1].points[3], {15, 15}));
}

TEST_CASE("S and T reflect the previous control point; quadratics are elevated exactly") {
  const auto s = parse("M 0 0 C 10 0 20 10 20 20 S 30 40 40 40");
  REQUIRE(s[0].segment_count() == 2);
  CHECK(near(s[0].points[4], {20, 30}));  // reflection of (20, 10) about (20, 20)
  const auto q = parse("M 0 0 Q 30 30 60 0 T 120 0");
  CHECK(near(q[0].points[1], {20, 20}));   // p0 + 2/3 (q - p0)
  CHECK(near(q[0].points[2], {40, 20}));   // p1 + 2/3 (q - p1)
  CHECK(near(q[0].points[4], {80, -20}));  // reflected control (90, -30) elevated
}

TEST_CASE("arcs: flags without separators, endpoints exact, midpoint on the circle") {
  const auto s = parse("M 0 50 a50 50 0 00100 0");  // flags "0" and "0" run into x = 100
  REQUIRE(s.size() == 1);
  const auto& p = s[0].points;
  CHECK(near(p.back(), {100, 50}));
  // A half circle of radius 50 about (50, 50): two 90-degree cubics, the middle anchor on it.
  REQUIRE(s[0].segment_count() == 2);
  const Vec2 mid = p[3];
  CHECK(std::hypot(mid.x - 50, mid.y - 50) == doctest::Approx(50).epsilon(1e-9));
  // A quarter arc's cubic midpoint (t = 1/2) lies on the circle to 3e-4 of the radius.
  const Vec2 a = p[0], b = p[1], c = p[2], d = p[3];
  const Vec2 m = 0.125 * a + 0.375 * b + 0.375 * c + 0.125 * d;
  CHECK(std::fabs(std::hypot(m.x - 50, m.y - 50) - 50) < 50 * 3e-4);
}

TEST_CASE("radii too small are scaled up; zero radius is a line") {
  const auto s = parse("M 0 0 A 1 1 0 0 1 10 0");
  CHECK(near(s[0].points.back(), {10, 0}));
  const Vec2 mid = s[0].points[3];
  CHECK(std::hypot(mid.x - 5, mid.y) == doctest::Approx(5).epsilon(1e-9));
  const auto z = parse("M 0 0 A 0 10 0 0 1 10 0");
  CHECK(z[0].segment_count() == 1);
  CHECK(near(z[0].points[1], {10.0 / 3, 0}));
}

TEST_CASE("errors keep what came before, as SVG asks") {
  svg::PathDataResult r;
  const auto s = parse("M 10 10 L 20 20 L 30 foo L 50 50", &r);
  CHECK_FALSE(r.ok);
  CHECK(r.error_offset == 16);
  REQUIRE(s.size() == 1);
  CHECK(s[0].segment_count() == 1);
  const auto none = parse("L 10 10", &r);  // must start with a moveto
  CHECK_FALSE(r.ok);
  CHECK(none.empty());
  parse("M 0 0 L 1e999 0", &r);
  CHECK(r.out_of_range);
}

TEST_CASE("a lone moveto draws nothing; M x y Z is a dot") {
  CHECK(parse("M 10 10").empty());
  CHECK(parse("M 10 10 M 20 20 L 30 30").size() == 1);
  const auto dot = parse("M 10 10 Z");
  REQUIRE(dot.size() == 1);
  CHECK(dot[0].closed);
  CHECK(dot[0].points.size() == 1);
}

}  // TEST_SUITE
