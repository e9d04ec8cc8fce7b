// Reading an SVG document into the scene model (see svgmotion/svg_reader.h).
//
// A recursive walk over pugixml's DOM that carries the computed style, the transform to canvas
// space, the accumulated opacity and the element's locator. Shapes become cubic paths in canvas
// space; <use> instantiates its target in place (with a stack to detect cycles); the root's
// viewBox and preserveAspectRatio map user space to the canvas. Styles cascade from
// presentation attributes, then <style> sheet rules (simple selectors, see css_sheet.h), then
// the style attribute. Unsupported features are counted per kind and reported as one warning
// each at the end, naming the first element. Elements with a foreign namespace prefix
// (sodipodi:, inkscape:, ...) are ignored.
#include "svgmotion/svg_reader.h"
#include "svg/utf8.h"

#include <pugixml.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <set>

#include "svg/css_color.h"
#include "svg/css_sheet.h"
#include "svg/gradient_reader.h"
#include "svg/path_data.h"
#include "svg/svg_number.h"
#include "svg/svg_style.h"
#include "svg/smil_spline.h"
#include "svg/smil_transform.h"
#include "svg/transform_list.h"
#include "svgmotion/error.h"

namespace svgm {

namespace {

using svg::ElementProps;
using svg::Paint;
using svg::PaintKind;
using svg::Style;

std::string_view local_name(const char* name) {
  const char* colon = std::strchr(name, ':');
  return colon ? std::string_view(colon + 1) : std::string_view(name);
}

std::string describe(pugi::xml_node n) {
  std::string s = "<" + std::string(local_name(n.name()));
  if (const char* id = n.attribute("id").value(); *id) s += " id=" + std::string(id);
  return s + ">";
}

// A size or coordinate for a message: whole pixels, or %g beyond 15 digits. Never a cast to an
// integer type, which is undefined behaviour for 1e308.
std::string px_text(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.15g", std::fabs(v) < 1e15 ? std::floor(v) : v);
  return b;
}

struct Viewport {
  double w = 100, h = 100;
};

// Elements walked in one document, copies through <use> included: bounds the work a small
// file of nested uses (each instantiating the previous one twice) can ask for.
constexpr size_t kMaxVisited = 1u << 20;

class Reader {
 public:
  Reader(std::string name, const SvgReadLimits& limits) : name_(std::move(name)), limits_(limits) {}

  Scene read(std::string_view text);

 private:
  [[noreturn]] void fail(const std::string& problem) const { throw Error(name_ + ": " + problem); }

  // Numeric attribute as a length in user units; `fallback` when absent or invalid. Throws on
  // nan/inf/overflow.
  double length(pugi::xml_node n, const char* attr, double fallback, double percent_of) const;
  bool has(pugi::xml_node n, const char* attr) const { return !n.attribute(attr).empty(); }

  void compute_style(pugi::xml_node n, const Style& parent, Style& s, ElementProps& props);
  void walk(pugi::xml_node n, const Style& parent, const Affine& ctm, float opacity,
            const std::string& locator, int group, const std::string& id_prefix, int depth,
            const Viewport& vp);
  void walk_children(pugi::xml_node n, const Style& s, const Affine& ctm, float opacity,
                     const std::string& locator, int group, const std::string& id_prefix,
                     int depth, const Viewport& vp);
  void add_shape(pugi::xml_node n, std::vector<Subpath> subpaths, const Style& s,
                 const Affine& ctm, float opacity, const std::string& locator, int group,
                 const std::string& id_prefix, float local_opacity, const Viewport& vp);
  // Clip paths and masks of an element (scene.h's ClipPath and Mask), for an element whose user
  // space maps to canvas by `ctm` and whose fill bounds there are `bbox`. -1 when the reference
  // is missing or recursive (drawn unclipped or unmasked, with a warning).
  pugi::xml_node enter_reference(const std::string& url, pugi::xml_node el, const char* kind,
                                 const char* property, const char* fallback);
  int resolve_clip(const std::string& url, pugi::xml_node el, const Affine& ctm,
                   const std::optional<svg::Box>& bbox, const Viewport& vp, int depth);
  int resolve_mask(const std::string& url, pugi::xml_node el, const Affine& ctm,
                   const std::optional<svg::Box>& bbox, const Viewport& vp, int depth);
  // Walks the children of a <clipPath> or <mask> into `sink` instead of the scene's paths.
  void walk_content(pugi::xml_node n, const Style& s, const Affine& ctm, bool clip,
                    std::vector<Path>* sink, int depth, const Viewport& vp);
  // The bounds, in the user space of `ctm`, of the paths added to the current output from index
  // `first` on (a container's bounding box).
  std::optional<svg::Box> added_bounds(size_t first, const Affine& ctm) const;
  std::vector<Subpath> shape_geometry(pugi::xml_node n, std::string_view tag, const Viewport& vp);
  bool animated_path(pugi::xml_node n, double time, std::vector<Subpath>& out);
  // A paint's flat colour; `gradient` is set to the gradient element of a gradient paint.
  bool resolve_paint(const Paint& p, const Style& s, pugi::xml_node el, Rgba* out,
                     pugi::xml_node* gradient);
  std::optional<Rgba> gradient_mean(pugi::xml_node g, int depth);
  Affine viewbox_transform(pugi::xml_node n, double w, double h, Viewport* inner);
  // Unsupported features: one warning line per kind, naming the first element and counting
  // the others, in order of first occurrence.
  void warn(pugi::xml_node n, const std::string& what) { note(what, describe(n), false); }
  void warn_skipped(std::string_view tag, const char* reason) {
    note("<" + std::string(tag) + "> " + reason, {}, true);
  }
  void note(const std::string& key, std::string first, bool skipped);
  std::vector<std::string> warning_lines() const;
  void collect_styles(pugi::xml_node root);
  // False for elements with a namespace prefix other than the root's (editor extensions).
  bool in_svg_namespace(pugi::xml_node n) const {
    const char* colon = std::strchr(n.name(), ':');
    if (!colon) return true;
    const std::string_view prefix(n.name(), static_cast<size_t>(colon - n.name()));
    return prefix == root_prefix_ || prefix == "svg";
  }

