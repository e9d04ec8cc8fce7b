// Gradient paint servers (see gradient_reader.h).
#include "svg/gradient_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <set>

#include "svg/css_color.h"
#include "svg/smil_transform.h"
#include "svg/svg_number.h"
#include "svg/svg_style.h"
#include "svg/transform_list.h"

namespace svgm::svg {

namespace {

// Longest href chain followed: deeper chains are cut (they are cycles or pathological).
constexpr int kMaxChain = 32;

std::string_view tag_of(pugi::xml_node n) {
  const char* colon = std::strchr(n.name(), ':');
  return colon ? std::string_view(colon + 1) : std::string_view(n.name());
}

bool is_gradient(pugi::xml_node n) {
  const std::string_view t = tag_of(n);
  return t == "linearGradient" || t == "radialGradient";
}

const char* href_of(pugi::xml_node n) {
  const char* h = n.attribute("xlink:href").value();
  return *h ? h : n.attribute("href").value();
}

// A gradient coordinate: a number (bounding box fraction or user units), a percentage of
// `percent_of`, or a length with a CSS absolute unit. Nothing when invalid or non-finite.
std::optional<double> coordinate(std::string_view v, double percent_of, bool bbox_units) {
  Cursor c{v};
  c.skip_ws();
  const auto x = c.number();
  if (!x || c.out_of_range) return std::nullopt;
  std::string unit(v.substr(c.pos));
  while (!unit.empty() && std::isspace(static_cast<unsigned char>(unit.back()))) unit.pop_back();
  double scale = 1;
  if (unit.empty() || unit == "px") scale = 1;
  else if (unit == "%") scale = bbox_units ? 0.01 : percent_of / 100;
  else if (unit == "pt") scale = 4.0 / 3.0;
  else if (unit == "pc") scale = 16;
  else if (unit == "mm") scale = 96 / 25.4;
  else if (unit == "cm") scale = 96 / 2.54;
  else if (unit == "in") scale = 96;
  else return std::nullopt;
  const double r = *x * scale;
  return std::isfinite(r) ? std::optional<double>(r) : std::nullopt;
}

// The extrema of one cubic coordinate (a, b, c, d Bernstein values) widen [lo, hi].
void cubic_extent(double a, double b, double c, double d, double& lo, double& hi) {
  lo = std::min({lo, a, d});
  hi = std::max({hi, a, d});
  // Derivative / 3: (b - a)(1-t)² + 2(c - b)(1-t)t + (d - c)t² = qa t² + qb t + qc.
  const double qa = (b - a) - 2 * (c - b) + (d - c), qb = 2 * ((c - b) - (b - a)), qc = b - a;
  auto at = [&](double t) {
    if (!(t > 0 && t < 1)) return;
    const double u = 1 - t;
    const double v = u * u * u * a + 3 * u * u * t * b + 3 * u * t * t * c + t * t * t * d;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  };
  if (std::fabs(qa) < 1e-12) {
    if (std::fabs(qb) > 1e-12) at(-qc / qb);
    return;
  }
  const double disc = qb * qb - 4 * qa * qc;
  if (disc < 0) return;
  const double s = std::sqrt(disc);
  at((-qb + s) / (2 * qa));
  at((-qb - s) / (2 * qa));
}

}  // namespace

std::optional<Box> subpath_bounds(const std::vector<Subpath>& subpaths, const Affine& m) {
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  for (const Subpath& sp : subpaths) {
    if (sp.points.empty()) continue;
    const Vec2 first = m.apply(sp.points[0]);
    x0 = std::min(x0, first.x); x1 = std::max(x1, first.x);
    y0 = std::min(y0, first.y); y1 = std::max(y1, first.y);
    for (size_t i = 0; i + 3 < sp.points.size(); i += 3) {
      const Vec2 p0 = m.apply(sp.points[i]), p1 = m.apply(sp.points[i + 1]),
                 p2 = m.apply(sp.points[i + 2]), p3 = m.apply(sp.points[i + 3]);
      cubic_extent(p0.x, p1.x, p2.x, p3.x, x0, x1);
      cubic_extent(p0.y, p1.y, p2.y, p3.y, y0, y1);
    }
  }
  if (!(x0 <= x1)) return std::nullopt;
  return Box{x0, y0, x1 - x0, y1 - y0};
}

std::vector<pugi::xml_node> GradientReader::chain(pugi::xml_node g) const {
  std::vector<pugi::xml_node> out;
  std::set<const void*> seen;
  while (g && is_gradient(g) && seen.insert(g.internal_object()).second &&
         static_cast<int>(out.size()) < kMaxChain) {
    out.push_back(g);
    const char* href = href_of(g);
    if (*href != '#') break;
    const auto it = ids_.find(href + 1);
    if (it == ids_.end()) break;
    g = it->second;
  }
  return out;
}

GradientStop GradientReader::read_stop(pugi::xml_node stop) {
  std::string colour = "black", opacity = "1", offset = "0";
  // Presentation attributes, then sheet rules, then the style attribute (the cascade order).
  auto take = [&](std::string_view k, std::string_view v) {
    if (k == "stop-color") colour = std::string(v);
    else if (k == "stop-opacity") opacity = std::string(v);
  };
  take("stop-color", stop.attribute("stop-color").empty() ? "black" : stop.attribute("stop-color").value());
  if (!stop.attribute("stop-opacity").empty()) take("stop-opacity", stop.attribute("stop-opacity").value());
  if (!sheet_.empty()) {
    sheet_.match("stop", stop.attribute("id").value(), stop.attribute("class").value(), matched_);
    for (const CssDeclaration* d : matched_) take(d->name, d->value);
  }
  if (const char* style = stop.attribute("style").value(); *style)
    for (const CssDeclaration& d : parse_declarations(style)) take(d.name, d.value);
  if (!stop.attribute("offset").empty()) offset = stop.attribute("offset").value();

  GradientStop s;
  // offset: a number or a percentage, clamped to [0, 1]; invalid is 0.
  {
    Cursor c{offset};
    c.skip_ws();
    if (const auto x = c.number(); x && std::isfinite(*x)) {
      double v = *x;
      if (c.peek() == '%') v /= 100;
      s.offset = static_cast<float>(std::clamp(v, 0.0, 1.0));
    }
  }
  // stop-color: inherit takes the parent gradient's own stop-color (the property is not
  // inherited further, so its parent's value is the initial black unless it sets one);
  // currentColor takes the nearest ancestor's color (stops do not see the painted element).
  auto trimmed = [](std::string v) {
    while (!v.empty() && std::isspace(static_cast<unsigned char>(v.back()))) v.pop_back();
    while (!v.empty() && std::isspace(static_cast<unsigned char>(v.front()))) v.erase(v.begin());
    return v;
  };
  colour = trimmed(colour);
  if (colour == "inherit") {
    colour = "black";
    if (const char* v = stop.parent().attribute("stop-color").value(); *v && std::string_view(v) != "inherit")
      colour = v;
  }
  Rgba c{0, 0, 0, 1};
  if (colour == "currentColor" || colour == "currentcolor") {
    for (pugi::xml_node up = stop; up; up = up.parent())
      if (const char* v = up.attribute("color").value(); *v) {
        if (const auto col = parse_color(v)) c = *col;
        break;
      }
  } else if (const auto col = parse_color(colour)) {
    c = *col;
  }
  float a = 1;
  parse_unit_interval(opacity, &a);
  c.a *= a;
  s.color = c;
  return s;
}

std::vector<GradientStop> GradientReader::stops(pugi::xml_node g) {
  for (pugi::xml_node n : chain(g)) {
    std::vector<GradientStop> out;
    for (pugi::xml_node c = n.first_child(); c; c = c.next_sibling()) {
      if (c.type() != pugi::node_element || tag_of(c) != "stop") continue;
      GradientStop s = read_stop(c);
      // Offsets never go back: a smaller one is raised to the largest so far.
      if (!out.empty()) s.offset = std::max(s.offset, out.back().offset);
      out.push_back(s);
    }
    if (!out.empty()) return out;
  }
  return {};
}

std::optional<Gradient> GradientReader::resolve(pugi::xml_node g, const std::optional<Box>& bbox,
                                                const Affine& ctm, double vp_w, double vp_h,
                                                double animation_time) {
  const std::vector<pugi::xml_node> nodes = chain(g);
  if (nodes.empty()) return std::nullopt;
  const bool radial = tag_of(g) == "radialGradient";
  // The first value of `attr` along the chain (of the same kind when `same_kind`).
  auto attr = [&](const char* name, bool same_kind) -> const char* {
    for (pugi::xml_node n : nodes) {
      if (same_kind && tag_of(n) != tag_of(g)) continue;
      if (const pugi::xml_attribute a = n.attribute(name); !a.empty()) return a.value();
    }
    return nullptr;
  };
  Gradient out;
  out.radial = radial;
  out.stops = stops(g);
  if (out.stops.empty()) return std::nullopt;

  const char* units = attr("gradientUnits", false);
  const bool bbox_units = !units || std::string_view(units) != "userSpaceOnUse";
  const char* spread = attr("spreadMethod", false);
  if (spread && std::string_view(spread) == "reflect") out.spread = Spread::Reflect;
  else if (spread && std::string_view(spread) == "repeat") out.spread = Spread::Repeat;

  Affine m = ctm;
  if (bbox_units) {
    if (!bbox || !(bbox->w > 0) || !(bbox->h > 0)) return std::nullopt;
    m = m * Affine{bbox->w, 0, 0, bbox->h, bbox->x, bbox->y};
  }
  Affine gt;
  if (const char* t = attr("gradientTransform", false)) {
    if (const auto parsed = parse_transform(t)) gt = *parsed;
  }
  if (animation_time >= 0) gt = animated_transform(g, animation_time, gt, "gradientTransform");
  m = m * gt;
  if (!(std::fabs(m.det()) > 0) || !std::isfinite(m.det())) return std::nullopt;
  out.to_canvas = m;
  out.id = g.attribute("id").value();
  out.user_space = !bbox_units;

  const double diag = std::sqrt(0.5 * (vp_w * vp_w + vp_h * vp_h));
  auto num = [&](const char* name, const char* fallback, double percent_of) {
    const char* v = attr(name, true);
    if (v)
      if (const auto x = coordinate(v, percent_of, bbox_units)) return *x;
    return *coordinate(fallback, percent_of, bbox_units);
  };
  if (!radial) {
    out.p1 = {num("x1", "0%", vp_w), num("y1", "0%", vp_h)};
    out.p2 = {num("x2", "100%", vp_w), num("y2", "0%", vp_h)};
    // A zero-length vector paints the last stop's colour (SVG 1.1, 13.2.2).
    if (out.p1 == out.p2) out.stops = {out.stops.back()};
  } else {
    out.center = {num("cx", "50%", vp_w), num("cy", "50%", vp_h)};
    out.r = num("r", "50%", diag);
    // fx and fy default to the resolved cx and cy.
    out.focal = {attr("fx", true) ? num("fx", "50%", vp_w) : out.center.x,
                 attr("fy", true) ? num("fy", "50%", vp_h) : out.center.y};
    out.fr = std::max(0.0, num("fr", "0%", diag));
    if (out.r < 0) return std::nullopt;  // a negative radius is an error: nothing painted
    // A zero radius paints the last stop's colour (SVG 1.1, 13.2.3).
    if (out.r == 0) out.stops = {out.stops.back()};
  }
  return out;
}

}  // namespace svgm::svg
