// SMIL keySplines timing as `render --time` reads it (svg/smil_spline.h): the compact export
// eases its keyframes with calcMode="spline"; a reader that ignored it would draw them linearly.
#include <doctest/doctest.h>

#include <pugixml.hpp>

#include "svg/smil_spline.h"
#include "svgmotion/svg_reader.h"

using namespace svgm;

TEST_SUITE("svg") {
  TEST_CASE("keySplines ease an interval; linear and missing entries do not") {
    pugi::xml_document doc;
    doc.load_string(R"(<animate calcMode="spline" keySplines="0.3333 0 0.6667 1;0.25 0.25 0.75 0.75"/>)");
    const pugi::xml_node a = doc.first_child();
    // (1/3, 0), (2/3, 1): smoothstep 3u^2 - 2u^3.
    CHECK(svg::spline_fraction(a, 0, 0.25) == doctest::Approx(3 * 0.0625 - 2 * 0.015625).epsilon(1e-3));
    CHECK(svg::spline_fraction(a, 0, 0.5) == doctest::Approx(0.5).epsilon(1e-9));
    CHECK(svg::spline_fraction(a, 1, 0.3) == doctest::Approx(0.3).epsilon(1e-6));  // on the diagonal
    CHECK(svg::spline_fraction(a, 2, 0.3) == 0.3);  // no entry: linear
    doc.load_string(R"(<animate calcMode="linear" keySplines="0 1 0 1"/>)");
    CHECK(svg::spline_fraction(doc.first_child(), 0, 0.3) == 0.3);
  }

  TEST_CASE("render --time draws a wrapper's eased animateTransform") {
    // A square moved 10 units right over 1 s with ease-in-out: at 0.25 s it is 1.5625 along.
    const char* text = R"(<svg xmlns="http://www.w3.org/2000/svg" width="40" height="40"><g>
      <rect id="sq" x="0" y="0" width="4" height="4"/>
      <animateTransform attributeName="transform" type="translate" additive="sum" dur="1s" repeatCount="indefinite"
        calcMode="spline" keyTimes="0;1" keySplines="0.3333 0 0.6667 1" values="0 0;10 0"/></g></svg>)";
    SvgReadLimits limits;
    limits.animation_time = 0.25;
    const Scene s = read_svg_string(text, "eased.svg", limits);
    REQUIRE(s.paths.size() == 1);
    CHECK(s.paths[0].to_canvas.e == doctest::Approx(10 * (3 * 0.0625 - 2 * 0.015625)).epsilon(1e-3));
  }
}
