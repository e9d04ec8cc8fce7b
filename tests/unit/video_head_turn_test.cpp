// A portrait's head nodding and shaking out of the picture's plane (procedural/head_turn.h): the
// ball's geometry computed by hand, and on the test bust (tests/data/motion/bust_portrait.svg,
// made for bust_head's tests) a nod dips the eyes straight down while a shake slides them aside
// with the top of the hair (the outline) held, where a turn in the plane about the neck moved
// the eyes sideways and the hair's top the farthest of all.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "procedural/head_turn.h"
#include "procedural/motion_plan.h"
#include "procedural/prompt_parse.h"

#include "motion_drawing.h"
using namespace svgm;
using svgm::test::Drawing;

namespace {

RigBox box(double x0, double y0, double x1, double y1) {
  RigBox b;
  b.add(Vec2{x0, y0});
  b.add(Vec2{x1, y1});
  return b;
}

// The index, in animate_plan's frame, of path `p`'s control point nearest `q`.
size_t point_near(const Scene& scene, int p, Vec2 q) {
  size_t i = 0, best = 0;
  double d = 1e300;
  for (size_t pi = 0; pi < scene.paths.size(); ++pi)
    for (const auto& sp : scene.paths[pi].subpaths)
      for (Vec2 c : sp.points) {
        if (static_cast<int>(pi) == p && std::hypot(c.x - q.x, c.y - q.y) < d) d = std::hypot(c.x - q.x, c.y - q.y), best = i;
        ++i;
      }
  return best;
}

// The largest displacement of point i from frame 0 over F frames, and its x and y then.
struct Move {
  double d = 0, dx = 0, dy = 0;
};
Move largest_move(const std::vector<Vec2>& pts, int F, size_t i) {
  const size_t per = pts.size() / static_cast<size_t>(F);
  Move m;
  for (int f = 1; f < F; ++f) {
    const Vec2 a = pts[i], b = pts[static_cast<size_t>(f) * per + i];
    if (std::hypot(b.x - a.x, b.y - a.y) > m.d) m = {std::hypot(b.x - a.x, b.y - a.y), b.x - a.x, b.y - a.y};
  }
  return m;
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("head turn: small shapes inside the ball are features (with its depth at their middle), the rest its outline") {
  const RigBox head = box(40, 20, 160, 140);  // middle (100, 80), radii 60
  const std::vector<HeadPath> p = head_paths(head, {box(50, 30, 150, 140), box(80, 75, 90, 85), box(150, 75, 170, 95)});
  REQUIRE(p.size() == 3);
  CHECK(p[0].depth == 0);                                                    // the face: the outline
  CHECK(p[1].depth == doctest::Approx(std::sqrt(1 - (15.0 / 60) * (15.0 / 60))));  // an eye at (85, 80)
  CHECK(p[2].depth == 0);                                                    // an ear, its middle beyond the rim
}

TEST_CASE("head turn: a pitch slides a feature down whole by r sin less towards the rim, and shortens the outline about the neck") {
  const RigBox head = box(40, 20, 160, 140);
  const Vec2 neck{100, 140};
  const double c30 = std::cos(M_PI / 6);
  const HeadPath outline, eyes{{100, 80}, 1}, mouth{{100, 116}, 0.8};
  // The outline: the top comes down by 120 (1 - cos), the chin stays on the neck.
  CHECK(head_turn_point(head, neck, HeadAxis::Pitch, 30, outline, {100, 20}).y == doctest::Approx(140 - 120 * c30));
  CHECK(head_turn_point(head, neck, HeadAxis::Pitch, 30, outline, {100, 140}).y == doctest::Approx(140));
  CHECK(head_turn_point(head, neck, HeadAxis::Pitch, 30, outline, {45, 150}).y == 150);  // hair hanging below the neck
  // A feature in the middle slides by r sin 30 = 30, every point of it alike.
  const Vec2 e = head_turn_point(head, neck, HeadAxis::Pitch, 30, eyes, {105, 85});
  CHECK(e.x == doctest::Approx(105));
  CHECK(e.y == doctest::Approx(115));
  // The mouth, 0.6 of the radius below the middle: 36 (cos - 1) + 0.8 * 60 sin = 19.2, still above the chin.
  const Vec2 m = head_turn_point(head, neck, HeadAxis::Pitch, 30, mouth, {100, 116});
  CHECK(m.y == doctest::Approx(116 + 36 * (c30 - 1) + 24));
  CHECK(m.y < 140);
  // Back (negative): the face tips up.
  CHECK(head_turn_point(head, neck, HeadAxis::Pitch, -30, eyes, {100, 80}).y < 80);
}

TEST_CASE("head turn: a yaw slides a feature aside by r sin, narrows the rim by cos; in the plane nothing changes") {
  const RigBox head = box(40, 20, 160, 140);
  const Vec2 neck{100, 140};
  const HeadPath outline, eyes{{100, 80}, 1};
  const Vec2 e = head_turn_point(head, neck, HeadAxis::Yaw, 30, eyes, {95, 80});
  CHECK(e.x == doctest::Approx(125));
  CHECK(e.y == doctest::Approx(80));
  const Vec2 rim = head_turn_point(head, neck, HeadAxis::Yaw, 30, outline, {160, 80});
  CHECK(rim.x == doctest::Approx(100 + 60 * std::cos(M_PI / 6)));
  CHECK(rim.y == 80);
  // The outline's point in the middle (1 - r^2 = 1) slides as a feature there; its top holds.
  CHECK(head_turn_point(head, neck, HeadAxis::Yaw, 30, outline, {100, 80}).x == doctest::Approx(130));
  CHECK(head_turn_point(head, neck, HeadAxis::Yaw, 30, outline, {100, 20}).x == doctest::Approx(100));
  const Vec2 same = head_turn_point(head, neck, HeadAxis::Plane, 30, eyes, {120, 70});
  CHECK(same.x == 120);
  CHECK(same.y == 70);
}

TEST_CASE("head turn: the verbs") {
  CHECK(head_axis_of("nod") == HeadAxis::Pitch);
  CHECK(head_axis_of("bow") == HeadAxis::Pitch);
  CHECK(head_axis_of("shake") == HeadAxis::Yaw);
  CHECK(head_axis_of("look") == HeadAxis::Yaw);
  CHECK(head_axis_of("lean") == HeadAxis::Plane);
}

TEST_CASE("head turn: on a bust a nod dips the eyes straight down, a shake slides them aside with the hair's top held") {
  const Drawing d("bust_portrait.svg");
  constexpr int F = 25;
  // The left eye (path 2, a circle about (85, 80)) and the hair's top (path 0, (100, 15)).
  const size_t eye = point_near(d.scene, 2, {85, 75}), hair_top = point_near(d.scene, 0, {100, 15});
  {
    const MotionPlan plan = plan_from_prompt(parse_prompt("she nods her head"), d.rig, 1);
    REQUIRE(plan.actions.size() == 1);
    CHECK(plan.actions[0].head_axis == HeadAxis::Pitch);
    const std::vector<Vec2> pts = animate_plan(d.scene, d.rig, plan, F);
    const Move m = largest_move(pts, F, eye);
    CHECK(m.dy > 10);                         // down, by about a sixth of the head's height
    CHECK(std::fabs(m.dx) < 0.25 * m.dy);     // straight down: turned in the plane it went aside
    CHECK(d.travel(plan, F)[4] == 0.0);       // the shoulders hold
  }
  {
    const MotionPlan plan = plan_from_prompt(parse_prompt("he shakes his head"), d.rig, 1);
    REQUIRE(plan.actions.size() == 1);
    CHECK(plan.actions[0].head_axis == HeadAxis::Yaw);
    const std::vector<Vec2> pts = animate_plan(d.scene, d.rig, plan, F);
    const Move m = largest_move(pts, F, eye);
    CHECK(std::fabs(m.dx) > 10);
    CHECK(std::fabs(m.dy) < 0.25 * std::fabs(m.dx));
    // On the ball's rim, straight above its middle: a yaw leaves it nearly (the ball's box is the
    // head lobe's outline, a little larger than the hair); turned in the plane about the neck,
    // 125 below it, it moved the most of any point.
    CHECK(largest_move(pts, F, hair_top).d < 5.0);
  }
}

}  // TEST_SUITE