  std::string name_;
  SvgReadLimits limits_;
  Scene scene_;
  std::map<std::string, pugi::xml_node> ids_;
  std::map<std::string, int> data_groups_;  // data-group of top-level <g> runs -> group
  std::set<const void*> use_stack_;
  struct WarningKind {
    std::string key, first;
    int count = 0;
    bool skipped = false;
  };
  std::vector<WarningKind> warnings_;
  svg::StyleSheet sheet_;
  svg::GradientReader gradient_reader_{ids_, sheet_};
  // Where shapes go: the scene's paths, or a clip path's or mask's content while one is read.
  std::vector<Path>* sink_ = nullptr;
  bool clip_content_ = false;  // inside a <clipPath>: geometry only, clip-rule for fill-rule
  int layer_ = -1;             // the innermost compositing layer being read (Scene::layers)
  std::set<const void*> reference_stack_;  // clipPath and mask elements being resolved
  std::string root_prefix_;
  std::vector<const svg::CssDeclaration*> matched_;
  int generated_ = 0;
  int anonymous_uses_ = 0;
  size_t segments_ = 0;
  size_t visited_ = 0;  // elements walked, <use> instances included (bounds "use bombs")
};

void Reader::note(const std::string& key, std::string first, bool skipped) {
  for (WarningKind& w : warnings_)
    if (w.key == key) {
      ++w.count;
      return;
    }
  warnings_.push_back({key, std::move(first), 1, skipped});
}

std::vector<std::string> Reader::warning_lines() const {
  std::vector<std::string> out;
  for (const WarningKind& w : warnings_) {
    if (w.skipped) {
      // key: "<text> elements skipped (text is not supported)" minus the count and plural.
      const size_t sp = w.key.find(' ');
      out.push_back(name_ + ": " + std::to_string(w.count) + " " + w.key.substr(0, sp) +
                    (w.count == 1 ? " element" : " elements") + w.key.substr(sp));
    } else if (w.count == 1) {
      out.push_back(name_ + ": " + w.first + ": " + w.key);
    } else {
      out.push_back(name_ + ": " + w.first + " and " + std::to_string(w.count - 1) + " more element" +
                    (w.count == 2 ? "" : "s") + ": " + w.key);
    }
  }
  return out;
}

// Rules of every <style> element (type text/css or none), wherever it is in the document.
void Reader::collect_styles(pugi::xml_node root) {
  int skipped = 0;
  pugi::xml_node first;
  for (pugi::xml_node n = root; n;) {
    if (n.type() == pugi::node_element && local_name(n.name()) == "style") {
      const std::string_view type = n.attribute("type").value();
      if (type.empty() || type == "text/css") {
        std::string css;
        for (pugi::xml_node c = n.first_child(); c; c = c.next_sibling())
          if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) css += c.value();
        skipped += sheet_.add(css);
        if (!first) first = n;
      }
    }
    // Pre-order traversal without recursion.
    if (pugi::xml_node c = n.first_child()) {
      n = c;
      continue;
    }
    while (n && n != root && !n.next_sibling()) n = n.parent();
    if (!n || n == root) break;
    n = n.next_sibling();
  }
  if (skipped > 0)
    note(std::to_string(skipped) + (skipped == 1 ? " CSS rule" : " CSS rules") +
             " ignored (only tag, .class and #id selectors are supported)",
         describe(first), false);
}

double Reader::length(pugi::xml_node n, const char* attr, double fallback, double percent_of) const {
  const pugi::xml_attribute a = n.attribute(attr);
  if (a.empty()) return fallback;
  std::string_view v = a.value();
  if (svg::spells_non_finite(v))
    fail(describe(n) + " " + attr + "=\"" + std::string(v) + "\": number out of range");
  svg::Cursor c{v};
  c.skip_ws();
  const auto x = c.number();
  if (c.out_of_range) fail(describe(n) + " " + attr + "=\"" + std::string(v) + "\": number out of range");
  if (!x) return fallback;
  std::string unit(v.substr(c.pos));
  while (!unit.empty() && std::isspace(static_cast<unsigned char>(unit.back()))) unit.pop_back();
  double scale = 1;
  if (unit.empty() || unit == "px") scale = 1;
  else if (unit == "%") scale = percent_of / 100;
  else if (unit == "pt") scale = 4.0 / 3.0;
  else if (unit == "pc") scale = 16;
  else if (unit == "mm") scale = 96 / 25.4;
  else if (unit == "cm") scale = 96 / 2.54;
  else if (unit == "in") scale = 96;
  else if (unit == "em") scale = 16;
  else if (unit == "ex") scale = 8;
  else return fallback;
  // 1e308in is a finite number but not a finite length: refused like an overflow.
  if (!std::isfinite(*x * scale))
    fail(describe(n) + " " + attr + "=\"" + std::string(v) + "\": number out of range");
  return *x * scale;
}

void Reader::compute_style(pugi::xml_node n, const Style& parent, Style& s, ElementProps& props) {
  s = parent;
  s.dashed = parent.dashed;
  auto apply = [&](std::string_view name, std::string_view value) {
    if (!svg::apply_declaration(name, value, parent, s, props))
      fail(describe(n) + " " + std::string(name) + "=\"" + std::string(value) + "\": number out of range");
  };
  // `color` first so that currentColor in this element's own fill/stroke sees it.
  if (const char* c = n.attribute("color").value(); *c) apply("color", c);
  for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute())
    if (std::strcmp(a.name(), "style") != 0 && std::strcmp(a.name(), "color") != 0) apply(a.name(), a.value());
  // Cascade: presentation attributes, then <style> sheet rules, then the style attribute.
  if (!sheet_.empty()) {
    sheet_.match(local_name(n.name()), n.attribute("id").value(), n.attribute("class").value(), matched_);
    for (const svg::CssDeclaration* d : matched_) apply(d->name, d->value);
  }
  if (const char* st = n.attribute("style").value(); *st)
    for (const svg::CssDeclaration& d : svg::parse_declarations(st)) apply(d.name, d.value);
}

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

