// The clock of an animated SVG (see smil_clock.h).
#include "export/smil_clock.h"

#include <pugixml.hpp>

#include <algorithm>
#include <cstdio>
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
  const auto fps = svg::parse_number(doc.document_element().attribute(kFrameRateAttribute).value());
  if (fps && *fps >= 1 && *fps <= 240) clock.fps = *fps;  // below 1 fps a GIF's delays overflow
  return clock;
}

std::string with_frame_rate(std::string_view text, std::string_view name, double fps) {
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed = doc.load_buffer(text.data(), text.size());
  if (!parsed) throw Error(std::string(name) + ": " + parsed.description());
  // The root's start tag: from its name to the first '>' outside a quoted value.
  const size_t begin = static_cast<size_t>(std::max<ptrdiff_t>(0, doc.document_element().offset_debug()));
  size_t end = begin;
  for (char quote = 0; end < text.size() && (quote || text[end] != '>'); ++end)
    if (quote ? text[end] == quote : (text[end] == '"' || text[end] == '\'')) quote = quote ? 0 : text[end];
  if (end > begin && text[end - 1] == '/') --end;  // <svg .../>
  char value[64];
  std::snprintf(value, sizeof value, "%.9g", fps);
  std::string out(text);
  const std::string key = std::string(" ") + kFrameRateAttribute + "=\"";
  const size_t at = std::string_view(text.data() + begin, end - begin).find(key);
  if (at != std::string_view::npos) {
    const size_t v = begin + at + key.size(), close = out.find('"', v);
    out.replace(v, close - v, value);
  } else {
    out.insert(end, key + value + "\"");
  }
  return out;
}

}  // namespace svgm
