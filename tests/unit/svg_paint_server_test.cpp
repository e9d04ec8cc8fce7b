// Reading paint servers, layers, clip paths and masks into the scene (svg/gradient_reader.h,
// svg_reader.cpp), and the spec's handling of stroke-miterlimit with a unit.
#include <doctest/doctest.h>

#include "svg/gradient_reader.h"
#include "svgmotion/svg_reader.h"

using namespace svgm;

TEST_SUITE("svg") {

TEST_CASE("a gradient takes attributes and stops through its href chain") {
  const Scene s = read_svg_string(
      "<svg xmlns='http://www.w3.org/2000/svg' width='100' height='100'>"
      "<linearGradient id='base' x1='10' x2='90' gradientUnits='userSpaceOnUse' spreadMethod='reflect'>"
      "<stop offset='0.2' stop-color='red'/><stop offset='0.1' stop-color='blue' stop-opacity='50%'/>"
      "</linearGradient>"
      "<linearGradient id='mid' href='#base' x1='20'/>"
      "<linearGradient id='top' href='#mid' gradientTransform='translate(5 0)'/>"
      "<rect width='100' height='100' fill='url(#top)' fill-opacity='0.5'/></svg>",
      "g.svg");
  REQUIRE(s.gradients.size() == 1);
  const Gradient& g = s.gradients[0];
  CHECK(!g.radial);
  CHECK(g.p1.x == 20);  // the nearest element that sets x1
  CHECK(g.p2.x == 90);
  CHECK(g.spread == Spread::Reflect);
  CHECK(g.to_canvas.apply({0, 0}).x == doctest::Approx(5));  // userSpaceOnUse: no box map
  CHECK(g.opacity == doctest::Approx(0.5));
  REQUIRE(g.stops.size() == 2);
  CHECK(g.stops[1].offset == doctest::Approx(0.2));  // a smaller offset is raised
  CHECK(g.stops[1].color.a == doctest::Approx(0.5));
  CHECK(s.paths[0].fill_gradient == 0);
}

TEST_CASE("degenerate gradients: no stops paint nothing, a zero radius its last stop") {
  const Scene s = read_svg_string(
      "<svg xmlns='http://www.w3.org/2000/svg' width='10' height='10'>"
      "<linearGradient id='none'/>"
      "<radialGradient id='zero' r='0'><stop stop-color='red'/><stop offset='1' stop-color='lime'/></radialGradient>"
      "<rect width='10' height='10' fill='url(#none)' stroke='black'/>"
      "<rect width='10' height='10' fill='url(#zero)'/></svg>",
      "d.svg");
  REQUIRE(s.paths.size() == 2);
  CHECK(!s.paths[0].has_fill);
  REQUIRE(s.paths[1].fill_gradient >= 0);
  const Gradient& g = s.gradients[s.paths[1].fill_gradient];
  REQUIRE(g.stops.size() == 1);
  CHECK(g.stops[0].color == Rgba{0, 1, 0, 1});
}

TEST_CASE("exact bounds of a cubic are its extrema, not its control points") {
  // y(t) of (0,0) (0,10) (10,10) (10,0) peaks at 7.5 for t = 1/2.
  const std::vector<Subpath> sp{{{{0, 0}, {0, 10}, {10, 10}, {10, 0}}, false}};
  const auto b = svg::subpath_bounds(sp);
  REQUIRE(b);
  CHECK(b->h == doctest::Approx(7.5));
  CHECK(b->w == doctest::Approx(10));
}

TEST_CASE("group opacity, clip paths and masks become layers; a lone shape folds its opacity") {
  const Scene s = read_svg_string(
      "<svg xmlns='http://www.w3.org/2000/svg' width='10' height='10'>"
      "<clipPath id='c' clipPathUnits='objectBoundingBox' clip-rule='evenodd'><rect width='0.5' height='1'/></clipPath>"
      "<mask id='m'><rect width='10' height='10' fill='white'/></mask>"
      "<g opacity='0.5'><rect width='4' height='4' opacity='0.25'/></g>"
      "<rect x='2' width='4' height='4' clip-path='url(#c)' mask='url(#m)'/></svg>",
      "l.svg");
  REQUIRE(s.paths.size() == 2);
  REQUIRE(s.layers.size() == 2);
  CHECK(s.layers[0].opacity == doctest::Approx(0.5));
  CHECK(s.paths[0].layer == 0);
  CHECK(s.paths[0].local_opacity == doctest::Approx(0.25));
  CHECK(s.paths[0].opacity == doctest::Approx(0.125));  // the fitter's product is unchanged
  CHECK(s.paths[1].layer == 1);
  REQUIRE(s.layers[1].clip == 0);
  REQUIRE(s.clips[0].paths.size() == 1);
  CHECK(s.clips[0].paths[0].fill_rule == FillRule::EvenOdd);
  // Bounding box units: the clip rectangle is the left half of the 4 px wide rect at x = 2.
  CHECK(s.clips[0].paths[0].subpaths[0].points[3].x == doctest::Approx(4));
  REQUIRE(s.layers[1].mask == 0);
  CHECK(s.masks[0].paths.size() == 1);
  CHECK(s.masks[0].luminance);
  CHECK(s.warnings.empty());
}

TEST_CASE("an element's layer ends with it, also when it draws nothing") {
  const Scene s = read_svg_string(
      "<svg xmlns='http://www.w3.org/2000/svg' width='10' height='10'>"
      "<use href='#missing' opacity='0.5'/><rect width='4' height='4'/></svg>",
      "u.svg");
  REQUIRE(s.paths.size() == 1);
  CHECK(s.paths[0].layer == -1);
}

TEST_CASE("stroke-miterlimit is a number: with a unit it is invalid and the default stays") {
  const Scene s = read_svg_string(
      "<svg xmlns='http://www.w3.org/2000/svg' width='10' height='10'>"
      "<path d='M0 0 L5 5 L0 9' stroke='black' stroke-miterlimit='10px'/>"
      "<path d='M0 0 L5 5 L0 9' stroke='black' stroke-miterlimit='10'/></svg>",
      "m.svg");
  CHECK(s.paths[0].stroke.miter_limit == 4);
  CHECK(s.paths[1].stroke.miter_limit == 10);
}

}  // TEST_SUITE
