// A fill and the outline drawn over it move as one (procedural/detail_binding.h, animate_plan):
// a drawing whose colours and line art are two groups (an arm's fill in the colour group, its
// black outline in the line group drawn on top, as openmoji draws them), on a rig made by hand so
// that each way the two used to part is set up exactly: the plan swings the outline's part and
// not the fill's; it swings both about different pivots; it bends a located limb whose paths are
// the outline's only. In every frame each point of the outline must lie on the moved fill's
// boundary (the outline traces it exactly at rest), and the arm must visibly move.
#include <doctest/doctest.h>

#include <cmath>

#include "geometry/curve_samples.h"
#include "procedural/motion_plan.h"
#include "svgmotion/svg_reader.h"

using namespace svgm;

namespace {

// Body 30..70 x 40..90, an arm 70..95 x 45..55 reaching right; then their outlines, on top.
constexpr const char* kDrawing = R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100" viewBox="0 0 100 100">
  <g id="color">
    <path d="M 30 40 L 70 40 L 70 90 L 30 90 Z" fill="#c03030"/>
    <path d="M 70 45 L 95 45 L 95 55 L 70 55 Z" fill="#30c030"/>
  </g>
  <g id="line">
    <path d="M 30 40 L 70 40 L 70 90 L 30 90 Z" fill="none" stroke="#000" stroke-width="2"/>
    <path d="M 70 45 L 95 45 L 95 55 L 70 55" fill="none" stroke="#000" stroke-width="2"/>
  </g>
</svg>)";

constexpr size_t kArmFill = 1, kArmLine = 3;
constexpr int kFrames = 9;

RigPart part(Role role, int parent, RigBox box, Vec2 pivot) {
  RigPart p;
  p.role = role;
  p.parent = parent;
  p.box = box;
  p.pivot = pivot;
  p.name = role_name(role);
  return p;
}

// Parts: 0 the body (root), 1 the arm's fill, 2 the line group, 3 the arm's outline; `of_path`
// puts the four paths in them.
Rig hand_rig(std::vector<int> of_path) {
  Rig rig;
  rig.parts = {part(Role::Root, -1, {30, 40, 70, 90}, {50, 90}), part(Role::UpperLimb, 0, {70, 45, 95, 55}, {70, 50}),
               part(Role::Detail, 0, {30, 40, 70, 90}, {50, 90}), part(Role::UpperLimb, 0, {70, 45, 95, 55}, {70, 50})};
  for (int g = 0; g < 4; ++g) rig.parts[g].chain_top = g == 0 ? -1 : g;
  rig.root = 0;
  rig.canvas = {0, 0, 100, 100};
  rig.figure = {30, 40, 95, 90};
  rig.part_of_path = std::move(of_path);
  return rig;
}

PlannedAction swing(int part, double deg) {
  PlannedAction a;
  a.verb = "swing";
  a.primitive = Primitive::Swing;
  a.target = Target::Named;
  a.parts = {part};
  a.sign = {1};
  a.phase = {0};
  a.amp = deg;
  return a;
}

size_t first_point(const Scene& s, size_t path) {
  size_t i = 0;
  for (size_t p = 0; p < path; ++p)
    for (const auto& sp : s.paths[p].subpaths) i += sp.points.size();
  return i;
}

struct Apart {
  double off = 0;    // the outline's farthest point from the moved fill's boundary, any frame
  double moved = 0;  // how far the arm's tip went
};

// The moved fill is a polygon (its cubics are lines): the distance of each moved outline point to
// its edges.
Apart measure(const Scene& scene, const Rig& rig, const MotionPlan& plan) {
  const std::vector<Vec2> pts = animate_plan(scene, rig, plan, kFrames);
  const size_t per = pts.size() / kFrames, fill0 = first_point(scene, kArmFill), line0 = first_point(scene, kArmLine);
  const size_t fill_n = scene.paths[kArmFill].subpaths[0].points.size(), line_n = scene.paths[kArmLine].subpaths[0].points.size();
  Apart r;
  for (int f = 0; f < kFrames; ++f) {
    auto at = [&](size_t i) { return pts[f * per + i]; };
    for (size_t k = 0; k < line_n; k += 3) {
      double d = 1e300;
      for (size_t j = 0; j + 3 < fill_n; j += 3) d = std::min(d, segment_distance(at(line0 + k), at(fill0 + j), at(fill0 + j + 3)));
      r.off = std::max(r.off, d);
    }
    const Vec2 tip = at(fill0 + 3);  // (95, 45) at rest
    r.moved = std::max(r.moved, std::hypot(tip.x - 95, tip.y - 45));
  }
  return r;
}

}  // namespace

TEST_SUITE("motion") {

TEST_CASE("traced fill: a still fill goes with the outline the plan swings") {
  const Scene scene = read_svg_string(kDrawing, "traced.svg");
  REQUIRE(scene.paths.size() == 4);
  // The arm's fill is in the body's part; its outline is a part of its own, and it swings.
  const Rig rig = hand_rig({0, 0, 2, 3});
  MotionPlan plan;
  plan.actions = {swing(3, 30)};
  const Apart r = measure(scene, rig, plan);
  CHECK(r.off < 1e-6);
  CHECK(r.moved > 5.0);  // 30 degrees about (70, 50) moves the tip about 13 px
}

TEST_CASE("traced fill: an outline swung its own way goes with its moving fill") {
  const Scene scene = read_svg_string(kDrawing, "traced.svg");
  Rig rig = hand_rig({0, 1, 2, 3});
  rig.parts[3].pivot = {95, 50};  // the outline's part turns about its far end
  MotionPlan plan;
  plan.actions = {swing(1, 30), swing(3, -20)};
  const Apart r = measure(scene, rig, plan);
  CHECK(r.off < 1e-6);
  CHECK(r.moved > 5.0);
}

TEST_CASE("traced fill: a located limb found as the outline's path bends its fill with it") {
  const Scene scene = read_svg_string(kDrawing, "traced.svg");
  const Rig rig = hand_rig({0, 0, 2, 2});  // colours in the body's part, lines in the line group
  PlannedAction a = swing(0, 30);
  a.region = Region::Located;
  a.silhouette = true;
  a.lobe_paths = {static_cast<int>(kArmLine)};
  ArmLobe l;
  l.side = 1;
  l.base0 = {70, 40};
  l.base1 = {70, 60};
  l.pivot = {70, 50};
  l.tip = {95, 50};
  l.outline = {{70, 40}, {97, 40}, {97, 60}, {70, 60}};
  a.lobes = {l};
  MotionPlan plan;
  plan.actions = {a};
  const Apart r = measure(scene, rig, plan);
  CHECK(r.off < 1e-6);
  CHECK(r.moved > 5.0);
}

}  // TEST_SUITE
