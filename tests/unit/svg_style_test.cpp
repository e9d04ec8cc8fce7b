// Transforms, colours and the reader's handling of styles, shapes, structure and bad input.
#include <doctest/doctest.h>

#include <cmath>

#include "svg/css_color.h"
#include "svg/transform_list.h"
#include "svgmotion/error.h"
#include "svgmotion/svg_reader.h"

using namespace svgm;

namespace {

bool same(const Affine& a, const Affine& b) {
  return std::fabs(a.a - b.a) < 1e-9 && std::fabs(a.b - b.b) < 1e-9 && std::fabs(a.c - b.c) < 1e-9 &&
         std::fabs(a.d - b.d) < 1e-9 && std::fabs(a.e - b.e) < 1e-9 && std::fabs(a.f - b.f) < 1e-9;
}

bool rgba(const std::optional<Rgba>& c, float r, float g, float b, float a = 1) {
  return c && std::fabs(c->r - r) < 1e-3 && std::fabs(c->g - g) < 1e-3 && std::fabs(c->b - b) < 1e-3 &&
         std::fabs(c->a - a) < 1e-3;
}

Scene read(const std::string& body, const std::string& root = "width=\"100\" height=\"100\"") {
  return read_svg_string("<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" " +
                             root + ">" + body + "</svg>",
                         "t.svg");
}

}  // namespace

