// Renders with browser edges (RasterPlan::browser_edges, kernels/lines.cl): every edge's end
// points at the nearest quarter pixel in y, as Chromium's rasteriser puts them, on both the
// OpenCL path and the CPU layer compositor; and the fitter's exact edges left as they were.
#include <doctest/doctest.h>

#include <cmath>

#include "raster/render_image.h"
#include "raster_test_support.h"
#include "scene_builders.h"

using namespace svgm;
using namespace svgm::test;

namespace {

// A 3-px horizontal stroke centred on y = 8.6: its sides lie at y = 7.1 and 10.1, which browser
// edges move to 7.0 and 10.0.
Scene thin_stroke() {
  return scene_of(32, 16, {stroked(polygon({{2, 8.6}, {30, 8.6}}, false), 3, LineJoin::Miter,
                                   LineCap::Butt)});
}

// The 8-bit red value at (x, y) over white: 255 * (1 - coverage) for black ink.
int red(const RgbaImage& img, int x, int y) {
  return img.rgba[4 * (static_cast<size_t>(y) * img.width + x)];
}

}  // namespace

TEST_SUITE("raster") {

TEST_CASE("browser edges put a thin stroke's sides on quarter pixels; exact edges do not") {
  const RgbaImage exact = render_image(runtime(), thin_stroke(), 32, false, false);
  const RgbaImage browser = render_image(runtime(), thin_stroke(), 32, false, true);
  // Exact: row 7 is 90 % covered, row 10 10 % (within one 8-bit level of rounding).
  CHECK(std::abs(red(exact, 16, 7) - 255 * 0.1) <= 1);
  CHECK(std::abs(red(exact, 16, 10) - 255 * 0.9) <= 1);
  // Browser: the sides at 7.0 and 10.0 cover rows 7..9 fully and row 10 not at all.
  for (int y = 7; y <= 9; ++y) CHECK(red(browser, 16, y) == 0);
  CHECK(red(browser, 16, 10) == 255);
  CHECK(red(browser, 16, 6) == 255);
}

TEST_CASE("browser edges of a diagonal stroke equal the exact fill of its snapped outline") {
  // A 3-px stroke from (4.3, 5.2) to (27.9, 13.7) with butt caps is the rectangle p ± h n; its
  // corners snapped to quarter pixels in y, filled exactly, is what browser edges must draw.
  const Vec2 a{4.3, 5.2}, b{27.9, 13.7};
  const double l = std::hypot(b.x - a.x, b.y - a.y), h = 1.5;
  const Vec2 n{-(b.y - a.y) / l * h, (b.x - a.x) / l * h};
  std::vector<Vec2> corners{a + n, b + n, b - n, a - n};
  for (Vec2& c : corners) c.y = std::floor(4 * c.y + 0.5) / 4;
  const Scene stroke = scene_of(32, 20, {stroked(polygon({a, b}, false), 3, LineJoin::Miter, LineCap::Butt)});
  const Scene outline = scene_of(32, 20, {filled(polygon(corners))});
  const RgbaImage got = render_image(runtime(), stroke, 32, false, true);
  const RgbaImage want = render_image(runtime(), outline, 32, false, false);
  int worst = 0;
  for (size_t i = 0; i < got.rgba.size(); ++i)
    worst = std::max(worst, std::abs(int{got.rgba[i]} - int{want.rgba[i]}));
  CHECK(worst <= 1);  // float rounding of the same polygon: one 8-bit level at most
}

TEST_CASE("the layer compositor snaps edges the same way") {
  // Group opacity 1 puts the scene through the CPU layer compositor (Scene::needs_layers).
  Scene s = thin_stroke();
  s.layers.push_back(Layer{});
  s.paths[0].layer = 0;
  REQUIRE(s.needs_layers());
  const RgbaImage exact = render_image(runtime(), s, 32, false, false);
  const RgbaImage browser = render_image(runtime(), s, 32, false, true);
  CHECK(std::abs(red(exact, 16, 7) - 255 * 0.1) <= 1);
  for (int y = 7; y <= 9; ++y) CHECK(red(browser, 16, y) == 0);
  CHECK(red(browser, 16, 10) == 255);
}

}  // TEST_SUITE
