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

TEST_CASE("implicit repeats: relative moveto pairs are relative linetos, H/V/C/Q/A repeat") {
  const auto s = parse("m 30 40 110 120 -20 -130 h 10 10 v -5 c 0 0 0 0 1 1 2 2 2 2 3 3");
  REQUIRE(s.size() == 1);
  REQUIRE(s[0].segment_count() == 7);
  CHECK(near(s[0].points[3], {140, 160}));
  CHECK(near(s[0].points[6], {120, 30}));
  CHECK(near(s[0].points[9], {130, 30}));
  CHECK(near(s[0].points[12], {140, 30}));
  CHECK(near(s[0].points[15], {140, 25}));
  CHECK(near(s[0].points[18], {141, 26}));
  CHECK(near(s[0].points[21], {144, 29}));  // relative to the previous curve's end
  const auto q = parse("M0 0Q1 1 2 0 3 -1 4 0");
  CHECK(q[0].segment_count() == 2);
}

TEST_CASE("after Z: the next command starts at the closed subpath's start (relative too)") {
  const auto s = parse("M 10 50 L 10 10 L 50 10 z A 5 5 0 0 1 150 150 M 0 0 l 10 0 z l 0 5 Z Z");
  REQUIRE(s.size() == 4);
  CHECK(s[0].closed);
  CHECK(s[0].segment_count() == 3);             // two lines and the closing one
  CHECK(near(s[1].points[0], {10, 50}));         // the arc starts where z returned
  CHECK(near(s[1].points.back(), {150, 150}));
  CHECK_FALSE(s[1].closed);
  CHECK(near(s[3].points[0], {0, 0}));
  CHECK(near(s[3].points[3], {0, 5}));
  CHECK(s[3].closed);                           // the second Z changes nothing
  CHECK(s[3].segment_count() == 2);
}

TEST_CASE("S and T without a curve before them use the current point") {
  const auto s = parse("M 30 40 S 171 45 180 155");
  CHECK(near(s[0].points[1], {30, 40}));
  const auto qs = parse("M 0 0 Q 10 10 20 0 S 30 10 40 0");  // S after Q: no reflection
  CHECK(near(qs[0].points[4], {20, 0}));
  const auto ct = parse("M 0 0 C 0 10 10 10 10 0 T 20 0");  // T after C: a straight quadratic
  CHECK(near(ct[0].points[4], {10 + 20.0 / 3 * 0, 0}));
  CHECK(near(ct[0].points[5], {20 - 10.0 * 2 / 3, 0}));
  const auto tt = parse("M 30 30 T 40 140 t 100 -30");  // T after T: the (degenerate) control
  CHECK(near(tt[0].points[4], {40 + 2.0 / 3 * 10, 140 + 2.0 / 3 * 110}));
}

TEST_CASE("arc flags: compact forms parse, bad flags stop the path") {
  svg::PathDataResult r;
  auto a = parse("M 100 100 h -25 a 25 25 0 1125 25 z", &r);
  CHECK(r.ok);
  CHECK(near(a[0].points.back(), {100, 100}));
  auto b = parse("M10-20A5.5.3-4 010-.1", &r);
  CHECK(r.ok);
  CHECK(near(b[0].points.back(), {0, -0.1}));
  auto c = parse("M 100 100 h 25 a 25 25 0 1 1-25 -25 z", &r);
  CHECK(r.ok);
  auto d = parse("M 100 100 h -25 a 25 25 0 -1 0 25 -25 z", &r);
  CHECK_FALSE(r.ok);
  CHECK(r.error_offset == 16);
  CHECK(d[0].segment_count() == 1);  // the h before the bad arc is kept
  parse("M 100 100 h 25 a25 25 0 6 0 -25 25 z", &r);
  CHECK_FALSE(r.ok);
  parse("M 100 100 h -25 a 25 2501 025 -25 z", &r);  // the flags become "0" and then "25": bad
  CHECK_FALSE(r.ok);
}