TEST_SUITE("svg") {

TEST_CASE("transform lists") {
  using svg::parse_transform;
  CHECK(same(*parse_transform("matrix(1 2 3 4 5 6)"), Affine{1, 2, 3, 4, 5, 6}));
  CHECK(same(*parse_transform("translate(10)"), Affine::translate(10, 0)));
  CHECK(same(*parse_transform("scale(2)"), Affine::scale(2, 2)));
  CHECK(same(*parse_transform("translate(10,20) scale(2, 3)"), Affine{2, 0, 0, 3, 10, 20}));
  // rotate(90 10 10) maps (20, 10) to (10, 20).
  const Vec2 p = parse_transform("rotate(90 10 10)")->apply({20, 10});
  CHECK(p.x == doctest::Approx(10));
  CHECK(p.y == doctest::Approx(20));
  CHECK(same(*parse_transform("skewX(45)"), Affine{1, 0, 1, 1, 0, 0}));
  CHECK(same(*parse_transform("skewY(45)"), Affine{1, 1, 0, 1, 0, 0}));
  CHECK_FALSE(parse_transform("rotate(1 2)"));
  CHECK_FALSE(parse_transform("frobnicate(1)"));
  bool bad = false;
  parse_transform("scale(1e999)", &bad);
  CHECK(bad);
}

TEST_CASE("colours: hex, rgb() with numbers and percentages, hsl, names, alpha") {
  using svg::parse_color;
  CHECK(rgba(parse_color("#f00"), 1, 0, 0));
  CHECK(rgba(parse_color("#00800080"), 0, 128 / 255.f, 0, 128 / 255.f));
  CHECK(rgba(parse_color("rgb(0, 127, 0)"), 0, 127 / 255.f, 0));
  CHECK(rgba(parse_color("RGB( 0%, 50%, 0% )"), 0, 0.5f, 0));
  CHECK(rgba(parse_color("rgba(0, 127, 0, 0.5)"), 0, 127 / 255.f, 0, 0.5f));
  CHECK_FALSE(parse_color("rgba(0, 127, 0, 50%)"));  // as resvg's reference rendering has it
  CHECK(rgba(parse_color("rgb(300, -5, 120%)"), 1, 0, 1));  // clamped
  CHECK(rgba(parse_color("hsl(120, 100%, 25%)"), 0, 0.5f, 0));
  CHECK(rgba(parse_color("LightGoldenRodYellow"), 250 / 255.f, 250 / 255.f, 210 / 255.f));
  CHECK(rgba(parse_color("transparent"), 0, 0, 0, 0));
  CHECK_FALSE(parse_color("#12345"));
  CHECK_FALSE(parse_color("notacolour"));
}

TEST_CASE("viewBox and preserveAspectRatio map user space to the canvas") {
  const Scene s = read("<rect x=\"0\" y=\"0\" width=\"10\" height=\"10\"/>",
                       "width=\"200\" height=\"100\" viewBox=\"0 0 10 10\"");
  CHECK(s.width == 200);
  CHECK(s.height == 100);
  REQUIRE(s.paths.size() == 1);
  // meet, xMidYMid: scale 10, centred horizontally: x from 50 to 150.
  CHECK(s.paths[0].subpaths[0].points[0].x == doctest::Approx(50));
  CHECK(s.paths[0].subpaths[0].points[3].x == doctest::Approx(150));
  const Scene n = read("<rect width=\"10\" height=\"10\"/>",
                       "width=\"200\" height=\"100\" viewBox=\"0 0 10 10\" preserveAspectRatio=\"none\"");
  CHECK(n.paths[0].subpaths[0].points[6].y == doctest::Approx(100));
  const Scene u = read("<rect width=\"1in\" height=\"10mm\"/>");
  CHECK(u.paths[0].subpaths[0].points[3].x == doctest::Approx(96));
  CHECK(u.paths[0].subpaths[0].points[6].y == doctest::Approx(37.795).epsilon(1e-4));
}

TEST_CASE("inheritance, style attribute precedence, opacity multiplies, currentColor") {
  const Scene s = read(
      "<g fill=\"red\" opacity=\"0.5\" color=\"blue\"><g opacity=\"0.5\">"
      "<rect width=\"5\" height=\"5\" fill=\"green\" style=\"fill: #0000ff; fill-opacity: 50%\"/>"
      "<rect width=\"5\" height=\"5\"/>"
      "<rect width=\"5\" height=\"5\" fill=\"currentColor\" stroke=\"red\" stroke-width=\"2\"/></g></g>");
  REQUIRE(s.paths.size() == 3);
  CHECK(rgba(s.paths[0].fill, 0, 0, 1, 0.5f));
  CHECK(s.paths[0].opacity == doctest::Approx(0.25));
  CHECK(rgba(s.paths[1].fill, 1, 0, 0));
  CHECK(rgba(s.paths[2].fill, 0, 0, 1));
  CHECK(s.paths[2].has_stroke);
  CHECK(s.paths[2].stroke.width == doctest::Approx(2));
}

TEST_CASE("shapes: rect auto radii, ellipse auto radius, polygon odd points, invisible ones") {
  const Scene s = read(
      "<rect width=\"20\" height=\"10\" rx=\"15\"/>"        // rx clamps to 10, ry = rx clamps to 5
      "<ellipse cx=\"50\" cy=\"50\" rx=\"-5\" ry=\"20\"/>"  // negative rx is auto: a circle
      "<polygon points=\"0,0 10,0 10,10 5\"/>"              // the odd 5 is ignored
      "<rect width=\"0\" height=\"10\"/><circle r=\"-1\"/>"
      "<rect width=\"5\" height=\"5\" display=\"none\"/><rect width=\"5\" height=\"5\" visibility=\"hidden\"/>");
  REQUIRE(s.paths.size() == 3);
  CHECK(s.paths[0].subpaths[0].points[0].x == doctest::Approx(10));
  const auto& e = s.paths[1].subpaths[0].points;
  CHECK(e[0].x == doctest::Approx(70));
  CHECK(s.paths[2].subpaths[0].segment_count() == 3);
  CHECK(s.paths[2].subpaths[0].closed);
}

TEST_CASE("use, defs and symbol; top-level groups; ids and locators") {
  const Scene s = read(
      "<defs><rect id=\"r\" width=\"10\" height=\"10\"/>"
      "<symbol id=\"sym\" viewBox=\"0 0 10 10\"><circle cx=\"5\" cy=\"5\" r=\"5\"/></symbol></defs>"
      "<g id=\"body\"><use id=\"u1\" xlink:href=\"#r\" x=\"20\"/><path d=\"M0 0 L 5 5 L 0 5 Z\"/></g>"
      "<use id=\"u2\" href=\"#sym\" width=\"40\" height=\"40\"/><rect id=\"lone\" width=\"1\" height=\"1\"/>");
  REQUIRE(s.paths.size() == 4);
  CHECK(s.paths[0].subpaths[0].points[0].x == doctest::Approx(20));
  CHECK(s.paths[0].id == "u1/r");
  CHECK(s.paths[0].locator == "/svg/g[1]/use[1]");
  CHECK(s.paths[1].locator == "/svg/g[1]/path[1]");
  CHECK(s.paths[2].subpaths[0].points[0].x == doctest::Approx(40));  // symbol scaled x4
  REQUIRE(s.groups.size() == 3);
  CHECK(s.groups[0].id == "body");
  CHECK(s.groups[0].paths == std::vector<int>{0, 1});
  CHECK(s.groups[2].id == "lone");
}

TEST_CASE("unsupported content gives one warning per kind and is skipped") {
  const Scene s = read(
      "<text>hi</text><text>again</text><image href=\"x.png\"/>"
      "<linearGradient id=\"g\"><stop offset=\"0\" stop-color=\"#000\"/><stop offset=\"1\" stop-color=\"#fff\"/></linearGradient>"
      "<rect width=\"5\" height=\"5\" fill=\"url(#g)\" clip-path=\"url(#c)\"/>");
  REQUIRE(s.paths.size() == 1);
  CHECK(rgba(s.paths[0].fill, 0.5f, 0.5f, 0.5f));
  REQUIRE(s.warnings.size() == 3);
  CHECK(s.warnings[0] == "t.svg: 2 <text> elements skipped (text is not supported)");
  CHECK(s.warnings[1] == "t.svg: 1 <image> element skipped (images are not supported)");
  CHECK(s.warnings[2] == "t.svg: <rect>: clip-path url(#c) is not a clipPath (drawn unclipped)");
}

TEST_CASE("malformed input is one error line naming the file") {
  auto msg = [](const std::string& text, SvgReadLimits lim = {}) {
    try {
      read_svg_string(text, "bad.svg", lim);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(msg("<svg><g></svg>") == "bad.svg: not well-formed XML at offset 10: Start-end tags mismatch");
  CHECK(msg("<html/>") == "bad.svg: root element is <html>, not <svg>");
  CHECK(msg("<svg width=\"1e9\" height=\"10\"/>") == "bad.svg: size 1000000000x10 is too large (limit 32768 px)");
  CHECK(msg("<svg width=\"10\" height=\"10\"><rect width=\"nan\" height=\"1\"/></svg>") ==
        "bad.svg: <rect> width=\"nan\": number out of range");
  CHECK(msg("<svg width=\"10\" height=\"10\"><path id=\"p\" d=\"M 0 0 L 1e999 0\"/></svg>") ==
        "bad.svg: <path id=p> d: number out of range");
  CHECK(msg("<svg width=\"10\" height=\"10\"><g id=\"a\"><use id=\"u\" href=\"#a\"/></g></svg>") ==
        "bad.svg: <use id=u> references itself (use cycle)");
  std::string deep = "<svg width=\"10\" height=\"10\">";
  for (int i = 0; i < 10000; ++i) deep += "<g>";
  for (int i = 0; i < 10000; ++i) deep += "</g>";
  CHECK(msg(deep + "</svg>") == "bad.svg: nesting deeper than 256 elements");
  SvgReadLimits small;
  small.max_file_bytes = 10 << 20;
  CHECK(msg(std::string(11 << 20, ' '), small) == "bad.svg: file is 11.0 MB, larger than the 10 MB limit");
  try {
    read_svg_file("/nonexistent/x.svg");
    FAIL("no error");
  } catch (const Error& e) {
    CHECK(std::string(e.what()) == "/nonexistent/x.svg: cannot open: No such file or directory");
  }
}

}  // TEST_SUITE
