// The SVG reader's shapes (svg_reader_internal.h): the geometry of path, rect, circle, ellipse,
// line, polyline and polygon as cubic subpaths (a path's d at a time of its SMIL animation
// when one is asked for), and the scene path made of a shape with its paints, stroke and ids.
#include <pugixml.hpp>

#include <algorithm>
#include <cmath>

#include "svg/path_data.h"
#include "svg/smil_spline.h"
#include "svg/svg_number.h"
#include "svg/svg_reader_internal.h"

namespace svgm::svg {

std::vector<Subpath> Reader::shape_geometry(pugi::xml_node n, std::string_view tag, const Viewport& vp) {
  std::vector<Subpath> out;
  auto ellipse = [&](double cx, double cy, double rx, double ry) {
    Subpath s;
    s.closed = true;
    s.points.push_back({cx + rx, cy});
    svg::arc_to_cubics({cx + rx, cy}, rx, ry, 0, false, true, {cx, cy + ry}, s.points);
    svg::arc_to_cubics({cx, cy + ry}, rx, ry, 0, false, true, {cx - rx, cy}, s.points);
    svg::arc_to_cubics({cx - rx, cy}, rx, ry, 0, false, true, {cx, cy - ry}, s.points);
    svg::arc_to_cubics({cx, cy - ry}, rx, ry, 0, false, true, {cx + rx, cy}, s.points);
    out.push_back(std::move(s));
  };
  auto lines = [](std::vector<Vec2> pts, bool closed) {
    Subpath s;
    s.closed = closed;
    s.points.push_back(pts[0]);
    for (size_t i = 1; i < pts.size(); ++i) {
      const Vec2 a = pts[i - 1], b = pts[i];
      s.points.insert(s.points.end(), {a + (1.0 / 3.0) * (b - a), a + (2.0 / 3.0) * (b - a), b});
    }
    if (closed && !(pts.back() == pts.front())) {
      const Vec2 a = pts.back(), b = pts.front();
      s.points.insert(s.points.end(), {a + (1.0 / 3.0) * (b - a), a + (2.0 / 3.0) * (b - a), b});
    }
    return s;
  };
  const double diag = std::sqrt(0.5 * (vp.w * vp.w + vp.h * vp.h));
  if (tag == "path") {
    if (limits_.animation_time >= 0 && animated_path(n, limits_.animation_time, out)) return out;
    const char* d = n.attribute("d").value();
    const svg::PathDataResult r = svg::parse_path_data(d, out);
    if (r.out_of_range) fail(describe(n) + " d: number out of range");
    if (!r.ok)
      scene_.warnings.push_back(name_ + ": " + describe(n) + ": bad path data at offset " +
                                std::to_string(r.error_offset) + ", drawn up to there");
  } else if (tag == "rect") {
    const double x = length(n, "x", 0, vp.w), y = length(n, "y", 0, vp.h);
    const double w = length(n, "width", 0, vp.w), h = length(n, "height", 0, vp.h);
    if (!(w > 0) || !(h > 0)) return out;
    double rx = length(n, "rx", -1, vp.w), ry = length(n, "ry", -1, vp.h);
    if (rx < 0 && ry < 0) rx = ry = 0;
    else if (rx < 0) rx = ry;
    else if (ry < 0) ry = rx;
    rx = std::min(rx, w / 2);
    ry = std::min(ry, h / 2);
    if (rx <= 0 || ry <= 0) {
      out.push_back(lines({{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}}, true));
    } else {
      Subpath s;
      s.closed = true;
      auto line = [&](Vec2 b) {
        const Vec2 a = s.points.back();
        s.points.insert(s.points.end(), {a + (1.0 / 3.0) * (b - a), a + (2.0 / 3.0) * (b - a), b});
      };
      s.points.push_back({x + rx, y});
      line({x + w - rx, y});
      svg::arc_to_cubics({x + w - rx, y}, rx, ry, 0, false, true, {x + w, y + ry}, s.points);
      line({x + w, y + h - ry});
      svg::arc_to_cubics({x + w, y + h - ry}, rx, ry, 0, false, true, {x + w - rx, y + h}, s.points);
      line({x + rx, y + h});
      svg::arc_to_cubics({x + rx, y + h}, rx, ry, 0, false, true, {x, y + h - ry}, s.points);
      line({x, y + ry});
      svg::arc_to_cubics({x, y + ry}, rx, ry, 0, false, true, {x + rx, y}, s.points);
      out.push_back(std::move(s));
    }
  } else if (tag == "circle") {
    const double r = length(n, "r", 0, diag);
    if (r > 0) ellipse(length(n, "cx", 0, vp.w), length(n, "cy", 0, vp.h), r, r);
  } else if (tag == "ellipse") {
    // SVG 2: a missing or negative (invalid) radius is "auto", which takes the other one.
    double rx = length(n, "rx", -1, vp.w), ry = length(n, "ry", -1, vp.h);
    if (rx < 0) rx = ry;
    if (ry < 0) ry = rx;
    if (rx > 0 && ry > 0) ellipse(length(n, "cx", 0, vp.w), length(n, "cy", 0, vp.h), rx, ry);
  } else if (tag == "line") {
    out.push_back(lines({{length(n, "x1", 0, vp.w), length(n, "y1", 0, vp.h)},
                         {length(n, "x2", 0, vp.w), length(n, "y2", 0, vp.h)}},
                        false));
  } else if (tag == "polyline" || tag == "polygon") {
    svg::Cursor c{n.attribute("points").value()};
    std::vector<Vec2> pts;
    c.skip_ws();
    while (!c.done()) {
      const auto x = c.number();
      if (!x) break;
      c.skip_comma_ws();
      const auto y = c.number();
      if (!y) break;  // an odd coordinate count ignores the last one
      pts.push_back({*x, *y});
      c.skip_comma_ws();
    }
    if (c.out_of_range) fail(describe(n) + " points: number out of range");
    if (pts.size() >= 2) out.push_back(lines(pts, tag == "polygon"));
  }
  return out;
}

// The shape of a path with a SMIL <animate attributeName="d"> at `time` seconds: the active
// keyframe interval by keyTimes (uniform when absent), numbers interpolated linearly (eased by
// keySplines with calcMode="spline") (for our
// own M/C/Z exports this is exactly SMIL's path interpolation), or the interval's first value
// for calcMode="discrete" or shapes of different structure. Returns false when there is no
// usable animation (the static d is used).
bool Reader::animated_path(pugi::xml_node n, double time, std::vector<Subpath>& out) {
  pugi::xml_node anim;
  for (pugi::xml_node c = n.first_child(); c; c = c.next_sibling())
    if (local_name(c.name()) == "animate" && std::string_view(c.attribute("attributeName").value()) == "d") anim = c;
  if (!anim) return false;
  std::vector<std::string> values;
  std::string_view v = anim.attribute("values").value();
  while (!v.empty()) {
    const size_t semi = v.find(';');
    std::string item(v.substr(0, semi));
    if (item.find_first_not_of(" \t\r\n") != std::string::npos) values.push_back(item);
    if (semi == std::string_view::npos) break;
    v.remove_prefix(semi + 1);
  }
  if (values.empty()) return false;
  std::vector<double> times;
  std::string_view kt = anim.attribute("keyTimes").value();
  while (!kt.empty()) {
    const size_t semi = kt.find(';');
    if (const auto t = svg::parse_number(kt.substr(0, semi))) times.push_back(*t);
    if (semi == std::string_view::npos) break;
    kt.remove_prefix(semi + 1);
  }
  if (times.size() != values.size()) {
    times.clear();
    for (size_t i = 0; i < values.size(); ++i)
      times.push_back(values.size() > 1 ? static_cast<double>(i) / (values.size() - 1) : 0.0);
  }
  const double seconds = svg::parse_clock_value(anim.attribute("dur").value()).value_or(0);
  if (!(seconds > 0)) return false;
  const std::string_view repeat = anim.attribute("repeatCount").value();
  double f = time / seconds;
  if (repeat == "indefinite") f -= std::floor(f);
  else if (const auto rc = svg::parse_number(repeat); rc && *rc > 0 && f < *rc) f -= std::floor(f);
  else if (f > 1) {
    if (std::string_view(anim.attribute("fill").value()) != "freeze") return false;  // ended
    f = 1;
  }
  size_t i = 0;
  while (i + 1 < times.size() && f >= times[i + 1]) ++i;
  std::vector<Subpath> a, b;
  svg::parse_path_data(values[i], a);
  const bool discrete = std::string_view(anim.attribute("calcMode").value()) == "discrete";
  if (i + 1 >= values.size() || discrete) {
    out = std::move(a);
    return true;
  }
  svg::parse_path_data(values[i + 1], b);
  const double span = times[i + 1] - times[i];
  const double u = svg::spline_fraction(anim, i, span > 0 ? std::clamp((f - times[i]) / span, 0.0, 1.0) : 0.0);
  bool same = a.size() == b.size();
  for (size_t s = 0; same && s < a.size(); ++s) same = a[s].points.size() == b[s].points.size();
  if (same)
    for (size_t s = 0; s < a.size(); ++s)
      for (size_t p = 0; p < a[s].points.size(); ++p)
        a[s].points[p] = (1 - u) * a[s].points[p] + u * b[s].points[p];
  out = std::move(a);
  return true;
}

void Reader::add_shape(pugi::xml_node n, std::vector<Subpath> subpaths, const Style& s,
                       const Affine& ctm, float opacity, const std::string& locator, int group,
                       const std::string& id_prefix, float local_opacity, const Viewport& vp) {
  ++generated_;
  if (subpaths.empty() || !s.visible) return;
  const std::optional<svg::Box> bbox = svg::subpath_bounds(subpaths);
  Path p;
  const char* id = n.attribute("id").value();
  p.id = *id ? std::string(id) : "path-" + std::to_string(generated_);
  if (!id_prefix.empty()) p.id = id_prefix + "/" + p.id;
  p.locator = locator;
  p.tag = std::string(local_name(n.name()));
  p.to_canvas = ctm;
  p.opacity = opacity;
  p.layer = layer_;
  p.local_opacity = local_opacity;
  // A gradient paint: the flat colour is its mean (for the fitter and exports), the render
  // draws the gradient itself; one that paints nothing (no stops, an empty box) is none.
  auto gradient = [&](pugi::xml_node g, float paint_opacity) {
    std::optional<Gradient> r = gradient_reader_.resolve(g, bbox, ctm, vp.w, vp.h, limits_.animation_time);
    if (!r) return -2;
    r->opacity = paint_opacity;
    scene_.gradients.push_back(std::move(*r));
    return static_cast<int>(scene_.gradients.size()) - 1;
  };
  pugi::xml_node fill_g, stroke_g;
  p.has_fill = clip_content_ || resolve_paint(s.fill, s, n, &p.fill, &fill_g);
  if (p.has_fill) p.fill.a *= s.fill_opacity;
  if (p.has_fill && fill_g) p.fill_gradient = gradient(fill_g, s.fill_opacity);
  if (p.fill_gradient == -2) p.has_fill = false, p.fill_gradient = -1;
  p.fill_rule = clip_content_ ? s.clip_rule : s.fill_rule;
  p.has_stroke = !clip_content_ && s.stroke_width > 0 && resolve_paint(s.stroke, s, n, &p.stroke.color, &stroke_g);
  if (p.has_stroke && stroke_g) p.stroke_gradient = gradient(stroke_g, s.stroke_opacity);
  if (p.stroke_gradient == -2) p.has_stroke = false, p.stroke_gradient = -1;
  if (p.has_stroke) {
    p.stroke.color.a *= s.stroke_opacity;
    p.stroke.width = s.stroke_width * ctm.mean_scale();
    p.stroke.join = s.join;
    p.stroke.cap = s.cap;
    p.stroke.miter_limit = s.miter_limit;
    for (const double d : s.dash_array) p.stroke.dashes.push_back(d * ctm.mean_scale());
    p.stroke.dash_offset = s.dash_offset * ctm.mean_scale();
    if (s.dashed) warn(n, "stroke-dasharray not supported (drawn solid)");
  }
  if (!p.has_fill && !p.has_stroke) return;
  for (Subpath& sp : subpaths) {
    for (Vec2& v : sp.points) {
      v = ctm.apply(v);
      // Finite numbers can still make infinite geometry (1e308 - -1e308 overflows, and so may
      // a transform), or numbers no float holds: the renderer would make NaN of them.
      if (!(std::fabs(v.x) <= limits_.max_coordinate && std::fabs(v.y) <= limits_.max_coordinate))
        fail(describe(n) + ": coordinates too large (beyond " + px_text(limits_.max_coordinate) +
             " in canvas space)");
    }
    segments_ += sp.segment_count();
  }
  if (p.has_stroke && !(p.stroke.width <= limits_.max_coordinate))
    fail(describe(n) + ": stroke-width too large (beyond " + px_text(limits_.max_coordinate) +
         " in canvas space)");
  if (segments_ > limits_.max_segments)
    fail("more than " + std::to_string(limits_.max_segments) + " path segments");
  p.subpaths = std::move(subpaths);
  if (sink_) {  // a clip path's or mask's content: not a part of the scene to fit
    sink_->push_back(std::move(p));
    return;
  }
  const int index = static_cast<int>(scene_.paths.size());
  if (group < 0) {
    p.group = static_cast<int>(scene_.groups.size());
    scene_.groups.push_back({p.id, {index}});
  } else {
    p.group = group;
    scene_.groups[group].paths.push_back(index);
  }
  scene_.paths.push_back(std::move(p));
}

}  // namespace svgm::svg
