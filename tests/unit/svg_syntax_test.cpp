// SVG micro-syntaxes on their own: numbers, transform lists, CSS colours, style declarations
// and style sheets.
#include <doctest/doctest.h>

#include <cmath>

#include "svg/css_color.h"
#include "svg/css_sheet.h"
#include "svg/svg_number.h"
#include "svg/svg_style.h"
#include "svg/transform_list.h"

using namespace svgm;

namespace {

bool same(const Affine& a, const Affine& b, double eps = 1e-12) {
  return std::fabs(a.a - b.a) < eps && std::fabs(a.b - b.b) < eps && std::fabs(a.c - b.c) < eps &&
         std::fabs(a.d - b.d) < eps && std::fabs(a.e - b.e) < eps && std::fabs(a.f - b.f) < eps;
}

// Colour as 0-255 channels and alpha, to compare with the CSS text.
bool rgb255(const std::optional<Rgba>& c, double r, double g, double b, double a = 1) {
  return c && std::fabs(c->r * 255 - r) < 0.01 && std::fabs(c->g * 255 - g) < 0.01 &&
         std::fabs(c->b * 255 - b) < 0.01 && std::fabs(c->a - a) < 1e-3;
}

}  // namespace

TEST_SUITE("svg") {

TEST_CASE("numbers: compact forms, exponents, units left alone, nan/inf/overflow flagged") {
  svg::Cursor c{"1.5.5-1e-2+3 .25e+1 1em 7."};
  CHECK(*c.number() == 1.5);
  CHECK(*c.number() == 0.5);
  CHECK(*c.number() == -0.01);
  CHECK(*c.number() == 3);
  c.skip_comma_ws();
  CHECK(*c.number() == 2.5);
  c.skip_comma_ws();
  CHECK(*c.number() == 1);
  CHECK(c.peek() == 'e');  // "1em": the e belongs to the unit
  c.pos += 2;
  c.skip_ws();
  CHECK(*c.number() == 7);
  CHECK(c.done());
  CHECK_FALSE(c.out_of_range);

  bool oor = false;
  CHECK(*svg::parse_number(" 1e-999 ", &oor) == 0);  // underflow is zero, not an error
  CHECK_FALSE(oor);
  for (const char* bad : {"1e999", "-1e400", "nan", "NaN", "inf", "-Infinity"}) {
    CAPTURE(bad);
    oor = false;
    CHECK_FALSE(svg::parse_number(bad, &oor));
    CHECK(oor);
  }
  for (const char* bad : {"", ".", "-", "e5", "1 2", "1,"}) {
    CAPTURE(bad);
    oor = false;
    CHECK_FALSE(svg::parse_number(bad, &oor));
    CHECK_FALSE(oor);
  }
  svg::Cursor f{"10 1,0"};
  CHECK(*f.flag() == true);
  CHECK(*f.flag() == false);
  f.skip_comma_ws();
  CHECK(*f.flag() == true);
  f.skip_comma_ws();
  CHECK(*f.flag() == false);
  CHECK_FALSE(svg::Cursor{"2"}.flag());
}

TEST_CASE("transform lists: each kind against hand-computed matrices") {
  using svg::parse_transform;
  const double c30 = std::sqrt(3.0) / 2, s30 = 0.5;
  CHECK(same(*parse_transform("rotate(30)"), Affine{c30, s30, -s30, c30, 0, 0}));
  // rotate(90 10 20) = translate(10 20) rotate(90) translate(-10 -20): (x, y) -> (30 - y, x + 10).
  CHECK(same(*parse_transform("rotate(90 10 20)"), Affine{0, 1, -1, 0, 30, 10}));
  CHECK(same(*parse_transform("rotate(90,10,20)"), Affine{0, 1, -1, 0, 30, 10}));
  CHECK(same(*parse_transform("skewX(30)"), Affine{1, 0, std::tan(M_PI / 6), 1, 0, 0}));
  CHECK(same(*parse_transform("skewY(-45)"), Affine{1, -1, 0, 1, 0, 0}));
  CHECK(same(*parse_transform("scale(2 3)"), Affine{2, 0, 0, 3, 0, 0}));
  CHECK(same(*parse_transform("scale(-1)"), Affine{-1, 0, 0, -1, 0, 0}));
  CHECK(same(*parse_transform("translate(-5.5e1)"), Affine{1, 0, 0, 1, -55, 0}));
  CHECK(same(*parse_transform("matrix(1,2,3,4,5,6)"), Affine{1, 2, 3, 4, 5, 6}));
  CHECK(same(*parse_transform("matrix(1-2-3 4.5.5 6)"), Affine{1, -2, -3, 4.5, 0.5, 6}));
  // Lists apply right to left: translate(10) scale(2) maps (1, 1) to (12, 2).
  const Affine list = *parse_transform(" translate(10) , scale(2)rotate(0)\n");
  CHECK(same(list, Affine{2, 0, 0, 2, 10, 0}));
  CHECK(same(*parse_transform("scale(2) translate(10)"), Affine{2, 0, 0, 2, 20, 0}));
  CHECK(same(*parse_transform("translate (1 2)"), Affine::translate(1, 2)));
  CHECK(same(*parse_transform(""), Affine{}));
  CHECK(same(*parse_transform("   "), Affine{}));
  for (const char* bad : {"matrix(1 0 0 1 0)", "scale(1 2 3)", "translate(1 2", "translate(1) x",
                          "rotate()", "skewX(1 2)", "Rotate(10)", "translate(1,,2)", "qwe"}) {
    CAPTURE(bad);
    bool oor = false;
    CHECK_FALSE(parse_transform(bad, &oor));
    CHECK_FALSE(oor);
  }
}

TEST_CASE("colours: every syntax of the resvg suite") {
  using svg::parse_color;
  CHECK(rgb255(parse_color("#080"), 0, 136, 0));
  CHECK(rgb255(parse_color("#0A0A"), 0, 170, 0, 170 / 255.0));
  CHECK(rgb255(parse_color("#008000"), 0, 128, 0));
  CHECK(rgb255(parse_color("#00800080"), 0, 128, 0, 128 / 255.0));
  CHECK(rgb255(parse_color("#AbCdEf"), 0xab, 0xcd, 0xef));
  CHECK_FALSE(parse_color("#qqq"));
  CHECK_FALSE(parse_color("#aaz"));
  CHECK_FALSE(parse_color("#12345"));
  CHECK_FALSE(parse_color("#"));
  CHECK(rgb255(parse_color("GreeN"), 0, 128, 0));
  CHECK(rgb255(parse_color("GREEN"), 0, 128, 0));
  CHECK(rgb255(parse_color("rebeccapurple"), 0x66, 0x33, 0x99));
  CHECK(rgb255(parse_color("grey"), 128, 128, 128));
  CHECK(rgb255(parse_color("darkslategray"), 0x2f, 0x4f, 0x4f));
  CHECK(rgb255(parse_color("yellowgreen"), 0x9a, 0xcd, 0x32));
  CHECK(rgb255(parse_color("aliceblue"), 0xf0, 0xf8, 0xff));
  CHECK_FALSE(parse_color("qwe13212"));
  CHECK(rgb255(parse_color("transparent"), 0, 0, 0, 0));
  CHECK(rgb255(parse_color(" rgb( 0 , 128 , 0 ) "), 0, 128, 0));
  CHECK(rgb255(parse_color("RGB(0%, 50%, 0%)"), 0, 127.5, 0));
  CHECK(rgb255(parse_color("rgb(0.8, 127.5, 14.2)"), 0.8, 127.5, 14.2));
  CHECK(rgb255(parse_color("rgb(-10%, 50%, 120%)"), 0, 127.5, 255));
  CHECK(rgb255(parse_color("rgb(59.6078431372549019607843137254%,98.431372549%,59.6078%)"), 152, 251, 152.0));
  CHECK(rgb255(parse_color("rgb(0, 127, 0, 0.5)"), 0, 127, 0, 0.5));
  CHECK(rgb255(parse_color("rgba(0, 127, 0, 0.5)"), 0, 127, 0, 0.5));
  CHECK(rgb255(parse_color("rgba(0, 127, 0, 0)"), 0, 127, 0, 0));
  CHECK(rgb255(parse_color("rgba(0, 127, 0, 2)"), 0, 127, 0, 1));
  CHECK(rgb255(parse_color("rgba(0%, 50%, 0%, 0.5)"), 0, 127.5, 0, 0.5));
  CHECK(rgb255(parse_color("rgb(0 127 0 / 0.25)"), 0, 127, 0, 0.25));
  CHECK(rgb255(parse_color("hsl(120, 100%, 25%)"), 0, 127.5, 0));
  CHECK(rgb255(parse_color("hsl(360, 100%, 25%)"), 127.5, 0, 0));
  CHECK(rgb255(parse_color("hsl(999, 100%, 25%)"), 82.875, 0, 127.5));  // 999 = 279 degrees
  CHECK(rgb255(parse_color("hsl(120, 100%, 25%, 0.5)"), 0, 127.5, 0, 0.5));
  CHECK(rgb255(parse_color("HSLA(240, 100%, 50%, 0.25)"), 0, 0, 255, 0.25));
  CHECK(rgb255(parse_color("hsl(0, 0%, 100%)"), 255, 255, 255));
  CHECK_FALSE(parse_color("rgb(1, 2)"));
  CHECK_FALSE(parse_color("rgb(1, 2, 3, 4, 5)"));
  CHECK_FALSE(parse_color("rgb(1, 2, x)"));
  CHECK_FALSE(parse_color("cmyk(1, 2, 3, 4)"));
  CHECK_FALSE(parse_color("none"));
  CHECK_FALSE(parse_color("currentColor"));
}

TEST_CASE("style declarations: opacities, percentages, keywords, inherit") {
  svg::Style parent, s;
  svg::ElementProps props;
  parent.fill_opacity = 0.25f;
  s = parent;
  CHECK(svg::apply_declaration("fill-opacity", "50%", parent, s, props));
  CHECK(s.fill_opacity == doctest::Approx(0.5));
  CHECK(svg::apply_declaration("fill-opacity", "inherit", parent, s, props));
  CHECK(s.fill_opacity == doctest::Approx(0.25));
  CHECK(svg::apply_declaration("stroke-opacity", "3", parent, s, props));
  CHECK(s.stroke_opacity == 1);
  CHECK(svg::apply_declaration("opacity", "-1", parent, s, props));
  CHECK(props.opacity == 0);
  CHECK(svg::apply_declaration("fill-rule", "evenodd", parent, s, props));
  CHECK(s.fill_rule == FillRule::EvenOdd);
  CHECK(svg::apply_declaration("stroke-width", "2mm", parent, s, props));
  CHECK(s.stroke_width == doctest::Approx(7.559055118));
  CHECK(svg::apply_declaration("stroke-miterlimit", "1", parent, s, props));
  CHECK(s.miter_limit == 1);
  CHECK(svg::apply_declaration("stroke-miterlimit", "0.9", parent, s, props));
  CHECK(s.miter_limit == 1);  // invalid: unchanged
  CHECK(svg::apply_declaration("display", "none", parent, s, props));
  CHECK(props.display_none);
  CHECK(svg::apply_declaration("clip-path", "url(#c)", parent, s, props));
  CHECK(props.has_clip);
  CHECK_FALSE(props.has_filter);
  CHECK(svg::apply_declaration("filter", "none", parent, s, props));
  CHECK_FALSE(props.has_filter);
  CHECK_FALSE(svg::apply_declaration("fill-opacity", "nan", parent, s, props));
  CHECK_FALSE(svg::apply_declaration("stroke-width", "1e999", parent, s, props));
  // A finite number in a unit that overflows (fuzz finding: css stroke_width_1e308in).
  const double width_before = s.stroke_width;
  CHECK_FALSE(svg::apply_declaration("stroke-width", "1e308in", parent, s, props));
  CHECK(s.stroke_width == width_before);
  // A miter limit is a plain number (SVG 2): one with a unit is ignored, whatever its size.
  const double miter_before = s.miter_limit;
  svg::apply_declaration("stroke-miterlimit", "1e308in", parent, s, props);
  CHECK(s.miter_limit == miter_before);
  CHECK_FALSE(svg::apply_declaration("stroke-miterlimit", "1e999", parent, s, props));
  CHECK(std::isfinite(s.miter_limit));
  CHECK(svg::apply_declaration("stroke-width", "1e300in", parent, s, props));  // finite: kept
  CHECK(s.stroke_width == doctest::Approx(96e300));
  float v = 0;
  CHECK(svg::parse_unit_interval("12.5%", &v));
  CHECK(v == doctest::Approx(0.125));
  CHECK_FALSE(svg::parse_unit_interval("0.5px", &v));
}

TEST_CASE("style sheets: selectors, specificity, source order, comments, at-rules") {
  svg::StyleSheet sheet;
  const int skipped = sheet.add(
      "/* a */ .a{fill:red} path{fill:blue;stroke:black} #x{fill:green !important}"
      " path.a.b{fill:yellow} *{stroke-width:2} g path{fill:pink} a:hover{fill:pink}"
      " @font-face{font-family:x} @import url(x.css); .a,.c{opacity:0.5}");
  CHECK(skipped == 4);
  std::vector<const svg::CssDeclaration*> m;
  sheet.match("path", "x", "b  a", m);
  std::vector<std::string> got;
  for (const auto* d : m) got.push_back(d->name + "=" + d->value);
  // specificity: * (0) < path (1) < .a (10) = .a (10, later) < path.a.b (21) < #x (100)
  CHECK(got == std::vector<std::string>{"stroke-width=2", "fill=blue", "stroke=black", "fill=red",
                                        "opacity=0.5", "fill=yellow", "fill=green"});
  sheet.match("rect", "", "c", m);
  REQUIRE(m.size() == 2);
  CHECK(m[1]->name == "opacity");
  sheet.match("rect", "", "ab", m);  // class names match whole words only
  CHECK(m.size() == 1);
  const auto decls = svg::parse_declarations(" fill : red ; ;stroke:url(#a) ; bogus; x:y/*c*/ ");
  REQUIRE(decls.size() == 3);
  CHECK(decls[0].name == "fill");
  CHECK(decls[0].value == "red");
  CHECK(decls[1].value == "url(#a)");
  CHECK(decls[2].value == "y");
}

}  // TEST_SUITE
