// A thing seen head-on told it goes away recedes towards its horizon, its ground staying; one
// told it comes nearer grows from far off (procedural/depth_travel.h). Before, a bus drawn from
// the front "driving away" slid sideways, crabwise, and "comes towards us" jiggled in place.
#include <doctest/doctest.h>

#include <cmath>

#include "procedural/depth_travel.h"
#include "procedural/motion_plan.h"

#include "motion_drawing.h"
#include "wordnet_or_skip.h"

using namespace svgm;
using svgm::test::Drawing;

namespace {

// The whole figure's travels in depth (a Pulse that goes), as their ways (-1 away, +1 nearer).
std::vector<int> depth_ways(const MotionPlan& plan) {
  std::vector<int> out;
  for (const auto& a : plan.actions)
    if (a.primitive == Primitive::Pulse && a.parts.empty() && a.goes) out.push_back(a.direction);
  return out;
}

// Whether the plan slides the whole figure sideways to go somewhere.
bool slides_off(const MotionPlan& plan) {
  for (const auto& a : plan.actions)
    if (a.primitive == Primitive::Slide && a.parts.empty() && a.goes) return true;
  return false;
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("depth travel: a bus drawn from the front is seen head-on, a van drawn from the side is not") {
  std::string why;
  CHECK(seen_head_on(Drawing("bus_front.svg").rig, &why));
  CAPTURE(why);
  CHECK_FALSE(seen_head_on(Drawing("van_side.svg").rig, &why));
}

TEST_CASE("depth travel: a bus seen head-on that drives away recedes towards the top of its road, which stays") {
  const Drawing d("bus_front.svg");
  const MotionPlan plan = plan_from_prompt(parse_prompt("the bus drives away"), d.rig, 1);
  CAPTURE(plan.summary());
  REQUIRE(depth_ways(plan) == std::vector<int>{-1});
  CHECK_FALSE(slides_off(plan));
  // The vanishing point: above the bus's middle (x 50), on its road's top (y 70); in the scene's
  // units, from the viewBox's corner (-30, -10): (80, 80).
  for (const auto& a : plan.actions)
    if (a.goes && a.primitive == Primitive::Pulse) {
      CHECK(a.vanish.x == doctest::Approx(50 + 30).epsilon(0.01));
      CHECK(a.vanish.y == doctest::Approx(70 + 10).epsilon(0.01));
    }
  const std::vector<double> moved = d.travel(plan, 13);
  CHECK(moved[0] < 0.5);  // the road stays
  // The body's top corners (20, 10) and (80, 10), 67.1 from (50, 70), go 1 - kFarScale of it
  // at the farthest (launch_at 1 at u 0.55; the frames at 0.5 and 0.583 are within 7 % of it).
  CHECK(moved[1] > 0.93 * (1 - kFarScale) * std::hypot(30, 60));
  CHECK(moved[1] <= (1 - kFarScale) * std::hypot(30, 60) + 1.5);  // (plus the drive's jitter)
  // Its foot rises towards the horizon: a tyre's bottom (y 74) 4 below it goes 4 * 0.55 up at most.
  CHECK(moved[5] < std::hypot(26, 4) * (1 - kFarScale) + 1.5);
}

TEST_CASE("depth travel: told a side, or seen from the side, it goes sideways; told it comes nearer, it grows") {
  const Drawing bus("bus_front.svg"), van("van_side.svg");
  const MotionPlan left = plan_from_prompt(parse_prompt("the bus drives away to the left"), bus.rig, 1);
  CHECK(depth_ways(left).empty());
  CHECK(slides_off(left));
  const MotionPlan side = plan_from_prompt(parse_prompt("the van drives away"), van.rig, 1);
  CHECK(depth_ways(side).empty());
  CHECK(slides_off(side));
  CHECK(depth_ways(plan_from_prompt(parse_prompt("the bus drives away on the spot"), bus.rig, 1)).empty());
  for (const char* prompt : {"the van drives towards the viewer", "the bus drives towards us"}) {
    CAPTURE(prompt);
    const MotionPlan near = plan_from_prompt(parse_prompt(prompt), std::string(prompt).find("van") != std::string::npos ? van.rig : bus.rig, 1);
    CHECK(depth_ways(near) == std::vector<int>{1});
    CHECK_FALSE(slides_off(near));
  }
}

TEST_CASE("depth travel: going away it shrinks to kFarScale and back; coming nearer it is far at first and ends at its size") {
  PlannedAction away, near;
  away.goes = near.goes = true;
  away.direction = -1, near.direction = 1;
  const double amp = 1 - kFarScale;
  CHECK(depth_scale(away, amp, 0) == doctest::Approx(1));
  CHECK(depth_scale(away, amp, 0.55) == doctest::Approx(kFarScale));
  CHECK(depth_scale(away, amp, 1) == doctest::Approx(1));
  CHECK(depth_scale(near, amp, 0.4) == doctest::Approx(kFarScale));  // farthest back (land_at: kLandBack)
  CHECK(depth_scale(near, amp, 0.9) == doctest::Approx(1));          // arrived (after kLandDown)
}

}  // TEST_SUITE
