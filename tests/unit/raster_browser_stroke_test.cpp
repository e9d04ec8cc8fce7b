// Strokes outlined as the browser outlines them (raster/browser_stroke.h): the chords of a
// quadratic edge, the quadratics of a circle's stroke sides, a straight stroke's rectangle, and
// the scene that draws strokes as fills. Every expected number is worked out by hand below.
#include <doctest/doctest.h>

#include <cmath>

#include "raster/browser_stroke.h"
#include "raster/render_image.h"
#include "raster_test_support.h"
#include "scene_builders.h"
#include "svgmotion/svg_reader.h"

using namespace svgm;
using namespace svgm::test;

namespace {

// Counts an outline contour's verbs of one kind.
int count(const OutlineContour& c, OutlineVerb::Kind k) {
  int n = 0;
  for (const OutlineVerb& v : c.verbs) n += v.kind == k;
  return n;
}

// The 8-bit red value at (x, y) over white: 255 * (1 - coverage) for black ink.
int red(const RgbaImage& img, int x, int y) {
  return img.rgba[4 * (static_cast<size_t>(y) * img.width + x)];
}

}  // namespace

TEST_SUITE("raster") {

TEST_CASE("browser edges draw a stroke at most a pixel wide as the browser's hairline") {
  // A 45-degree line from (2, 2.5) to (26, 26.5), 1 px wide. Chromium draws it as a hairline:
  // in column 14 a one-pixel-tall box centred on the line's height at the column's centre,
  // y = 2.5 + (14.5 - 2) = 15, which covers rows 14 and 15 half each (1 in all), where a
  // 1-px-wide band (exact edges) spreads sqrt(2) px of ink over rows 13 to 16.
  const Scene s = scene_of(28, 28, {stroked(polygon({{2, 2.5}, {26, 26.5}}, false), 1,
                                            LineJoin::Miter, LineCap::Butt)});
  const RgbaImage hair = render_image(runtime(), s, 28, false, true);
  CHECK(std::abs(red(hair, 14, 14) - 127.5) <= 1);
  CHECK(std::abs(red(hair, 14, 15) - 127.5) <= 1);
  CHECK(red(hair, 14, 13) == 255);
  CHECK(red(hair, 14, 16) == 255);
  // Ink in the column: 1 px for the hairline, sqrt(2) px for the exact band.
  const RgbaImage exact = render_image(runtime(), s, 28, false, false);
  double ink_hair = 0, ink_exact = 0;
  for (int y = 8; y < 22; ++y) {
    ink_hair += 1 - red(hair, 14, y) / 255.0;
    ink_exact += 1 - red(exact, 14, y) / 255.0;
  }
  CHECK(ink_hair == doctest::Approx(1.0).epsilon(0.02));
  CHECK(ink_exact == doctest::Approx(std::sqrt(2.0)).epsilon(0.02));
  // Half as wide: the same hairline at half alpha (0.25 coverage per row).
  Scene thin = s;
  thin.paths[0].stroke.width = 0.5;
  const RgbaImage half = render_image(runtime(), thin, 28, false, true);
  CHECK(std::abs(red(half, 14, 14) - 255 * 0.75) <= 1);
}


TEST_CASE("a quadratic edge becomes 2^k chords with Skia's y snapping") {
  // Bulge (2 p1 - p0 - p2) / 4 = (2.5, -2.5) px: max + min/2 = 3.75 px = 30 eighths, 5 bits,
  // so k = 5 / 2 = 2: four chords at t = 1/4, 1/2, 3/4.
  const Vec2 q[3] = {{0, 0}, {10, 0}, {10, 10}};
  const std::vector<Vec2> c = browser_quad_chords(q);
  REQUIRE(c.size() == 5);
  // t = 1/4: (4.375, 0.625), a 0.625 px rise: y to the nearest quarter, 0.75.
  CHECK(c[1].x == doctest::Approx(4.375));
  CHECK(c[1].y == doctest::Approx(0.75));
  // t = 1/2: (7.5, 2.5), a 1.875 px rise: already on a quarter.
  CHECK(c[2].x == doctest::Approx(7.5));
  CHECK(c[2].y == doctest::Approx(2.5));
  // t = 3/4: (9.375, 5.625), a 3.125 px rise (>= 2): y to the whole pixel 6, slid along the
  // chord from (7.5, 2.5) of slope 1.875 / 3.125 = 0.6 in x per y: x = 9.375 + 0.6 * 0.375.
  CHECK(c[3].x == doctest::Approx(9.6));
  CHECK(c[3].y == doctest::Approx(6.0));
  CHECK(c[4].x == doctest::Approx(10.0));
  CHECK(c[4].y == doctest::Approx(10.0));
  // The same quadratic walked upwards gives the same chords in reverse order.
  const Vec2 r[3] = {q[2], q[1], q[0]};
  const std::vector<Vec2> rc = browser_quad_chords(r);
  REQUIRE(rc.size() == 5);
  CHECK(rc[1].x == doctest::Approx(9.6));
  CHECK(rc[1].y == doctest::Approx(6.0));
}

TEST_CASE("a quadratic's inner chord points carry its start's quarter-pixel snap") {
  // In 1/256 px the start y 0.1 is 25/256 = 0.0977, which snaps to the quarter 0: Skia steps
  // its forward differences from there, so every inner point moves up by 0.0977. Bulge
  // |2 p1 - p0 - p2| / 4 = 615/256 / 4 -> 154/256 px = 5 eighths (rounded), 3 bits: k = 1, two
  // chords. The middle point (8, 0.75 * 0.0977 + 0.25 * 2.5 = 0.698) lies at 0.600 and snaps to
  // 0.5 (0.698 itself would snap to 0.75).
  const Vec2 q[3] = {{0, 0.1}, {8, 0.1}, {16, 2.5}};
  const std::vector<Vec2> c = browser_quad_chords(q);
  REQUIRE(c.size() == 3);
  CHECK(c[0].y == 0.0);
  CHECK(c[1].x == doctest::Approx(8.0));
  CHECK(c[1].y == 0.5);
  CHECK(c[2].y == 2.5);
  // The same quadratic after another one that ends at its start: it starts from the outline's
  // point (0, 0.1), not from the previous quadratic's snapped last point (0, 0), which would
  // put the middle point at 0.625 and snap it to 0.75.
  OutlineContour two;
  two.start = {-16, 2.5};
  two.verbs = {{OutlineVerb::Quad, {-8, 0.1}, {0, 0.1}}, {OutlineVerb::Quad, {8, 0.1}, {16, 2.5}}};
  const std::vector<std::vector<Vec2>> polys = browser_outline_polygons({two});
  REQUIRE(polys.size() == 1);
  const std::vector<Vec2>& poly = polys[0];
  REQUIRE(poly.size() == 5);  // start, the first's middle and end, the second's middle and end
  CHECK(poly[3].x == doctest::Approx(8.0));
  CHECK(poly[3].y == 0.5);
}

TEST_CASE("a chord of no height is dropped: the next one starts from the last real one") {
  // y = t^2, x = 32 t (2 - t): bulge (2048 + 64 / 2) / 256 px = 65 eighths, 7 bits, k = 3:
  // points at t = 1/8 .. 7/8 snap to y 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75. Those at 1/8 and 2/8
  // share the start's row, 4/8 that of 3/8, 6/8 that of 5/8: Skia draws no edge for them.
  const Vec2 q[3] = {{0, 0}, {32, 0}, {32, 1}};
  const std::vector<Vec2> c = browser_quad_chords(q);
  const std::vector<Vec2> want = {{0, 0}, {19.5, 0.25}, {27.5, 0.5}, {31.5, 0.75}, {32, 1}};
  REQUIRE(c.size() == want.size());
  for (size_t i = 0; i < want.size(); ++i) {
    CHECK(c[i].x == doctest::Approx(want[i].x));
    CHECK(c[i].y == doctest::Approx(want[i].y));
  }
}

TEST_CASE("a nearly straight quadratic still gets Skia's minimum of two chords") {
  // Bulge 0.1 px (25 / 256) rounds to 1 eighth: 1 bit, k = 0, raised to 1.
  const Vec2 q[3] = {{0, 0}, {5, 5.2}, {10, 10}};
  CHECK(browser_quad_chords(q).size() == 3);
}

TEST_CASE("a circle's stroke sides are quadratics within a quarter pixel of the true offset") {
  // A quadratic through the offset points at both ends of an arc of angle a, with its control
  // point where their tangents meet, misses the arc's middle by R ((c + 1/c) / 2 - 1),
  // c = cos(a / 2): for a quarter turn 0.0607 R, for an eighth 0.00314 R. Sides of radius 31.5
  // and 28.5 (r = 30, width 3) so take two quadratics per quarter (0.099 px and 0.089 px are
  // within 0.25, 1.9 px are not); sides of radius 101 and 99 (r = 100, width 2) take four, as
  // an eighth misses by 0.32 px there.
  for (const auto& [r, width, per_quarter] : {std::tuple{30, 3, 2}, std::tuple{100, 2, 4}}) {
    const std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"240\" height=\"240\">"
                            "<circle cx=\"120\" cy=\"120\" r=\"" + std::to_string(r) +
                            "\" fill=\"none\" stroke=\"#000\" stroke-width=\"" +
                            std::to_string(width) + "\"/></svg>";
    const Scene s = read_svg_string(svg, "circle.svg");
    REQUIRE(s.paths.size() == 1);
    const std::vector<OutlineContour> o = browser_stroke_outline(s.paths[0], Affine{});
    REQUIRE(o.size() == 2);  // outer side, inner side reversed
    for (const OutlineContour& c : o) {
      CHECK(count(c, OutlineVerb::Quad) == 4 * per_quarter);
      CHECK(c.verbs.size() == static_cast<size_t>(4 * per_quarter));
    }
  }
}

TEST_CASE("a join's inner dip goes to where the inner sides cross, not to the pivot") {
  // A right-angled V, 2 px wide, turning at (10, 10): the inner sides are y = x - sqrt 2 and
  // y = 20 - x - sqrt 2, which cross at X = (10, 10 - sqrt 2). The inner side still ends at
  // E = (10 + 1/sqrt 2, 10 - 1/sqrt 2) and restarts at B = (10 - 1/sqrt 2, 10 - 1/sqrt 2), but
  // dips to X between them; the pivot itself is no vertex (the miter tip is (10, 10 + sqrt 2)).
  const Path p = stroked(polygon({{0, 0}, {10, 10}, {20, 0}}, false), 2, LineJoin::Miter,
                         LineCap::Butt);
  const std::vector<OutlineContour> o = browser_stroke_outline(p, Affine{});
  REQUIRE(o.size() == 1);
  const double s2 = std::sqrt(2.0), h = 1 / s2;
  auto has = [&](Vec2 v) {
    for (const OutlineVerb& verb : o[0].verbs)
      if (std::hypot(verb.p.x - v.x, verb.p.y - v.y) < 1e-9) return true;
    return false;
  };
  CHECK(has({10, 10 - s2}));
  CHECK(has({10 + h, 10 - h}));
  CHECK(has({10 - h, 10 - h}));
  CHECK(has({10, 10 + s2}));
  CHECK_FALSE(has({10, 10}));
}

TEST_CASE("a straight stroke with butt caps outlines its rectangle") {
  // From (2, 8.6) to (30, 8.6), 3 px wide: sides at y = 7.1 and 10.1.
  const Path p = stroked(polygon({{2, 8.6}, {30, 8.6}}, false), 3, LineJoin::Miter, LineCap::Butt);
  const std::vector<std::vector<Vec2>> polys =
      browser_outline_polygons(browser_stroke_outline(p, Affine{}));
  REQUIRE(polys.size() == 1);
  double area = 0;
  const std::vector<Vec2>& q = polys[0];
  for (size_t i = 0; i < q.size(); ++i) {
    const Vec2 a = q[i], b = q[(i + 1) % q.size()];
    area += a.x * b.y - a.y * b.x;
    CHECK((std::fabs(a.y - 7.1) < 1e-9 || std::fabs(a.y - 10.1) < 1e-9));
    CHECK((std::fabs(a.x - 2) < 1e-9 || std::fabs(a.x - 30) < 1e-9));
  }
  CHECK(std::fabs(area) / 2 == doctest::Approx(28.0 * 3.0));
}

TEST_CASE("browser strokes become fills right after their path's own fill") {
  Path both = stroked(polygon({{2, 2}, {20, 2}, {20, 12}}), 2, LineJoin::Round, LineCap::Round,
                      {1, 0, 0, 1});
  both.has_fill = true;
  both.fill = {0, 0, 1, 1};
  Scene s = scene_of(24, 16, {filled(polygon({{0, 0}, {4, 0}, {4, 4}})), both});
  s.groups.push_back({"g", {1}});
  const Scene b = with_browser_strokes(s, Affine{});
  REQUIRE(b.paths.size() == 3);
  CHECK(!b.paths[0].has_stroke);            // no stroke: unchanged
  CHECK(b.paths[1].has_fill);               // the path's fill, stroke removed
  CHECK(!b.paths[1].has_stroke);
  CHECK(b.paths[1].fill.b == 1);
  CHECK(b.paths[2].has_fill);               // then its stroke as a nonzero fill
  CHECK(b.paths[2].fill.r == 1);
  CHECK(b.paths[2].fill_rule == FillRule::NonZero);
  CHECK(!b.paths[2].has_stroke);
  CHECK(b.groups[0].paths == std::vector<int>{1});
}

}  // TEST_SUITE