Affine Reader::viewbox_transform(pugi::xml_node n, double w, double h, Viewport* inner) {
  inner->w = w;
  inner->h = h;
  const char* vb = n.attribute("viewBox").value();
  if (!*vb) return {};
  svg::Cursor c{vb};
  double v[4];
  for (double& x : v) {
    c.skip_comma_ws();
    const auto num = c.number();
    if (c.out_of_range) fail(describe(n) + " viewBox: number out of range");
    if (!num) return {};
    x = *num;
  }
  if (v[2] <= 0 || v[3] <= 0) return {};
  inner->w = v[2];
  inner->h = v[3];
  // preserveAspectRatio: ["defer"] <align> ["meet" | "slice"]; anything unknown is the default.
  std::string_view par = n.attribute("preserveAspectRatio").value();
  auto word = [&par]() {
    while (!par.empty() && std::isspace(static_cast<unsigned char>(par.front()))) par.remove_prefix(1);
    size_t k = 0;
    while (k < par.size() && !std::isspace(static_cast<unsigned char>(par[k]))) ++k;
    const std::string_view w = par.substr(0, k);
    par.remove_prefix(k);
    return w;
  };
  std::string_view align = word(), mode = "meet";
  if (align == "defer") align = word();
  if (const std::string_view m = word(); !m.empty()) mode = m;
  static constexpr std::string_view kAligns[] = {"none", "xMinYMin", "xMidYMin", "xMaxYMin",
                                                 "xMinYMid", "xMidYMid", "xMaxYMid",
                                                 "xMinYMax", "xMidYMax", "xMaxYMax"};
  if (std::find(std::begin(kAligns), std::end(kAligns), align) == std::end(kAligns)) align = "xMidYMid";
  double sx = w / v[2], sy = h / v[3];
  if (align == "none") return Affine::scale(sx, sy) * Affine::translate(-v[0], -v[1]);
  const double s = mode == "slice" ? std::max(sx, sy) : std::min(sx, sy);
  double tx = -v[0] * s, ty = -v[1] * s;
  const double ex = w - v[2] * s, ey = h - v[3] * s;
  if (align.substr(0, 4) == "xMid") tx += ex / 2;
  else if (align.substr(0, 4) == "xMax") tx += ex;
  if (align.substr(4) == "YMid") ty += ey / 2;
  else if (align.substr(4) == "YMax") ty += ey;
  return Affine{s, 0, 0, s, tx, ty};
}

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

