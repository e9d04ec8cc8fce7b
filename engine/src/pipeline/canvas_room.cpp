// Room to move (see canvas_room.h).
#include "pipeline/canvas_room.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <pugixml.hpp>
#include <sstream>

#include "procedural/prompt_parse.h"
#include "procedural/travel_words.h"
#include "svg/document_order.h"
#include "svg/svg_number.h"
#include "svgmotion/error.h"

namespace svgm {

namespace {

// A shape covering the whole canvas as a rectangle would (a backdrop, a sky): not the figure.
// A disc filling the canvas (a face) is the figure: its outline encloses about pi/4 of its box.
bool backdrop(const Path& p, double W, double H) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300, area = 0;
  for (const Subpath& sp : p.subpaths) {
    for (const Vec2& q : sp.points) {
      x0 = std::min(x0, q.x), y0 = std::min(y0, q.y), x1 = std::max(x1, q.x), y1 = std::max(y1, q.y);
    }
    // Shoelace over the on-curve points: enough to tell a rectangle from a disc.
    for (size_t i = 0; i + 3 < sp.points.size(); i += 3) {
      const Vec2 a = sp.points[i], b = sp.points[i + 3];
      area += a.x * b.y - b.x * a.y;
    }
    if (sp.points.size() >= 4) {
      const Vec2 a = sp.points.back(), b = sp.points.front();
      area += a.x * b.y - b.x * a.y;
    }
  }
  if (!(x1 > x0 && y1 > y0)) return false;
  const bool covers = (x1 - x0) >= 0.97 * W && (y1 - y0) >= 0.97 * H;
  return covers && std::fabs(area) / 2 >= 0.9 * (x1 - x0) * (y1 - y0);
}

std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// "36", "36px", "2.5in": the number scaled, the unit kept; a percentage or no number: unchanged.
std::string scaled_length(std::string_view v, double f) {
  size_t i = 0;
  while (i < v.size() && std::isspace(static_cast<unsigned char>(v[i]))) ++i;
  svg::Cursor c{v.substr(i)};
  const auto num = c.number();
  if (!num || c.out_of_range) return std::string(v);
  const std::string unit(v.substr(i + c.pos));
  if (unit.find('%') != std::string::npos) return std::string(v);
  return number_text(*num * f) + unit;
}

}  // namespace

FigureSpan figure_span(const Scene& scene) {
  FigureSpan s;
  const double W = std::max(scene.width, 1e-9), H = std::max(scene.height, 1e-9);
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const Path& p : scene.paths) {
    const bool painted = (p.has_fill && p.fill.a > 0) || (p.has_stroke && p.stroke.color.a > 0 && p.stroke.width > 0);
    if (!painted || p.opacity <= 0 || backdrop(p, W, H)) continue;
    const double r = p.has_stroke ? 0.5 * p.stroke.width : 0;
    for (const Subpath& sp : p.subpaths)
      for (const Vec2& q : sp.points) {
        x0 = std::min(x0, q.x - r), y0 = std::min(y0, q.y - r);
        x1 = std::max(x1, q.x + r), y1 = std::max(y1, q.y + r);
      }
  }
  if (!(x1 > x0 && y1 > y0)) return s;
  // Only what lies on the canvas counts: a shape hanging off its edge is cut there anyway.
  s.x = (std::min(x1, W) - std::max(x0, 0.0)) / W;
  s.y = (std::min(y1, H) - std::max(y0, 0.0)) / H;
  s.empty = false;
  return s;
}

double auto_room(const Scene& scene, const std::string& prompt, char* why, size_t size) {
  const FigureSpan span = figure_span(scene);
  if (span.empty) return 0;
  // The prompt read once, and only for a figure wide or tall enough for its words to matter.
  const bool words = !prompt.empty() && std::max(span.x, span.y) >= kTravelFills;
  const ParsedPrompt said = words ? parse_prompt(prompt) : ParsedPrompt{};
  if (words && span.x >= kTravelFills && sends_figure_one_way(said)) {
    if (why) std::snprintf(why, size, "the prompt tells the figure a way to go and it spans %.0f %% of its canvas's width", 100 * span.x);
    return kTurnRoom;
  }
  if (words && launches_figure(said)) {
    if (why) std::snprintf(why, size, "the prompt launches the figure and it spans %.0f %% of its canvas's %s", 100 * std::max(span.x, span.y),
                           span.x >= span.y ? "width" : "height");
    return kTurnRoom;
  }
  if (std::max(span.x, span.y) >= kFillsCanvas) {
    if (why) std::snprintf(why, size, "the drawing fills %.0f %% of its canvas's %s", 100 * std::max(span.x, span.y), span.x >= span.y ? "width" : "height");
    return kAutoRoom;
  }
  if (words && span.x >= kTravelFills && sends_figure_across(said)) {
    if (why) std::snprintf(why, size, "the prompt sends the figure across and it spans %.0f %% of its canvas's width", 100 * span.x);
    return kAutoRoom;
  }
  if (words && carries_figure_about(said)) {
    if (why)
      std::snprintf(why, size, "the prompt carries the figure about in the air and it spans %.0f %% of its canvas's %s",
                    100 * std::max(span.x, span.y), span.x >= span.y ? "width" : "height");
    return kAutoRoom;
  }
  return 0;
}

std::string give_canvas_room(std::string_view text, std::string_view name, const Scene& scene, double share) {
  const std::string who(name);
  if (!(share > 0 && share <= 0.5)) throw Error(who + ": room must be a share in (0, 0.5]");
  pugi::xml_document doc;
  if (!doc.load_buffer(text.data(), text.size(), kKeepDocumentParse))
    throw Error(who + ": not a readable XML document");
  pugi::xml_node root = doc.document_element();
  if (std::string_view(root.name()) != "svg" && std::string_view(root.name()).ends_with(":svg") == false)
    throw Error(who + ": the root element is not <svg>");
  double vb[4] = {0, 0, scene.width, scene.height};
  if (pugi::xml_attribute a = root.attribute("viewBox")) {
    svg::Cursor c{a.value()};
    for (double& x : vb) {
      c.skip_comma_ws();
      const auto num = c.number();
      if (!num || c.out_of_range) throw Error(who + ": viewBox \"" + std::string(a.value()) + "\" is not four numbers");
      x = *num;
    }
    if (!(vb[2] > 0 && vb[3] > 0)) throw Error(who + ": viewBox \"" + std::string(a.value()) + "\" has no area");
  }
  const double f = 1 + 2 * share;
  const std::string box = number_text(vb[0] - share * vb[2]) + " " + number_text(vb[1] - share * vb[3]) + " " +
                          number_text(vb[2] * f) + " " + number_text(vb[3] * f);
  (root.attribute("viewBox") ? root.attribute("viewBox") : root.append_attribute("viewBox")).set_value(box.c_str());
  for (const char* side : {"width", "height"})
    if (pugi::xml_attribute a = root.attribute(side)) a.set_value(scaled_length(a.value(), f).c_str());
  // Said in the document, so a reader knows the drawing's own canvas (Scene::room): a backdrop
  // reaches its edges, not the room's.
  (root.attribute(kRoomAttribute) ? root.attribute(kRoomAttribute) : root.append_attribute(kRoomAttribute))
      .set_value(number_text(share).c_str());
  std::ostringstream out;
  doc.save(out, "", pugi::format_raw | pugi::format_no_declaration, pugi::encoding_utf8);
  return out.str();
}

}  // namespace svgm
