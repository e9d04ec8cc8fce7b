// The colour correction's palette (fit/target/correction_palette.h): gradient-painted paths give no
// colour, and the share of the canvas gradients show at rest, counted by hand on pixel-aligned
// rectangles, decides whether a drawing is corrected at all.
#include <doctest/doctest.h>

#include <string>

#include "fit/target/correction_palette.h"
#include "svgmotion/svg_reader.h"

#include "raster_test_support.h"

using namespace svgm;
using svgm::test::runtime;

namespace {

// A 40x40 canvas: a red left half, a linear gradient over the top right quarter, and `extra`.
Scene canvas_with(const std::string& extra) {
  return read_svg_string(R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="40" height="40">
  <defs><linearGradient id="g"><stop offset="0" stop-color="#ff8800"/><stop offset="1" stop-color="#ffee00"/></linearGradient></defs>
  <rect x="0" y="0" width="20" height="40" fill="#ff0000"/>
  <rect x="20" y="0" width="20" height="20" fill="url(#g)"/>)svg" + extra + "</svg>",
                         "t");
}

}  // namespace

TEST_SUITE("fit") {

TEST_CASE("gradients give no colour to the correction, and a quarter of the canvas in gradients turns it off") {
  const CorrectionPalette p = correction_palette(runtime(), canvas_with(""), 40);
  // 400 of 1600 pixels, exactly covered: black renders as 0, so the share is exact.
  CHECK(p.gradient_share == doctest::Approx(0.25).epsilon(1e-9));
  CHECK_FALSE(p.usable);
  REQUIRE(p.colours.size() == 1);  // the red rectangle's; not the gradient's mean stop colour
  CHECK(p.colours[0] == std::array<float, 3>{1, 0, 0});
}

TEST_CASE("gradient paint hidden under a flat path does not count") {
  // A blue rectangle over the gradient's top half: 200 of its 400 pixels still show.
  const CorrectionPalette p =
      correction_palette(runtime(), canvas_with(R"(<rect x="20" y="0" width="20" height="10" fill="#0000ff"/>)"), 40);
  CHECK(p.gradient_share == doctest::Approx(0.125).epsilon(1e-9));
  CHECK(p.colours.size() == 2);
}

TEST_CASE("a small gradient highlight keeps the correction for the flat rest") {
  // Only a 4x4 gradient (16 of 1600 pixels, 1%) and a stroked flat square.
  const Scene s = read_svg_string(R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="40" height="40">
  <defs><radialGradient id="g"><stop offset="0" stop-color="#ffffff"/><stop offset="1" stop-color="#88ccff"/></radialGradient></defs>
  <rect x="5" y="5" width="20" height="20" fill="#336699" stroke="#000000" stroke-width="2"/>
  <rect x="30" y="30" width="4" height="4" fill="url(#g)"/></svg>)svg",
                                  "t");
  const CorrectionPalette p = correction_palette(runtime(), s, 40);
  CHECK(p.gradient_share == doctest::Approx(0.01).epsilon(1e-9));
  CHECK(p.usable);
  CHECK(p.colours.size() == 2);  // the square's fill and stroke
}

TEST_CASE("a drawing without gradients is measured without a render") {
  const Scene s = read_svg_string(R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="40" height="40">
  <rect x="5" y="5" width="20" height="20" fill="#336699"/></svg>)svg",
                                  "t");
  const CorrectionPalette p = correction_palette(runtime(), s, 40);
  CHECK(p.gradient_share == 0);
  CHECK(p.usable);
  CHECK(p.colours.size() == 1);
}

}  // TEST_SUITE
