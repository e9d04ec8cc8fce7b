// Stroke expansion facts computable by hand: the covered area of strokes with each join and
// cap, on both the OpenCL kernels and the CPU reference.
#include <doctest/doctest.h>

#include <cmath>

#include "raster_test_support.h"
#include "scene_builders.h"

using namespace svgm;
using namespace svgm::test;

namespace {

RasterPlanOptions fine() {
  RasterPlanOptions o;
  o.flatten_tolerance_px = 1e-3;  // arcs of round joins/caps within 1e-3 px of the circle
  return o;
}

void check_area(const Scene& s, double want, double rel) {
  const double cl = alpha_sum(render_cl(s, 1, fine()));
  const double rf = alpha_sum(render_ref(s, fine()));
  CHECK(cl == doctest::Approx(want).epsilon(rel));
  CHECK(rf == doctest::Approx(want).epsilon(rel));
}

}  // namespace

TEST_SUITE("raster") {

TEST_CASE("open line strokes: butt, square and round caps") {
  const auto line = polygon({{10, 20}, {50, 20}}, false);
  // 40 x 4 body; square caps add 2 x (4 x 2); round caps add a disc of radius 2.
  check_area(scene_of(64, 40, {stroked(line, 4, LineJoin::Miter, LineCap::Butt)}), 160.0, 1e-5);
  check_area(scene_of(64, 40, {stroked(line, 4, LineJoin::Miter, LineCap::Square)}), 176.0, 1e-5);
  check_area(scene_of(64, 40, {stroked(line, 4, LineJoin::Miter, LineCap::Round)}),
             160.0 + M_PI * 4.0, 2e-4);
}

TEST_CASE("right-angle joins: miter, bevel and round") {
  const auto corner = polygon({{10, 10}, {40, 10}, {40, 40}}, false);
  // Union of the bars [10,42]x[8,12] and [38,42]x[12,40] = 128 + 112 = 240 with the miter
  // corner; a bevel cuts the corner's outer 2x2 square in half; a round join replaces that
  // square by a quarter disc of radius 2.
  check_area(scene_of(64, 64, {stroked(corner, 4, LineJoin::Miter, LineCap::Butt)}), 240.0, 1e-5);
  check_area(scene_of(64, 64, {stroked(corner, 4, LineJoin::Bevel, LineCap::Butt)}), 238.0, 1e-5);
  check_area(scene_of(64, 64, {stroked(corner, 4, LineJoin::Round, LineCap::Butt)}),
             236.0 + M_PI, 2e-4);
}

TEST_CASE("a miter beyond the limit falls back to a bevel; miter-clip cuts it at the limit") {
  // A 90 degree corner has miter ratio sqrt(2) = 1.414: limit 1.4 refuses it.
  auto corner = stroked(polygon({{10, 10}, {40, 10}, {40, 40}}, false), 4, LineJoin::Miter, LineCap::Butt);
  corner.stroke.miter_limit = 1.4;
  check_area(scene_of(64, 64, {corner}), 238.0, 1e-5);
  // miter-clip at limit 1.2: the clip line is 1.2 * 2 = 2.4 from the pivot along the diagonal;
  // the bevel's chord is at sqrt(2) and the miter tip at 2 sqrt(2). Kept area beyond the bevel:
  // the tip triangle (area 2) minus the part beyond the clip line, a similar triangle scaled
  // by (2 sqrt 2 - 2.4) / (2 sqrt 2 - sqrt 2).
  corner.stroke.join = LineJoin::MiterClip;
  corner.stroke.miter_limit = 1.2;
  const double k = (2 * std::sqrt(2.0) - 2.4) / std::sqrt(2.0);
  check_area(scene_of(64, 64, {corner}), 238.0 + 2.0 * (1 - k * k), 1e-5);
}

TEST_CASE("a closed square stroke is the outer square minus the inner one") {
  const auto sq = polygon({{10, 10}, {40, 10}, {40, 40}, {10, 40}}, true);
  check_area(scene_of(64, 64, {stroked(sq, 4, LineJoin::Miter, LineCap::Butt)}), 34.0 * 34 - 26.0 * 26, 1e-5);
  check_area(scene_of(64, 64, {stroked(sq, 4, LineJoin::Round, LineCap::Butt)}),
             34.0 * 34 - 26.0 * 26 - 4 * (4 - M_PI), 2e-4);
}

TEST_CASE("a zero-length subpath draws a dot with round caps, a square with square caps") {
  Subpath dot;
  dot.points = {{20, 20}};
  check_area(scene_of(40, 40, {stroked(dot, 6, LineJoin::Miter, LineCap::Round)}), M_PI * 9, 5e-4);
  check_area(scene_of(40, 40, {stroked(dot, 6, LineJoin::Miter, LineCap::Square)}), 36.0, 1e-5);
  CHECK(alpha_sum(render_cl(scene_of(40, 40, {stroked(dot, 6, LineJoin::Miter, LineCap::Butt)}))) == 0.0);
}

TEST_CASE("a stroke around a circle is an annulus") {
  const double r = 15, w = 3;
  const double want = M_PI * ((r + w / 2) * (r + w / 2) - (r - w / 2) * (r - w / 2));
  check_area(scene_of(48, 48, {stroked(circle({24, 24}, r), w, LineJoin::Miter, LineCap::Butt)}), want, 1e-3);
}

}  // TEST_SUITE