std::optional<svg::Box> Reader::added_bounds(size_t first, const Affine& ctm) const {
  const std::vector<Path>& paths = sink_ ? *sink_ : scene_.paths;
  const Affine to_user = ctm.inverse();
  std::optional<svg::Box> out;
  for (size_t i = first; i < paths.size(); ++i) {
    const auto b = svg::subpath_bounds(paths[i].subpaths, to_user);
    if (!b) continue;
    if (!out) {
      out = b;
      continue;
    }
    const double x0 = std::min(out->x, b->x), y0 = std::min(out->y, b->y);
    const double x1 = std::max(out->x + out->w, b->x + b->w), y1 = std::max(out->y + out->h, b->y + b->h);
    out = svg::Box{x0, y0, x1 - x0, y1 - y0};
  }
  return out;
}

void Reader::walk_content(pugi::xml_node n, const Style& s, const Affine& ctm, bool clip,
                          std::vector<Path>* sink, int depth, const Viewport& vp) {
  // Content paths get no ids of their own: the generated ids of the scene's paths stay what
  // they were without it.
  const int generated = generated_, uses = anonymous_uses_;
  std::vector<Path>* outer_sink = sink_;
  const bool outer_clip = clip_content_;
  const int outer_layer = layer_;
  sink_ = sink;
  clip_content_ = clip;
  layer_ = -1;
  walk_children(n, s, ctm, 1.0f, "", -1, "content", depth + 1, vp);
  sink_ = outer_sink;
  clip_content_ = outer_clip;
  layer_ = outer_layer;
  generated_ = generated;
  anonymous_uses_ = uses;
}

// The `kind` element that `url` names, now on the reference stack (the caller erases it), or a
// null node after one warning when there is none or it is already being resolved (a cycle).
pugi::xml_node Reader::enter_reference(const std::string& url, pugi::xml_node el, const char* kind,
                                       const char* property, const char* fallback) {
  const auto it = ids_.find(url);
  const std::string what = std::string(property) + " url(#" + url + ")";
  if (it == ids_.end() || local_name(it->second.name()) != kind) {
    warn(el, what + " is not a " + kind + " (" + fallback + ")");
    return {};
  }
  if (!reference_stack_.insert(it->second.internal_object()).second) {
    warn(el, what + " refers to itself (" + fallback + ")");
    return {};
  }
  return it->second;
}

int Reader::resolve_clip(const std::string& url, pugi::xml_node el, const Affine& ctm,
                         const std::optional<svg::Box>& bbox, const Viewport& vp, int depth) {
  const pugi::xml_node node = enter_reference(url, el, "clipPath", "clip-path", "drawn unclipped");
  if (!node) return -1;
  Style cs;
  ElementProps cp;
  compute_style(node, Style{}, cs, cp);
  Affine m = ctm;
  if (const char* t = node.attribute("transform").value(); *t)
    if (const auto tm = svg::parse_transform(t)) m = m * *tm;
  const int index = static_cast<int>(scene_.clips.size());
  scene_.clips.emplace_back();
  const bool bbox_units = std::string_view(node.attribute("clipPathUnits").value()) == "objectBoundingBox";
  // Bounding box units on an empty box clip everything away (the element is not drawn).
  if (!bbox_units || (bbox && bbox->w > 0 && bbox->h > 0)) {
    if (bbox_units) m = m * Affine{bbox->w, 0, 0, bbox->h, bbox->x, bbox->y};
    std::vector<Path> paths;
    if (std::fabs(m.det()) > 0 && std::isfinite(m.det())) walk_content(node, cs, m, true, &paths, depth, vp);
    scene_.clips[index].paths = std::move(paths);
  }
  if (cp.has_clip && !cp.clip_url.empty()) {
    const int nested = resolve_clip(cp.clip_url, node, ctm, bbox, vp, depth);
    scene_.clips[index].clip = nested;
  }
  reference_stack_.erase(node.internal_object());
  return index;
}

