// Coverage facts of the OpenCL rasteriser that can be computed by hand: half-pixel edges,
// circle areas, fill rules, off-canvas geometry, batches of frames.
#include <doctest/doctest.h>

#include <cmath>

#include "opencl/runtime.h"
#include "raster/raster_cl.h"
#include "raster/raster_plan.h"
#include "raster_test_support.h"
#include "scene_builders.h"

using namespace svgm;
using namespace svgm::test;

namespace {

std::vector<float> render(const Scene& scene, int frames = 1, RasterPlanOptions opt = {}) {
  return render_cl(scene, frames, opt);
}

float alpha_at(const std::vector<float>& img, int w, int x, int y, int frame = 0, int h = 0) {
  return img[((static_cast<size_t>(frame) * h + y) * w + x) * 4 + 3];
}

}  // namespace

TEST_SUITE("raster") {

TEST_CASE("a square on half-pixel boundaries covers edge pixels by exactly one half") {
  const Scene s = scene_of(10, 10, {filled(polygon({{2.5, 2.5}, {6.5, 2.5}, {6.5, 6.5}, {2.5, 6.5}}))});
  const auto img = render(s);
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x) {
      const bool in_x = x >= 3 && x <= 5, in_y = y >= 3 && y <= 5;
      const bool edge_x = x == 2 || x == 6, edge_y = y == 2 || y == 6;
      double want = 0;
      if (in_x && in_y) want = 1;
      else if ((edge_x && in_y) || (in_x && edge_y)) want = 0.5;
      else if (edge_x && edge_y) want = 0.25;
      CAPTURE(x);
      CAPTURE(y);
      CHECK(alpha_at(img, 10, x, y) == doctest::Approx(want).epsilon(1e-6));
    }
}

TEST_CASE("summed coverage of a circle equals its area to 0.1%") {
  for (double r : {5.0, 20.0, 47.5}) {
    const Scene s = scene_of(100, 100, {filled(circle({50.3, 49.6}, r))});
    RasterPlanOptions opt;
    opt.flatten_tolerance_px = 0.001;
    const double area = M_PI * r * r;
    CAPTURE(r);
    CHECK(std::fabs(alpha_sum(render(s, 1, opt)) - area) / area < 1e-3);
  }
}

TEST_CASE("evenodd leaves the centre of a self-overlapping star empty, nonzero fills it") {
  std::vector<Vec2> star;
  for (int i = 0; i < 5; ++i) {
    const double a = -M_PI / 2 + i * 4 * M_PI / 5;  // every second vertex of a pentagon
    star.push_back({32 + 28 * std::cos(a), 32 + 28 * std::sin(a)});
  }
  const auto nz = render(scene_of(64, 64, {filled(polygon(star), {0, 0, 0, 1}, FillRule::NonZero)}));
  const auto eo = render(scene_of(64, 64, {filled(polygon(star), {0, 0, 0, 1}, FillRule::EvenOdd)}));
  CHECK(alpha_at(nz, 64, 32, 33) == doctest::Approx(1.0));
  CHECK(alpha_at(eo, 64, 32, 33) == doctest::Approx(0.0));
  // A point of the star (winding 1) is filled by both rules.
  CHECK(alpha_at(nz, 64, 32, 8) == doctest::Approx(1.0));
  CHECK(alpha_at(eo, 64, 32, 8) == doctest::Approx(1.0));
}

TEST_CASE("shapes partly off the canvas cover exactly their visible part") {
  // A rectangle from x = -50 to 5.5 and y = -3 to 200 on a 10x10 canvas: columns 0..4 full,
  // column 5 half, the rest empty, on every row.
  const Scene s = scene_of(10, 10, {filled(polygon({{-50, -3}, {5.5, -3}, {5.5, 200}, {-50, 200}}))});
  const auto img = render(s);
  for (int y = 0; y < 10; ++y) {
    CHECK(alpha_at(img, 10, 0, y) == doctest::Approx(1.0));
    CHECK(alpha_at(img, 10, 4, y) == doctest::Approx(1.0));
    CHECK(alpha_at(img, 10, 5, y) == doctest::Approx(0.5));
    CHECK(alpha_at(img, 10, 6, y) == doctest::Approx(0.0));
  }
  // Entirely right of the canvas except for its left edge's half pixel.
  const auto img2 = render(scene_of(10, 10, {filled(polygon({{9.5, 2}, {40, 2}, {40, 8}, {9.5, 8}}))}));
  CHECK(alpha_at(img2, 10, 9, 4) == doctest::Approx(0.5));
  CHECK(alpha_at(img2, 10, 8, 4) == doctest::Approx(0.0));
}

TEST_CASE("a diagonal edge splits its pixels by the trapezoid areas") {
  // Triangle (0,0) (8,0) (0,8): pixels on the diagonal x + y = 7 are half covered, those
  // strictly inside are full.
  const auto img = render(scene_of(8, 8, {filled(polygon({{0, 0}, {8, 0}, {0, 8}}))}));
  for (int x = 0; x < 8; ++x) {
    CHECK(alpha_at(img, 8, x, 7 - x) == doctest::Approx(0.5).epsilon(1e-5));
    if (x < 7) CHECK(alpha_at(img, 8, x, 6 - x) == doctest::Approx(1.0).epsilon(1e-5));
  }
}

TEST_CASE("opacity and painter's order composite as 'over'") {
  // Red at alpha 0.5 over opaque blue: (0.5, 0, 0.5), alpha 1.
  Path blue = filled(polygon({{0, 0}, {4, 0}, {4, 4}, {0, 4}}), {0, 0, 1, 1});
  Path red = filled(polygon({{0, 0}, {4, 0}, {4, 4}, {0, 4}}), {1, 0, 0, 1});
  red.opacity = 0.5f;
  const auto img = render(scene_of(4, 4, {blue, red}));
  CHECK(img[0] == doctest::Approx(0.5));
  CHECK(img[1] == doctest::Approx(0.0));
  CHECK(img[2] == doctest::Approx(0.5));
  CHECK(img[3] == doctest::Approx(1.0));
}

TEST_CASE("every frame of a batch renders the same pose identically") {
  const Scene s = scene_of(40, 30, {filled(circle({20, 15}, 11)), filled(polygon({{3, 3}, {30, 5}, {12, 27}}), {1, 0, 0, 0.7f})});
  const auto img = render(s, 5);
  const size_t per = 40 * 30 * 4;
  for (int k = 1; k < 5; ++k)
    CHECK(std::equal(img.begin(), img.begin() + per, img.begin() + k * per));
}

}  // TEST_SUITE
