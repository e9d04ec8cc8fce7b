// What a figure hangs from (hang_support.h): a bar drawn across the top of a figure hanging
// from it (tests/data/motion/hang_from_bar.svg) is its support, gripped at its middle; the same
// bar under a figure standing on it is none. "hangs from the branch" names it; the bar stays while
// the figure sways about its grip.
#include <doctest/doctest.h>

#include <cmath>

#include "svgmotion/svg_reader.h"
#include "procedural/hang_support.h"
#include "procedural/motion_plan.h"
#include "procedural/prompt_parse.h"
#include "test_paths.h"
#include "wordnet_or_skip.h"

using namespace svgm;

namespace {

Scene scene_of(const char* f) { return read_svg_file(svgm::test::data_path(f)); }
Rig rig_of(const char* f, const Scene& s) { return build_rig(s, read_source_names(svgm::test::data_path(f))); }
int path_index(const Scene& s, const std::string& id) {
  for (size_t i = 0; i < s.paths.size(); ++i)
    if (s.paths[i].id == id) return static_cast<int>(i);
  return -1;
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("a bar across the top of a hanging figure is its support, gripped on its line above the figure's middle") {
  const char* f = "motion/hang_from_bar.svg";
  const Scene s = scene_of(f);
  const Rig rig = rig_of(f, s);
  const HangSupport h = hang_support(s, rig);
  REQUIRE(h.found);
  for (size_t i = 0; i < s.paths.size(); ++i) CHECK(h.paths[i] == (s.paths[i].id == "rail"));
  // On the bar (y 10-14), above the middle of the figure below it (symmetric about x = 50; its
  // control points nearly so).
  CHECK(h.grip.y > 10);
  CHECK(h.grip.y < 14);
  CHECK(std::fabs(h.grip.x - 50) < 1);
}

TEST_CASE("the same bar under a figure standing on it holds nothing up") {
  const char* f = "motion/stand_on_bar.svg";
  const Scene s = scene_of(f);
  CHECK_FALSE(hang_support(s, rig_of(f, s)).found);
}

TEST_CASE("'hangs from the branch' keeps the bar still and swings the figure about its grip") {
  if (!wordnet_or_skip()) return;
  const char* f = "motion/hang_from_bar.svg";
  const Scene s = scene_of(f);
  const Rig rig = rig_of(f, s);
  const MotionPlan plan = plan_from_prompt(parse_prompt("it hangs from the branch and sways"), rig, 1);
  CHECK(plan.hang == "from the branch");
  CHECK(plan_from_prompt(parse_prompt("it sways"), rig, 1).hang.empty());
  CHECK(plan_from_prompt(parse_prompt("it hangs from its branch and sways"), rig, 1).hang.empty());
  const HangSupport h = hang_support(s, rig);
  const int frames = 9;
  const std::vector<Vec2> pts = animate_plan(s, rig, plan, frames);
  size_t n = 0;
  for (const Path& p : s.paths)
    for (const Subpath& sp : p.subpaths) n += sp.points.size();
  REQUIRE(pts.size() == n * frames);
  const int bar = path_index(s, "rail"), body = path_index(s, "body");
  double bar_moved = 0, body_moved = 0, grip_dist_change = 0;
  size_t k = 0;
  for (size_t pi = 0; pi < s.paths.size(); ++pi)
    for (const Subpath& sp : s.paths[pi].subpaths)
      for (const Vec2& q : sp.points) {
        for (int fr = 0; fr < frames; ++fr) {
          const Vec2 m = pts[fr * n + k];
          const double d = std::hypot(m.x - q.x, m.y - q.y);
          if (static_cast<int>(pi) == bar) bar_moved = std::max(bar_moved, d);
          if (static_cast<int>(pi) == body) {
            body_moved = std::max(body_moved, d);
            // A pendulum about the grip: every point keeps its distance from it.
            const Vec2 g = h.grip;
            grip_dist_change = std::max(grip_dist_change, std::fabs(std::hypot(m.x - g.x, m.y - g.y) - std::hypot(q.x - g.x, q.y - g.y)));
          }
        }
        ++k;
      }
  CHECK(bar_moved < 1e-9);
  CHECK(body_moved > 2);
  CHECK(grip_dist_change < 0.05);
}

}
