// A person's arms in a sport pose (issue 35): a ball player up to the chest in water, drawn as
// openmoji draws people (tests/data/motion/polo_in_water.svg: the water a band as wide as the
// figure, the body and its one raised arm one outline, the head and the ball discs apart).
// The rig reads the limbs without the water (support_band.h), the one limb rising from the upper
// body is an arm when the head is drawn apart (skeleton_lobes.h), a one-sided arm verb takes the
// side its arm is on, and a person's swing or pull of a thing held moves the arms
// (held_things.h).
#include <doctest/doctest.h>

#include "svgmotion/svg_reader.h"
#include "procedural/motion_plan.h"
#include "procedural/prompt_parse.h"
#include "procedural/skeleton_lobes.h"
#include "test_paths.h"
#include "wordnet_or_skip.h"

using namespace svgm;

namespace {

const char* kPolo = "motion/polo_in_water.svg";
Scene polo() { return read_svg_file(svgm::test::data_path(kPolo)); }
Rig polo_rig(const Scene& s) { return build_rig(s, read_source_names(svgm::test::data_path(kPolo))); }

// The raised arm: from the shoulder (85-92, 68-80) up to the hand at (50-61, 15-22).
bool is_raised_arm(const ArmLobe& l) { return l.tip.x < 70 && l.tip.y < 35 && l.pivot.x > 70 && l.pivot.y > 50; }

}  // namespace

TEST_SUITE("video") {

TEST_CASE("a player in water: the limb raised above the shoulders is an arm, and the water has no limbs") {
  const Scene s = polo();
  const Rig rig = polo_rig(s);
  int raised = 0;
  for (const ArmLobe& l : rig.limbs) {
    // No limb is based in the water (from y 130 down): with it, the water was the core and
    // the raised arm its tail.
    CHECK(l.pivot.y < 130);
    if (is_raised_arm(l)) {
      ++raised;
      CHECK(l.kind == LobeKind::Arm);  // not the head: the head is the disc apart
      CHECK(l.side == -1);
    }
  }
  CHECK(raised == 1);
}

TEST_CASE("a one-sided arm verb with no side said takes the side the only arm is on, on every seed") {
  if (!wordnet_or_skip()) return;
  // A body 0..100 square with one arm limb, raised at its left (the other under water).
  Rig rig;
  RigPart body;
  body.name = "root";
  body.role = Role::Root;
  body.box.add(Vec2{0, 0});
  body.box.add(Vec2{100, 100});
  body.pivot = {50, 100};
  rig.parts = {body};
  rig.root = 0;
  rig.figure = body.box;
  ArmLobe arm;
  arm.kind = LobeKind::Arm;
  arm.side = -1;
  arm.pivot = {40, 40};
  arm.base0 = {36, 44};
  arm.base1 = {44, 36};
  arm.tip = {15, 5};
  arm.outline = {{36, 44}, {11, 9}, {19, 1}, {44, 36}};
  rig.limbs = {arm};
  for (uint32_t seed = 1; seed <= 8; ++seed) {
    CAPTURE(seed);
    const MotionPlan plan = plan_from_prompt(parse_prompt("the player throws the ball"), rig, seed);
    REQUIRE(plan.actions.size() == 1);
    const PlannedAction& a = plan.actions[0];
    CHECK(a.verb == "throw");
    CHECK(a.region == Region::Sides);
    CHECK(a.region_side == -1);
    CHECK(a.lobes.size() == 1);  // none on the coin's right side: the whole body's sides bent
  }
}

TEST_CASE("a person's swing or pull of a thing held moves the arms; a swing of nothing held rocks the figure") {
  if (!wordnet_or_skip()) return;
  const Scene s = polo();
  const Rig rig = polo_rig(s);
  const MotionPlan club = plan_from_prompt(parse_prompt("the golfer swings the club"), rig, 1);
  REQUIRE(club.actions.size() == 1);
  CHECK(club.actions[0].verb == "wield");
  CHECK(club.actions[0].target == Target::Arms);
  CHECK(!club.actions[0].lobes.empty());
  const MotionPlan oars = plan_from_prompt(parse_prompt("the rower pulls the oars"), rig, 1);
  REQUIRE(oars.actions.size() == 1);
  CHECK(oars.actions[0].verb == "haul");
  CHECK(oars.actions[0].target == Target::Arms);
  // No object: the swing is the figure's own (a rock), as before.
  const MotionPlan alone = plan_from_prompt(parse_prompt("the golfer swings"), rig, 1);
  REQUIRE(!alone.actions.empty());
  CHECK(alone.actions[0].verb != "wield");
  // A figure with no arms found: the whole-figure reading stays (else its sides would bend).
  const Scene blob = read_svg_string(R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
      <circle cx="50" cy="50" r="40" fill="#333"/></svg>)", "blob.svg");
  const MotionPlan none = plan_from_prompt(parse_prompt("the golfer swings the club"), build_rig(blob, {}), 1);
  REQUIRE(!none.actions.empty());
  CHECK(none.actions[0].verb == "rock");
}

}  // TEST_SUITE
