// Style declarations (see svg_style.h).
#include "svg/svg_style.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include "svg/css_color.h"
#include "svg/svg_number.h"

namespace svgm::svg {

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

// fill/stroke values: none | currentColor | <color> | url(#id) [fallback]. False if invalid.
bool parse_paint(std::string_view v, const Style& style, Paint* out) {
  v = trim(v);
  if (v == "none") { *out = Paint{}; return true; }
  if (v == "currentColor" || v == "currentcolor") {
    *out = Paint{PaintKind::CurrentColor, style.color, {}, false, PaintKind::None};
    return true;
  }
  if (v.substr(0, 4) == "url(") {
    const size_t close = v.find(')');
    if (close == std::string_view::npos) return false;
    std::string_view ref = trim(v.substr(4, close - 4));
    if (!ref.empty() && (ref.front() == '\'' || ref.front() == '"')) ref = ref.substr(1, ref.size() - 2);
    if (ref.empty() || ref.front() != '#') return false;
    Paint p;
    p.kind = PaintKind::Url;
    p.url = std::string(ref.substr(1));
    const std::string_view rest = trim(v.substr(close + 1));
    if (!rest.empty()) {
      p.has_fallback = true;
      Paint fb;
      if (!parse_paint(rest, style, &fb) || fb.kind == PaintKind::Url) return false;
      p.fallback = fb.kind;
      p.color = fb.color;
    }
    *out = p;
    return true;
  }
  if (const auto c = parse_color(v)) {
    *out = Paint{PaintKind::Color, *c, {}, false, PaintKind::None};
    return true;
  }
  return false;
}

// The id in "url(#id)" (quotes allowed), or "" for anything else.
std::string url_id(std::string_view v) {
  if (v.substr(0, 4) != "url(") return {};
  const size_t close = v.find(')');
  if (close == std::string_view::npos) return {};
  std::string_view ref = trim(v.substr(4, close - 4));
  if (ref.size() >= 2 && (ref.front() == '\'' || ref.front() == '"')) ref = ref.substr(1, ref.size() - 2);
  if (ref.empty() || ref.front() != '#') return {};
  return std::string(ref.substr(1));
}

// stroke-miterlimit: a plain number (SVG 2, 13.5.3); "4px" or "20%" are invalid, so the
// declaration is ignored. False when invalid; `bad` for nan/inf/overflow.
bool parse_plain_number(std::string_view v, double* out, bool* bad) {
  v = trim(v);
  if (spells_non_finite(v)) { *bad = true; return false; }
  Cursor c{v};
  const auto n = c.number();
  if (c.out_of_range) { *bad = true; return false; }
  if (!n || !c.done()) return false;
  *out = *n;
  return true;
}

bool parse_length_number(std::string_view v, double* out, bool* bad) {
  // A stroke width: a number with an optional unit.
  v = trim(v);
  if (spells_non_finite(v)) { *bad = true; return false; }
  Cursor c{v};
  const auto n = c.number();
  if (c.out_of_range) { *bad = true; return false; }
  if (!n) return false;
  const std::string_view unit = v.substr(c.pos);
  double scale = 1;
  if (unit.empty() || unit == "px") scale = 1;
  else if (unit == "pt") scale = 4.0 / 3.0;
  else if (unit == "mm") scale = 96 / 25.4;
  else if (unit == "cm") scale = 96 / 2.54;
  else if (unit == "in") scale = 96;
  else if (unit == "pc") scale = 16;
  else if (unit == "em") scale = 16;
  else if (unit == "ex") scale = 8;
  else return false;
  // 1e308in is a finite number but not a finite length: refused like an overflow (as
  // svg_reader.cpp does for attribute lengths), never kept as an infinite stroke width.
  if (!std::isfinite(*n * scale)) { *bad = true; return false; }
  *out = *n * scale;
  return true;
}

}  // namespace

bool parse_unit_interval(std::string_view v, float* out) {
  v = trim(v);
  Cursor c{v};
  const auto n = c.number();
  if (!n) return false;
  double x = *n;
  if (c.peek() == '%') { x /= 100; ++c.pos; }
  if (!c.done()) return false;
  *out = static_cast<float>(std::clamp(x, 0.0, 1.0));
  return true;
}

