// The paths of each part of the rig (see part_rig.h): the scene's groups split by the document's
// names, round paths split off as wheels, what a wheel carries split from its stand
// (units_of); and after a first assembly, limbs a grouper merged with the body and hands drawn
// at the face split off as parts of their own (split_root_limbs, split_head_holds).
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "procedural/hands_at_head.h"
#include "procedural/part_rig_internal.h"
#include "procedural/scenery.h"
#include "procedural/stroke_rig.h"
#include "procedural/wheel_riders.h"
#include "procedural/wheel_sets.h"

namespace svgm::part_rig_internal {

namespace {

// A group whose paths the document names apart splits into at most this many parts (more, and
// the names are per-path labels rather than parts: the group stays whole).
constexpr size_t kMaxNamedSplit = 16;
// A round path at least this share of the canvas is split from its group as a wheel.
constexpr double kWheelPathArea = 0.02;
// A path of a many-path root is a limb of its own (split_root_limbs) when its area is at least
// this share of the root's core path and less than this share of its box lies in the core's.
constexpr double kLimbPathArea = 0.15;
constexpr double kLimbInCore = 0.5;

// What a wheel carries, drawn in one group with what holds it (a ferris wheel's spokes, hub and
// cabins grouped with its stand; a spoke grouped with a leg of the stand): in every part of
// several paths, the paths that turn with a wheel (wheel_riders.h, the largest wheel first)
// become a part of their own that hangs from it, and when at least kMinSymmetricRiders of
// its paths ride on the wheel's rim (cabins, in sets: in_rider_sets), each of those becomes a part of its own (it rides
// round upright, motion_plan.cpp). What is left (the stand) stays a part that holds still.
// Kept whole, the spokes held still with the stand while the rim turned, and cabins grouped
// with them never rode.
// A part holding a scene's subject and scenery with it (a carriage and the meadow and rails
// under it: scenery.h) becomes two: the subject's paths, and the scenery's as a part of its own
// that stays with the background; a band of scenery alone (edge_to_edge) stays with it too.
void split_scenery(const Scene& scene, Units& U) {
  const std::vector<char> scenery = scenery_paths(scene);
  const size_t n = U.paths.size();
  for (size_t u = 0; u < n; ++u) {
    std::vector<int> subject, rest;
    for (int pi : U.paths[u]) (scenery[static_cast<size_t>(pi)] ? rest : subject).push_back(pi);
    // A part all scenery that runs from edge to edge (the rails in a group of their own) stays
    // too: left to the rig's roles, the rails under a carriage were its legs and drove with it.
    if (subject.empty() && !rest.empty() && edge_to_edge(scene, rest)) U.scenery.insert(rest.front());
    if (subject.empty() || rest.empty()) continue;
    U.paths[u] = subject;
    U.split[u] = 1;
    U.scenery.insert(rest.front());
    U.paths.push_back(rest);
    U.group.push_back(U.group[u]);
    U.split.push_back(1);
  }
}

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

}  // namespace

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
  const std::set<int> set_wheels = wheel_set_paths(scene);
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
      // of its own, so that it can turn while the frame holds; so is a small one of a set of
      // wheels low in a wide drawing (a car's, a tram's: wheel_sets.h).
      std::vector<int> rest;
      for (int pi : ps) {
        if (ps.size() > 1 && (round_path(scene.paths[pi], kWheelPathArea * scene.width * scene.height) || set_wheels.count(pi))) {
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
  split_scenery(scene, U);
  split_wheel_loads(scene, U);
  return U;
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

}  // namespace svgm::part_rig_internal
