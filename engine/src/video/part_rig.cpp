// The part rig (see part_rig.h).
#include "video/part_rig.h"

#include <pugixml.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "svg/document_order.h"
#include "scene/backdrop.h"
#include "video/shape_overlap.h"
#include "svgmotion/svg_reader.h"
#include "geometry/curve_samples.h"
#include "video/hands_at_head.h"
#include "video/skeleton_lobes.h"
#include "video/stroke_rig.h"
#include "video/wheel_riders.h"

namespace svgm {

namespace {

// Repeated elements: paths whose box is at most this share of the canvas area, similar when
// their widths and heights agree within this factor, at least kRepeatedMin of them.
constexpr double kRepeatedArea = 0.02;
constexpr double kRepeatedSimilar = 1.6;
constexpr size_t kRepeatedMin = 3;
// A round part's outline (its control polygon) fills this share of its box: a circle drawn with
// four cubics gives 0.90 (the control polygon is an octagon), a square 1, a triangle 0.5.
constexpr double kRoundFillMin = 0.65;
constexpr double kRoundFillMax = 0.93;
// A group whose paths the document names apart splits into at most this many parts (more, and
// the names are per-path labels rather than parts: the group stays whole).
constexpr size_t kMaxNamedSplit = 16;
// A round path at least this share of the canvas is split from its group as a wheel.
constexpr double kWheelPathArea = 0.02;
// A path of a many-path root is a limb of its own (split_root_limbs) when its area is at least
// this share of the root's core path and less than this share of its box lies in the core's.
constexpr double kLimbPathArea = 0.15;
constexpr double kLimbInCore = 0.5;
// A single stroke folds back on itself (a hairpin) when its endpoints lie closer together than
// this share of the farthest reach of its curve from their middle.
constexpr double kStrokeFold = 0.5;
// A part above the root more than this many times as tall as wide is a raised limb, not the
// head (a bird's wing raised above its back; heads in the bench drawings are 0.6-1.5).
constexpr double kHeadMaxAspect = 2.0;
// In a line drawing (stroke_rig.h): the head's middle lies above this share of the body's height
// from its top (its strokes sit on the shoulders; an arm stroke drawn from the shoulder out and
// up is no head), strokes alongside the root lie within this share of the figure's extent across
// the root's middle, and a stroke's end touches another's curve within this share of the
// figure's diagonal.
constexpr double kLineHeadTop = 0.1;
constexpr double kLineAcross = 0.2;
constexpr double kLineTouch = 0.03;

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

double shoelace(const std::vector<Vec2>& p) {
  double s = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    const Vec2& a = p[i];
    const Vec2& b = p[(i + 1) % p.size()];
    s += a.x * b.y - b.x * a.y;
  }
  return 0.5 * s;
}

RigBox path_box(const Path& p) {
  RigBox b;
  for (const auto& sp : p.subpaths)
    for (const Vec2& q : sp.points) b.add(q);
  return b;
}

double overlap(const RigBox& a, const RigBox& b) {
  const double ox = std::min(a.x1, b.x1) - std::max(a.x0, b.x0), oy = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
  return ox > 0 && oy > 0 ? ox * oy : 0;
}

double gap(const RigBox& a, const RigBox& b) {
  const double dx = std::max({0.0, a.x0 - b.x1, b.x0 - a.x1}), dy = std::max({0.0, a.y0 - b.y1, b.y0 - a.y1});
  return std::hypot(dx, dy);
}

// A near-square box that its first outline fills about as a circle does, at least `min_area`.
bool round_outline(const RigBox& box, double outline, double min_area) {
  const double aspect = box.w() / std::max(box.h(), 1e-9);
  const double fill = outline / std::max(box.area(), 1e-9);
  return aspect > 0.8 && aspect < 1.25 && fill > kRoundFillMin && fill < kRoundFillMax && box.area() > min_area;
}

bool round_path(const Path& p, double min_area) {
  return !p.subpaths.empty() && round_outline(path_box(p), std::fabs(shoelace(p.subpaths[0].points)), min_area);
}

}  // namespace

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

namespace {

// The paths of each part to be: per part its paths, scene group, whether its group was split
// (its name then comes from its own paths, not the grouper's group name), and the round paths
// split from their group as wheels.
struct Units {
  std::vector<std::vector<int>> paths;
  std::vector<int> group;
  std::vector<char> split;
  std::set<int> wheels;
  int root = -1;  // the root's index when it is already known (split_root_limbs)
  std::set<int> from_root;  // parts split from the root's group (split_root_limbs)
  std::map<int, int> carried_by;  // a path that turns with a wheel -> the wheel's path (split_wheel_loads)
  std::map<int, int> held_by;     // the first path of hands taken from the head -> the first path of
                                  // the arm holding them (split_head_holds)
};

// Each hanging part's chain top: the part its chain hangs from the root by (the guard stops a
// cycle of parents).
void set_chain_tops(Rig& rig) {
  const int G = static_cast<int>(rig.parts.size());
  for (int g = 0; g < G; ++g) {
    RigPart& P = rig.parts[g];
    if (P.parent < 0) continue;
    int top = g, guard = 0;
    while (rig.parts[top].parent != rig.root && rig.parts[top].parent >= 0 && guard++ < G) top = rig.parts[top].parent;
    P.chain_top = top;
  }
}

// Points on a path's curves, each cubic at quarters.
std::vector<Vec2> curve_points(const Path& p) { return curve_samples(p, 4); }

}  // namespace

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