bool apply_declaration(std::string_view name, std::string_view value, const Style& parent,
                       Style& s, ElementProps& props) {
  value = trim(value);
  if (value == "inherit") {
    // Inherited properties already hold the parent's value unless set earlier on this element.
    if (name == "fill") s.fill = parent.fill;
    else if (name == "stroke") s.stroke = parent.stroke;
    else if (name == "color") s.color = parent.color;
    else if (name == "fill-opacity") s.fill_opacity = parent.fill_opacity;
    else if (name == "stroke-opacity") s.stroke_opacity = parent.stroke_opacity;
    else if (name == "stroke-width") s.stroke_width = parent.stroke_width;
    return true;
  }
  bool bad = false;
  if (name == "fill") {
    Paint p;
    if (parse_paint(value, s, &p)) s.fill = p;
  } else if (name == "stroke") {
    Paint p;
    if (parse_paint(value, s, &p)) s.stroke = p;
  } else if (name == "color") {
    if (const auto c = parse_color(value)) s.color = *c;
  } else if (name == "fill-opacity") {
    if (spells_non_finite(value)) return false;
    parse_unit_interval(value, &s.fill_opacity);
  } else if (name == "stroke-opacity") {
    if (spells_non_finite(value)) return false;
    parse_unit_interval(value, &s.stroke_opacity);
  } else if (name == "opacity") {
    if (spells_non_finite(value)) return false;
    parse_unit_interval(value, &props.opacity);
  } else if (name == "fill-rule") {
    if (value == "evenodd") s.fill_rule = FillRule::EvenOdd;
    else if (value == "nonzero") s.fill_rule = FillRule::NonZero;
  } else if (name == "stroke-width") {
    double w;
    if (parse_length_number(value, &w, &bad) && w >= 0) s.stroke_width = w;
  } else if (name == "stroke-linejoin") {
    if (value == "miter" || value == "arcs") s.join = LineJoin::Miter;
    else if (value == "miter-clip") s.join = LineJoin::MiterClip;
    else if (value == "round") s.join = LineJoin::Round;
    else if (value == "bevel") s.join = LineJoin::Bevel;
  } else if (name == "stroke-linecap") {
    if (value == "butt") s.cap = LineCap::Butt;
    else if (value == "round") s.cap = LineCap::Round;
    else if (value == "square") s.cap = LineCap::Square;
  } else if (name == "stroke-miterlimit") {
    double m;
    if (parse_plain_number(value, &m, &bad) && m >= 1) s.miter_limit = m;
  } else if (name == "stroke-dasharray") {
    s.dashed = value != "none" && !value.empty();
    // Lengths separated by commas and/or spaces; an odd list is repeated (SVG 1.1, 11.4); a
    // negative or unreadable length, or a zero sum, draws solid.
    s.dash_array.clear();
    double sum = 0;
    if (s.dashed) {
      std::string_view rest = trim(value);
      while (!rest.empty()) {
        const size_t cut = rest.find_first_of(", \t\n\r");
        double d;
        if (!parse_length_number(rest.substr(0, cut), &d, &bad) || d < 0) {
          s.dash_array.clear();
          break;
        }
        s.dash_array.push_back(d);
        sum += d;
        rest = cut == std::string_view::npos ? std::string_view{} : trim(rest.substr(cut + 1));
        while (!rest.empty() && rest.front() == ',') rest = trim(rest.substr(1));
      }
    }
    if (!(sum > 0)) s.dash_array.clear();
    if (s.dash_array.size() % 2) s.dash_array.insert(s.dash_array.end(), s.dash_array.begin(), s.dash_array.end());
  } else if (name == "stroke-dashoffset") {
    double d;
    if (parse_length_number(value, &d, &bad)) s.dash_offset = d;
  } else if (name == "visibility") {
    if (value == "hidden" || value == "collapse") s.visible = false;
    else if (value == "visible") s.visible = true;
  } else if (name == "display") {
    props.display_none = value == "none";
  } else if (name == "clip-rule") {
    if (value == "evenodd") s.clip_rule = FillRule::EvenOdd;
    else if (value == "nonzero") s.clip_rule = FillRule::NonZero;
  } else if (name == "clip-path") {
    props.has_clip = value != "none";
    props.clip_url = url_id(value);
  } else if (name == "mask") {
    props.has_mask = value != "none";
    props.mask_url = url_id(value);
  } else if (name == "mask-type") {
    props.mask_type = std::string(value);
  } else if (name == "filter") {
    props.has_filter = value != "none";
  } else if (name == "marker-start" || name == "marker-mid" || name == "marker-end" || name == "marker") {
    props.has_marker = props.has_marker || value != "none";
  }
  return !bad;
}

}  // namespace svgm::svg
