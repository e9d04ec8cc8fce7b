// The limbs of a silhouette's skeleton as lobes (procedural/skeleton_lobes.h): what a limb holds,
// drawn apart from the figure at its hand, moves with the limb; a piece drawn apart at the
// shoulders (a head) does not.
#include <doctest/doctest.h>

#include "svgmotion/svg_reader.h"
#include "procedural/skeleton_lobes.h"

using namespace svgm;

namespace {

// How many of path `p`'s control points lie in `lobe`.
int points_in(const Scene& s, int p, const ArmLobe& lobe) {
  int n = 0;
  for (const Subpath& sp : s.paths[p].subpaths)
    for (const Vec2& q : sp.points) n += lobe_depth(lobe, q) > 0;
  return n;
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("a sword drawn apart from the hand holding it is part of the arm's lobe; a head drawn apart from the shoulders is not") {
  // A figure facing the viewer: a torso, two legs, an arm out to each side, and, each its own
  // stroke, a sword from just beyond the left hand (a 2 px gap) and a head floating 3 px above
  // the shoulders. The gap is a hand's grip, not a join, the way openmoji draw a fencer.
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">
           <path d="M 90 95 L 170 95 L 170 105 L 110 105 L 110 130 L 120 190 L 108 190 L 100 140
                    L 92 190 L 80 190 L 90 130 L 90 105 L 30 105 L 30 95 Z" fill="#333"/>
           <path d="M 26 100 L 5 40" stroke="#000" stroke-width="4" fill="none"/>
           <circle cx="100" cy="80" r="12" fill="#333"/></svg>)", "swordsman.svg");
  const std::vector<ArmLobe> lobes = skeleton_lobes(s, {0, 1, 2});
  int left_arm = -1, right_arm = -1;
  for (size_t i = 0; i < lobes.size(); ++i) {
    if (lobes[i].tip.y < 120 && lobes[i].tip.x < 60) left_arm = static_cast<int>(i);
    if (lobes[i].tip.y < 120 && lobes[i].tip.x > 140) right_arm = static_cast<int>(i);
  }
  REQUIRE(left_arm >= 0);
  REQUIRE(right_arm >= 0);
  // Every point of the sword lies in the left arm's lobe, none in the other limbs'.
  const int sword_points = static_cast<int>(s.paths[1].subpaths.at(0).points.size());
  CHECK(points_in(s, 1, lobes[left_arm]) == sword_points);
  for (size_t i = 0; i < lobes.size(); ++i) {
    if (static_cast<int>(i) != left_arm) CHECK(points_in(s, 1, lobes[i]) == 0);
    CHECK(points_in(s, 2, lobes[i]) == 0);  // the head rides with no limb
  }
}

}  // TEST_SUITE
