// A figure sent somewhere goes steadily forward most of the loop and glides back (procedural/
// travel_profile.h), instead of rocking there and back about where it stands; a crawl goes by
// steps, its rear planted while its body stretches ahead, its front planted while it gathers up.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "procedural/eye_cue.h"
#include "procedural/gait_travel.h"
#include "procedural/motion_plan.h"
#include "procedural/travel_profile.h"

#include "motion_drawing.h"
using namespace svgm;
using svgm::test::Drawing;
using svgm::test::eye_tail_animal;

namespace {

// The smallest and largest x of the figure's points in frame f of `pts` (every path).
std::pair<double, double> x_span(const std::vector<Vec2>& pts, int F, int f) {
  const size_t per = pts.size() / F;
  double lo = 1e300, hi = -1e300;
  for (size_t i = 0; i < per; ++i) lo = std::min(lo, pts[f * per + i].x), hi = std::max(hi, pts[f * per + i].x);
  return {lo, hi};
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("travel profile: forward at a steady pace two thirds of the loop, then back; a crawl's ends planted in turn") {
  CHECK(going_at(0) == doctest::Approx(0));
  CHECK(going_at(1.0 / 3) == doctest::Approx(1));       // the end of the forward run, ahead
  CHECK(going_at(0.5) == doctest::Approx(0));           // half way back
  CHECK(going_at(2.0 / 3) == doctest::Approx(-1));      // the start of the run, behind
  CHECK(going_at(0.1) == doctest::Approx(0.3));         // steady: 2 units over 2/3 of the loop
  CHECK(going_at(0.9) == doctest::Approx(-0.3));
  CHECK(going_at(1.1) == doctest::Approx(going_at(0.1)));
  // A crawl: the rear still while the body stretches, the front still while it gathers, and one
  // step (2 / kCrawlSteps) gained per stretch.
  const double step = 2.0 / kCrawlSteps;
  const CrawlPose rest = crawl_at(0);
  CHECK(rest.rear == doctest::Approx(0));
  CHECK(rest.stretch == doctest::Approx(0));
  CHECK(crawl_at(1.0 / 12).rear == doctest::Approx(0));        // step 2, stretching: the rear planted
  CHECK(crawl_at(1.0 / 6).stretch == doctest::Approx(1));      // fully stretched
  CHECK(crawl_at(1.0 / 4).rear + crawl_at(1.0 / 4).stretch * step == doctest::Approx(1));  // gathering: the front at 1
  CHECK(crawl_at(1.0 / 3 - 1e-9).rear == doctest::Approx(1));
  CHECK(crawl_at(2.0 / 3).rear == doctest::Approx(-1));        // back behind, gathered
  CHECK(crawl_at(2.0 / 3).stretch == doctest::Approx(0));
  CHECK(crawl_at(0.5).stretch == doctest::Approx(0));          // gliding back: no stretch
}

TEST_CASE("travel: an animal that walks with no direction goes its way farthest a third of the loop in, a visible distance") {
  Drawing d = eye_tail_animal();  // a four-legged animal, its eye on the snout at the left
  REQUIRE(d.rig.eye_side == -1);
  const MotionPlan plan = plan_from_prompt(parse_prompt("the animal walks"), d.rig, 1);
  const int F = 25;  // t = f / 24: frame 8 is a third of the loop in
  const std::vector<Vec2> pts = animate_plan(d.scene, d.rig, plan, F);
  const double left0 = x_span(pts, F, 0).first;
  // Going left at a steady pace over frames 0..8, then gliding back behind and coming again.
  for (int f = 1; f <= 8; ++f) CHECK(x_span(pts, F, f).first < x_span(pts, F, f - 1).first);
  double farthest = 0;
  int at = 0;
  for (int f = 0; f < F; ++f)
    if (left0 - x_span(pts, F, f).first > farthest) farthest = left0 - x_span(pts, F, f).first, at = f;
  CHECK(at == 8);
  CHECK(farthest >= 0.85 * kTravelReach * d.rig.figure.w());
}

TEST_CASE("travel: a caterpillar that crawls, told or not where, stretches ahead of its planted rear and gathers behind its planted front") {
  Drawing d = eye_tail_animal();
  for (const char* prompt : {"the caterpillar crawls", "the caterpillar crawls slowly to the left"}) {
    CAPTURE(prompt);
    const MotionPlan plan = plan_from_prompt(parse_prompt(prompt), d.rig, 1);
    int inching = 0;
    for (const auto& a : plan.actions)
      if (a.parts.empty() && (a.primitive == Primitive::Slide || a.primitive == Primitive::Stretch)) {
        CHECK(a.inches);
        CHECK(a.direction == -1);
        CHECK(a.amp >= 0.85 * kTravelReach);  // told "slowly to the left", it crept 4 % of its width
        ++inching;
      }
    CHECK(inching == 2);
    const int F = 25;
    const std::vector<Vec2> pts = animate_plan(d.scene, d.rig, plan, F);
    // Frames 0..4 (t to 1/6): the body stretches left, its rear (the right end) where it was;
    // frames 4..8: it gathers up, its front (the left end) where it was. Each step gains ground.
    CHECK(x_span(pts, F, 4).second == doctest::Approx(x_span(pts, F, 0).second));
    CHECK(x_span(pts, F, 4).first < x_span(pts, F, 0).first - 0.05 * d.rig.figure.w());
    CHECK(x_span(pts, F, 8).first == doctest::Approx(x_span(pts, F, 4).first));
    CHECK(x_span(pts, F, 8).second < x_span(pts, F, 4).second - 0.05 * d.rig.figure.w());
  }
}

TEST_CASE("travel: a crawl fitted to a canvas it fills keeps its ends planted in both steps, at every frame") {
  Drawing d = eye_tail_animal();  // 8 units of room each side of a 204-unit figure: the canvas cuts the travel
  MotionPlan plan = plan_from_prompt(parse_prompt("the caterpillar crawls"), d.rig, 1);
  const int F = 25;  // t = f / 24
  fit_plan(d.scene, d.rig, plan, F, 9);
  double slide = 0, stretch = 0;
  for (const auto& a : plan.actions)
    if (a.inches) (a.primitive == Primitive::Slide ? slide : stretch) = plan.amplitude(a);
  REQUIRE(slide > 0);
  CHECK(stretch == doctest::Approx(slide));  // scaled as one: the stretch is the slide's step
  const std::vector<Vec2> pts = animate_plan(d.scene, d.rig, plan, F);
  // Going left: the rear is the right end, the front the left. The second step (frames 0..8):
  // stretching to frame 4, the rear where it stood; gathering to frame 8, the front where it
  // reached. The first step (frames 16..24, from behind): stretching to frame 20, gathering to 24.
  for (int f : {1, 2, 3, 4}) CHECK(x_span(pts, F, f).second == doctest::Approx(x_span(pts, F, 0).second));
  for (int f : {5, 6, 7, 8}) CHECK(x_span(pts, F, f).first == doctest::Approx(x_span(pts, F, 4).first));
  for (int f : {17, 18, 19, 20}) CHECK(x_span(pts, F, f).second == doctest::Approx(x_span(pts, F, 16).second));
  for (int f : {21, 22, 23, 24}) CHECK(x_span(pts, F, f).first == doctest::Approx(x_span(pts, F, 20).first));
  CHECK(x_span(pts, F, 6).second < x_span(pts, F, 4).second - 0.01 * d.rig.figure.w());  // the rear did gather up
}

TEST_CASE("travel: a crawl's own words are whole words ('creepy' or 'crawlspace' send nothing crawling)") {
  Drawing d = eye_tail_animal();
  auto inches = [&](const char* prompt) {
    const MotionPlan plan = plan_from_prompt(parse_prompt(prompt), d.rig, 1);
    return std::any_of(plan.actions.begin(), plan.actions.end(), [](const PlannedAction& a) { return a.inches; });
  };
  CHECK(inches("the box inches to the left"));
  CHECK(inches("the box crept to the left"));
  CHECK_FALSE(inches("the creepy box moves to the left"));
  CHECK_FALSE(inches("the box moves to the left out of the crawlspace"));
}

}  // TEST_SUITE
