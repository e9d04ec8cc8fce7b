// Fuzz target: CSS as SVG documents carry it: a <style> sheet (rules, selectors, comments,
// at-rules, nested braces) and `style` attribute declarations applied to a computed style.
// Properties checked on every input:
//  - no crash or sanitizer report;
//  - declarations have a non-empty name and name and value trimmed of white space;
//  - matching an element returns declarations of the sheet, lowest precedence first, for any
//    tag, id and class list;
//  - applying every declaration keeps the style usable: opacities and colours in [0, 1], a
//    stroke width finite and >= 0, a miter limit finite and >= 1.
#include <cctype>
#include <cmath>
#include <string_view>
#include <vector>

#include "fuzz_check.h"
#include "svg/css_sheet.h"
#include "svg/svg_style.h"

namespace {

bool trimmed(std::string_view s) {
  auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; };
  return s.empty() || (!space(s.front()) && !space(s.back()));
}

bool unit(float v) { return v >= 0 && v <= 1; }
bool unit(const svgm::Rgba& c) { return unit(c.r) && unit(c.g) && unit(c.b) && unit(c.a); }

void check_style(const svgm::svg::Style& s, const svgm::svg::ElementProps& p) {
  FUZZ_REQUIRE(unit(s.fill_opacity) && unit(s.stroke_opacity) && unit(p.opacity), "opacities in [0, 1]");
  FUZZ_REQUIRE(unit(s.fill.color) && unit(s.stroke.color) && unit(s.color), "colours in [0, 1]");
  FUZZ_REQUIRE(std::isfinite(s.stroke_width) && s.stroke_width >= 0, "stroke width finite, >= 0");
  FUZZ_REQUIRE(std::isfinite(s.miter_limit) && s.miter_limit >= 1, "miter limit finite, >= 1");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view css(reinterpret_cast<const char*>(data), size);

  // As a `style` attribute.
  const svgm::svg::Style parent;
  svgm::svg::Style style = parent;
  svgm::svg::ElementProps props;
  for (const auto& d : svgm::svg::parse_declarations(css)) {
    FUZZ_REQUIRE(!d.name.empty() && trimmed(d.name) && trimmed(d.value), "declarations trimmed");
    svgm::svg::apply_declaration(d.name, d.value, parent, style, props);
    check_style(style, props);
  }

  // As a <style> sheet, matched against a few elements.
  svgm::svg::StyleSheet sheet;
  FUZZ_REQUIRE(sheet.add(css) >= 0, "a count of skipped selectors");
  struct Element { std::string_view tag, id, classes; };
  static constexpr Element kElements[] = {
      {"path", "", ""}, {"rect", "a", "st0"}, {"g", "body", "st0 st1  arm"}, {"circle", "", " x "}};
  std::vector<const svgm::svg::CssDeclaration*> matched;
  for (const auto& e : kElements) {
    matched.clear();
    sheet.match(e.tag, e.id, e.classes, matched);
    svgm::svg::Style s = parent;
    svgm::svg::ElementProps p;
    for (const auto* d : matched) {
      FUZZ_REQUIRE(d != nullptr && !d->name.empty(), "matched declarations are real");
      svgm::svg::apply_declaration(d->name, d->value, parent, s, p);
    }
    check_style(s, p);
  }
  return 0;
}
