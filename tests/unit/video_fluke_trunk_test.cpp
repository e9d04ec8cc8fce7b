// A body drawn as one thick terminal branch of its skeleton (motion/limbs.cpp's trunk): a whale
// whose tail fluke forks off a thin stalk (tests/data/motion/fluke_tail.svg) has its body as the
// core and the stalk with both lobes as one limb, turning about the stalk's root; before, the
// fork's junction was the core and the whole body hung from it as a limb.
#include <doctest/doctest.h>

#include <string>

#include "svgmotion/svg_reader.h"
#include "procedural/skeleton_lobes.h"
#include "test_paths.h"

using namespace svgm;

TEST_SUITE("video") {

TEST_CASE("a whale's forked fluke on a thin stalk is one limb turning about the stalk's root; the body is no limb") {
  // The drawing: an ellipse (the body, x 5-75, y 34-66) and a stalk from its top right (x 68-75,
  // y 22-46) forking at y 17-22 into two lobes with tips near (60.5, 9.5) and (84.5, 9.5).
  const Scene s = read_svg_file(svgm::test::data_path("motion/fluke_tail.svg"));
  const std::vector<ArmLobe> lobes = skeleton_lobes(s, {0, 1});
  REQUIRE(lobes.size() == 1);
  const ArmLobe& fluke = lobes[0];
  double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
  for (Vec2 q : fluke.outline) x0 = std::min(x0, q.x), y0 = std::min(y0, q.y), x1 = std::max(x1, q.x), y1 = std::max(y1, q.y);
  // Both lobes' tips lie in it (the outline's box reaches both, within its 1 px of growth).
  CHECK(x0 < 60);
  CHECK(x1 > 85);
  CHECK(y0 < 9);
  // The body stays out: the lobe ends below the stalk's root, far from the body's left end.
  CHECK(y1 < 52);
  CHECK(x0 > 50);
  // It turns about the stalk's root, where the stalk leaves the body (x 68-75, y 40-48), not at
  // the fork (y 17-22).
  CHECK(fluke.pivot.x > 64);
  CHECK(fluke.pivot.x < 77);
  CHECK(fluke.pivot.y > 38);
  CHECK(fluke.pivot.y < 50);
}

}  // TEST_SUITE
