// Limbs from the silhouette skeleton (motion/limbs.h): a stick figure's five limbs with their
// labels, sides and tips, a quadruped's legs, head and tail (and a leg standing off its tail's
// branch, which the tail does not own), a bent arm's elbow, and which limb owns which points,
// paths and pixels.
#include <doctest/doctest.h>

#include <cmath>

#include "motion/limbs.h"
#include "motion_masks.h"

using namespace svgm;
using namespace svgm::motion;

namespace {

double distance(Vec2 a, Vec2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

int count(const Figure& f, LimbKind k) {
  int n = 0;
  for (const auto& L : f.limbs) n += L.kind == k;
  return n;
}

// The limb of kind k whose tip is nearest `near`, or -1.
// motion_masks::quadruped without its tail.
cv::Mat tailless_quadruped() {
  cv::Mat m(160, 220, CV_8U, cv::Scalar(0));
  cv::ellipse(m, {110, 70}, {55, 22}, 0, 0, 360, 255, cv::FILLED);
  for (int x : {70, 85, 135, 150}) cv::line(m, {x, 80}, {x, 140}, 255, 8);
  cv::line(m, {155, 60}, {180, 30}, 255, 10);
  cv::ellipse(m, {188, 25}, {16, 10}, 0, 0, 360, 255, cv::FILLED);
  return m;
}

int find(const Figure& f, LimbKind k, Vec2 near) {
  int best = -1;
  for (size_t i = 0; i < f.limbs.size(); ++i)
    if (f.limbs[i].kind == k && (best < 0 || distance(f.limbs[i].tip_pos, near) < distance(f.limbs[best].tip_pos, near)))
      best = static_cast<int>(i);
  return best;
}

}  // namespace

TEST_SUITE("motion") {
  TEST_CASE("a stick figure has a head, two arms and two legs on the ground") {
    const Skeleton s = skeletonise(motion_masks::stick_figure());
    const Figure f = find_limbs(s);
    CHECK(f.upright);
    REQUIRE(f.limbs.size() == 5);
    CHECK(count(f, LimbKind::Head) == 1);
    CHECK(count(f, LimbKind::Arm) == 2);
    CHECK(count(f, LimbKind::Leg) == 2);
    const int head = find(f, LimbKind::Head, {80, 30});
    REQUIRE(head >= 0);
    CHECK(distance(f.limbs[head].tip_pos, {80, 30}) <= 3);
    CHECK(f.limbs[head].tip_radius == doctest::Approx(14).epsilon(0.1));
    const int arm_l = find(f, LimbKind::Arm, {50, 80}), arm_r = find(f, LimbKind::Arm, {110, 80});
    REQUIRE((arm_l >= 0 && arm_r >= 0 && arm_l != arm_r));
    CHECK(f.limbs[arm_l].side == -1);
    CHECK(f.limbs[arm_r].side == 1);
    CHECK(distance(f.limbs[arm_l].tip_pos, {50, 80}) <= 3);
    CHECK(distance(f.limbs[arm_r].tip_pos, {110, 80}) <= 3);
    for (Vec2 foot : {Vec2{60, 145}, Vec2{100, 145}}) {
      const int leg = find(f, LimbKind::Leg, foot);
      REQUIRE(leg >= 0);
      CHECK(f.limbs[leg].grounded);
      CHECK(distance(f.limbs[leg].tip_pos, foot) <= 3);
      CHECK(distance(s.nodes[f.limbs[leg].joint].pos, {80, 95}) <= 8);  // the hips: the axis forks below the lines' meeting point
      CHECK_FALSE(f.limbs[leg].bent);
    }
    CHECK_FALSE(f.limbs[arm_l].grounded);
  }

  TEST_CASE("a quadruped has four legs down, a head at its front and a tail at its back") {
    const Figure f = find_limbs(skeletonise(motion_masks::quadruped()));
    CHECK_FALSE(f.upright);
    CHECK(count(f, LimbKind::Leg) == 4);
    CHECK(count(f, LimbKind::Head) == 1);
    CHECK(count(f, LimbKind::Tail) == 1);
    const int head = find(f, LimbKind::Head, {188, 25}), tail = find(f, LimbKind::Tail, {25, 45});
    REQUIRE((head >= 0 && tail >= 0));
    CHECK(distance(f.limbs[head].tip_pos, {188, 25}) <= 10);
    CHECK(distance(f.limbs[tail].tip_pos, {25, 45}) <= 3);
    for (const auto& L : f.limbs)
      if (L.kind == LimbKind::Leg) CHECK(L.tip_pos.y >= 135);
  }

  TEST_CASE("a tail hanging down from the top of the body's back end is a tail, not a leg") {
    // The quadruped's tail redrawn as a cow's: from the top of its back end (58, 55) down to
    // (40, 110), off the ground the four legs stand on.
    cv::Mat m = motion_masks::quadruped();
    cv::line(m, {58, 65}, {25, 45}, 0, 7);  // rub out the sideways tail
    cv::ellipse(m, {110, 70}, {55, 22}, 0, 0, 360, 255, cv::FILLED);
    cv::line(m, {60, 56}, {40, 110}, 255, 5);
    const Figure f = find_limbs(skeletonise(m));
    CHECK(count(f, LimbKind::Leg) == 4);
    const int tail = find(f, LimbKind::Tail, {40, 110});
    REQUIRE(tail >= 0);
    CHECK(distance(f.limbs[tail].tip_pos, {40, 110}) <= 4);
    CHECK_FALSE(f.limbs[tail].grounded);
  }

  TEST_CASE("a leg standing on a fork of the tail's branch is the body's: the tail's region leaves it") {
    // A quadruped facing right whose back leg stands from (70, 80) down to the ground line (y
    // 110) the front legs stand on, and whose thin tail leaves that leg low, at (70, 100), and
    // rises to (5, 30): one branch of the skeleton with two ends (a tiger's hind leg drawn off
    // the root of its tail). The tail is its longest path, off the ground.
    cv::Mat m(160, 220, CV_8U, cv::Scalar(0));
    cv::ellipse(m, {110, 70}, {55, 22}, 0, 0, 360, 255, cv::FILLED);
    for (int x : {135, 150}) cv::line(m, {x, 80}, {x, 110}, 255, 8);
    cv::line(m, {155, 60}, {180, 30}, 255, 10);
    cv::ellipse(m, {188, 25}, {16, 10}, 0, 0, 360, 255, cv::FILLED);
    cv::line(m, {70, 80}, {70, 110}, 255, 8);
    cv::line(m, {70, 100}, {5, 30}, 255, 5);
    const Skeleton s = skeletonise(m);
    const Figure f = find_limbs(s);
    const int tail = find(f, LimbKind::Tail, {5, 30});
    REQUIRE(tail >= 0);
    CHECK(distance(f.limbs[tail].tip_pos, {5, 30}) <= 4);
    CHECK_FALSE(f.limbs[tail].grounded);
    REQUIRE(f.limbs[tail].more_tips.size() == 1);  // the foot
    CHECK_FALSE(f.limbs[tail].standing_edges.empty());
    const cv::Mat regions = limb_regions(s, f);
    CHECK(regions.at<int>(46, 20) == tail);   // on the tail
    CHECK(regions.at<int>(107, 70) == -1);    // the foot is the body's
    CHECK(assign_points(s, f, {{70, 108}, {20, 46}}) == std::vector<int>{-1, tail});
  }

  TEST_CASE("a tail's branch through a thick rump starts where it gets thin: the rump is the body's") {
    // A quadruped facing right: a body 30 tall (x 40-150), a rump 44 tall round (50, 70) its
    // tail's branch runs through, and a thin tail (5 wide) from the rump's back (14, 70) up to
    // (2, 20). The tail's base is where its branch leaves the rump, not inside it.
    cv::Mat m(160, 220, CV_8U, cv::Scalar(0));
    cv::ellipse(m, {100, 70}, {50, 15}, 0, 0, 360, 255, cv::FILLED);
    cv::ellipse(m, {50, 70}, {36, 22}, 0, 0, 360, 255, cv::FILLED);
    for (int x : {60, 75, 125, 140}) cv::line(m, {x, 80}, {x, 115}, 255, 8);
    cv::line(m, {145, 62}, {175, 35}, 255, 10);
    cv::ellipse(m, {185, 28}, {16, 10}, 0, 0, 360, 255, cv::FILLED);
    cv::line(m, {16, 70}, {2, 20}, 255, 5);
    const Skeleton s = skeletonise(m);
    const Figure f = find_limbs(s);
    const int tail = find(f, LimbKind::Tail, {2, 20});
    REQUIRE(tail >= 0);
    const Limb& L = f.limbs[tail];
    CHECK(L.body_radius > 0);
    CHECK(L.base.x < 22);  // out of the rump (its back edge at x 14)
    const cv::Mat regions = limb_regions(s, f);
    CHECK(regions.at<int>(40, 8) == tail);  // on the thin tail
    CHECK(regions.at<int>(70, 40) == -1);   // the rump's middle is the body's
    CHECK(regions.at<int>(58, 30) == -1);
  }

  TEST_CASE("a tail whose branch runs through a foot on the ground starts past the foot") {
    // A quadruped facing right whose tail (5 wide) runs from its back end (58, 65) down to a
    // hind foot standing on the ground (a disc at (45, 136), r 8: its short spur is pruned, so
    // no branch of its own ends there), then curls up off the ground to (12, 108), as a tail
    // drawn down the rump and touching the hind foot. The foot is the body's, the curl the tail.
    cv::Mat m = tailless_quadruped();
    cv::line(m, {58, 65}, {45, 132}, 255, 5);
    cv::circle(m, {45, 136}, 8, 255, cv::FILLED);
    cv::line(m, {45, 134}, {12, 108}, 255, 5);
    const Skeleton s = skeletonise(m);
    const Figure f = find_limbs(s);
    const int tail = find(f, LimbKind::Tail, {12, 108});
    REQUIRE(tail >= 0);
    const Limb& L = f.limbs[tail];
    CHECK(distance(L.tip_pos, {12, 108}) <= 7);  // the thinning stops short of a line's end
    CHECK(L.body_until == L.base_index);
    CHECK(L.base.x < 45);  // past the foot's middle
    CHECK(L.base.y > 110);
    const cv::Mat regions = limb_regions(s, f);
    CHECK(regions.at<int>(142, 45) == -1);    // the foot on the ground is the body's
    CHECK(regions.at<int>(100, 50) == -1);    // and so is the stretch down to it
    CHECK(regions.at<int>(117, 24) == tail);  // the curl is the tail
  }

  TEST_CASE("a tail lying along the ground stays whole") {
    // The same quadruped whose tail runs from its back end down to the ground and along it to
    // (5, 140): its tip is on the ground line, so no foot is split off it.
    cv::Mat m = tailless_quadruped();
    cv::line(m, {58, 65}, {40, 138}, 255, 5);
    cv::line(m, {40, 138}, {5, 140}, 255, 5);
    const Figure f = find_limbs(skeletonise(m));
    for (const Limb& L : f.limbs) CHECK(L.body_until == 0);
  }

  TEST_CASE("a bent arm's elbow is where it bends") {
    cv::Mat m = motion_masks::stick_figure();
    cv::line(m, {80, 55}, {115, 60}, 255, 8);  // upper arm out to the right, forearm up
    cv::line(m, {115, 60}, {120, 25}, 255, 8);
    const Figure f = find_limbs(skeletonise(m));
    int bent = -1;
    for (size_t i = 0; i < f.limbs.size(); ++i)
      if (distance(f.limbs[i].tip_pos, {120, 25}) <= 4) bent = static_cast<int>(i);
    REQUIRE(bent >= 0);
    CHECK(f.limbs[bent].bent);
    CHECK(distance(f.limbs[bent].bend, {115, 60}) <= 5);
  }

  TEST_CASE("points, paths and pixels go to the limb they lie on") {
    const Skeleton s = skeletonise(motion_masks::stick_figure());
    const Figure f = find_limbs(s);
    const int head = find(f, LimbKind::Head, {80, 30}), arm_l = find(f, LimbKind::Arm, {50, 80}),
              leg_r = find(f, LimbKind::Leg, {100, 145});
    REQUIRE((head >= 0 && arm_l >= 0 && leg_r >= 0));
    // Control points: a head outline point, a hand, the belly (the core), a foot.
    const std::vector<Vec2> pts = {{70, 22}, {52, 79}, {83, 78}, {98, 140}, {57, 76}, {81, 20}};
    const std::vector<int> owner = assign_points(s, f, pts);
    CHECK(owner == std::vector<int>{head, arm_l, -1, leg_r, arm_l, head});
    // Paths by their points' votes: path 0 = head points, path 1 = two hand points and a belly one.
    const std::vector<int> paths = assign_paths(s, f, {{70, 22}, {81, 20}, {52, 79}, {57, 76}, {83, 78}}, {0, 0, 1, 1, 1}, 3);
    CHECK(paths == std::vector<int>{head, arm_l, -1});
    // Pixels: the right foot's pixels are the right leg's, the belly's the core's.
    const cv::Mat regions = limb_regions(s, f);
    CHECK(regions.at<int>(140, 98) == leg_r);
    CHECK(regions.at<int>(75, 80) == -1);
    CHECK(regions.at<int>(5, 5) == -2);
    cv::Mat foot(s.height, s.width, CV_8U, cv::Scalar(0)), empty = foot.clone();
    cv::circle(foot, {99, 142}, 5, 255, cv::FILLED);
    CHECK(assign_path_masks(regions, static_cast<int>(f.limbs.size()), {foot, empty}) == std::vector<int>{leg_r, -1});
  }
}
