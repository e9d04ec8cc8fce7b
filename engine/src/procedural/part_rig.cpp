// The part rig (see part_rig.h): the rig's boxes, roles and name words, the document's names
// (read_source_names), a stroke limb's pivot, and build_rig, which chooses the parts
// (part_rig_units.cpp) and assembles them (part_rig_assemble.cpp).
#include "procedural/part_rig.h"

#include <pugixml.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <set>

#include "svg/document_order.h"
#include "svgmotion/svg_reader.h"
#include "procedural/part_locator.h"
#include "procedural/part_rig_internal.h"

namespace svgm {

namespace {

// A single stroke folds back on itself (a hairpin) when its endpoints lie closer together than
// this share of the farthest reach of its curve from their middle.
constexpr double kStrokeFold = 0.5;

}  // namespace

namespace part_rig_internal {

bool is_generic_word(const std::string& w) {
  static const std::set<std::string> generic = {
      "path", "paths", "g", "group", "groups", "layer", "layers", "svgid", "svg", "shape", "shapes", "rect",
      "circle", "ellipse", "polygon", "polyline", "line", "st", "cls", "fil", "str", "object", "clip", "mask",
      "defs", "use", "image", "id", "part", "element", "fill", "stroke", "color", "colour", "copy", "vector",
      "graphic", "artwork", "art", "drawing", "item", "emoji", "noto", "xmlid", "linear", "gradient", "radial",
      "icon", "svgrepo", "inkscape", "sodipodi", "untitled", "new", "run", "fg", "obj", "component", "cmp",
      "compound", "a", "b", "c", "d", "e", "f", "x", "y", "u", "mesh", "pattern", "sketch", "lines"};
  return generic.count(w) > 0 || w.size() < 3;
}

bool meaningful(const std::string& name) {
  for (const auto& w : name_words(name))
    if (!is_generic_word(w)) return true;
  return false;
}

bool has_word(const std::vector<std::string>& words, std::initializer_list<const char*> any) {
  for (const auto& w : words)
    for (const char* a : any)
      if (w == a || (w.size() == std::string(a).size() + 1 && w.back() == 's' && w.rfind(a, 0) == 0)) return true;
  return false;
}

}  // namespace part_rig_internal

using namespace part_rig_internal;

void RigBox::add(Vec2 p) {
  x0 = std::min(x0, p.x);
  y0 = std::min(y0, p.y);
  x1 = std::max(x1, p.x);
  y1 = std::max(y1, p.y);
}

void RigBox::add(const RigBox& b) {
  if (b.empty()) return;
  add(Vec2{b.x0, b.y0});
  add(Vec2{b.x1, b.y1});
}

const char* role_name(Role r) {
  switch (r) {
    case Role::Root: return "root";
    case Role::Head: return "head";
    case Role::UpperLimb: return "upper limb";
    case Role::LowerLimb: return "lower limb";
    case Role::Tail: return "tail";
    case Role::Detail: return "detail";
    case Role::Background: return "background";
  }
  return "?";
}

std::vector<std::string> name_words(const std::string& name) {
  std::vector<std::string> out;
  std::string w;
  auto flush = [&] {
    if (!w.empty() && !std::all_of(w.begin(), w.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
      out.push_back(w);
    w.clear();
  };
  for (size_t i = 0; i < name.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(name[i]);
    if (!std::isalnum(c)) { flush(); continue; }
    // camelCase boundary: a capital after a lower-case letter.
    if (std::isupper(c) && i > 0 && std::islower(static_cast<unsigned char>(name[i - 1]))) flush();
    if (std::isdigit(c) != (!w.empty() && std::isdigit(static_cast<unsigned char>(w.back())))) flush();
    w += static_cast<char>(std::tolower(c));
  }
  flush();
  return out;
}

SourceNames read_source_names(const std::string& original) {
  SourceNames out;
  Scene scene;
  try {
    scene = read_svg_file(original);
  } catch (const std::exception&) {
    return out;
  }
  pugi::xml_document doc;
  if (!doc.load_file(original.c_str())) return out;
  for (const Path& p : scene.paths) {
    pugi::xml_node n = find_locator(doc, p.locator);
    std::string loc = p.locator;
    std::vector<NamedElement> chain;
    while (n && n.type() == pugi::node_element && n.parent().type() == pugi::node_element) {
      std::string name;
      const char* label = n.attribute("inkscape:label").value();
      const std::string title = n.child("title").text().get();
      if (*label && meaningful(label)) name = label;
      else if (!title.empty() && meaningful(title)) name = title;
      else if (meaningful(n.attribute("id").value())) name = n.attribute("id").value();
      else if (meaningful(n.attribute("class").value())) name = n.attribute("class").value();
      if (!name.empty()) chain.push_back({loc, name});
      n = n.parent();
      loc = loc.substr(0, loc.rfind('/'));
    }
    if (!chain.empty()) out[p.id] = std::move(chain);
  }
  return out;
}

std::optional<Vec2> stroke_limb_pivot(const Path& p, Vec2 joint) {
  // Only an open stroke drawn without fill: a filled outline's ends say nothing of its shape.
  const bool filled = p.has_fill && p.fill.a > 0;
  if (filled || !p.has_stroke || p.subpaths.size() != 1 || p.subpaths[0].closed || p.subpaths[0].points.size() < 4)
    return std::nullopt;
  const std::vector<Vec2> on = curve_points(p);
  const Vec2 a = on.front(), b = on.back(), mid = 0.5 * (a + b);
  auto dist = [](Vec2 u, Vec2 v) { return std::hypot(u.x - v.x, u.y - v.y); };
  // The stroke's two ends: its endpoints, or, when it folds back on itself (its endpoints
  // closer together than kStrokeFold of its reach from their middle: a hairpin, as a sketch
  // draws an arm down and back up), the endpoints' middle and the fold's tip.
  Vec2 apex = mid;
  for (const Vec2& q : on)
    if (dist(q, mid) > dist(apex, mid)) apex = q;
  Vec2 e0 = a, e1 = b;
  if (dist(a, b) < kStrokeFold * dist(apex, mid)) { e0 = mid; e1 = apex; }
  return dist(e0, joint) <= dist(e1, joint) ? e0 : e1;
}

Rig build_rig(const Scene& scene, const SourceNames& names, const std::vector<std::string>& group_names) {
  Units U = units_of(scene, names);
  Rig rig = assemble(scene, names, group_names, U);
  if (split_root_limbs(scene, rig, U)) rig = assemble(scene, names, group_names, U);
  if (split_head_holds(scene, rig, U)) rig = assemble(scene, names, group_names, U);
  rig.elements = figure_elements(scene, rig);
  return rig;
}

}  // namespace svgm