int Reader::resolve_mask(const std::string& url, pugi::xml_node el, const Affine& ctm,
                         const std::optional<svg::Box>& bbox, const Viewport& vp, int depth) {
  const pugi::xml_node node = enter_reference(url, el, "mask", "mask", "drawn unmasked");
  if (!node) return -1;
  Style ms;
  ElementProps mp;
  compute_style(node, Style{}, ms, mp);
  const int index = static_cast<int>(scene_.masks.size());
  scene_.masks.emplace_back();
  scene_.masks[index].luminance = mp.mask_type != "alpha";
  const bool box_ok = bbox && bbox->w > 0 && bbox->h > 0;
  const bool region_bbox = std::string_view(node.attribute("maskUnits").value()) != "userSpaceOnUse";
  const bool content_bbox = std::string_view(node.attribute("maskContentUnits").value()) == "objectBoundingBox";
  // The region: x, y, width, height (default -10%, -10%, 120%, 120%) in bounding box fractions
  // or user units; with bounding box units on an empty box the region is empty (nothing drawn).
  if (!region_bbox || box_ok) {
    double x, y, w, h;
    Affine to_user;
    if (region_bbox) {
      x = length(node, "x", -0.1, 1), y = length(node, "y", -0.1, 1);
      w = length(node, "width", 1.2, 1), h = length(node, "height", 1.2, 1);
      to_user = Affine{bbox->w, 0, 0, bbox->h, bbox->x, bbox->y};
    } else {
      x = length(node, "x", -0.1 * vp.w, vp.w), y = length(node, "y", -0.1 * vp.h, vp.h);
      w = length(node, "width", 1.2 * vp.w, vp.w), h = length(node, "height", 1.2 * vp.h, vp.h);
    }
    if (w > 0 && h > 0) {
      const Affine m = ctm * to_user;
      Subpath r;
      r.closed = true;
      const Vec2 corners[] = {{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}, {x, y}};
      r.points.push_back(m.apply(corners[0]));
      for (int i = 1; i < 5; ++i) {
        const Vec2 a = m.apply(corners[i - 1]), b = m.apply(corners[i]);
        r.points.insert(r.points.end(), {a + (1.0 / 3.0) * (b - a), a + (2.0 / 3.0) * (b - a), b});
      }
      scene_.masks[index].region.push_back(std::move(r));
    }
  }
  if (!content_bbox || box_ok) {
    Affine m = ctm;
    if (content_bbox) m = m * Affine{bbox->w, 0, 0, bbox->h, bbox->x, bbox->y};
    std::vector<Path> paths;
    walk_content(node, ms, m, false, &paths, depth, vp);
    scene_.masks[index].paths = std::move(paths);
  }
  if (mp.has_mask && !mp.mask_url.empty()) {
    const int nested = resolve_mask(mp.mask_url, node, ctm, bbox, vp, depth);
    scene_.masks[index].mask = nested;
  }
  reference_stack_.erase(node.internal_object());
  return index;
}

void Reader::walk_children(pugi::xml_node n, const Style& s, const Affine& ctm, float opacity,
                           const std::string& locator, int group, const std::string& id_prefix,
                           int depth, const Viewport& vp) {
  std::map<std::string, int> seen;
  const bool is_switch = local_name(n.name()) == "switch";
  for (pugi::xml_node c = n.first_child(); c; c = c.next_sibling()) {
    if (c.type() != pugi::node_element) continue;
    const std::string tag(local_name(c.name()));
    const int index = ++seen[tag];  // locators count names without prefix (as smil_writer does)
    if (!in_svg_namespace(c)) continue;  // sodipodi:*, inkscape:*, i:pgf ...
    // Inside a <use> copy (id_prefix set) every shape keeps the use element's locator.
    const std::string loc = !id_prefix.empty() ? locator : locator + "/" + tag + "[" + std::to_string(index) + "]";
    walk(c, s, ctm, opacity, loc, group, id_prefix, depth + 1, vp);
    if (is_switch) break;  // a switch renders its first child (no conditional attributes here)
  }
}

