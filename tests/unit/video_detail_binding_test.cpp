// Outlines ride on the fills they are drawn on (procedural/detail_binding.h: bind_to_hosts): a drawing whose
// colours and line art are two groups, as openmoji draws them, keeps its outlines on its moving
// fills; the outline of the still body stays; a stroke running from the body onto the neck
// stretches across the joint, its body end still and its neck end with the neck.
#include <doctest/doctest.h>

#include <cmath>

#include "svgmotion/svg_reader.h"
#include "procedural/detail_binding.h"
#include "procedural/motion_plan.h"
#include "test_paths.h"

using namespace svgm;

namespace {

std::string data(const char* name) { return svgm::test::data_path(std::string("motion/") + name); }

// Index of the first point of `path` in a frame of animate_plan's output.
size_t first_point(const Scene& s, size_t path) {
  size_t i = 0;
  for (size_t p = 0; p < path; ++p)
    for (const auto& sp : s.paths[p].subpaths) i += sp.points.size();
  return i;
}

// The index within a frame of the point of `path` at (x, y) at rest.
size_t point_at(const Scene& s, size_t path, double x, double y) {
  size_t i = first_point(s, path);
  for (const auto& sp : s.paths[path].subpaths)
    for (const Vec2& q : sp.points) {
      if (std::hypot(q.x - x, q.y - y) < 1e-6) return i;
      ++i;
    }
  FAIL("no point at " << x << "," << y << " in path " << path);
  return 0;
}

}  // namespace

TEST_SUITE("motion") {

TEST_CASE("detail binding: the outlines of a moving neck go with its fill; the shell's outline holds") {
  const Scene scene = read_svg_file(data("outlined_turtle.svg"));
  const Rig rig = build_rig(scene, read_source_names(data("outlined_turtle.svg")));
  REQUIRE(scene.paths.size() == 7);
  const int neck = rig.part_of_path[1], line = rig.part_of_path[3];
  REQUIRE(neck >= 0);
  REQUIRE(line >= 0);
  CHECK(rig.parts[line].role == Role::Detail);
  CHECK(neck != rig.root);
  // Binding: the neck's outline to the neck's fill (path 1), the shell's outline to fills of the
  // shell's part (the shell's, and the tail's where they meet: it holds as the shell does).
  const auto bound = bind_to_hosts(scene, rig);
  REQUIRE(bound[4].size() == scene.paths[4].subpaths[0].points.size());
  for (int b : bound[4]) CHECK(b == 1);
  REQUIRE(bound[3].size() == scene.paths[3].subpaths[0].points.size());
  for (int b : bound[3]) CHECK(rig.part_of_path[b] == rig.part_of_path[0]);

  const MotionPlan plan = plan_from_steps(parse_explicit_plan("nod:" + rig.parts[neck].name), rig, 1);
  const int F = 9;
  const std::vector<Vec2> pts = animate_plan(scene, rig, plan, F);
  const size_t per = pts.size() / F;
  double neck_moved = 0;
  for (int f = 1; f < F; ++f) {
    auto at = [&](size_t i) { return pts[f * per + i]; };
    // The head's tip: the fill's point and the outline's point at (20, 70) stay together.
    const Vec2 fill_tip = at(point_at(scene, 1, 20, 70)), line_tip = at(point_at(scene, 4, 20, 70));
    CHECK(std::hypot(fill_tip.x - line_tip.x, fill_tip.y - line_tip.y) < 1e-9);
    neck_moved = std::max(neck_moved, std::hypot(fill_tip.x - 20, fill_tip.y - 70));
    // The shell's outline and the body end of the shared stroke hold still.
    for (size_t i = first_point(scene, 3); i < first_point(scene, 4); ++i)
      CHECK(std::hypot(at(i).x - pts[i].x, at(i).y - pts[i].y) < 1e-9);
    const size_t body_end = point_at(scene, 5, 100, 130);
    CHECK(std::hypot(at(body_end).x - 100, at(body_end).y - 130) < 1e-9);
    // Its neck end goes with the neck.
    const Vec2 fill_joint = at(point_at(scene, 1, 40, 80)), line_joint = at(point_at(scene, 5, 40, 80));
    CHECK(std::hypot(fill_joint.x - line_joint.x, fill_joint.y - line_joint.y) < 1e-9);
  }
  CHECK(neck_moved > 3.0);  // the nod is visible: the test is not of a motion that does nothing
}

}  // TEST_SUITE
