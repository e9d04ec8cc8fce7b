// A figure sent against the way it faces turns round to go (procedural/travel_profile.h,
// gait_travel.h's goes_against_facing): mirrored about its vertical axis while it goes the told
// way, turned back to come home facing its own way, at rest at both ends of the loop; the turn
// never narrows it past what the pixel ranker reads as a colour vanishing or jumping. Told its
// own way, or with its facing not known, it goes as before.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "procedural/eye_cue.h"
#include "procedural/gait_travel.h"
#include "procedural/motion_plan.h"
#include "procedural/travel_profile.h"
#include "rank/pixel_ranker.h"

#include "motion_drawing.h"
using namespace svgm;
using svgm::test::Drawing;
using svgm::test::eye_tail_animal;

namespace {

// Whether the plan's travel (the whole figure's slide) turns round.
int turning_slides(const MotionPlan& plan) {
  int n = 0;
  for (const auto& a : plan.actions) n += a.primitive == Primitive::Slide && a.parts.empty() && a.turns_round;
  return n;
}

// The middle of path `p`'s points in frame f of `pts`.
Vec2 path_middle(const Scene& scene, const std::vector<Vec2>& pts, int F, int f, size_t p) {
  size_t first = 0;
  for (size_t q = 0; q < p; ++q)
    for (const auto& sp : scene.paths[q].subpaths) first += sp.points.size();
  size_t n = 0;
  for (const auto& sp : scene.paths[p].subpaths) n += sp.points.size();
  const size_t per = pts.size() / F;
  Vec2 sum{0, 0};
  for (size_t i = 0; i < n; ++i) sum = sum + pts[f * per + first + i];
  return (1.0 / static_cast<double>(n)) * sum;
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("turn round: at rest at both ends, mirrored going out, facing its own way coming home") {
  CHECK(turned_going_at(0).along == 0);
  CHECK(turned_going_at(0).turns == 0);
  CHECK(turned_going_at(kTurnShare).along == doctest::Approx(0));
  CHECK(turned_going_at(kTurnShare).turns == doctest::Approx(0.5));
  CHECK(turned_going_at(0.5).along == doctest::Approx(1));
  CHECK(turned_going_at(0.5 + kTurnShare).turns == doctest::Approx(1));
  CHECK(turned_going_at(1 - 1e-9).along == doctest::Approx(0).epsilon(1e-6));
  // Its width: whole facing either way, kTurnRoundEdge edge on, mirrored past it.
  CHECK(turned_width(0) == doctest::Approx(1));
  CHECK(turned_width(0.5) == doctest::Approx(-1));
  CHECK(turned_width(1) == doctest::Approx(1));
  CHECK(std::fabs(turned_width(0.2499)) == doctest::Approx(kTurnRoundEdge).epsilon(1e-3));
  CHECK(turned_width(0.2) > 0);
  CHECK(turned_width(0.3) < 0);
  CHECK(turned_width(0.7) < 0);
  CHECK(turned_width(0.8) > 0);
  // The ranker's 16 frames of a 49-frame loop: no width (a colour's area) changes by 55 % or
  // more between two of them, and none falls under kRankVanishRatio of its rest (pixel_ranker.h).
  double jump = 0, least = 1;
  for (int k = 0; k + 1 < 16; ++k) {
    const double a = std::fabs(turned_width(turned_going_at(std::lround(k * 48.0 / 15) / 48.0).turns));
    const double b = std::fabs(turned_width(turned_going_at(std::lround((k + 1) * 48.0 / 15) / 48.0).turns));
    jump = std::max(jump, std::fabs(a - b) / std::max(a, b));
    least = std::min({least, a, b});
  }
  CHECK(jump < 0.55);
  CHECK(least >= kRankVanishRatio);
}

TEST_CASE("turn round: an animal facing left told to walk right turns round; told left, untold or facing unknown, it does not") {
  Drawing d = eye_tail_animal();  // a four-legged animal, its eye on the snout at the left
  REQUIRE(d.rig.eye_side == -1);
  for (const char* prompt : {"the animal walks to the right", "the dog trots off to the right", "the fish swims to the right"}) {
    CAPTURE(prompt);
    CHECK(turning_slides(plan_from_prompt(parse_prompt(prompt), d.rig, 1)) == 1);
  }
  for (const char* prompt : {"the animal walks to the left", "the animal walks", "the animal walks on the spot"}) {
    CAPTURE(prompt);
    CHECK(turning_slides(plan_from_prompt(parse_prompt(prompt), d.rig, 1)) == 0);
  }
  std::string why;
  CHECK(goes_against_facing(d.rig, FigureClass::Quadruped, 1, &why));
  CHECK(why == "it faces left (its eye): it turns round to go right and turns back to come home facing its own way");
  CHECK_FALSE(goes_against_facing(d.rig, FigureClass::Quadruped, -1, nullptr));
  // A person seen from the front: no facing known, no turn.
  const Drawing man("stick_figure.svg");
  CHECK(turning_slides(plan_from_prompt(parse_prompt("the man walks to the right"), man.rig, 1)) == 0);
}

TEST_CASE("turn round: the animal's eye goes to its right side going out, back to its left coming home, at rest at the loop's ends") {
  Drawing d = eye_tail_animal();
  MotionPlan plan = plan_from_prompt(parse_prompt("the animal walks to the right"), d.rig, 1);
  const int F = 49;  // t = f / 48
  fit_plan(d.scene, d.rig, plan, F, 15);
  CHECK(plan.warnings.empty());
  REQUIRE(turning_slides(plan) == 1);
  const std::vector<Vec2> pts = animate_plan(d.scene, d.rig, plan, F);
  const double cx = d.rig.figure.centre().x;
  const Vec2 rest = path_middle(d.scene, pts, F, 0, 1);  // the eye (path 1)
  REQUIRE(rest.x < cx);
  // Going out (frames 10..23, turned round): the eye at the right of the figure's rest middle,
  // beyond its mirror image of rest by the way it has gone; farthest a half loop in.
  const double mirrored = 2 * cx - rest.x;
  for (int f = 10; f <= 23; ++f) CHECK(path_middle(d.scene, pts, F, f, 1).x > mirrored + 0.01);
  for (int f = 11; f <= 23; ++f) CHECK(path_middle(d.scene, pts, F, f, 1).x > path_middle(d.scene, pts, F, f - 1, 1).x);
  // Coming home (frames 34..47, facing its own way): the eye at the left, going left to rest.
  for (int f = 34; f <= 47; ++f) {
    CHECK(path_middle(d.scene, pts, F, f, 1).x < cx);
    CHECK(path_middle(d.scene, pts, F, f, 1).x >= rest.x - 1e-9);
    CHECK(path_middle(d.scene, pts, F, f, 1).x < path_middle(d.scene, pts, F, f - 1, 1).x + 1e-9);
  }
  const size_t per = pts.size() / F;
  for (size_t i = 0; i < per; ++i) {
    CHECK(pts[(F - 1) * per + i].x == doctest::Approx(pts[i].x));
    CHECK(pts[(F - 1) * per + i].y == doctest::Approx(pts[i].y));
  }
}

}  // TEST_SUITE