void Reader::walk(pugi::xml_node n, const Style& parent, const Affine& parent_ctm, float opacity,
                  const std::string& locator, int group, const std::string& id_prefix, int depth,
                  const Viewport& vp) {
  if (depth > limits_.max_depth) fail("nesting deeper than " + std::to_string(limits_.max_depth) + " elements");
  if (++visited_ > kMaxVisited)
    fail("more than " + std::to_string(kMaxVisited) + " elements to draw (nested <use> copies)");
  const std::string_view tag = local_name(n.name());
  static const std::set<std::string_view> kShapes = {"path", "rect", "circle", "ellipse", "line",
                                                     "polyline", "polygon"};
  static const std::set<std::string_view> kContainers = {"g", "a", "switch"};
  const bool shape = kShapes.count(tag) != 0;
  if (!shape && !kContainers.count(tag) && tag != "use" && tag != "svg") {
    if (tag == "text") warn_skipped(tag, "skipped (text is not supported)");
    else if (tag == "image") warn_skipped(tag, "skipped (images are not supported)");
    else if (tag == "foreignObject") warn_skipped(tag, "skipped (foreignObject is not supported)");
    else if (tag == "video" || tag == "audio" || tag == "canvas" || tag == "iframe")
      warn_skipped(tag, "skipped (not supported)");
    return;  // defs, symbol (only through use), title, metadata, editor elements ...
  }
  Style s;
  ElementProps props;
  compute_style(n, parent, s, props);
  if (props.display_none) return;
  if (clip_content_ && (props.has_clip || props.has_mask))
    warn(n, "clip-path or mask inside a clipPath ignored");
  if (!clip_content_ && props.has_clip && props.clip_url.empty())
    warn(n, "clip-path ignored (only url(#id) references are supported)");
  if (!clip_content_ && props.has_mask && props.mask_url.empty())
    warn(n, "mask ignored (only url(#id) references are supported)");
  if (props.has_filter) warn(n, "filter ignored (filters are not supported)");
  if (props.has_marker) warn(n, "markers ignored (markers are not supported)");
  Affine own;
  if (const char* t = n.attribute("transform").value(); *t) {
    bool bad = false;
    const auto m = svg::parse_transform(t, &bad);
    if (bad) fail(describe(n) + " transform: number out of range");
    if (m) own = *m;
    else warn(n, "invalid transform ignored");  // as resvg and browsers do
  }
  if (limits_.animation_time >= 0) own = svg::animated_transform(n, limits_.animation_time, own);
  Affine ctm = parent_ctm * own;
  // A singular transform (e.g. scale(0)) draws nothing, and has no inverse for exporters. One
  // whose determinant overflows (scale(1e200)) puts everything beyond max_coordinate: refused
  // like the coordinates it makes, not silently dropped.
  if (const double det = ctm.det(); !std::isfinite(det))
    fail(describe(n) + ": scale to canvas space too large (its transforms and the viewBox overflow)");
  else if (!(std::fabs(det) > 0))
    return;
  const float op = opacity * props.opacity;

  // A compositing layer (scene.h) for group opacity, clip-path and mask. A shape's opacity is
  // folded into its paint when it has a fill or a stroke but not both (one draw, one blend).
  const bool both_paints = s.fill.kind != PaintKind::None && s.stroke.kind != PaintKind::None && s.stroke_width > 0;
  const bool clipped = !clip_content_ && !props.clip_url.empty();
  const bool masked = !clip_content_ && !props.mask_url.empty();
  const bool layered = !clip_content_ && (clipped || masked || (props.opacity < 1 && (!shape || both_paints)));
  const int saved_layer = layer_;
  // Every way out of this element (early returns included) leaves the layer it entered in.
  struct LayerRestore {
    int& layer;
    int saved;
    ~LayerRestore() { layer = saved; }
  } restore{layer_, layer_};
  int own_layer = -1;
  if (layered) {
    own_layer = static_cast<int>(scene_.layers.size());
    scene_.layers.push_back({layer_, props.opacity, -1, -1});
    layer_ = own_layer;
  }
  const size_t first_added = sink_ ? sink_->size() : scene_.paths.size();
  // Clip and mask are resolved once the content is read, for its bounding box.
  auto finish_layer = [&](const std::optional<svg::Box>& bbox) {
    layer_ = saved_layer;
    if (own_layer < 0) return;
    if (clipped) {
      const int c = resolve_clip(props.clip_url, n, ctm, bbox, vp, depth);
      scene_.layers[own_layer].clip = c;
    }
    if (masked) {
      const int m = resolve_mask(props.mask_url, n, ctm, bbox, vp, depth);
      scene_.layers[own_layer].mask = m;
    }
  };

  if (shape) {
    std::vector<Subpath> geometry = shape_geometry(n, tag, vp);
    const std::optional<svg::Box> bbox = svg::subpath_bounds(geometry);
    add_shape(n, std::move(geometry), s, ctm, op, locator, group, id_prefix, layered ? 1.0f : props.opacity, vp);
    finish_layer(bbox);
    return;
  }
  if (clip_content_ && tag != "use") return;  // a clipPath holds shapes and uses of shapes
  if (tag == "use") {
    const char* href = n.attribute("xlink:href").value();
    if (!*href) href = n.attribute("href").value();
    if (*href != '#') {
      if (*href) warn(n, "external references are not supported (skipped)");
      return;
    }
    const auto it = ids_.find(href + 1);
    if (it == ids_.end()) {
      warn(n, "reference to a missing element skipped");
      return;
    }
    const pugi::xml_node target = it->second;
    if (use_stack_.count(target.internal_object()) || use_stack_.count(n.internal_object()))
      fail(describe(n) + " references itself (use cycle)");
    for (pugi::xml_node up = n.parent(); up; up = up.parent())
      if (up == target) fail(describe(n) + " references itself (use cycle)");
    use_stack_.insert(n.internal_object());
    use_stack_.insert(target.internal_object());
    ctm = ctm * Affine::translate(length(n, "x", 0, vp.w), length(n, "y", 0, vp.h));
    // Ids of shapes drawn through a use: "<use id>/<shape id>", nested uses chained; a use
    // without an id is "use-N" (N counts such uses in drawing order).
    const char* uid = n.attribute("id").value();
    const std::string own = *uid ? std::string(uid) : "use-" + std::to_string(++anonymous_uses_);
    const std::string prefix = id_prefix.empty() ? own : id_prefix + "/" + own;
    const int g = group < 0 && depth == 1 ? -2 : group;  // top-level use: one group of its own
    int use_group = g;
    if (g == -2) {
      use_group = static_cast<int>(scene_.groups.size());
      scene_.groups.push_back({prefix, {}});
    }
    if (local_name(target.name()) == "symbol") {
      Viewport inner;
      const double w = length(n, "width", vp.w, vp.w), h = length(n, "height", vp.h, vp.h);
      const Affine vb = viewbox_transform(target, w, h, &inner);
      Style ts;
      ElementProps tp;
      compute_style(target, s, ts, tp);
      if (!tp.display_none && w > 0 && h > 0) {
        const int outer = layer_;
        if (tp.opacity < 1 && !clip_content_) {
          scene_.layers.push_back({layer_, tp.opacity, -1, -1});
          layer_ = static_cast<int>(scene_.layers.size()) - 1;
        }
        walk_children(target, ts, ctm * vb, op * tp.opacity, locator, use_group, prefix, depth + 1, inner);
        layer_ = outer;
      }
    } else {
      walk(target, s, ctm, op, locator, use_group, prefix, depth + 1, vp);
    }
    if (g == -2 && scene_.groups[use_group].paths.empty()) scene_.groups.pop_back();
    use_stack_.erase(n.internal_object());
    use_stack_.erase(target.internal_object());
    finish_layer(added_bounds(first_added, ctm));
    return;
  }
  Viewport inner = vp;
  if (tag == "svg" && depth > 0) {  // nested viewport
    const double w = length(n, "width", vp.w, vp.w), h = length(n, "height", vp.h, vp.h);
    if (!(w > 0) || !(h > 0)) return;
    ctm = ctm * Affine::translate(length(n, "x", 0, vp.w), length(n, "y", 0, vp.h)) *
          viewbox_transform(n, w, h, &inner);
    warn(n, "nested <svg> drawn without clipping to its viewport");
  }
  int g = group;
  bool new_group = false;
  if (tag == "g" && depth == 1) {  // a top-level group is a part that moves together
    // Runs of one part split by paint order (grouped_svg.h) share a data-group: join them.
    const char* part = n.attribute("data-group").value();
    const auto joined = *part ? data_groups_.find(part) : data_groups_.end();
    if (joined != data_groups_.end()) {
      g = joined->second;
    } else {
      g = static_cast<int>(scene_.groups.size());
      const char* id = n.attribute("id").value();
      scene_.groups.push_back({*part ? part : *id ? id : "group-" + std::to_string(g + 1), {}, n.attribute("data-name").value()});
      if (*part) data_groups_[part] = g;
      new_group = true;
    }
  }
  walk_children(n, s, ctm, op, locator, g, id_prefix, depth, inner);
  finish_layer(added_bounds(first_added, ctm));
  if (new_group && scene_.groups[g].paths.empty()) {
    scene_.groups.pop_back();
    for (auto it = data_groups_.begin(); it != data_groups_.end();)
      it = it->second == g ? data_groups_.erase(it) : std::next(it);
  }
}

