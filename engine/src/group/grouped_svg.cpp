// The flat grouped SVG writer (see grouped_svg.h).
#include "group/grouped_svg.h"
#include "svgmotion/atomic_file.h"

#include <pugixml.hpp>

#include <sstream>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "svg/svg_number.h"
#include "svgmotion/error.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

// v rounded to 1/scale (1e-5 by default): compact, and far below a pixel.
void append_number(std::string& s, double v, double scale = 1e5) { svg::append_rounded(s, v, scale); }

std::string number(double v) {
  std::string s;
  append_number(s, v);
  return s;
}

std::string path_d(const Path& path) {
  std::string d;
  for (const Subpath& sp : path.subpaths) {
    if (sp.points.empty()) continue;
    for (size_t i = 0; i < sp.points.size(); ++i) {
      if (i == 0) d += d.empty() ? "M" : " M";
      else if (i % 3 == 1) d += " C";
      d += ' ';
      append_number(d, sp.points[i].x);
      d += ' ';
      append_number(d, sp.points[i].y);
    }
    if (sp.closed) d += " Z";
  }
  return d;
}

// #rrggbb when the colour is exactly 8-bit, else rgb() with percentages.
std::string colour(const Rgba& c) {
  const float ch[3] = {c.r, c.g, c.b};
  bool exact = true;
  for (float v : ch) exact = exact && std::fabs(v * 255.0 - std::round(v * 255.0)) < 1e-4;
  if (exact) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", static_cast<int>(std::lround(c.r * 255.0)),
                  static_cast<int>(std::lround(c.g * 255.0)), static_cast<int>(std::lround(c.b * 255.0)));
    return buf;
  }
  std::string s = "rgb(";
  for (int i = 0; i < 3; ++i) {
    if (i) s += ',';
    append_number(s, std::clamp(static_cast<double>(ch[i]), 0.0, 1.0) * 100.0, 1e4);
    s += '%';
  }
  return s + ")";
}

const char* join_name(LineJoin j) {
  switch (j) {
    case LineJoin::Miter: return "miter";
    case LineJoin::MiterClip: return "miter-clip";
    case LineJoin::Round: return "round";
    case LineJoin::Bevel: return "bevel";
  }
  return "miter";
}

const char* cap_name(LineCap c) {
  switch (c) {
    case LineCap::Butt: return "butt";
    case LineCap::Round: return "round";
    case LineCap::Square: return "square";
  }
  return "butt";
}

std::string paint_style(const Path& p) {
  std::string s;
  if (p.has_fill) {
    s += "fill:" + colour(p.fill) + ";fill-opacity:" + number(p.fill.a);
  } else {
    s += "fill:none";
  }
  s += std::string(";fill-rule:") + (p.fill_rule == FillRule::EvenOdd ? "evenodd" : "nonzero");
  if (p.has_stroke) {
    s += ";stroke:" + colour(p.stroke.color) + ";stroke-opacity:" + number(p.stroke.color.a) +
         ";stroke-width:" + number(p.stroke.width) + ";stroke-linejoin:" + join_name(p.stroke.join) +
         ";stroke-linecap:" + cap_name(p.stroke.cap) +
         ";stroke-miterlimit:" + number(p.stroke.miter_limit);
  } else {
    s += ";stroke:none";
  }
  if (p.opacity != 1) s += ";opacity:" + number(p.opacity);
  return s;
}

std::string_view local_name(const char* name) {
  const char* colon = std::strchr(name, ':');
  return colon ? std::string_view(colon + 1) : std::string_view(name);
}

// The suffix of a group's run (0-based): "", "-b", ..., "-z", then "-27", "-28", ...
std::string run_suffix(int run) {
  if (run == 0) return "";
  if (run < 26) return std::string("-") + static_cast<char>('a' + run);
  return "-" + std::to_string(run + 1);
}

}  // namespace

void write_grouped_svg(const fs::path& source, const Scene& scene,
                       const std::vector<std::vector<int>>& groups, const fs::path& out,
                       const std::vector<std::string>& names) {
  const size_t n = scene.paths.size();
  std::vector<int> group_of(n, -1);
  for (size_t k = 0; k < groups.size(); ++k)
    for (int i : groups[k]) {
      if (i < 0 || static_cast<size_t>(i) >= n || group_of[static_cast<size_t>(i)] >= 0)
        throw Error(out.string() + ": internal: groups do not partition the scene's paths");
      group_of[static_cast<size_t>(i)] = static_cast<int>(k);
    }
  for (int g : group_of)
    if (g < 0) throw Error(out.string() + ": internal: groups do not partition the scene's paths");

  pugi::xml_document doc;
  pugi::xml_node root = doc.append_child("svg");
  root.append_attribute("xmlns") = "http://www.w3.org/2000/svg";
  root.append_attribute("xmlns:xlink") = "http://www.w3.org/1999/xlink";
  root.append_attribute("width") = number(scene.width).c_str();
  root.append_attribute("height") = number(scene.height).c_str();
  root.append_attribute("viewBox") =
      ("0 0 " + number(scene.width) + " " + number(scene.height)).c_str();
  // The room the drawing was given is kept for the stages after (Scene::room: its backdrops).
  if (scene.room > 0) root.append_attribute(kRoomAttribute) = number(scene.room).c_str();

  // The source's top-level <defs> and <style>.
  pugi::xml_document src;
  if (!source.empty() && src.load_file(source.c_str(), pugi::parse_default)) {
    pugi::xml_node sroot = src.document_element();
    for (pugi::xml_attribute a = sroot.first_attribute(); a; a = a.next_attribute()) {
      const std::string_view name = a.name();
      if (name.starts_with("xmlns:") && name != "xmlns:xlink") root.append_copy(a);
    }
    for (pugi::xml_node c = sroot.first_child(); c; c = c.next_sibling()) {
      if (c.type() != pugi::node_element) continue;
      const std::string_view tag = local_name(c.name());
      if (tag == "defs" || tag == "style") root.append_copy(c);
    }
  }

  std::vector<int> runs(groups.size(), 0);
  pugi::xml_node g;
  int current = -1;
  for (size_t i = 0; i < n; ++i) {
    const int k = group_of[i];
    if (k != current || !g) {
      const std::string name = "group-" + std::to_string(k + 1);
      g = root.append_child("g");
      g.append_attribute("id") = (name + run_suffix(runs[static_cast<size_t>(k)]++)).c_str();
      g.append_attribute("data-group") = name.c_str();
      if (static_cast<size_t>(k) < names.size() && !names[static_cast<size_t>(k)].empty())
        g.append_attribute("data-name") = names[static_cast<size_t>(k)].c_str();
      current = k;
    }
    const Path& p = scene.paths[i];
    pugi::xml_node e = g.append_child("path");
    e.append_attribute("id") = p.id.c_str();
    e.append_attribute("d") = path_d(p).c_str();
    e.append_attribute("style") = paint_style(p).c_str();
  }

  std::ostringstream text;
  doc.save(text, "  ", pugi::format_indent, pugi::encoding_utf8);
  write_file_atomic(out, text.str());
}

}  // namespace svgm
