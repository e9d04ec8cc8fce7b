// Test drawings of the motion planner (tests/data/motion) and how far a plan moves their paths:
// one copy for the plan, locator, petal and elongated-part tests.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "svgmotion/svg_reader.h"
#include "procedural/eye_cue.h"
#include "procedural/motion_plan.h"
#include "test_paths.h"

namespace svgm::test {

// A drawn element whose control points are the corners of the box x0,y0-x1,y1 (its area the
// box's), filled with luma `lightness`: an eye, a body, a mark on a rig made by hand.
inline RigElement box_element(double x0, double y0, double x1, double y1, double lightness) {
  RigElement e;
  for (Vec2 q : {Vec2{x0, y0}, Vec2{x1, y0}, Vec2{x1, y1}, Vec2{x0, y1}}) e.box.add(q), e.points.push_back(q);
  e.area = (x1 - x0) * (y1 - y0);
  e.lightness = lightness;
  return e;
}

inline std::string motion_data(const char* name) { return svgm::test::data_path(std::string("motion/") + name); }

// Largest displacement from frame 0 of the points of each path of `scene`, over F frames of
// animate_plan's output `pts`.
inline std::vector<double> path_travel(const Scene& scene, const std::vector<Vec2>& pts, int F) {
  const size_t per = pts.size() / F;
  std::vector<double> out(scene.paths.size(), 0);
  size_t i = 0;
  for (size_t p = 0; p < scene.paths.size(); ++p)
    for (const auto& sp : scene.paths[p].subpaths)
      for (size_t q = 0; q < sp.points.size(); ++q, ++i)
        for (int f = 1; f < F; ++f)
          out[p] = std::max(out[p], std::hypot(pts[f * per + i].x - pts[i].x, pts[f * per + i].y - pts[i].y));
  return out;
}

// A drawing of tests/data/motion with its rig.
struct Drawing {
  Scene scene;
  Rig rig;
  explicit Drawing(const char* name)
      : scene(read_svg_file(motion_data(name))), rig(build_rig(scene, read_source_names(motion_data(name)))) {}
  // Largest displacement from frame 0 of the points of each scene path over `plan`'s frames.
  std::vector<double> travel(const MotionPlan& plan, int F = 13) const { return path_travel(scene, animate_plan(scene, rig, plan, F), F); }
};

// A drawing of tests/data/motion mirrored left to right (x -> width - x), its rig rebuilt from
// the mirrored paths alone: a figure facing or pointing the other way.
inline Drawing mirrored_drawing(const char* name) {
  Drawing d(name);
  for (Path& p : d.scene.paths)
    for (auto& sp : p.subpaths)
      for (Vec2& q : sp.points) q.x = d.scene.width - q.x;
  d.rig = build_rig(d.scene, {});
  return d;
}

// eye_tail.svg, a four-legged animal whose eye on its snout at the left shows it faces left,
// with that facing read (apply_eye_cue): the travel, turn and gait tests' animal.
inline Drawing eye_tail_animal() {
  Drawing d("eye_tail.svg");
  apply_eye_cue(d.rig, d.scene, d.scene);
  return d;
}

}  // namespace svgm::test
