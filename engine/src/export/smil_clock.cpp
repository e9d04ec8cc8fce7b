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
  // An attribute already there (a re-export of an exported file, a hand edit: either quote,
  // any space round its '=') gets the new value; a second one would make the file unreadable.
  const std::string_view attr = kFrameRateAttribute;
  auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  for (size_t p = begin; p < end; ++p) {
    if (text[p] == '"' || text[p] == '\'') {  // skip a quoted value whole
      const size_t close = text.find(text[p], p + 1);
      if (close == std::string_view::npos || close >= end) break;
      p = close;
      continue;
    }
    if (!space(text[p]) || text.substr(p + 1, attr.size()) != attr) continue;
    size_t q = p + 1 + attr.size();
    while (q < end && space(text[q])) ++q;
    if (q >= end || text[q] != '=') continue;
    for (++q; q < end && space(text[q]);) ++q;
    if (q >= end || (text[q] != '"' && text[q] != '\'')) continue;
    const size_t close = text.find(text[q], q + 1);
    if (close == std::string_view::npos || close >= end) break;
    out.replace(q + 1, close - q - 1, value);
    return out;
  }
  out.insert(end, std::string(" ") + std::string(attr) + "=\"" + value + "\"");
  return out;
}

}  // namespace svgm