Scene Reader::read(std::string_view text) {
  pugi::xml_document doc;
  const pugi::xml_parse_result r = doc.load_buffer(text.data(), text.size(), pugi::parse_default);
  if (!r)
    fail("not well-formed XML at offset " + std::to_string(r.offset) + ": " + r.description());
  pugi::xml_node root = doc.document_element();
  if (!root || local_name(root.name()) != "svg")
    fail("root element is <" + std::string(root ? local_name(root.name()) : "nothing") + ">, not <svg>");
  if (const char* colon = std::strchr(root.name(), ':')) root_prefix_.assign(root.name(), colon);
  // Ids, for use, gradients and patterns; collected iteratively (depth may be large).
  std::vector<pugi::xml_node> stack{root};
  while (!stack.empty()) {
    pugi::xml_node n = stack.back();
    stack.pop_back();
    if (const char* id = n.attribute("id").value(); *id) {
      // Ids travel into JSON (palettes, groups, layers): they must be text.
      if (!valid_utf8(id)) fail("<" + std::string(local_name(n.name())) + "> has an id that is not valid UTF-8 text");
      ids_.emplace(id, n);
    }
    for (pugi::xml_node c = n.last_child(); c; c = c.previous_sibling())
      if (c.type() == pugi::node_element) stack.push_back(c);
  }
  // Canvas size: width/height (default 100% of the viewBox size), viewBox mapped into it.
  double vbw = 0, vbh = 0;
  {
    svg::Cursor c{root.attribute("viewBox").value()};
    double v[4];
    bool ok = true;
    for (double& x : v) {
      c.skip_comma_ws();
      const auto num = c.number();
      if (c.out_of_range) fail("<svg> viewBox: number out of range");
      if (!num) { ok = false; break; }
      x = *num;
    }
    if (ok && v[2] > 0 && v[3] > 0) { vbw = v[2]; vbh = v[3]; }
  }
  auto side = [&](const char* attr, double vb) {
    const double fallback = vb > 0 ? vb : 100;
    const char* v = root.attribute(attr).value();
    if (*v && std::strchr(v, '%')) return fallback * length(root, attr, 100, 100) / 100;
    return length(root, attr, fallback, fallback);
  };
  const double w = side("width", vbw), h = side("height", vbh);
  if (w > limits_.max_canvas_px || h > limits_.max_canvas_px)
    fail("size " + px_text(w) + "x" + px_text(h) + " is too large (limit " +
         px_text(limits_.max_canvas_px) + " px)");
  if (!(w > 0) || !(h > 0)) fail("width and height must be positive");
  scene_.width = w;
  scene_.height = h;
  Viewport vp;
  const Affine view = viewbox_transform(root, w, h, &vp);
  collect_styles(root);
  Style base;
  ElementProps props;
  compute_style(root, base, base, props);
  if (props.display_none) return std::move(scene_);
  Affine ctm = view;
  if (const char* t = root.attribute("transform").value(); *t) {
    bool bad = false;
    const auto m = svg::parse_transform(t, &bad);
    if (bad) fail("<svg> transform: number out of range");
    if (m) ctm = ctm * *m;
    if (const double det = ctm.det(); !std::isfinite(det))
      fail("<svg>: scale to canvas space too large (its transform and viewBox overflow)");
    else if (!(std::fabs(det) > 0))
      return std::move(scene_);
  }
  if (props.opacity < 1) {
    scene_.layers.push_back({-1, props.opacity, -1, -1});
    layer_ = 0;
  }
  walk_children(root, base, ctm, props.opacity, "/svg", -1, "", 0, vp);
  if (!props.clip_url.empty() || !props.mask_url.empty())
    warn(root, "clip-path and mask on the root <svg> ignored");
  for (std::string& line : warning_lines()) scene_.warnings.push_back(std::move(line));
  return std::move(scene_);
}

