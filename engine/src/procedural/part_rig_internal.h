// What the files of the part rig share (part_rig.cpp names and reads the document,
// part_rig_units.cpp chooses the paths of each part, part_rig_assemble.cpp gives the parts
// their roles, parents and pivots): the parts to be and the small geometry helpers more than
// one of them calls. Not part of the engine's interface: include it only from those files.
#pragma once

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "geometry/curve_samples.h"
#include "procedural/part_rig.h"

namespace svgm::part_rig_internal {

// A round part's outline (its control polygon) fills this share of its box: a circle drawn with
// four cubics gives 0.90 (the control polygon is an octagon), a square 1, a triangle 0.5.
inline constexpr double kRoundFillMin = 0.65;
inline constexpr double kRoundFillMax = 0.93;

bool is_generic_word(const std::string& w);
bool meaningful(const std::string& name);
bool has_word(const std::vector<std::string>& words, std::initializer_list<const char*> any);

inline RigBox path_box(const Path& p) {
  RigBox b;
  for (const auto& sp : p.subpaths)
    for (const Vec2& q : sp.points) b.add(q);
  return b;
}

inline double overlap(const RigBox& a, const RigBox& b) {
  const double ox = std::min(a.x1, b.x1) - std::max(a.x0, b.x0), oy = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
  return ox > 0 && oy > 0 ? ox * oy : 0;
}

inline double gap(const RigBox& a, const RigBox& b) {
  const double dx = std::max({0.0, a.x0 - b.x1, b.x0 - a.x1}), dy = std::max({0.0, a.y0 - b.y1, b.y0 - a.y1});
  return std::hypot(dx, dy);
}

// A near-square box that its first outline fills about as a circle does, at least `min_area`.
// A wheel seen at a slant is an oval at most this many times as long as wide (a bicycle's
// wheels drawn in perspective: under 2); a ground band or a shadow under a vehicle is flatter.
inline constexpr double kWheelFlatMax = 2.5;

inline bool round_outline(const RigBox& box, double outline, double min_area) {
  const double aspect = box.w() / std::max(box.h(), 1e-9);
  const double fill = outline / std::max(box.area(), 1e-9);
  return aspect > 0.8 && aspect < 1.25 && fill > kRoundFillMin && fill < kRoundFillMax && box.area() > min_area;
}

inline bool round_path(const Path& p, double min_area) {
  return !p.subpaths.empty() && round_outline(path_box(p), std::fabs(shoelace(p.subpaths[0].points)), min_area);
}

// Points on a path's curves, each cubic at quarters.
inline std::vector<Vec2> curve_points(const Path& p) { return curve_samples(p, 4); }

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
  std::set<int> scenery;          // the first path of each part taken from a scene's subject as
                                  // its scenery (split_scenery)
};

// The parts: the scene's groups, each split by the names of its paths where the document
// names them apart (part_rig_units.cpp).
Units units_of(const Scene& scene, const SourceNames& names);

// The rig of the parts `U` (build_rig's work after the parts are chosen; part_rig_assemble.cpp).
Rig assemble(const Scene& scene, const SourceNames& names, const std::vector<std::string>& group_names, const Units& U);

// Limbs a grouper merged with the body become parts of their own (part_rig_units.cpp). True when
// the root was split.
bool split_root_limbs(const Scene& scene, const Rig& rig, Units& U);

// Hands drawn at the face become parts that hang from their arm (part_rig_units.cpp). True when
// the head was split.
bool split_head_holds(const Scene& scene, const Rig& rig, Units& U);

}  // namespace svgm::part_rig_internal
