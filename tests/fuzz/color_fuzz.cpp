// Fuzz target: CSS colours (#hex, rgb()/rgba(), hsl()/hsla(), names, transparent). Properties
// checked on every input: no crash or sanitizer report; a colour that parses has every
// component, alpha included, in [0, 1] (the renderer multiplies them without clamping); and
// the colour written back as rgba() with percentages parses to the same colour within 1e-6
// (the parser agrees with itself on the functional syntax).
#include <cmath>
#include <cstdio>
#include <string_view>

#include "fuzz_check.h"
#include "svg/css_color.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view s(reinterpret_cast<const char*>(data), size);
  const auto c = svgm::svg::parse_color(s);
  if (!c) return 0;
  for (const float v : {c->r, c->g, c->b, c->a})
    FUZZ_REQUIRE(v >= 0 && v <= 1, "colour components in [0, 1]");
  char back[128];
  std::snprintf(back, sizeof back, "rgba(%.9g%%, %.9g%%, %.9g%%, %.9g)", 100.0 * c->r, 100.0 * c->g,
                100.0 * c->b, static_cast<double>(c->a));
  const auto again = svgm::svg::parse_color(back);
  FUZZ_REQUIRE(again.has_value(), "rgba() with percentages parses");
  FUZZ_REQUIRE(std::fabs(again->r - c->r) <= 1e-6 && std::fabs(again->g - c->g) <= 1e-6 &&
                   std::fabs(again->b - c->b) <= 1e-6 && std::fabs(again->a - c->a) <= 1e-6,
               "rgba() written back reads as the same colour");
  return 0;
}
