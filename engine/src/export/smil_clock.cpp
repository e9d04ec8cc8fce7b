// The clock of an animated SVG (see smil_clock.h).
#include "export/smil_clock.h"

#include <pugixml.hpp>

#include <algorithm>
#include <cstring>
#include <string>

#include "svg/svg_number.h"
#include "svgmotion/error.h"

namespace svgm {

SmilClock smil_clock(std::string_view text, std::string_view name) {
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed = doc.load_buffer(text.data(), text.size());
  if (!parsed) throw Error(std::string(name) + ": " + parsed.description());
  SmilClock clock;
  for (const pugi::xpath_node& x : doc.select_nodes("//*[local-name()='animate' or local-name()='animateTransform']")) {
    const pugi::xml_node a = x.node();
    const auto dur = svg::parse_clock_value(a.attribute("dur").value());
    if (!dur || !(*dur > 0)) continue;
    ++clock.animations;
    const std::string_view repeat = a.attribute("repeatCount").value();
    double pass = *dur;
    if (repeat == "indefinite") clock.repeats = true;
    else if (const auto n = svg::parse_number(repeat); n && *n > 0) pass *= *n;
    clock.duration_s = std::max(clock.duration_s, pass);
  }
  return clock;
}

}  // namespace svgm
