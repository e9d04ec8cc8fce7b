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
//
// This file holds the document (root, canvas size, ids), the style cascade, lengths, the
// viewBox and the warnings; the walk, shapes, paints and clip/mask references are in the
// svg_reader_*.cpp files beside it (svg_reader_internal.h).
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

#include "svg/css_sheet.h"
#include "svg/svg_number.h"
#include "svg/svg_reader_internal.h"
#include "svg/svg_style.h"
#include "svg/transform_list.h"
#include "svgmotion/error.h"

namespace svgm::svg {

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
  {
    svg::Cursor c{root.attribute(kRoomAttribute).value()};
    const auto room = c.number();
    if (room && !c.out_of_range && *room > 0 && *room <= 0.5) scene_.room = *room;
  }
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

}  // namespace svgm::svg

namespace svgm {

namespace {

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
  return svg::Reader(std::string(name), limits).read(text);
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
