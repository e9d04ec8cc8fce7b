// The SVG reader's paints (svg_reader_internal.h): a fill or stroke's flat colour, a gradient's
// being its stops' mean (the fitter and the exports work with flat colours; the render draws
// the gradient itself, see gradient_reader.h).
#include <pugixml.hpp>

#include "svg/css_color.h"
#include "svg/css_sheet.h"
#include "svg/svg_reader_internal.h"
#include "svg/svg_style.h"

namespace svgm::svg {

std::optional<Rgba> Reader::gradient_mean(pugi::xml_node g, int depth) {
  double r = 0, gg = 0, b = 0, a = 0;
  int n = 0;
  for (pugi::xml_node stop = g.first_child(); stop; stop = stop.next_sibling()) {
    if (local_name(stop.name()) != "stop") continue;
    Style st;
    Rgba c{0, 0, 0, 1};
    float opacity = 1;
    auto take = [&](std::string_view k, std::string_view v) {
      if (k == "stop-color") {
        if (const auto col = svg::parse_color(v)) c = *col;
      } else if (k == "stop-opacity") {
        svg::parse_unit_interval(v, &opacity);
      }
    };
    take("stop-color", stop.attribute("stop-color").value());
    if (!stop.attribute("stop-opacity").empty()) take("stop-opacity", stop.attribute("stop-opacity").value());
    if (!sheet_.empty()) {
      sheet_.match("stop", stop.attribute("id").value(), stop.attribute("class").value(), matched_);
      for (const svg::CssDeclaration* d : matched_) take(d->name, d->value);
    }
    if (const char* style = stop.attribute("style").value(); *style)
      for (const svg::CssDeclaration& d : svg::parse_declarations(style)) take(d.name, d.value);
    // Premultiplied sums: a transparent stop does not pull the mean colour towards black.
    const double alpha = c.a * opacity;
    r += c.r * alpha; gg += c.g * alpha; b += c.b * alpha; a += alpha;
    ++n;
  }
  if (n == 0) {
    // Stops may come from the gradient this one references.
    const char* href = g.attribute("xlink:href").value();
    if (!*href) href = g.attribute("href").value();
    if (*href == '#' && depth < 16) {
      const auto it = ids_.find(href + 1);
      if (it != ids_.end()) return gradient_mean(it->second, depth + 1);
    }
    return std::nullopt;
  }
  if (a <= 0) return Rgba{0, 0, 0, 0};
  return Rgba{static_cast<float>(r / a), static_cast<float>(gg / a), static_cast<float>(b / a),
              static_cast<float>(a / n)};
}

bool Reader::resolve_paint(const Paint& p, const Style& s, pugi::xml_node el, Rgba* out,
                           pugi::xml_node* gradient) {
  switch (p.kind) {
    case PaintKind::None: return false;
    case PaintKind::Color: *out = p.color; return true;
    case PaintKind::CurrentColor: *out = s.color; return true;
    case PaintKind::Url: {
      const auto it = ids_.find(p.url);
      if (it != ids_.end()) {
        const std::string_view tag = local_name(it->second.name());
        if (tag == "linearGradient" || tag == "radialGradient") {
          if (const auto m = gradient_mean(it->second, 0)) {
            *out = *m;
            *gradient = it->second;
            return true;
          }
          return false;
        }
        if (tag == "pattern") warn(el, "pattern paint not supported (fallback colour or none used)");
      } else {
        warn(el, "paint url(#" + p.url + ") not found (fallback colour or none used)");
      }
      if (p.has_fallback && p.fallback != PaintKind::None) {
        *out = p.fallback == PaintKind::CurrentColor ? s.color : p.color;
        return true;
      }
      return false;
    }
  }
  return false;
}

}  // namespace svgm::svg