namespace {

// What a wheel carries, drawn in one group with what holds it (a ferris wheel's spokes, hub and
// cabins grouped with its stand; a spoke grouped with a leg of the stand): in every part of
// several paths, the paths that turn with a wheel (wheel_riders.h, the largest wheel first)
// become a part of their own that hangs from it, and when at least kMinSymmetricRiders of
// its paths ride on the wheel's rim (cabins, in sets: in_rider_sets), each of those becomes a part of its own (it rides
// round upright, motion_plan.cpp). What is left (the stand) stays a part that holds still.
// Kept whole, the spokes held still with the stand while the rim turned, and cabins grouped
// with them never rode.
void split_wheel_loads(const Scene& scene, Units& U) {
  std::vector<int> wheels(U.wheels.begin(), U.wheels.end());
  std::sort(wheels.begin(), wheels.end(), [&](int a, int b) { return path_box(scene.paths[a]).area() > path_box(scene.paths[b]).area(); });
  if (wheels.empty()) return;
  // The riders of each wheel among all the scene's paths: on its rim (rides_wheel), or small
  // and stacked under one that is (a cabin's body hanging below the rim under its roof); of
  // those, the ones in sets (in_rider_sets).
  std::map<int, std::set<int>> riders_of;
  for (int w : wheels) {
    const RigBox wb = path_box(scene.paths[w]);
    std::vector<int> cand;
    std::vector<char> is_cand(scene.paths.size(), 0);
    std::vector<char> turns(scene.paths.size(), 0);
    for (size_t pi = 0; pi < scene.paths.size(); ++pi) {
      if (static_cast<int>(pi) == w) continue;
      const RigBox b = path_box(scene.paths[pi]);
      turns[pi] = turns_with_wheel(b, curve_points(scene.paths[pi]), wb);
      if (!turns[pi] && rides_wheel(b, wb)) {
        cand.push_back(static_cast<int>(pi));
        is_cand[pi] = 1;
      }
    }
    for (bool grew = !cand.empty(); grew;) {
      grew = false;
      for (size_t pi = 0; pi < scene.paths.size(); ++pi) {
        if (static_cast<int>(pi) == w || is_cand[pi] || turns[pi]) continue;
        const RigBox b = path_box(scene.paths[pi]);
        bool stacked = false;
        for (int r : cand) stacked = stacked || riders_stack(b, path_box(scene.paths[r]));
        if (stacked && b.area() <= kRideMaxArea * wb.area()) {
          cand.push_back(static_cast<int>(pi));
          is_cand[pi] = 1;
          grew = true;
        }
      }
    }
    std::vector<RigBox> boxes;
    for (int pi : cand) boxes.push_back(path_box(scene.paths[pi]));
    const std::vector<char> in_set = in_rider_sets(boxes);
    for (size_t i = 0; i < cand.size(); ++i)
      if (in_set[i]) riders_of[w].insert(cand[i]);
  }
  Units out = U;
  out.paths.clear();
  out.group.clear();
  out.split.clear();
  for (size_t u = 0; u < U.paths.size(); ++u) {
    std::vector<int> rest = U.paths[u];
    std::vector<std::vector<int>> pieces;
    for (int w : wheels) {
      if (rest.size() < 2 || std::find(rest.begin(), rest.end(), w) != rest.end()) break;
      const RigBox wb = path_box(scene.paths[w]);
      std::vector<int> inside, riders, others;
      for (int pi : rest) {
        const RigBox b = path_box(scene.paths[pi]);
        if (turns_with_wheel(b, curve_points(scene.paths[pi]), wb)) inside.push_back(pi);
        else if (riders_of[w].count(pi)) riders.push_back(pi);
        else others.push_back(pi);
      }
      if (riders.size() < static_cast<size_t>(kMinSymmetricRiders)) {
        others.insert(others.end(), riders.begin(), riders.end());
        riders.clear();
      }
      if (inside.empty() && riders.empty()) continue;
      for (int pi : inside) out.carried_by[pi] = w;
      if (!inside.empty()) pieces.push_back(inside);
      for (int pi : riders) pieces.push_back({pi});
      std::sort(others.begin(), others.end());
      rest = others;
      if (rest.empty()) break;
    }
    if (!rest.empty()) pieces.push_back(rest);
    std::sort(pieces.begin(), pieces.end());  // in paint order of their first paths
    for (auto& piece : pieces) {
      out.paths.push_back(piece);
      out.group.push_back(U.group[u]);
      out.split.push_back(U.split[u] || pieces.size() > 1);
    }
  }
  U = std::move(out);
}

// The parts: the scene's groups, each split by the names of its paths where the document
// names them apart (a grouper may merge a rider's named legs into the bicycle they overlap).
Units units_of(const Scene& scene, const SourceNames& names) {
  Units U;
  std::vector<std::vector<int>>& unit_paths = U.paths;
  std::vector<int>& unit_group = U.group;
  std::vector<char>& unit_split = U.split;
  std::set<int>& wheel_paths = U.wheels;
  // A line drawing's strokes are each a part: a grouper joins a sketch's strokes by where they
  // cross (a horse's neck with its foreleg), not by the limb they draw.
  if (is_line_drawing(scene)) {
    for (size_t g = 0; g < scene.groups.size(); ++g)
      for (int pi : scene.groups[g].paths) {
        unit_paths.push_back({pi});
        unit_group.push_back(static_cast<int>(g));
        unit_split.push_back(scene.groups[g].paths.size() > 1);
      }
    return U;
  }
  for (size_t g = 0; g < scene.groups.size(); ++g) {
    std::map<std::string, std::vector<int>> by_name;  // innermost named element -> paths
    for (int pi : scene.groups[g].paths) {
      const auto it = names.find(scene.paths[pi].id);
      by_name[it == names.end() ? std::string() : it->second.front().locator].push_back(pi);
    }
    // Not when one named element holds all of them (the document's own "arm_right" group,
    // whose paths are "upper_arm_right" and "hand_right": the grouper kept it as a part).
    std::map<std::string, size_t> holders;
    for (int pi : scene.groups[g].paths)
      if (const auto it = names.find(scene.paths[pi].id); it != names.end())
        for (const auto& e : it->second) ++holders[e.locator];
    bool held = false;
    for (const auto& [loc, n] : holders) held = held || n == scene.groups[g].paths.size();
    bool split = !held && by_name.size() >= 2 && by_name.size() <= kMaxNamedSplit;
    if (!split) by_name = {{"", scene.groups[g].paths}};
    std::vector<std::vector<int>> units;
    for (auto& [loc, ps] : by_name) {
      // A large round path among others (a wheel in a bicycle, a ferris wheel's rim) is a part
      // of its own, so that it can turn while the frame holds.
      std::vector<int> rest;
      for (int pi : ps) {
        if (ps.size() > 1 && round_path(scene.paths[pi], kWheelPathArea * scene.width * scene.height)) {
          units.push_back({pi});
          wheel_paths.insert(pi);
        }
        else rest.push_back(pi);
      }
      if (!rest.empty()) units.push_back(rest);
    }
    split = split || units.size() > 1;
    std::sort(units.begin(), units.end());  // in paint order of their first paths
    for (auto& u : units) {
      unit_paths.push_back(std::move(u));
      unit_group.push_back(static_cast<int>(g));
      unit_split.push_back(split);
    }
  }
  split_wheel_loads(scene, U);
  return U;
}

// The rig of the parts `U` (build_rig's work after the parts are chosen).
Rig assemble(const Scene& scene, const SourceNames& names, const std::vector<std::string>& group_names, const Units& U) {
  Rig rig;
  rig.canvas.add(Vec2{0, 0});
  rig.canvas.add(Vec2{scene.width, scene.height});
  const std::vector<std::vector<int>>& unit_paths = U.paths;
  const std::vector<int>& unit_group = U.group;
  const std::vector<char>& unit_split = U.split;
  const std::set<int>& wheel_paths = U.wheels;
  const int G = static_cast<int>(unit_paths.size());
  const size_t n_paths = scene.paths.size();
  rig.parts.resize(G);
  rig.part_of_path.assign(n_paths, -1);
  std::vector<double> mean_index(G, 0);
  for (int g = 0; g < G; ++g) {
    RigPart& P = rig.parts[g];
    P.group = unit_group[g];
    for (int pi : unit_paths[g]) {
      rig.part_of_path[pi] = g;
      mean_index[g] += pi;
      for (const auto& sp : scene.paths[pi].subpaths) {
        for (const Vec2& q : sp.points) P.box.add(q);
        P.area += std::fabs(shoelace(sp.points));
      }
    }
    if (!unit_paths[g].empty()) mean_index[g] /= static_cast<double>(unit_paths[g].size());
    P.base_x0 = P.box.x1;
    P.base_x1 = P.box.x0;
    for (int pi : unit_paths[g])
      for (const auto& sp : scene.paths[pi].subpaths)
        for (const Vec2& q : sp.points)
          if (q.y >= P.box.y1 - 0.25 * P.box.h()) {
            P.base_x0 = std::min(P.base_x0, q.x);
            P.base_x1 = std::max(P.base_x1, q.x);
          }
  }

  // Names: the named element that best covers the part's paths (precision times recall).
  std::map<std::string, int> element_total;
  for (const Path& p : scene.paths)
    if (auto it = names.find(p.id); it != names.end())
      for (const auto& e : it->second) ++element_total[e.locator];
  for (int g = 0; g < G; ++g) {
    RigPart& P = rig.parts[g];
    if (!unit_split[g] && P.group < static_cast<int>(group_names.size()) && meaningful(group_names[P.group])) {
      P.name = group_names[P.group];
      P.named = true;
    } else {
      std::map<std::string, std::pair<int, std::string>> in_part;
      for (int pi : unit_paths[g])
        if (auto it = names.find(scene.paths[pi].id); it != names.end())
          for (const auto& e : it->second) {
            auto& slot = in_part[e.locator];
            ++slot.first;
            slot.second = e.name;
          }
      double best = 0.25;  // at least half the part's paths and half the element's
      for (const auto& [loc, hit] : in_part) {
        const double score = static_cast<double>(hit.first) / unit_paths[g].size() *
                             hit.first / std::max(1, element_total[loc]);
        if (score > best || (score == best && P.named && loc.size() > 0)) {
          best = score;
          P.name = hit.second;
          P.named = true;
        }
      }
    }
    // A wheel split from a named group is that group's wheel ("bicycle_wheel").
    if (P.named && unit_paths[g].size() == 1 && wheel_paths.count(unit_paths[g][0]) && !has_word(name_words(P.name), {"wheel", "tire", "tyre"}))
      P.name += "_wheel";
    for (const auto& w : name_words(P.name))
      if (!is_generic_word(w)) P.words.push_back(w);
  }

  // Background.
  const double CW = scene.width, CH = scene.height;
  int figure_parts = 0;
  for (int g = 0; g < G; ++g) {
    RigPart& P = rig.parts[g];
    if (P.box.empty()) continue;
    if (has_word(P.words, {"background", "bg", "sky", "ground", "floor", "backdrop", "scenery", "landscape", "hill", "mountain",
                             "mud", "grass", "road", "terrain", "field", "wall"})) {
      P.role = Role::Background;
      P.why = "named as background";
    } else if (is_backdrop(P.box.x0, P.box.y0, P.box.x1, P.box.y1, mean_index[g] / static_cast<double>(n_paths), CW, CH)) {
      P.role = Role::Background;
      P.why = "large, at the canvas edges, painted first";
    } else {
      ++figure_parts;
    }
  }
  if (figure_parts == 0)  // nothing left to animate: there is no background
    for (auto& P : rig.parts)
      if (P.role == Role::Background) { P.role = Role::Detail; P.why.clear(); }
  for (const auto& P : rig.parts)
    if (P.role != Role::Background) rig.figure.add(P.box);
  if (rig.figure.empty()) return rig;

  // A line drawing (stroke_rig.h): each part one stroke, sized by its curve's length and
  // placed by its curve's box; elsewhere the part's area and its control points' box.
  const bool line = is_line_drawing(scene);
  std::vector<RigBox> cbox(G);
  std::vector<double> size(G, 0);
  RigBox cfigure;
  for (int g = 0; g < G; ++g) {
    cbox[g] = rig.parts[g].box;
    size[g] = rig.parts[g].area;
    if (!line || unit_paths[g].size() != 1) continue;
    cbox[g] = stroke_box(scene.paths[unit_paths[g][0]]);
    size[g] = stroke_length(scene.paths[unit_paths[g][0]]);
    if (rig.parts[g].role != Role::Background) cfigure.add(cbox[g]);
  }
  if (!line) cfigure = rig.figure;

  // Root: a part named body/torso, else the largest central part.
  const Vec2 fc = cfigure.centre();
  const double fdiag = std::hypot(rig.figure.w(), rig.figure.h());
  const double cdiag = std::hypot(cfigure.w(), cfigure.h());
  double best = -1;
  for (int g = 0; g < G; ++g) {
    const RigPart& P = rig.parts[g];
    if (P.role == Role::Background || P.box.empty()) continue;
    const Vec2 c = cbox[g].centre();
    const double d = std::hypot(c.x - fc.x, c.y - fc.y) / (0.25 * cdiag);
    double score = std::max(size[g], 1e-9) / (1 + d * d);
    if (has_word(P.words, {"body", "torso", "trunk"})) score = 1e300;
    if (g == U.root) score = 1e301;
    // What a wheel carries hangs from the wheel: it is never the root (its wheel may be).
    if (U.carried_by.count(unit_paths[g].front())) score = 0;
    if (score > best) { best = score; rig.root = g; }
  }
  RigPart& R = rig.parts[rig.root];
  R.role = Role::Root;
  R.why = R.why.empty() ? "largest central part" : R.why;
  R.pivot = {R.box.centre().x, R.box.y1};
  R.chain_top = rig.root;

  // Parents and pivots. A part hangs from the larger part whose shape it overlaps most
  // (video/shape_overlap.h: boxes let a trident across the head take the horn from the hood).
  std::vector<PartShape> shape(static_cast<size_t>(G));
  for (int g = 0; g < G; ++g) shape[static_cast<size_t>(g)] = part_shape(scene, unit_paths[g]);
  for (int g = 0; g < G; ++g) {
    RigPart& P = rig.parts[g];
    if (g == rig.root || P.role == Role::Background || P.box.empty()) continue;
    int parent = rig.root;
    double best_overlap = shape_overlap(shape[g], shape[rig.root]), best_gap = gap(P.box, R.box);
    // What turns with a wheel hangs from it (split_wheel_loads), not from the stand whose box
    // holds its box. A limb split from the root's group hangs from the root (the grouper drew
    // it with the body, not with a raised arm's neighbour, the head).
    int wheel = -1;
    if (const auto it = U.carried_by.find(unit_paths[g].front()); it != U.carried_by.end())
      for (int h = 0; h < G; ++h)
        if (h != g && unit_paths[h].size() == 1 && unit_paths[h][0] == it->second) wheel = h;
    int arm = -1;
    if (const auto it = U.held_by.find(unit_paths[g].front()); it != U.held_by.end())
      for (int h = 0; h < G; ++h)
        if (h != g && !unit_paths[h].empty() && unit_paths[h].front() == it->second) arm = h;
    if (wheel >= 0) {
      parent = wheel;
      P.carried = true;
    }
    else if (arm >= 0) parent = arm;  // hands taken from the head hang from their arm (split_head_holds)
    else if (!line && P.area < R.area && !U.from_root.count(g))
      for (int h = 0; h < G; ++h) {
        const RigPart& Q = rig.parts[h];
        if (h == g || h == rig.root || Q.role == Role::Background || Q.box.empty()) continue;
        // A wheel does not hang from what it carries.
        if (const auto it = U.carried_by.find(unit_paths[h].front()); it != U.carried_by.end() && it->second == unit_paths[g].front())
          continue;
        if (!(Q.area > P.area || (Q.area == P.area && h < g))) continue;
        const double o = shape_overlap(shape[g], shape[h]), gp = gap(P.box, Q.box);
        if (o > best_overlap || (best_overlap == 0 && o == 0 && gp < best_gap)) {
          best_overlap = o;
          best_gap = gp;
          parent = h;
        }
      }
    P.parent = parent;
    const RigBox& pb = rig.parts[parent].box;
    const double pad = 0.01 * fdiag;
    Vec2 sum;
    int count = 0;
    Vec2 nearest;
    double nd = 1e300;
    for (int pi : unit_paths[g])
      for (const auto& sp : scene.paths[pi].subpaths)
        for (const Vec2& q : sp.points) {
          if (q.x >= pb.x0 - pad && q.x <= pb.x1 + pad && q.y >= pb.y0 - pad && q.y <= pb.y1 + pad) {
            sum = sum + q;
            ++count;
          }
          const double d = std::hypot(q.x - pb.centre().x, q.y - pb.centre().y);
          if (d < nd) { nd = d; nearest = q; }
        }
    // Points inside the parent's box: their centroid, pulled towards the parent's centre a
    // little when the part lies wholly inside the box (so a detail turns about its middle).
    P.pivot = count > 0 ? (1.0 / count) * sum : nearest;
  }
  // Chains: a limb's segments move with it.
  set_chain_tops(rig);

  // The body the limbs are placed against: the root; in a line drawing the root with the
  // strokes alongside it (a torso drawn as a bundle of hairpins), which hold still with it.
  RigBox body = line ? cbox[rig.root] : R.box;
  std::vector<char> in_body(G, 0);
  if (line) {
    const bool upright = cbox[rig.root].h() >= cbox[rig.root].w();
    const double across = kLineAcross * (upright ? cfigure.w() : cfigure.h());
    for (int g = 0; g < G; ++g)
      if (g != rig.root && rig.parts[g].role != Role::Background && lies_alongside(cbox[g], cbox[rig.root], across)) {
        in_body[g] = 1;
        body.add(cbox[g]);
      }
  }
  const double head_top = line ? kLineHeadTop : 0.25;

  // Roles of the parts hanging from the root, then names decide where they say something.
  const Vec2 rc = body.centre();
  const double rw = std::max(body.w(), 1e-9), rh = std::max(body.h(), 1e-9);
  int head = -1;
  for (int g = 0; g < G; ++g) {
    RigPart& P = rig.parts[g];
    if (P.parent != rig.root) continue;
    const RigBox& pbox = cbox[g];
    const Vec2 c = pbox.centre();
    const double dx = c.x - rc.x;
    const bool inside = overlap(pbox, body) >= 0.8 * pbox.area();
    if (in_body[g]) { P.role = Role::Detail; P.why = "a stroke alongside the root (the body)"; }
    else if (inside) { P.role = Role::Detail; P.why = "inside the root"; }
    else if (std::fabs(dx) < 0.35 * rw && c.y < body.y0 + head_top * rh && pbox.h() > kHeadMaxAspect * pbox.w()) {
      P.role = Role::UpperLimb;
      P.why = "above the root, tall and thin (a raised wing or arm)";
    } else if (std::fabs(dx) < 0.35 * rw && c.y < body.y0 + head_top * rh) {
      P.role = Role::Head;
      P.why = "central, above the root";
      if (head < 0 || P.area > rig.parts[head].area) head = g;
    } else if (c.y <= rc.y + 0.1 * rh && std::fabs(dx) >= 0.2 * rw) { P.role = Role::UpperLimb; P.why = "beside the root, upper half"; }
    else if (c.y > rc.y + 0.1 * rh) { P.role = Role::LowerLimb; P.why = "below the root's middle"; }
    else { P.role = Role::Detail; P.why = "near the root's middle"; }
    P.side = std::fabs(dx) < 0.1 * rw ? 0 : (dx < 0 ? 1 : -1);  // figure's own side: mirrored
  }
  // Only the largest head is the head; a smaller part above the root with its middle beside
  // the head is an arm raised above the shoulders, the others details of the head.
  for (int g = 0; g < G; ++g) {
    RigPart& P = rig.parts[g];
    if (P.role != Role::Head || g == head) continue;
    const RigBox& hb = cbox[head];
    if (cbox[g].centre().x < hb.x0 || cbox[g].centre().x > hb.x1) { P.role = Role::UpperLimb; P.why = "above the root, beside the head (a raised arm)"; }
    else { P.role = Role::Detail; P.why = "above the root (a smaller head part)"; }
  }
  // Tail: the attached part reaching farthest sideways at the root's height, not the head.
  int tail = -1;
  double reach = 0.5 * rw;
  for (int g = 0; g < G; ++g) {
    const RigPart& P = rig.parts[g];
    if (P.parent != rig.root || P.role == Role::Head || P.role == Role::Detail) continue;
    const RigBox& pbox = cbox[g];
    const Vec2 c = pbox.centre();
    const double far = std::max(std::fabs(pbox.x0 - rc.x), std::fabs(pbox.x1 - rc.x));
    if (c.y >= body.y0 && c.y <= body.y1 && far > reach && cfigure.w() > cfigure.h()) { reach = far; tail = g; }
  }
  if (tail >= 0) { rig.parts[tail].role = Role::Tail; rig.parts[tail].why = "reaches farthest sideways at the root's height"; }

  // A line drawing's limb strokes turn about their end nearer the body (stroke_body_end), and
  // hang from a longer stroke of the same limb whose curve one of their ends touches (a shin
  // drawn on from a thigh, a foot from a shin, the strokes of one leg meeting at its foot), else
  // from the root. Hung from the stroke its box overlaps most, a torso stroke swung with a
  // smaller arm stroke and the arms hung from a detail; a runner's back-leg strokes, meeting at
  // the foot but each turning about its own end, crossed each other and the target tore (the
  // ranker flagged a stroke's visible area falling from 40 to 11 px in a frame).
  if (line) {
    const double touch = kLineTouch * cdiag;
    for (int g = 0; g < G; ++g) {
      RigPart& P = rig.parts[g];
      if (g == rig.root || P.parent != rig.root || in_body[g] || unit_paths[g].size() != 1 ||
          (P.role != Role::UpperLimb && P.role != Role::LowerLimb && P.role != Role::Tail))
        continue;
      const Vec2 joint = {body.centre().x, P.role == Role::UpperLimb ? body.y0 : body.y1};
      P.pivot = stroke_body_end(scene.paths[unit_paths[g][0]], body, joint);
      P.why += "; one stroke, turns about its end nearer the body";
      double nearest = touch;
      const auto ends = stroke_ends(scene.paths[unit_paths[g][0]]);
      for (int h = 0; h < G; ++h) {
        const RigPart& Q = rig.parts[h];
        if (h == g || h == rig.root || in_body[h] || Q.role != P.role || unit_paths[h].size() != 1 || size[h] <= size[g]) continue;
        for (const Vec2& e : ends) {
          const double d = distance_to_stroke(e, scene.paths[unit_paths[h][0]]);
          if (d <= nearest) { nearest = d; P.parent = h; }
        }
      }
    }
    set_chain_tops(rig);
  }
  for (int g = 0; g < G; ++g) {
    RigPart& P = rig.parts[g];
    if (P.role == Role::Background || g == rig.root) continue;
    if (P.parent != rig.root && P.chain_top >= 0) { P.role = rig.parts[P.chain_top].role; P.side = rig.parts[P.chain_top].side; P.why = "hangs from " + rig.parts[P.parent].name; }
    if (has_word(P.words, {"head", "face"})) { P.role = Role::Head; P.why = "named"; }
    else if (has_word(P.words, {"arm", "hand", "wing", "forearm", "fist"})) { P.role = Role::UpperLimb; P.why = "named"; }
    else if (has_word(P.words, {"leg", "foot", "feet", "shin", "thigh"})) { P.role = Role::LowerLimb; P.why = "named"; }
    else if (has_word(P.words, {"tail"})) { P.role = Role::Tail; P.why = "named"; }
    if (has_word(P.words, {"right"})) P.side = 1;
    else if (has_word(P.words, {"left"})) P.side = -1;
  }

  // A limb drawn as one open stroke (a line drawing's arm or leg) turns about its end nearest
  // the body's joints: the root's top centre (shoulders) for an upper limb, its bottom centre
  // (hips) for a lower limb (stroke_limb_pivot). The centroid of its points inside the root's
  // box took a stroke hanging from the shoulder to the hip by its lower end: its top swung
  // across the neck (a runner sketch's arm strokes).
  for (int g = 0; g < G; ++g) {
    RigPart& P = rig.parts[g];
    if (line || P.parent != rig.root || unit_paths[g].size() != 1 || (P.role != Role::UpperLimb && P.role != Role::LowerLimb))
      continue;
    const Vec2 joint = {R.box.centre().x, P.role == Role::UpperLimb ? R.box.y0 : R.box.y1};
    if (const auto end = stroke_limb_pivot(scene.paths[unit_paths[g][0]], joint)) {
      P.pivot = *end;
      P.why += "; one stroke, turns about its end nearest the root's " + std::string(P.role == Role::UpperLimb ? "top" : "bottom");
    }
  }

  // Arms drawn in a part's largest filled, closed outline (outline_lobes.h).
  for (int g = 0; g < G; ++g) {
    RigPart& P = rig.parts[g];
    if (P.role == Role::Background) continue;
    int largest = -1;
    double most = 0;
    for (int pi : unit_paths[g]) {
      const Path& p = scene.paths[pi];
      if (!(p.has_fill && p.fill.a > 0) || p.subpaths.empty() || !p.subpaths[0].closed) continue;
      const double a = std::fabs(shoelace(p.subpaths[0].points));
      if (a > most) { most = a; largest = pi; }
    }
    if (largest >= 0) P.arm_lobes = arm_lobes(scene.paths[largest]);
  }

  // The limbs of the figure's silhouette.
  {
    std::vector<int> figure_paths;
    for (int g = 0; g < G; ++g)
      if (rig.parts[g].role != Role::Background) figure_paths.insert(figure_paths.end(), unit_paths[g].begin(), unit_paths[g].end());
    std::sort(figure_paths.begin(), figure_paths.end());
    rig.limbs = skeleton_lobes(scene, figure_paths);
  }

  // Round parts (wheels).
  for (int g = 0; g < G; ++g) {
    RigPart& P = rig.parts[g];
    if (P.box.empty() || P.role == Role::Background) continue;
    double outline = 0;
    for (int pi : unit_paths[g])
      if (!scene.paths[pi].subpaths.empty())
        outline = std::max(outline, std::fabs(shoelace(scene.paths[pi].subpaths[0].points)));
    P.round = has_word(P.words, {"wheel", "tire", "tyre"}) || round_outline(P.box, outline, 0.005 * CW * CH);
    // A wheel split from its group turns; it is no limb to swing.
    if (unit_paths[g].size() == 1 && wheel_paths.count(unit_paths[g][0]) && g != rig.root) {
      P.role = Role::Detail;
      P.why = "a round path of its group (a wheel)";
    }
    // A line drawing's stroke that winds once round an oval (a sketched bicycle's wheel) is
    // round too, and no limb: the rig took a wheel below the body for a leg, and pedalling
    // swung it about its top like a shin. Its box is its curve's: a wheel spins about the middle
    // of the oval drawn, not of the cubic's handles (18 units off in livesketch's biking).
    if (line && g != rig.root && unit_paths[g].size() == 1 && is_loop_stroke(scene.paths[unit_paths[g][0]])) {
      P.box = cbox[g];
      P.wheel_plane = loop_plane(scene.paths[unit_paths[g][0]]);
      P.round = true;
      P.role = Role::Detail;
      P.why = "a stroke drawn round an oval (a wheel)";
    }
  }

  // Default names from roles.
  std::map<std::string, int> used;
  for (int g = 0; g < G; ++g) {
    RigPart& P = rig.parts[g];
    if (!P.name.empty()) continue;
    std::string base = P.role == Role::Root ? "root" : P.role == Role::Head ? "head" : P.role == Role::Tail ? "tail"
                     : P.role == Role::Background ? "background" : P.role == Role::UpperLimb ? "limb_upper"
                     : P.role == Role::LowerLimb ? "limb_lower" : P.round ? "wheel" : "detail";
    if ((P.role == Role::UpperLimb || P.role == Role::LowerLimb) && P.side != 0) base += P.side > 0 ? "_right" : "_left";
    const int k = used[base]++;
    P.name = k == 0 ? base : base + "_" + std::to_string(k + 1);
  }
  // Names seen twice get a number, so a plan pattern can tell them apart.
  std::map<std::string, int> count, seen;
  for (const auto& P : rig.parts) ++count[P.name];
  for (auto& P : rig.parts)
    if (count[P.name] > 1 && P.named) P.name += "_" + std::to_string(++seen[P.name]);

  // Repeated elements: small paths of similar size (with the smaller paths inside each).
  struct Elem { RigBox box; std::vector<int> paths; };
  std::vector<int> small;
  for (size_t i = 0; i < n_paths; ++i) {
    const int g = rig.part_of_path[i];
    if (g >= 0 && rig.parts[g].role == Role::Background) continue;
    const RigBox b = path_box(scene.paths[i]);
    if (!b.empty() && b.area() > 0 && b.area() <= kRepeatedArea * CW * CH) small.push_back(static_cast<int>(i));
  }
  std::vector<RigBox> boxes(n_paths);
  for (int i : small) boxes[i] = path_box(scene.paths[i]);
  std::sort(small.begin(), small.end(), [&](int a, int b) { return boxes[a].area() > boxes[b].area(); });
  std::vector<Elem> elems;
  for (int i : small) {
    const Vec2 c = boxes[i].centre();
    bool attached = false;
    for (auto& e : elems)
      if (c.x >= e.box.x0 && c.x <= e.box.x1 && c.y >= e.box.y0 && c.y <= e.box.y1 && boxes[i].area() < 0.5 * e.box.area()) {
        e.paths.push_back(i);
        attached = true;
        break;
      }
    if (!attached) elems.push_back({boxes[i], {i}});
  }
  std::vector<std::vector<int>> clusters;  // indices into elems
  auto similar = [](const RigBox& a, const RigBox& b) {
    const double rw = std::max(a.w(), b.w()) / std::max(std::min(a.w(), b.w()), 1e-9);
    const double rh = std::max(a.h(), b.h()) / std::max(std::min(a.h(), b.h()), 1e-9);
    return rw <= kRepeatedSimilar && rh <= kRepeatedSimilar;
  };
  for (size_t e = 0; e < elems.size(); ++e) {
    bool placed = false;
    for (auto& c : clusters) {
      if (!similar(elems[c.front()].box, elems[e].box)) continue;
      bool clash = false;  // members of a set do not overlap each other much
      for (int o : c) clash = clash || overlap(elems[o].box, elems[e].box) > 0.3 * std::min(elems[o].box.area(), elems[e].box.area());
      if (clash) continue;
      c.push_back(static_cast<int>(e));
      placed = true;
      break;
    }
    if (!placed) clusters.push_back({static_cast<int>(e)});
  }
  size_t best_cluster = clusters.size();
  for (size_t c = 0; c < clusters.size(); ++c)
    if (clusters[c].size() >= kRepeatedMin && (best_cluster == clusters.size() || clusters[c].size() > clusters[best_cluster].size()))
      best_cluster = c;
  if (best_cluster < clusters.size()) {
    for (int e : clusters[best_cluster]) {
      std::vector<int> ps = elems[e].paths;
      std::sort(ps.begin(), ps.end());
      rig.repeated.push_back(ps);
    }
    rig.repeated_why = std::to_string(rig.repeated.size()) + " small paths of similar size";
  }
  return rig;
}

// A root of several paths may hold limbs drawn as shapes of their own that a grouper merged
// with the body (a figure's two raised arms grouped with its shirt): its core path (the
// largest central one, as the root is chosen among parts) stays the root, and each path at
// least kLimbPathArea of the core's area whose middle lies outside the core's box, that
// mostly lies outside it and keeps to one side of the core's middle, becomes a part of its
// own that hangs from the core. True when the root was split.
bool split_root_limbs(const Scene& scene, const Rig& rig, Units& U) {
  if (rig.root < 0) return false;
  const std::vector<int> ps = U.paths[rig.root];
  if (ps.size() < 2) return false;
  const RigBox& pb = rig.parts[rig.root].box;
  const double quarter = 0.25 * std::max(std::hypot(pb.w(), pb.h()), 1e-9);
  std::vector<RigBox> box(ps.size());
  std::vector<double> area(ps.size(), 0);
  size_t core = 0;
  double best = -1;
  for (size_t i = 0; i < ps.size(); ++i) {
    box[i] = path_box(scene.paths[ps[i]]);
    for (const auto& sp : scene.paths[ps[i]].subpaths) area[i] += std::fabs(shoelace(sp.points));
    const Vec2 d = box[i].centre() - pb.centre();
    const double score = area[i] / (1 + (d.x * d.x + d.y * d.y) / (quarter * quarter));
    if (!box[i].empty() && score > best) { best = score; core = i; }
  }
  const RigBox& cb = box[core];
  std::vector<int> rest, limbs;
  for (size_t i = 0; i < ps.size(); ++i) {
    const Vec2 c = box[i].centre();
    // ... and on one side of the core's middle: one path across it (both arms drawn as one
    // shape with the shoulders) is no single limb.
    const bool one_side = box[i].x1 < cb.centre().x || box[i].x0 > cb.centre().x;
    const bool outside = one_side && (c.x < cb.x0 || c.x > cb.x1 || c.y < cb.y0 || c.y > cb.y1);
    const bool limb = i != core && !box[i].empty() && area[i] >= kLimbPathArea * area[core] && outside &&
                      overlap(box[i], cb) < kLimbInCore * box[i].area();
    (limb ? limbs : rest).push_back(ps[i]);
  }
  if (limbs.empty()) return false;
  const auto at = U.paths.begin() + rig.root + 1;
  const int group = U.group[rig.root];
  U.paths[rig.root] = rest;
  const size_t pos = static_cast<size_t>(rig.root) + 1;
  U.paths.insert(at, limbs.size(), {});
  U.group.insert(U.group.begin() + pos, limbs.size(), group);
  U.split.insert(U.split.begin() + pos, limbs.size(), 1);
  for (size_t k = 0; k < limbs.size(); ++k) U.paths[pos + k] = {limbs[k]};
  U.root = rig.root;
  for (size_t k = 0; k < limbs.size(); ++k) U.from_root.insert(static_cast<int>(pos + k));
  return true;
}

// Hands drawn at the face (hands_at_head.h): in the head's part, the paths an arm holds become
// a part of their own per arm (appended, so no part's index moves) that hangs from that arm. True
// when the head was split.
bool split_head_holds(const Scene& scene, const Rig& rig, Units& U) {
  std::vector<int> arms;
  std::vector<RigBox> arm_boxes;
  for (size_t g = 0; g < rig.parts.size(); ++g)
    if (rig.parts[g].role == Role::UpperLimb && !U.paths[g].empty()) {
      arms.push_back(static_cast<int>(g));
      arm_boxes.push_back(rig.parts[g].box);
    }
  bool split = false;
  for (size_t g = 0; g < rig.parts.size() && !arms.empty(); ++g) {
    if (rig.parts[g].role != Role::Head || rig.parts[g].parent != rig.root || U.paths[g].size() < 2) continue;
    const std::vector<int> ps = U.paths[g];
    std::vector<RigBox> boxes;
    std::vector<double> areas;
    for (int pi : ps) {
      boxes.push_back(path_box(scene.paths[pi]));
      double a = 0;
      for (const auto& sp : scene.paths[pi].subpaths) a += std::fabs(shoelace(sp.points));
      areas.push_back(a);
    }
    const std::vector<int> held = held_at_head(boxes, areas, arm_boxes);
    std::map<int, std::vector<int>> by_arm;
    std::vector<int> rest;
    for (size_t i = 0; i < ps.size(); ++i) (held[i] >= 0 ? by_arm[held[i]] : rest).push_back(ps[i]);
    if (by_arm.empty() || rest.empty()) continue;
    U.paths[g] = rest;
    U.split[g] = 1;
    for (const auto& [a, hand] : by_arm) {
      U.paths.push_back(hand);
      U.group.push_back(U.group[g]);
      U.split.push_back(1);
      U.held_by[hand.front()] = U.paths[arms[a]].front();
    }
    split = true;
  }
  return split;
}

}  // namespace

Rig build_rig(const Scene& scene, const SourceNames& names, const std::vector<std::string>& group_names) {
  Units U = units_of(scene, names);
  Rig rig = assemble(scene, names, group_names, U);
  if (split_root_limbs(scene, rig, U)) rig = assemble(scene, names, group_names, U);
  if (split_head_holds(scene, rig, U)) rig = assemble(scene, names, group_names, U);
  return rig;
}

}  // namespace svgm
