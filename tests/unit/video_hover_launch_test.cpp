// Machines that fly and launches with no room, on drawings made for these tests (issue 35): a
// flying saucer that hovers bobs whole, never narrowing (no wings to beat: its sides bent as
// wings made it look as if it turned about its vertical axis); a jet filling its canvas's top
// takes off from a runway that stays, along its nose (flight_axis.h), never smaller; two fallen leaves tumble each its own way;
// a kick scooter's plain wheels, its steering column hung from the front one, bounce the body.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "procedural/figure_pieces.h"
#include "procedural/invisible_spin.h"
#include "procedural/motion_plan.h"
#include "procedural/motion_plan_internal.h"

#include "motion_drawing.h"
using namespace svgm;
using svgm::test::Drawing;

namespace {

// The box of every point of the scene's paths in `paths` at frame f of animate_plan's output.
RigBox frame_box(const Scene& scene, const std::vector<Vec2>& pts, int F, int f, const std::vector<size_t>& paths) {
  const size_t per = pts.size() / F;
  RigBox b;
  size_t i = 0;
  for (size_t p = 0; p < scene.paths.size(); ++p)
    for (const auto& sp : scene.paths[p].subpaths)
      for (size_t q = 0; q < sp.points.size(); ++q, ++i)
        if (std::find(paths.begin(), paths.end(), p) != paths.end()) b.add(pts[f * per + i]);
  return b;
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("hovers: a flying saucer bobs up and down whole, keeping its width in every frame") {
  const Drawing d("saucer.svg");
  MotionPlan plan = plan_from_prompt(parse_prompt("the flying saucer hovers"), d.rig, 1);
  // No wing beat: an object that flies has no wings (the note says so); only whole motions.
  for (const PlannedAction& a : plan.actions) {
    CHECK(a.target == Target::Whole);
    CHECK(a.primitive != Primitive::Swing);
  }
  CHECK(std::any_of(plan.notes.begin(), plan.notes.end(), [](const std::string& n) { return n.find("no wings to beat") != std::string::npos; }));
  const int F = 25;
  fit_plan(d.scene, d.rig, plan, F, 9);
  const std::vector<Vec2> pts = animate_plan(d.scene, d.rig, plan, F);
  const std::vector<size_t> all = {0, 1, 2, 3, 4};
  const RigBox rest = frame_box(d.scene, pts, F, 0, all);
  double up = 0, down = 0;
  for (int f = 0; f < F; ++f) {
    const RigBox b = frame_box(d.scene, pts, F, f, all);
    CHECK(b.w() == doctest::Approx(rest.w()).epsilon(1e-6));  // the hull never narrows
    CHECK(b.h() == doctest::Approx(rest.h()).epsilon(1e-6));
    up = std::max(up, rest.y0 - b.y0);
    down = std::max(down, b.y0 - rest.y0);
  }
  // Up and down by the floor (8 % of the figure's diagonal, fit_plan's raise) between them.
  const double diag = std::hypot(d.rig.figure.w(), d.rig.figure.h());
  CHECK(up + down >= 0.08 * diag);
  CHECK(up > 0);
  CHECK(down > 0);
}

TEST_CASE("hovers: a machine the prompt names no class for, or a creature's class, beats no wings it does not have") {
  const Drawing d("saucer.svg");
  // "UFO": no class; "blimp": WordNet's first blimp is a very fat person (a biped). Neither finds
  // wings on the saucer, so neither bends its sides (a turn about its vertical axis, narrowing).
  for (const char* prompt : {"the UFO hovers", "the blimp hovers", "it hovers over the town"}) {
    CAPTURE(prompt);
    const MotionPlan plan = plan_from_prompt(parse_prompt(prompt), d.rig, 1);
    REQUIRE(!plan.actions.empty());
    for (const PlannedAction& a : plan.actions) {
      CHECK(a.target == Target::Whole);
      CHECK(a.region != Region::Sides);
    }
    CHECK(std::any_of(plan.notes.begin(), plan.notes.end(), [](const std::string& n) { return n.find("wing beat") != std::string::npos; }));
  }
  // A bird keeps its wing beat where it has wings (bird.svg's are parts of their own).
  const Drawing bird("bird.svg");
  const MotionPlan flap = plan_from_prompt(parse_prompt("the bird hovers"), bird.rig, 1);
  CHECK(std::any_of(flap.actions.begin(), flap.actions.end(), [](const PlannedAction& a) { return a.primitive == Primitive::Swing; }));
}

TEST_CASE("launches: a jet at the canvas's top takes off from a runway that stays, along its nose, never smaller") {
  const Drawing d("runway_jet.svg");
  MotionPlan plan = plan_from_prompt(parse_prompt("the plane takes off from the runway"), d.rig, 1);
  CHECK(plan.ground == "from the runway");
  REQUIRE(!plan.actions.empty());
  CHECK(plan.actions[0].verb == "takeoff");
  // Its nose, the narrow end of its fuselage up and to the right (the runway left out of its
  // shape: flight_axis.h), is its way: no shrink towards its top, no sideways slide.
  CHECK(plan.actions[0].heading.x > 0.5);
  CHECK(plan.actions[0].heading.y < -0.5);
  for (const PlannedAction& a : plan.actions) CHECK((a.primitive == Primitive::Bob || a.primitive == Primitive::Shake));
  const int F = 25;
  fit_plan(d.scene, d.rig, plan, F, 9);
  const std::vector<Vec2> pts = animate_plan(d.scene, d.rig, plan, F);
  const std::vector<double> t = test::path_travel(d.scene, pts, F);
  for (size_t p = 0; p < 4; ++p) CHECK(t[p] == 0.0);  // the runway and its dashes
  // The jet: never below where it stood, never smaller, never out of the canvas (its top at the
  // canvas's top: the pipeline gives a launch room, pipeline/canvas_room.h; here it has none).
  const std::vector<size_t> jet = {4, 5, 6};
  const RigBox rest = frame_box(d.scene, pts, F, 0, jet);
  for (int f = 0; f < F; ++f) {
    const RigBox b = frame_box(d.scene, pts, F, f, jet);
    CHECK(b.y1 <= rest.y1 + 1e-9);
    CHECK(b.y0 >= -1e-9);
    CHECK(b.w() == doctest::Approx(rest.w()).epsilon(1e-9));
  }
  // "launches" is a launch too, not a drive along the ground.
  const MotionPlan launch = plan_from_prompt(parse_prompt("the plane launches"), d.rig, 1);
  REQUIRE(!launch.actions.empty());
  CHECK(launch.actions[0].verb == "takeoff");
  CHECK(launch.ground == "off the ground");
}

TEST_CASE("tumbles: two leaves drawn apart fall, turn and drift each its own way, staying in the canvas") {
  const Drawing d("two_leaves.svg");
  REQUIRE(piece_count(figure_pieces(d.rig)) == 2);
  MotionPlan plan = plan_from_prompt(parse_prompt("the leaves tumble in the wind"), d.rig, 1);
  REQUIRE(!plan.actions.empty());
  for (const PlannedAction& a : plan.actions) {
    CHECK(a.verb == "tumble");
    CHECK(a.apart);
  }
  const int F = 25;
  fit_plan(d.scene, d.rig, plan, F, 9);
  const std::vector<Vec2> pts = animate_plan(d.scene, d.rig, plan, F);
  const std::vector<size_t> left = {0, 1}, right = {2, 3};
  const RigBox l0 = frame_box(d.scene, pts, F, 0, left), r0 = frame_box(d.scene, pts, F, 0, right);
  double l_fall = 0, r_fall = 0;
  bool apart = false;  // a frame where one drifts left while the other drifts right
  for (int f = 0; f < F; ++f) {
    const RigBox l = frame_box(d.scene, pts, F, f, left), r = frame_box(d.scene, pts, F, f, right);
    for (const RigBox& b : {l, r}) {
      CHECK(b.x0 >= 0);
      CHECK(b.y0 >= 0);
      CHECK(b.x1 <= 200);
      CHECK(b.y1 <= 200);
    }
    l_fall = std::max(l_fall, l.centre().y - l0.centre().y);
    r_fall = std::max(r_fall, r.centre().y - r0.centre().y);
    const double dl = l.centre().x - l0.centre().x, dr = r.centre().x - r0.centre().x;
    apart = apart || (dl * dr < 0 && std::fabs(dl) > 1 && std::fabs(dr) > 1);
  }
  // Both fall (by 8 % of the figure's height at least), not by the same distance, and drift
  // apart; each leaf's points travel the floor (8 % of the figure's diagonal).
  CHECK(l_fall >= 0.08 * d.rig.figure.h());
  CHECK(r_fall >= 0.08 * d.rig.figure.h());
  CHECK(std::fabs(l_fall - r_fall) > 1);
  CHECK(apart);
  const std::vector<double> t = test::path_travel(d.scene, pts, F);
  const double diag = std::hypot(d.rig.figure.w(), d.rig.figure.h());
  CHECK(std::max(t[0], t[1]) >= 0.08 * diag);
  CHECK(std::max(t[2], t[3]) >= 0.08 * diag);
}

TEST_CASE("tumbles: leaves tumbling in the wind on one leaf with no limbs: the figure tumbles itself, down and back in the canvas") {
  // "leaves" names limbs the drawing has none of: a stand-in was found, and a fall moves no
  // part (only drops and the figure itself fall): the leaf stood still and the ranker flagged
  // every candidate 'no motion'.
  const Drawing d("leaf_in_wind.svg");
  MotionPlan plan = plan_from_prompt(parse_prompt("leaves tumbling in the wind"), d.rig, 1);
  REQUIRE(!plan.actions.empty());
  for (const PlannedAction& a : plan.actions) {
    INFO(a.why);
    CHECK(a.verb == "tumble");
    CHECK(a.target == Target::Whole);
  }
  const int F = 25;
  fit_plan(d.scene, d.rig, plan, F, 9);
  const std::vector<Vec2> pts = animate_plan(d.scene, d.rig, plan, F);
  const std::vector<size_t> leaf = {0, 1};
  const RigBox b0 = frame_box(d.scene, pts, F, 0, leaf);
  double fall = 0;
  for (int f = 0; f < F; ++f) {
    const RigBox b = frame_box(d.scene, pts, F, f, leaf);
    CHECK(b.x0 >= 0);
    CHECK(b.y0 >= 0);
    CHECK(b.x1 <= 200);
    CHECK(b.y1 <= 200);
    fall = std::max(fall, b.centre().y - b0.centre().y);
  }
  CHECK(fall >= 0.08 * d.rig.figure.h());  // it goes down, the floor at least
  const RigBox last = frame_box(d.scene, pts, F, F - 1, leaf);
  CHECK(last.centre().y == doctest::Approx(b0.centre().y).epsilon(0.01));  // and back: the loop closes
}

TEST_CASE("wheels: a scooter's plain wheels look the same turned though its column hangs from one; the body bounces") {
  const Drawing d("kick_scooter.svg");
  MotionPlan plan = plan_from_prompt(parse_prompt("the scooter's wheels spin"), d.rig, 1);
  REQUIRE(!plan.actions.empty());
  const PlannedAction& spin = plan.actions[0];
  REQUIRE(spin.primitive == Primitive::Spin);
  REQUIRE(spin.parts.size() == 2);
  // The column (path 5) hangs from a spun wheel: what the rule must see past.
  const int column = d.rig.part_of_path.at(5);
  REQUIRE(std::any_of(spin.parts.begin(), spin.parts.end(), [&](int w) { return motion_plan_internal::part_under(d.rig, column, w); }));
  CHECK(looks_same_turned(d.scene, d.rig, spin.parts));
  fit_plan(d.scene, d.rig, plan, 25, 9);
  REQUIRE(plan.actions.size() == 2);
  CHECK(plan.actions[1].primitive == Primitive::Bob);
  CHECK(plan.actions[1].target == Target::Whole);
  const std::vector<double> t = d.travel(plan, 25);
  CHECK(t[4] > 0);  // the deck bounces
  CHECK(t[5] > 0);  // and the column with it
}

}  // TEST_SUITE
