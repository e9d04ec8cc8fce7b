// Things that move by themselves on drawings made for these tests (issue 35): a candle's flame
// flickers about its base while the candle and the cake hold, a fire drawn as one blaze flickers
// whole from its base, a plume of steam rises (its top goes up, its base stays where it leaves
// the pot), and a drawing with no repeated drops whose prompt says it tumbles falls whole.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "procedural/flame_core.h"
#include "procedural/flame_lick.h"
#include "procedural/motion_plan.h"
#include "procedural/part_locator.h"

#include "motion_drawing.h"
using namespace svgm;
using svgm::test::Drawing;

namespace {

// The points of path `p` of `scene` at frame f of animate_plan's output `pts` (F frames).
std::vector<Vec2> path_points(const Scene& scene, const std::vector<Vec2>& pts, int F, size_t p, int f) {
  const size_t per = pts.size() / F;
  size_t first = 0;
  for (size_t q = 0; q < p; ++q)
    for (const auto& sp : scene.paths[q].subpaths) first += sp.points.size();
  size_t n = 0;
  for (const auto& sp : scene.paths[p].subpaths) n += sp.points.size();
  return {pts.begin() + f * per + first, pts.begin() + f * per + first + n};
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("flames: a candle's flame is the tip drawn over it; 'flame' names the kind") {
  CHECK(part_shape_of("flames", FigureClass::None) == PartShape::Flames);
  CHECK(part_shape_of("flame", FigureClass::Flame) == PartShape::Flames);
  const Drawing d("candle_flames.svg");
  const LocatedPart f = locate_part(d.rig, PartShape::Flames);
  // Two tips (each flame over a candle), the first with its core; not the candles under them.
  CHECK(f.lobes.size() == 2);
  CHECK(f.paths == std::vector<int>{3, 4, 5});
  for (const ArmLobe& l : f.lobes) CHECK(l.pivot.y == doctest::Approx(78));  // each flame's lowest middle
}

TEST_CASE("flames: the candle flames flicker, each about its base; the cake and the candles hold") {
  const Drawing d("candle_flames.svg");
  const MotionPlan plan = plan_from_prompt(parse_prompt("the candle flames flicker"), d.rig, 1);
  REQUIRE(plan.actions.size() == 1);  // the flicker's stretch of the whole figure is left out
  const PlannedAction& a = plan.actions[0];
  CHECK(a.verb == "flicker");
  CHECK(a.region == Region::Located);
  CHECK(a.primitive == Primitive::Swing);
  CHECK(a.cycles >= 3);
  CHECK(a.why.find("the flames found as flames: 2 tips drawn above the body's top") != std::string::npos);
  const auto t = d.travel(plan);
  CHECK(t[0] == 0.0);  // the cake
  CHECK(t[1] == 0.0);  // the candles
  CHECK(t[2] == 0.0);
  CHECK(t[3] > 5.0);   // the flames and the core of one
  CHECK(t[4] > 2.0);
  CHECK(t[5] > 5.0);
}

TEST_CASE("flames: candles that flicker, no flame named, flicker by their flames; the stretch of the whole is left out") {
  const Drawing d("candle_flames.svg");
  const MotionPlan plan = plan_from_prompt(parse_prompt("the candles flicker"), d.rig, 1);
  REQUIRE(plan.actions.size() == 1);
  CHECK(plan.actions[0].verb == "flicker");
  CHECK(plan.actions[0].region == Region::Located);
  CHECK(plan.actions[0].lobe_paths == std::vector<int>{3, 4, 5});
  const auto t = d.travel(plan);
  CHECK(t[0] == 0.0);
  CHECK(t[1] == 0.0);
  CHECK(t[3] > 5.0);
}

TEST_CASE("flames: a fire drawn as one blaze flickers whole, bending and stretching up from its base") {
  const Drawing d("blaze.svg");
  const MotionPlan plan = plan_from_prompt(parse_prompt("the fire flickers"), d.rig, 1);
  REQUIRE(plan.actions.size() == 2);
  CHECK(plan.actions[0].verb == "flicker");
  CHECK(plan.actions[0].primitive == Primitive::Bend);
  CHECK(plan.actions[0].anchored == 4);  // held at its bottom
  CHECK(plan.actions[1].primitive == Primitive::Stretch);
  const int F = 13;
  const std::vector<Vec2> pts = animate_plan(d.scene, d.rig, plan, F);
  // The tip (100, 20) moves more than 8 % of the figure's height (160); the bottom of the
  // outline (its lowest point, y about 172) hardly at all.
  const std::vector<Vec2> rest = path_points(d.scene, pts, F, 0, 0);
  size_t low = 0;
  for (size_t i = 0; i < rest.size(); ++i)
    if (rest[i].y > rest[low].y) low = i;
  double tip = 0, base = 0;
  for (int f = 1; f < F; ++f) {
    const std::vector<Vec2> q = path_points(d.scene, pts, F, 0, f);
    tip = std::max(tip, std::hypot(q[0].x - rest[0].x, q[0].y - rest[0].y));
    base = std::max(base, std::hypot(q[low].x - rest[low].x, q[low].y - rest[low].y));
  }
  CHECK(tip > 0.08 * 160);
  CHECK(base < 0.25 * tip);
}

TEST_CASE("plumes: steam rises from the pot, swelling up from its base; the pot holds") {
  const Drawing d("steam_pot.svg");
  const MotionPlan plan = plan_from_prompt(parse_prompt("steam rises from the pot"), d.rig, 1);
  REQUIRE(plan.actions.size() == 1);
  const PlannedAction& a = plan.actions[0];
  CHECK(a.region == Region::Located);
  CHECK(a.primitive == Primitive::Pulse);
  CHECK(a.why.find("a plume rises: it swells up from its base") != std::string::npos);
  const int F = 13;
  const std::vector<Vec2> pts = animate_plan(d.scene, d.rig, plan, F);
  const std::vector<Vec2> rest = path_points(d.scene, pts, F, 1, 0);
  auto top = [](const std::vector<Vec2>& q) { double y = 1e9; for (Vec2 p : q) y = std::min(y, p.y); return y; };
  auto bottom = [](const std::vector<Vec2>& q) { double y = -1e9; for (Vec2 p : q) y = std::max(y, p.y); return y; };
  double highest = top(rest), lowest = bottom(rest);
  for (int f = 1; f < F; ++f) {
    const std::vector<Vec2> q = path_points(d.scene, pts, F, 1, f);
    highest = std::min(highest, top(q));
    lowest = std::max(lowest, bottom(q));
  }
  // Its top goes up at least 8 % of the figure's height (150: y 30 to 180); its base (y 100,
  // where it leaves the pot) does not go down into the pot.
  CHECK(top(rest) - highest >= 0.08 * 150);
  CHECK(lowest - bottom(rest) < 1.0);
  CHECK(d.travel(plan)[0] == 0.0);  // the pot
}

TEST_CASE("a fall with no repeated drops: the feather tumbles, the whole of it going down first and back") {
  const Drawing d("feather.svg");
  REQUIRE(d.rig.repeated.empty());
  const MotionPlan plan = plan_from_prompt(parse_prompt("the feather tumbles to the ground"), d.rig, 1);
  REQUIRE(plan.actions.size() == 3);
  CHECK(plan.actions[0].verb == "tumble");
  CHECK(plan.actions[0].primitive == Primitive::Bob);
  CHECK(plan.actions[0].vertical == -1);  // down and back, never above where it was
  CHECK(plan.actions[1].primitive == Primitive::Rock);
  CHECK(plan.actions[2].primitive == Primitive::Slide);  // drifting on the air
  CHECK(plan.actions[0].why.find("nothing drawn apart to fall: the figure falls itself") != std::string::npos);
  const int F = 13;
  const std::vector<Vec2> pts = animate_plan(d.scene, d.rig, plan, F);
  // The quill's top (100, 40) goes down more than 8 % of the figure's height (140) at mid-loop.
  const Vec2 rest = path_points(d.scene, pts, F, 1, 0)[0], mid = path_points(d.scene, pts, F, 1, F / 2)[0];
  CHECK(mid.y - rest.y > 0.08 * 140);
}

TEST_CASE("plumes: a puff over a chimney of bands rises; the bands standing on the roof under it stay") {
  // The bands touch edge to edge from the roof (y 110) up to the puff (y 20-50): each carries the
  // next, the puff carries nothing (plume_stacks.h). Without the rule the two upper bands rose
  // with it.
  const Drawing d("chimney_puff.svg");
  const LocatedPart p = locate_part(d.rig, PartShape::Jet);
  CHECK(p.paths == std::vector<int>{3});
  CHECK(p.why.find("3 with another drawn on them edge to edge stay") != std::string::npos);
  const MotionPlan plan = plan_from_prompt(parse_prompt("smoke rises from the chimney"), d.rig, 1);
  REQUIRE(plan.actions.size() == 1);
  CHECK(plan.actions[0].primitive == Primitive::Pulse);
  const auto t = d.travel(plan);
  CHECK(t[0] == 0.0);  // the building
  CHECK(t[1] == 0.0);  // the red bands
  CHECK(t[2] == 0.0);  // the white band
  CHECK(t[3] > 0.08 * 160 * 0.5);  // the puff's top goes up
}

TEST_CASE("plumes: a thin curl of smoke whose box is larger than its cigarette's is the plume") {
  const Drawing d("curl_over_bar.svg");
  CHECK(d.rig.elements.size() == 2);
  const LocatedPart p = locate_part(d.rig, PartShape::Jet);
  REQUIRE(p.lobes.size() == 1);
  CHECK(p.paths == std::vector<int>{1});
  CHECK(p.lobes[0].pivot.y == doctest::Approx(140));  // the curl's lowest middle, where it leaves the bar
  const auto t = d.travel(plan_from_prompt(parse_prompt("smoke rises from the cigarette"), d.rig, 1));
  CHECK(t[0] == 0.0);
  CHECK(t[1] > 8.0);
}

TEST_CASE("plumes: a cup's rim and the coffee in it, as wide as the saucer's top, stay; the wisps over them rise") {
  const Drawing d("steam_cup_rim.svg");
  const LocatedPart p = locate_part(d.rig, PartShape::Jet);
  REQUIRE(p.lobes.size() == 1);
  CHECK(p.paths == std::vector<int>{4, 5});  // the two wisps: not the rim (2) nor the coffee (3)
  const auto t = d.travel(plan_from_prompt(parse_prompt("steam curls up from the cup of coffee"), d.rig, 1));
  for (int i = 0; i < 4; ++i) CHECK(t[i] == 0.0);  // the saucer, the cup, its rim, the coffee
  CHECK(t[4] > 8.0);
  CHECK(t[5] > 8.0);
}

TEST_CASE("flames: a heart drawn over the lower half of a blaze holds; the blaze's stretch above it flickers") {
  const Drawing d("heart_blaze.svg");
  CHECK(blunt_top(d.rig.elements[1]));   // the heart's two lobes
  CHECK(!blunt_top(d.rig.elements[0]));  // the blaze's one tip
  const LocatedPart f = locate_part(d.rig, PartShape::Flames);
  REQUIRE(f.lobes.size() == 1);
  CHECK(f.paths == std::vector<int>{0});
  CHECK(f.lobes[0].pivot.x == doctest::Approx(100));
  CHECK(f.lobes[0].pivot.y == doctest::Approx(85));  // the heart's top
  const MotionPlan plan = plan_from_prompt(parse_prompt("the flames around the heart flicker"), d.rig, 1);
  REQUIRE(!plan.actions.empty());
  CHECK(plan.actions[0].region == Region::Located);
  // The heart's points on its curve hold; its handles near the flames' base line turn less than
  // a pixel (the bend's smoothing of the neighbouring tangents), 1 % of the figure's height.
  const int F = 13;
  const std::vector<Vec2> pts = animate_plan(d.scene, d.rig, plan, F);
  const std::vector<Vec2> rest = path_points(d.scene, pts, F, 1, 0);
  double on_curve = 0;
  for (int f = 1; f < F; ++f) {
    const std::vector<Vec2> q = path_points(d.scene, pts, F, 1, f);
    for (size_t i = 0; i < q.size(); i += 3) on_curve = std::max(on_curve, std::hypot(q[i].x - rest[i].x, q[i].y - rest[i].y));
  }
  CHECK(on_curve == 0.0);
  const auto t = d.travel(plan);
  CHECK(t[1] < 0.01 * 165);  // the heart
  CHECK(t[0] > 5.0);   // the flame's tip
}

TEST_CASE("flames: the tongues of a blaze are its top edge's tips, each licking half a cycle after its neighbour") {
  // A zigzag top edge: tips at x 0, 40 and 80 (y 0), notches between them 30 lower, the blaze's
  // bottom at 50.
  const std::vector<Vec2> zigzag = {{0, 0}, {20, 30}, {40, 0}, {60, 30}, {80, 0}, {0, 50}, {80, 50}};
  CHECK(tongue_spacing(zigzag) == doctest::Approx(40));
  // Notches 5 deep (under kTongueProminence of the height 50): one tongue, no spacing.
  const std::vector<Vec2> wiggle = {{0, 0}, {20, 5}, {40, 0}, {60, 5}, {80, 0}, {0, 50}, {80, 50}};
  CHECK(tongue_spacing(wiggle) == 0.0);
  // The phase: flat over each tongue (within a quarter of the gap of its tip), half a cycle a tongue.
  CHECK(tongue_phase(40, 0, -5) == 0.0);
  CHECK(tongue_phase(40, 0, 10) == 0.0);
  CHECK(tongue_phase(40, 0, 20) == doctest::Approx(0.25));
  CHECK(tongue_phase(40, 0, 35) == 0.5);
  CHECK(tongue_phase(40, 0, 45) == 0.5);
  CHECK(tongue_phase(40, 0, 90) == 1.0);
  CHECK(tongue_phase(0, 0, 90) == 0.0);  // one tongue
}

TEST_CASE("flames: a blaze's tongues lick in turn, and the lick folds the blaze at no amplitude") {
  const Drawing d("heart_three_tongues.svg");
  const LocatedPart f = locate_part(d.rig, PartShape::Flames);
  REQUIRE(f.lobes.size() == 1);
  CHECK(f.lobes[0].kind == LobeKind::Blaze);
  CHECK(f.lobes[0].tongue_spacing == doctest::Approx(55));  // tips at 45, 100, 155
  MotionPlan plan = plan_from_prompt(parse_prompt("the flames around the heart flicker"), d.rig, 1);
  REQUIRE(!plan.actions.empty());
  // The three tips (points 3, 9 and 15 of the blaze): half a cycle apart, the side tips rise
  // while the middle one falls and back (a turn of the whole blaze about the heart's top raised one
  // side tip and lowered the other).
  const int F = 25;
  const std::vector<Vec2> pts = animate_plan(d.scene, d.rig, plan, F);
  const std::vector<Vec2> rest = path_points(d.scene, pts, F, 0, 0);
  int in_turn = 0;
  for (int k = 1; k < F - 1; ++k) {
    const std::vector<Vec2> q = path_points(d.scene, pts, F, 0, k);
    const double left = q[3].y - rest[3].y, mid = q[9].y - rest[9].y, right = q[15].y - rest[15].y;
    if (std::fabs(mid) > 1 && left * mid < 0 && right * mid < 0) ++in_turn;
  }
  CHECK(in_turn >= F / 2);
  // The heart holds, the tips move at least 8 % of the figure's size (its diagonal, ~230).
  const auto t = d.travel(plan);
  CHECK(t[1] == 0.0);
  CHECK(t[0] > 0.08 * 230);
  // Folds at no amplitude: mapped at 80 degrees, every small cell of a grid over the blaze's area
  // above the heart stays the same way round (none turned over) at every frame.
  PlannedAction a = plan.actions[0];
  for (int k = 0; k <= 24; ++k)
    for (double y = 15; y < 85; y += 2)
      for (double x = 20; x < 180; x += 2) {
        const Vec2 p = flame_lick(f.lobes[0], a, 80, k / 24.0, {x, y});
        const Vec2 px = flame_lick(f.lobes[0], a, 80, k / 24.0, {x + 0.01, y});
        const Vec2 py = flame_lick(f.lobes[0], a, 80, k / 24.0, {x, y + 0.01});
        const double cross = (px.x - p.x) * (py.y - p.y) - (px.y - p.y) * (py.x - p.x);
        REQUIRE(cross > 0);
      }
}

TEST_CASE("flames: a heart in a part of its own, drawn on the blaze, holds: it rides on none of the flames") {
  const Drawing d("heart_blaze_groups.svg");
  REQUIRE(d.rig.parts.size() == 2);
  const LocatedPart f = locate_part(d.rig, PartShape::Flames);
  CHECK(f.paths == std::vector<int>{0});
  CHECK(f.holds == std::vector<int>{1});  // the heart
  const auto t = d.travel(plan_from_prompt(parse_prompt("the flames around the heart flicker"), d.rig, 1));
  CHECK(t[1] == 0.0);  // the heart, every point
  CHECK(t[0] > 5.0);   // the flame's tip
}

TEST_CASE("flames: a flame's pointed core is no thing burning: a blaze with one finds no flames over a core") {
  const Drawing d("blaze.svg");
  CHECK(!blunt_top(d.rig.elements[1]));
  CHECK(flames_over_core(d.rig, 0).lobes.empty());
}

}  // TEST_SUITE