TEST_CASE("arcs with extreme finite radii: exact where representable, never NaN") {
  auto all_finite = [](const std::vector<Subpath>& s) {
    for (const auto& sp : s)
      for (const Vec2& v : sp.points)
        if (!std::isfinite(v.x) || !std::isfinite(v.y)) return false;
    return true;
  };
  // A radius of 1e-300 squares to zero (the spec's lambda divides by it): it is scaled up to
  // the half circle on the chord, exactly as radius 1 is above.
  const auto tiny = parse("M 0 0 A 1e-300 1e-300 0 0 1 10 0");
  REQUIRE(tiny.size() == 1);
  REQUIRE(all_finite(tiny));
  CHECK(tiny[0].segment_count() == 2);
  CHECK(near(tiny[0].points.back(), {10, 0}));
  CHECK(std::hypot(tiny[0].points[3].x - 5, tiny[0].points[3].y) == doctest::Approx(5).epsilon(1e-9));
  // F.6.6 scales both radii by the same factor: 1e-300 : 1 over a chord of 10 becomes a half
  // ellipse with radii 5 and 5e300, whose middle anchor is (5, -+5e300).
  const auto thin = parse("M 0 0 A 1e-300 1 0 0 1 10 0");
  REQUIRE(thin.size() == 1);
  REQUIRE(all_finite(thin));
  CHECK(thin[0].segment_count() == 2);
  CHECK(near(thin[0].points.back(), {10, 0}));
  CHECK(thin[0].points[3].x == doctest::Approx(5).epsilon(1e-9));
  CHECK(std::fabs(thin[0].points[3].y) == doctest::Approx(5e300).epsilon(1e-9));
  // A radius of 1e308 squares to infinity: the small arc over a chord of 10 bends by 1e-307,
  // so it is the chord.
  const auto big = parse("M 0 0 A 1e308 1e308 0 0 1 10 0");
  REQUIRE(big.size() == 1);
  REQUIRE(all_finite(big));
  CHECK(big[0].segment_count() == 1);
  CHECK(near(big[0].points[1], {10.0 / 3, 0}));
  CHECK(near(big[0].points[3], {10, 0}));
  // Radii a million chords long still go through the centre, and stay on the circle.
  const auto wide = parse("M 0 0 A 1e7 1e7 0 0 1 10 0");
  REQUIRE(all_finite(wide));
  REQUIRE(wide[0].segment_count() == 1);
  const double cy = std::sqrt(1e14 - 25);  // the centre is (5, +-cy): either side of the chord
  const Vec2 q = wide[0].points[3];
  CHECK(near(q, {10, 0}));
  const Vec2 m = 0.125 * wide[0].points[0] + 0.375 * wide[0].points[1] + 0.375 * wide[0].points[2] +
                 0.125 * wide[0].points[3];
  CHECK(std::min(std::fabs(std::hypot(m.x - 5, m.y - cy) - 1e7), std::fabs(std::hypot(m.x - 5, m.y + cy) - 1e7)) <
        1e-6);
  // The large arc of a 1e308 circle leaves the double range: the points are left infinite
  // (for the reader to refuse), never NaN, and nothing undefined happens on the way.
  const auto huge = parse("M 0 0 A 1e308 1e308 0 1 1 10 0");
  REQUIRE(huge.size() == 1);
  for (const Vec2& v : huge[0].points) CHECK((!std::isnan(v.x) && !std::isnan(v.y)));
  // Endpoints at +-1e308: the midpoint frame halves before it subtracts.
  const auto far = parse("M 1e308 1e308 A 1e308 1e308 0 0 1 -1e308 -1e308");
  REQUIRE(far.size() == 1);
  for (const Vec2& v : far[0].points) CHECK((!std::isnan(v.x) && !std::isnan(v.y)));
}

TEST_CASE("arcs on a rotated ellipse: anchors and cubic midpoints on the ellipse") {
  // Ellipse centre (100, 100), radii 50 and 25, rotated 30 degrees; from angle 10 to 200
  // degrees the positive way (190 degrees: large arc, sweep).
  const double phi = M_PI / 6, cp = std::cos(phi), sp = std::sin(phi);
  auto on = [&](double t) {
    const double x = 50 * std::cos(t), y = 25 * std::sin(t);
    return Vec2{100 + cp * x - sp * y, 100 + sp * x + cp * y};
  };
  // |residual| of the ellipse equation at a point (0 exactly on it).
  auto residual = [&](Vec2 p) {
    const double dx = p.x - 100, dy = p.y - 100;
    const double u = cp * dx + sp * dy, v = -sp * dx + cp * dy;
    return std::fabs(u * u / 2500 + v * v / 625 - 1);
  };
  const Vec2 p0 = on(10 * M_PI / 180), p1 = on(200 * M_PI / 180);
  const std::string d = "M " + std::to_string(p0.x) + " " + std::to_string(p0.y) + " A 50 25 30 1 1 " +
                        std::to_string(p1.x) + " " + std::to_string(p1.y);
  // to_string keeps 6 decimals: the endpoints are on the ellipse to about 1e-6.
  svg::PathDataResult r;
  const auto s = parse(d, &r);
  REQUIRE(r.ok);
  REQUIRE(s.size() == 1);
  CHECK(s[0].segment_count() == 3);  // 190 degrees: three pieces of at most 90
  const auto& p = s[0].points;
  CHECK(p.back().x == std::stod(std::to_string(p1.x)));  // the endpoint is exact
  CHECK(p.back().y == std::stod(std::to_string(p1.y)));
  for (size_t i = 0; i + 3 < p.size(); i += 3) {
    CHECK(residual(p[i + 3]) < 1e-6);
    const Vec2 mid = 0.125 * p[i] + 0.375 * p[i + 1] + 0.375 * p[i + 2] + 0.125 * p[i + 3];
    CHECK(residual(mid) < 1e-6);
  }
}

TEST_CASE("more errors: numbers without a command, double commas, unknown commands") {
  svg::PathDataResult r;
  CHECK(parse("10 10 L 20 20", &r).empty());
  CHECK(r.error_offset == 0);
  auto s = parse("M 0,,0 L 5 5", &r);
  CHECK_FALSE(r.ok);
  CHECK(s.empty());
  s = parse("M 0 0 L 5 5 X 1 1", &r);
  CHECK_FALSE(r.ok);
  CHECK(r.error_offset == 12);
  CHECK(s[0].segment_count() == 1);
  s = parse("M 0 0 L 5 5 Z 3 3", &r);  // numbers after Z are an error
  CHECK_FALSE(r.ok);
  CHECK(s.size() == 1);
  CHECK(s[0].closed);
  s = parse("M 30 40 L 110 160 L 150#80", &r);
  CHECK(r.error_offset == 18);
  CHECK(s[0].segment_count() == 1);
  parse("M 0 0 L nan 0", &r);
  CHECK(r.out_of_range);
  s = parse("  M\n10\t10 L 20,20  ", &r);
  CHECK(r.ok);
  CHECK(s[0].segment_count() == 1);
}

TEST_CASE("zero-length segments are kept (they carry caps)") {
  const auto s = parse("M 70 100 L 70 100 M 130 100 L 130 100");
  REQUIRE(s.size() == 2);
  CHECK(s[0].segment_count() == 1);
  CHECK(s[1].segment_count() == 1);
  CHECK(parse("M 0 0 A 10 10 0 0 1 0 0").empty());  // an arc to its own start draws nothing
}

}  // TEST_SUITE