// A byte count for messages: "100.0 MB", "12.5 KB", "900 bytes"; `whole` drops a ".0".
std::string byte_size(size_t n, bool whole) {
  const double kib = 1024.0, mib = kib * 1024;
  char buf[64];
  if (n < 1024) {
    std::snprintf(buf, sizeof buf, "%zu bytes", n);
  } else {
    const bool mb = n >= (1u << 20);
    const double v = n / (mb ? mib : kib);
    std::snprintf(buf, sizeof buf, whole && v == std::floor(v) ? "%.0f %s" : "%.1f %s", v, mb ? "MB" : "KB");
  }
  return buf;
}

[[noreturn]] void too_big(const std::string& name, size_t size, size_t limit) {
  throw Error(name + ": file is " + byte_size(size, false) + ", larger than the " +
              byte_size(limit, true) + " limit");
}

}  // namespace

Scene read_svg_string(std::string_view text, std::string_view name, const SvgReadLimits& limits) {
  if (text.size() > limits.max_file_bytes) too_big(std::string(name), text.size(), limits.max_file_bytes);
  return Reader(std::string(name), limits).read(text);
}

Scene read_svg_file(const std::filesystem::path& file, const SvgReadLimits& limits) {
  const std::string name = file.string();
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) throw Error(name + ": is a folder, not an SVG file");
  const auto size = std::filesystem::file_size(file, ec);
  if (ec) throw Error(name + ": cannot open: " + (ec == std::errc::no_such_file_or_directory ? std::string("No such file or directory") : ec.message()));
  if (size > limits.max_file_bytes) too_big(name, size, limits.max_file_bytes);
  std::ifstream f(file, std::ios::binary);
  if (!f) throw Error(name + ": cannot open: " + std::strerror(errno));
  std::string text(size, '\0');
  f.read(text.data(), static_cast<std::streamsize>(size));
  if (!f) throw Error(name + ": cannot read: " + std::strerror(errno));
  return read_svg_string(text, name, limits);
}

}  // namespace svgm
