// Motion plans and their frames on drawings made for these tests (tests/data/motion): the
// prompt's parts move and the others hold still, mirrored wings, one arm on the figure's own
// side, drops falling each in its own phase while the background stays, a wheel turning about
// its own centre, loops that close, nothing leaving the canvas, and exact errors and warnings.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "svgmotion/error.h"
#include "svgmotion/svg_reader.h"
#include "procedural/invisible_spin.h"
#include "procedural/motion_plan.h"
#include "procedural/motion_plan_internal.h"
#include "procedural/support_band.h"
#include "geometry/rigid_bodies.h"
#include "rank/pixel_ranker.h"

#include "motion_drawing.h"
using namespace svgm;
using svgm::test::Drawing;
using svgm::test::path_travel;

namespace {

std::string data(const char* name) { return test::motion_data(name); }

struct Fixture {
  Scene scene;
  Rig rig;
  explicit Fixture(const char* name) : scene(read_svg_file(data(name))), rig(build_rig(scene, read_source_names(data(name)))) {}
  MotionPlan plan(const std::string& prompt, uint32_t seed = 1) const {
    return plan_from_prompt(parse_prompt(prompt), rig, seed);
  }
  // Largest displacement from frame 0 of the points of each scene path.
  std::vector<double> travel(const std::vector<Vec2>& pts, int F) const { return path_travel(scene, pts, F); }
  size_t first_point(int path) const {
    size_t i = 0;
    for (int p = 0; p < path; ++p)
      for (const auto& sp : scene.paths[p].subpaths) i += sp.points.size();
    return i;
  }
};

// Calls visit(rest, move) for every point of every frame: its position in frame 0 and how far
// it is from there.
template <class Visit>
void each_move(const std::vector<Vec2>& pts, int F, Visit visit) {
  const size_t per = pts.size() / F;
  for (int f = 0; f < F; ++f)
    for (size_t i = 0; i < per; ++i) visit(pts[i], pts[f * per + i] - pts[i]);
}

double loop_gap(const std::vector<Vec2>& pts, int F) {
  const size_t per = pts.size() / F;
  double m = 0;
  for (size_t i = 0; i < per; ++i) m = std::max(m, std::hypot(pts[(F - 1) * per + i].x - pts[i].x, pts[(F - 1) * per + i].y - pts[i].y));
  return m;
}

}  // namespace

TEST_SUITE("motion") {

TEST_CASE("flapping: both wings swing, mirrored; the body only bobs; the loop closes") {
  const Fixture fx("bird.svg");
  MotionPlan plan = fx.plan("A bird is flapping");
  REQUIRE(plan.actions.size() == 2);
  CHECK(plan.actions[0].verb == "flap");
  CHECK(plan.actions[0].primitive == Primitive::Swing);
  CHECK(plan.actions[0].parts == std::vector<int>{1, 2});
  CHECK(plan.actions[1].primitive == Primitive::Bob);
  const int F = 25;
  const auto pts = animate_plan(fx.scene, fx.rig, plan, F);
  const size_t per = pts.size() / F;
  // Wing tips (20,70) and (180,70): mirror images of each other in every frame, relative to
  // the body (which moves by the bob only).
  const size_t lt = fx.first_point(1) + 1, rt = fx.first_point(2) + 1, body = fx.first_point(0);
  double rise = 0;
  for (int f = 0; f < F; ++f) {
    const Vec2 b = pts[f * per + body] - pts[body];
    const Vec2 l = pts[f * per + lt] - b, r = pts[f * per + rt] - b;
    CHECK(l.y == doctest::Approx(r.y).epsilon(1e-9));
    CHECK(l.x - 20 == doctest::Approx(180 - r.x).epsilon(1e-9));
    rise = std::max(rise, std::fabs(l.y - 70));
    CHECK(b.x == doctest::Approx(0));  // the bob is vertical
  }
  CHECK(rise > 10.0);
  CHECK(loop_gap(pts, F) < 1e-9);
}

TEST_CASE("a beat of the wings swings them, mirrored; a named heart's beat is a pulse") {
  const Fixture fx("bird.svg");
  const MotionPlan plan = fx.plan("the dove beats its wings");
  REQUIRE(plan.actions.size() == 1);
  const PlannedAction& a = plan.actions[0];
  CHECK(a.verb == "pulse");
  CHECK(a.primitive == Primitive::Swing);
  CHECK(a.parts == std::vector<int>{1, 2});
  CHECK(a.why.find("limbs beat back and forth: a swing") != std::string::npos);
  const int F = 13;
  const auto t = fx.travel(animate_plan(fx.scene, fx.rig, plan, F), F);
  CHECK(t[0] == 0.0);  // the body
  CHECK(t[1] > 10.0);
  CHECK(t[2] == doctest::Approx(t[1]));
  // Not a limb: the verb keeps its own primitive.
  CHECK(fx.plan("the bird's body beats").actions[0].primitive == Primitive::Pulse);
}

TEST_CASE("a prompt naming the limbs leaves out its limb verbs' whole-figure accents; the body holds") {
  const Fixture fx("bird.svg");
  // (Flies: a hover's bob is the hover itself, kept whatever limbs are named: carried_flight.h.)
  const MotionPlan plan = fx.plan("A bird flies, flapping its wings");
  REQUIRE(plan.actions.size() == 1);  // one swing of the wings (flap repeats fly's), no bob
  for (const auto& a : plan.actions) {
    CHECK(a.primitive == Primitive::Swing);
    CHECK(a.parts == std::vector<int>{1, 2});
  }
  REQUIRE(plan.notes.size() == 1);
  CHECK(plan.notes[0] == "the prompt names the limbs that move: the whole-figure fly's bob, flap's bob left out");
  const auto t = fx.travel(animate_plan(fx.scene, fx.rig, plan, 13), 13);
  CHECK(t[0] == 0.0);  // the body
  CHECK(t[1] > 10.0);
  CHECK(t[2] > 10.0);
  // A verb of the whole figure the prompt says stays ("jumps"), and an unnamed flap keeps its bob.
  const MotionPlan jump = fx.plan("the bird jumps and flaps its wings");
  CHECK(jump.actions.front().primitive == Primitive::Hop);
  CHECK(fx.plan("the bird flaps").actions.size() == 2);
}

TEST_CASE("a whole-figure verb aimed at a part swings it by degrees, not by the verb's figure heights") {
  const Fixture fx("stick_figure.svg");
  const MotionPlan plan = fx.plan("his legs squatting");
  REQUIRE(plan.actions.size() == 1);
  CHECK(plan.actions[0].primitive == Primitive::Swing);
  CHECK(plan.actions[0].amp > 15.0);  // 20 degrees, +-15 %
  CHECK(plan.actions[0].amp < 25.0);
  // A rock aimed at a part is a swing in the same unit, larger by as much as the figure is
  // larger than the part (the arms' tips move about as far as the figure's top would have).
  const MotionPlan sway = fx.plan("he sways his arms");
  REQUIRE(!sway.actions.empty());
  CHECK(sway.actions[0].primitive == Primitive::Swing);
  double longest = 0;
  for (int p : sway.actions[0].parts) longest = std::max(longest, std::hypot(fx.rig.parts[p].box.w(), fx.rig.parts[p].box.h()));
  const double ratio = std::hypot(fx.rig.figure.w(), fx.rig.figure.h()) / longest;
  CHECK(ratio > 1.5);  // the drawing makes the test tell the two apart
  CHECK(sway.actions[0].amp > 5 * 0.85 * std::min(ratio, 4.0) - 1e-9);
  CHECK(sway.actions[0].amp < 5 * 1.15 * std::min(ratio, 4.0) + 1e-9);
}

TEST_CASE("waving the right arm moves the part named for the figure's right; nothing else moves") {
  const Fixture fx("stick_figure.svg");
  for (uint32_t seed = 0; seed < 4; ++seed) {
    const MotionPlan plan = fx.plan("The man waves his right arm", seed);
    REQUIRE(plan.actions.size() == 1);
    REQUIRE(plan.actions[0].parts.size() == 1);
    CHECK(fx.rig.parts[plan.actions[0].parts[0]].name == "Right Arm");
    const auto t = fx.travel(animate_plan(fx.scene, fx.rig, plan, 13), 13);
    for (size_t p = 0; p < t.size(); ++p) {
      if (fx.rig.part_of_path[p] == plan.actions[0].parts[0]) CHECK(t[p] > 5.0);
      else CHECK(t[p] == 0.0);
    }
  }
  // Both arms when the noun is plural; the legs kick on the figure's own left (the viewer's right).
  CHECK(fx.plan("waving his arms").actions[0].parts.size() == 2);
  const MotionPlan kick = fx.plan("kicks his left leg");
  REQUIRE(kick.actions[0].parts.size() == 1);
  CHECK(fx.rig.parts[kick.actions[0].parts[0]].name == "limb_lower_left");
}

TEST_CASE("walking: the legs swing in opposite phase, the arms too, the body bobs") {
  const Fixture fx("stick_figure.svg");
  const MotionPlan plan = fx.plan("the man walks");
  REQUIRE(plan.actions.size() == 3);
  CHECK(plan.actions[0].phase == std::vector<double>{0, 0.5});
  CHECK(plan.actions[1].parts.size() == 2);
  CHECK(plan.actions[2].primitive == Primitive::Bob);
}

TEST_CASE("rain falls and the umbrella sways: drops fall in their own phases, the background holds") {
  const Fixture fx("rain_scene.svg");
  MotionPlan plan = fx.plan("rain falls on the umbrella and it sways");
  REQUIRE(plan.actions.size() == 2);
  CHECK(plan.actions[0].primitive == Primitive::Fall);
  CHECK(plan.actions[1].primitive == Primitive::Sway);
  const int F = 25;
  fit_plan(fx.scene, fx.rig, plan, F, 9);
  const auto pts = animate_plan(fx.scene, fx.rig, plan, F);
  const size_t per = pts.size() / F;
  const auto t = fx.travel(pts, F);
  CHECK(t[0] == 0.0);   // the background rect
  CHECK(t[1] > 1.0);    // the canopy sways
  // The drops: each falls (its apex goes down by several pixels between some frames), and two
  // drops are not in the same phase.
  std::vector<std::vector<double>> dy(fx.rig.repeated.size());
  for (size_t e = 0; e < fx.rig.repeated.size(); ++e) {
    const size_t apex = fx.first_point(fx.rig.repeated[e][0].path);
    for (int f = 0; f < F; ++f) dy[e].push_back(pts[f * per + apex].y);
    CHECK(*std::max_element(dy[e].begin(), dy[e].end()) - *std::min_element(dy[e].begin(), dy[e].end()) > 5.0);
  }
  double differ = 0;
  for (int f = 0; f < F; ++f) differ = std::max(differ, std::fabs((dy[0][f] - dy[0][0]) - (dy[1][f] - dy[1][0])));
  CHECK(differ > 2.0);
  // Nothing leaves the canvas (with the margin), except what was outside it at rest.
  const double m = kFrameMargin * 200;
  for (int f = 0; f < F; ++f)
    for (size_t i = 0; i < per; ++i) {
      const Vec2 q = pts[f * per + i], r = pts[i];
      const bool rest_inside = r.x >= m && r.x <= 200 - m && r.y >= m && r.y <= 200 - m;
      if (rest_inside) CHECK((q.x >= m - 1e-6 && q.x <= 200 - m + 1e-6 && q.y >= m - 1e-6 && q.y <= 200 - m + 1e-6));
    }
}

TEST_CASE("a wheel turns about its own centre; the stand holds still; one turn closes the loop") {
  const Fixture fx("wheel.svg");
  const MotionPlan plan = fx.plan("the wheel turns slowly");
  REQUIRE(plan.actions.size() == 1);
  CHECK(plan.actions[0].primitive == Primitive::Spin);
  CHECK(plan.actions[0].parts == std::vector<int>{1});
  const int F = 13;
  const auto pts = animate_plan(fx.scene, fx.rig, plan, F);
  const size_t per = pts.size() / F;
  const auto t = fx.travel(pts, F);
  CHECK(t[0] == 0.0);
  CHECK(t[1] > 100.0);  // the rim's points go round
  for (int f = 0; f < F; ++f)
    for (size_t i = fx.first_point(1); i < per; ++i)  // distances to the centre (100,100) kept
      CHECK(std::hypot(pts[f * per + i].x - 100, pts[f * per + i].y - 100) ==
            doctest::Approx(std::hypot(pts[i].x - 100, pts[i].y - 100)).epsilon(1e-9));
  CHECK(loop_gap(pts, F) < 1e-9);
}

TEST_CASE("a standing figure's pirouette turns it about its vertical axis, inside the canvas, mirrored at half turn") {
  const Fixture fx("stick_figure.svg");  // the figure spans x 45-155 (middle 100), 146 px tall
  for (const char* prompt : {"the dancer pirouettes on one toe", "he turns around", "she twirls"}) {
    INFO(prompt);
    MotionPlan plan = fx.plan(prompt);
    REQUIRE(plan.actions.size() == 1);
    CHECK(plan.actions[0].primitive == Primitive::Turn);
    CHECK(plan.actions[0].target == Target::Whole);
    const int F = 49;
    fit_plan(fx.scene, fx.rig, plan, F, 15);
    CHECK(plan.warnings.empty());
    const auto pts = animate_plan(fx.scene, fx.rig, plan, F);
    const size_t per = pts.size() / F;
    // Inside the canvas and the figure's own columns; heights kept; the width never below
    // kTurnEdgeWidth of it (what the pixel ranker calls a colour vanishing).
    for (int f = 0; f < F; ++f) {
      RigBox b;
      for (size_t i = 0; i < per; ++i) {
        const Vec2 q = pts[f * per + i], r = pts[i];
        CHECK(q.y == doctest::Approx(r.y));
        CHECK(q.x >= 45 - 1e-9);
        CHECK(q.x <= 155 + 1e-9);
        b.add(q);
      }
      CHECK(b.w() >= kRankVanishRatio * 110 - 1e-6);
    }
    // Half a turn: the back shown as the front mirrored about the middle (the right arm, drawn
    // at x 45-85, is at 115-155).
    const size_t arm = fx.first_point(2);
    CHECK(pts[24 * per + arm].x == doctest::Approx(200 - pts[arm].x));
    CHECK(loop_gap(pts, F) < 1e-9);
  }
  // A round figure still spins in the image's plane.
  const Fixture wheel("wheel.svg");
  CHECK(wheel.plan("the wheel turns slowly").actions[0].primitive == Primitive::Spin);
}

TEST_CASE("a limb part too small to move visibly is not swung: the region of the body bends instead") {
  // A cactus drawn as one shape, its arms in its outline, with a 2 px spot beside its top that
  // the rig is made to take for an upper limb (a twemoji cactus's was): swung, the spot moved
  // 0.6 % of the figure at four times its swing, and the pixel ranker called it 'no motion'.
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">
           <g><path d="M 90 20 L 110 20 L 110 100 L 150 100 L 150 60 L 165 60 L 165 115 L 110 115 L 110 185 L 90 185 L 90 125 L 35 125 L 35 70 L 50 70 L 50 110 L 90 110 Z" fill="#3a3"/></g>
           <g><rect x="120" y="40" width="2" height="2" fill="#fff"/></g></svg>)", "cactus.svg");
  Rig rig = build_rig(s, {});
  const int spot = rig.part_of_path[1];
  REQUIRE(spot >= 0);
  REQUIRE(spot != rig.root);
  rig.parts[spot].role = Role::UpperLimb;
  rig.parts[spot].parent = rig.root;
  const MotionPlan plan = plan_from_prompt(parse_prompt("the cactus wiggles its arms"), rig, 1);
  REQUIRE(!plan.actions.empty());
  for (const auto& a : plan.actions) {
    INFO(a.why);
    CHECK(std::find(a.parts.begin(), a.parts.end(), spot) == a.parts.end());
  }
  CHECK(plan.actions[0].region == Region::Sides);
}

TEST_CASE("wheels a verb implies are never the root: pedalling does not spin the whole drawing") {
  const Fixture fx("wheel.svg");  // the round part is the root here
  const MotionPlan plan = fx.plan("pedalling");
  for (const auto& a : plan.actions) CHECK(a.primitive != Primitive::Spin);
  REQUIRE(!plan.warnings.empty());
  CHECK(plan.warnings.back() == "'pedalling': no round part other than the root for the wheels; pedal is left out");
}

TEST_CASE("a jump near the top edge is scaled down to stay in the canvas, with a warning") {
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
           <rect x="30" y="4" width="40" height="60" fill="#f00"/></svg>)", "edge.svg");
  const Rig rig = build_rig(s, {});
  MotionPlan plan = plan_from_prompt(parse_prompt("it jumps wildly"), rig, 1);
  REQUIRE(plan.actions.size() == 1);
  const int F = 25;
  fit_plan(s, rig, plan, F, 9);
  CHECK(plan.actions[0].scale < 1.0);  // the jump's own scale; nothing else had to shrink
  CHECK(plan.scale == 1.0);
  REQUIRE(plan.notes.size() == 1);
  CHECK(plan.notes[0].find("the amplitude of jump (hop) scaled to") == 0);
  CHECK(plan.notes[0].find(": at full size it would leave the canvas") != std::string::npos);
  const auto pts = animate_plan(s, rig, plan, F);
  double top = 1e9;
  for (const Vec2& q : pts) top = std::min(top, q.y);
  CHECK(top >= 1.0 - 1e-6);  // 1 % of 100: the margin
  CHECK(top < 3.5);          // and it still jumps
}

TEST_CASE("a swing too fast for the fitter's keyframes gets more of them (up to twice), then is slowed by amplitude") {
  const Fixture fx("bird.svg");
  MotionPlan plan = plan_from_steps(parse_explicit_plan("flap:wing* wildly fast"), fx.rig, 1);
  const int F = 49;
  fit_plan(fx.scene, fx.rig, plan, F, 15);
  // 15 keyframes cannot follow it; 29 (2 x 14 gaps + 1) are the most it may ask for.
  CHECK(plan.keyframes > 15);
  CHECK(plan.keyframes <= 29);
  const int K = plan.keyframes;
  const auto pts = animate_plan(fx.scene, fx.rig, plan, F);
  const size_t per = pts.size() / F;
  const double max_step = kMaxStep * std::hypot(200.0, 200.0);
  for (int k = 1; k < K; ++k) {
    const int fa = static_cast<int>(std::lround((k - 1) * 48.0 / (K - 1))), fb = static_cast<int>(std::lround(k * 48.0 / (K - 1)));
    for (size_t i = 0; i < per; ++i) CHECK(std::hypot(pts[fb * per + i].x - pts[fa * per + i].x, pts[fb * per + i].y - pts[fa * per + i].y) <= max_step + 1e-9);
  }
  // The fewest that follow: one keyframe fewer does not.
  bool broken = false;
  for (int k = 1; k < K - 1 && !broken; ++k) {
    const int fa = static_cast<int>(std::lround((k - 1) * 48.0 / (K - 2))), fb = static_cast<int>(std::lround(k * 48.0 / (K - 2)));
    for (size_t i = 0; i < per; ++i)
      broken = broken || std::hypot(pts[fb * per + i].x - pts[fa * per + i].x, pts[fb * per + i].y - pts[fa * per + i].y) > max_step + 1e-9;
  }
  if (K > 15) CHECK(broken);
}

TEST_CASE("a wild wave turns the arm at most kMaxTurn degrees from one keyframe to the next; bending sleeves are not held to it") {
  const Fixture fx("stick_figure.svg");
  const int F = 49, K = 15;
  // The angle about the arm's pivot of the arm's point farthest from it, at every keyframe.
  auto turns = [&](const MotionPlan& plan, int K) {
    const int arm = plan.actions[0].parts[0];
    const Vec2 c = fx.rig.parts[arm].pivot;
    const auto pts = animate_plan(fx.scene, fx.rig, plan, F);
    const size_t per = pts.size() / F;
    int path = 0;
    while (fx.rig.part_of_path[path] != arm) ++path;
    size_t far = fx.first_point(path);
    for (size_t i = far; i < fx.first_point(path + 1); ++i)
      if (std::hypot(pts[i].x - c.x, pts[i].y - c.y) > std::hypot(pts[far].x - c.x, pts[far].y - c.y)) far = i;
    double largest = 0;
    for (int k = 1; k < K; ++k) {
      const int fa = static_cast<int>(std::lround((k - 1) * (F - 1.0) / (K - 1))), fb = static_cast<int>(std::lround(k * (F - 1.0) / (K - 1)));
      const Vec2 a = pts[fa * per + far] - c, b = pts[fb * per + far] - c;
      largest = std::max(largest, std::fabs(std::atan2(a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y)) * 180 / M_PI);
    }
    return largest;
  };
  MotionPlan plan = fx.plan("The man waves his right arm wildly");
  REQUIRE(plan.actions.size() == 1);
  REQUIRE(fx.rig.parts[plan.actions[0].parts[0]].name == "Right Arm");
  CHECK(turns(plan, K) > 30.0);  // 35 degrees wildly (x1.6), two waves: about 49 per keyframe
  fit_plan(fx.scene, fx.rig, plan, F, K);
  // Twice the keyframes first (29), then the amplitude: between the keyframes the fitter takes,
  // the arm turns at most kMaxTurn, and no less than the amplitude's last step of 0.8 needs.
  CHECK(plan.keyframes > K);
  const double after = turns(plan, plan.keyframes);
  CHECK(after <= kMaxTurn + 1e-6);
  CHECK(after > 0.8 * kMaxTurn);
  CHECK(turns(plan, K) > kMaxTurn);  // more than 15 keyframes could follow: the motion was not cut to them

  // Short sleeves of one sweater shape (no arm parts: its sides bend) wave as far as asked: a
  // region bending keeps its outline whole, so the turn limit is not for it.
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">
           <g><path d="M 80 100 L 120 100 L 125 190 L 75 190 Z" fill="#fc0"/></g>
           <g><path d="M 65 40 L 135 40 L 135 55 L 120 55 L 120 100 L 80 100 L 80 55 L 65 55 Z" fill="#00f"/></g></svg>)",
      "sweater.svg");
  const Rig rig = build_rig(s, {});
  MotionPlan sleeves = plan_from_prompt(parse_prompt("she is waving her arms"), rig, 1);
  REQUIRE(sleeves.actions.size() == 1);
  REQUIRE(sleeves.actions[0].region == Region::Sides);
  REQUIRE(sleeves.actions[0].amp > 1.2 * kMaxTurn);  // 35 degrees, give or take 15 %: two waves turn
                                                     // that far from one keyframe to the next
  fit_plan(s, rig, sleeves, F, K);
  CHECK(sleeves.amplitude(sleeves.actions[0]) == sleeves.actions[0].amp);
}

TEST_CASE("an explicit plan moves exactly the parts it names; a pattern naming nothing is an error") {
  const Fixture fx("stick_figure.svg");
  const MotionPlan plan = plan_from_steps(parse_explicit_plan("wave:left*, nod:head"), fx.rig, 3);
  REQUIRE(plan.actions.size() == 2);
  CHECK(plan.source == "stages.video.options.motion");
  CHECK(fx.rig.parts[plan.actions[0].parts.at(0)].name == "left arm");
  CHECK(fx.rig.parts[plan.actions[1].parts.at(0)].name == "head");
  CHECK_THROWS_WITH_AS(plan_from_steps(parse_explicit_plan("flap:tail*"), fx.rig, 1),
                       "stages.video.options.motion: 'tail*' matches no part (parts: torso, left arm, Right Arm, "
                       "limb_lower_right, limb_lower_left, head)",
                       Error);
}

TEST_CASE("a prompt with no motion word sways gently, naming the words it did not understand") {
  const Fixture fx("bird.svg");
  const MotionPlan plan = fx.plan("nothing happens here");
  REQUIRE(plan.actions.size() == 1);
  CHECK(plan.actions[0].primitive == Primitive::Sway);
  REQUIRE(plan.warnings.size() == 1);
  CHECK(plan.warnings[0] == "no motion understood in the prompt (not understood: nothing, happens, here); the figure sways gently");
  CHECK(plan.not_understood == std::vector<std::string>{"nothing", "happens", "here"});
  // motion.json says the sway is the fallback (report.html warns with it) and which way it goes.
  const auto j = motion_report(fx.scene, fx.rig, plan);
  CHECK(j["plan"][0]["fallback"] == true);
  CHECK(j["plan"][0]["direction"].get<std::string>().rfind("side to side, ", 0) == 0);
}

TEST_CASE("a part said of itself that the drawing has none of is the drawing: 'the face yawns' moves the whole face") {
  const Fixture fx("plain_face.svg");
  // The face is the drawing: the yawn (a breath, lexicon anchors) swells it all; the head's nod
  // turns it all. Before, the pulse was left out for want of a head and the figure swayed.
  for (const char* prompt : {"the face yawns", "the head nods"}) {
    CAPTURE(prompt);
    const MotionPlan plan = fx.plan(prompt);
    REQUIRE_FALSE(plan.actions.empty());
    CHECK(plan.actions[0].verb == (std::string(prompt) == "the face yawns" ? "pulse" : "nod"));
    CHECK(plan.actions[0].target == Target::Whole);
    CHECK(plan.actions[0].primitive != Primitive::Sway);
    CHECK(plan.warnings.empty());
  }
  // A figure that has the part moves the part ("the head nods" on a figure with a head).
  const Fixture figure("stick_figure.svg");
  const MotionPlan nod = figure.plan("the head nods");
  REQUIRE_FALSE(nod.actions.empty());
  CHECK(nod.actions[0].target == Target::Head);
}

TEST_CASE("the report names the parts, the root and the plan with amplitudes and reasons") {
  const Fixture fx("bird.svg");
  const MotionPlan plan = fx.plan("a bird flapping its wings gently");
  const auto j = motion_report(fx.scene, fx.rig, plan);
  CHECK(j["root"] == "root");
  CHECK(j["parts"].size() == 4);
  CHECK(j["parts"][1]["role"] == "upper limb");
  CHECK(j["parts"][1]["side"] == "right");
  CHECK(j["plan"][0]["verb"] == "flap");
  CHECK(j["plan"][0]["parts"] == nlohmann::json::array({"limb_upper_right", "limb_upper_left"}));
  CHECK(j["plan"][0]["unit"] == "degrees");
  CHECK(j["plan"][0]["amplitude"].get<double>() <= 30 * 0.5 * 1.15 + 1e-9);
  CHECK(j["plan"][0]["why"].get<std::string>().find("gently") != std::string::npos);
  CHECK(j["plan"][0]["fallback"] == false);
  CHECK(j["plan"][0]["words"] == "a bird flapping its wings gently");
  CHECK(j["plan"][0]["direction"] == "back and forth, mirrored (together, opposite turns)");
}

TEST_CASE("seeds vary the amplitude; the same seed gives the same frames") {
  const Fixture fx("bird.svg");
  const auto a = animate_plan(fx.scene, fx.rig, fx.plan("flapping", 1), 9);
  const auto b = animate_plan(fx.scene, fx.rig, fx.plan("flapping", 2), 9);
  CHECK(a == animate_plan(fx.scene, fx.rig, fx.plan("flapping", 1), 9));
  CHECK(a != b);
}

}  // TEST_SUITE

TEST_SUITE("motion") {

TEST_CASE("a stroke's handle outside the canvas does not freeze the motion; its curve stays inside") {
  // The stroke bulges to x = 6.25 while its handles lie at x = -5 (a line drawing's strokes
  // near the edge): only the drawn curve has to stay in the canvas.
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
           <rect x="40" y="20" width="30" height="70" fill="#f00"/>
           <path d="M 40 20 C -5 40 -5 60 40 80" fill="none" stroke="#000" stroke-width="2"/></svg>)", "handle.svg");
  const Rig rig = build_rig(s, {});
  MotionPlan plan = plan_from_prompt(parse_prompt("it sways"), rig, 1);
  REQUIRE(plan.actions.size() == 1);
  const int F = 25;
  fit_plan(s, rig, plan, F, 9);
  CHECK(plan.warnings.empty());
  CHECK(plan.amplitude(plan.actions[0]) > 0.3 * plan.actions[0].amp);  // it still sways
  const auto pts = animate_plan(s, rig, plan, F);
  const size_t per = pts.size() / F;
  double left = 1e9;
  for (int f = 0; f < F; ++f) {
    // The stroke's points are the last four of the frame: its curve at t = 1/2.
    const Vec2* c = &pts[f * per + per - 4];
    left = std::min(left, (0.125 * c[0] + 0.375 * c[1] + 0.375 * c[2] + 0.125 * c[3]).x);
  }
  CHECK(left >= 1 - 1e-6);  // 1 % of 100: the margin
  CHECK(left < 6.0);        // and it moved towards the edge
}

namespace {

// A cobra drawn as its raised body (the root) and a coil lying beside its base.
Scene cobra() {
  return read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
           <path d="M 40 10 L 60 10 L 60 90 L 40 90 Z" fill="#0a0"/>
           <path d="M 60 75 L 95 75 L 95 90 L 60 90 Z" fill="#070"/></svg>)", "cobra.svg");
}

}  // namespace

TEST_CASE("a part low beside a raised body is no stand-in for the head: the body's top bends") {
  // A cobra drawn as its raised body (the root) and a coil lying beside its base.
  const Scene s = cobra();
  const Rig rig = build_rig(s, {});
  REQUIRE(rig.root == 0);
  // A swing of the head bends the body's top; a wave along the head has no part to run along
  // (before, the coil stood in and the motion went to the wrong end of the drawing).
  const MotionPlan nod = plan_from_prompt(parse_prompt("it nods its head"), rig, 1);
  REQUIRE(nod.actions.size() == 1);
  CHECK(nod.actions[0].parts == std::vector<int>{0});
  CHECK(nod.actions[0].region == Region::Top);
  const MotionPlan slither = plan_from_prompt(parse_prompt("its head slithers"), rig, 1);
  for (const auto& a : slither.actions) CHECK(std::find(a.parts.begin(), a.parts.end(), 1) == a.parts.end());
  REQUIRE_FALSE(slither.warnings.empty());
  CHECK(slither.warnings[0].find("no part for the head") != std::string::npos);
}

TEST_CASE("'the cobra snake sways, its hood slightly flared': the figure sways, its hood is not the target") {
  // The cobra of the test above: its raised body (the root) and a coil lying beside its base.
  const Scene s = cobra();
  const Rig rig = build_rig(s, {});
  const MotionPlan plan = plan_from_prompt(parse_prompt("The hypnotized cobra snake sways gently, its hood slightly flared."), rig, 1);
  REQUIRE(plan.actions.size() == 1);  // no slither from "snake"
  CHECK(plan.actions[0].primitive == Primitive::Sway);
  CHECK(plan.actions[0].target == Target::Whole);
  CHECK(plan.actions[0].region == Region::None);  // not the top of the body alone, as a head
  // Asked of the hood, it is the hood's.
  const MotionPlan hood = plan_from_prompt(parse_prompt("The snake sways its hood."), rig, 1);
  REQUIRE(hood.actions.size() == 1);
  CHECK(hood.actions[0].target == Target::Head);
  CHECK(hood.actions[0].region == Region::Top);
}

TEST_CASE("a sway that would push a canvas-filling drawing out is scaled alone; the rain keeps its size") {
  // A canopy reaching 4 units from the left and right edges, three drops above it.
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
           <path d="M 4 20 L 96 20 L 96 45 L 4 45 Z" fill="#00f"/><rect x="48" y="45" width="4" height="51" fill="#444"/>
           <rect x="20" y="5" width="4" height="6" fill="#0af"/><rect x="48" y="8" width="4" height="6" fill="#0af"/>
           <rect x="76" y="5" width="4" height="6" fill="#0af"/></svg>)", "canopy.svg");
  const Rig rig = build_rig(s, {});
  REQUIRE(rig.repeated.size() == 3);
  MotionPlan plan = plan_from_prompt(parse_prompt("rain falls and it sways wildly"), rig, 1);
  REQUIRE(plan.actions.size() == 2);
  REQUIRE(plan.actions[1].primitive == Primitive::Sway);
  const int F = 25;
  fit_plan(s, rig, plan, F, 9);
  CHECK(plan.actions[0].scale == 1.0);  // the fall is not shrunk by the sway's limit
  CHECK(plan.actions[1].scale < 1.0);
  CHECK(plan.actions[1].scale > 0.2);   // it still sways visibly
  CHECK(plan.scale == 1.0);
  REQUIRE(plan.notes.size() == 1);
  CHECK(plan.notes[0].find("the amplitude of sway (sway) scaled to") == 0);
  const auto pts = animate_plan(s, rig, plan, F);
  for (const Vec2& q : pts) CHECK((q.x >= 1 - 1e-6 && q.x <= 99 + 1e-6 && q.y >= 1 - 1e-6 && q.y <= 99 + 1e-6));
}

TEST_CASE("a group whose paths the document names apart splits into named parts; a hill is background") {
  const Fixture fx("rider.svg");
  std::vector<std::string> names;
  for (const auto& P : fx.rig.parts) names.push_back(P.name);
  // The hill, the bicycle (its frame: the group's name), its two wheels split off as round
  // parts, the torso, the leg, the collar: seven parts from one group.
  REQUIRE(fx.rig.parts.size() == 7);
  for (const char* n : {"hill", "bicycle", "bicycle_wheel_1", "bicycle_wheel_2", "torso", "leg", "collar"})
    CHECK(std::count(names.begin(), names.end(), n) == 1);
  for (const auto& P : fx.rig.parts) {
    CHECK(P.group == 0);
    if (P.name == "hill") CHECK(P.role == Role::Background);
    if (P.name == "leg") CHECK(P.role == Role::LowerLimb);
  }
}

TEST_CASE("pedalling spins the two wheels, not the round collar up on the rider; the hill holds") {
  const Fixture fx("rider.svg");
  MotionPlan plan = fx.plan("he is pedalling");
  REQUIRE(plan.actions.size() == 2);
  CHECK(plan.actions[0].primitive == Primitive::Swing);
  for (int p : plan.actions[0].parts) CHECK(!fx.rig.parts[p].round);  // the wheels turn, they do not swing
  CHECK(plan.actions[1].primitive == Primitive::Spin);
  REQUIRE(plan.actions[1].parts.size() == 2);
  for (int p : plan.actions[1].parts) {
    CHECK(fx.rig.parts[p].round);
    CHECK(fx.rig.parts[p].box.w() == doctest::Approx(80));
  }
  const int F = 13;
  const auto t = fx.travel(animate_plan(fx.scene, fx.rig, plan, F), F);
  CHECK(t[0] == 0.0);  // the hill
  CHECK(t[1] > 60.0);  // a wheel's points go round
}

TEST_CASE("a sketched bicycle's wheels, each one stroke round an oval, spin in their slanted planes; the leg's bend leaves them whole") {
  // tests/data/motion/sketch_bike.svg: a line drawing whose wheels are open strokes winding
  // most of the way round ovals 36 wide and 52 tall. Pedalling spins them (the rig took a wheel
  // for a leg before) about their own centres, in the plane the oval is drawn in: every point on
  // the oval stays on it (a turn in the drawing's plane would tumble the oval: a point 26 above
  // the centre goes to 26 beside it, 8 outside the oval's half width). The rider's body stroke
  // bends at its lower part for the legs; the wheels keep out of that bend, each moved by one
  // affine map per frame (the body stroke's handles reach over both wheels, so without that
  // the bend took them: 0.8 off their ovals, and no single map moved them).
  const Fixture fx("sketch_bike.svg");
  MotionPlan plan = fx.plan("he is pedalling");
  std::vector<int> wheels;
  for (const auto& a : plan.actions)
    if (a.primitive == Primitive::Spin) wheels = a.parts;
  REQUIRE(wheels.size() == 2);
  for (int w : wheels) {
    CHECK(fx.rig.parts[w].round);
    CHECK(fx.rig.parts[w].role != Role::LowerLimb);
  }
  const int F = 13;
  fit_plan(fx.scene, fx.rig, plan, F, 9);
  CHECK(plan.warnings.empty());
  const auto pts = animate_plan(fx.scene, fx.rig, plan, F);
  const size_t per = pts.size() / F;
  // The handlebar, a straight stroke whose box has no area, does not ride round a wheel.
  CHECK(fx.travel(pts, F)[5] < 2.0);
  for (int path : {3, 4}) {
    const double cx = path == 3 ? 58 : 146, cy = 128;
    const size_t first = fx.first_point(path);
    double off = 0, moved = 0;
    for (int f = 0; f < F; ++f)
      for (size_t i = first; i < first + 13; i += 3) {  // the on-curve points
        const Vec2 q = pts[f * per + i];
        off = std::max(off, std::fabs(std::hypot((q.x - cx) / 18, (q.y - cy) / 26) - 1));
        moved = std::max(moved, std::hypot(q.x - pts[i].x, q.y - pts[i].y));
      }
    CHECK(off < 0.01);    // on the oval (the last point, short of closing, sits on it too)
    CHECK(moved > 30.0);  // round it
  }
  const RigidBodies bodies = rigid_bodies(fx.scene, pts, F, 1e-6);
  CHECK(bodies.body[3] >= 0);
  CHECK(bodies.body[4] >= 0);
  CHECK(bodies.body[3] != bodies.body[4]);
}

TEST_CASE("arms with no part of their own bend the widest upper part, with the hand inside it") {
  // Trousers (the largest part), a sweater whose sleeves reach out to both sides, a hand at the
  // end of the left sleeve (a part of its own, hanging inside the sweater's box).
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">
           <g><path d="M 80 100 L 120 100 L 125 190 L 75 190 Z" fill="#fc0"/></g>
           <g><path d="M 30 40 L 170 40 L 170 55 L 120 55 L 120 100 L 80 100 L 80 55 L 30 55 Z" fill="#00f"/></g>
           <g><rect x="30" y="56" width="8" height="8" fill="#fa8"/></g></svg>)", "sweater.svg");
  const Rig rig = build_rig(s, {});
  MotionPlan plan = plan_from_prompt(parse_prompt("she is waving her arms"), rig, 1);
  REQUIRE(plan.actions.size() == 1);
  REQUIRE(plan.actions[0].parts.size() == 1);
  CHECK(plan.actions[0].parts[0] == 1);  // the sweater, not the trousers (the root)
  CHECK(plan.actions[0].region == Region::Sides);
  const int F = 13;
  const auto pts = animate_plan(s, rig, plan, F);
  const size_t per = pts.size() / F;
  std::vector<double> t(3, 0);
  size_t i = 0;
  for (size_t p = 0; p < 3; ++p)
    for (const auto& sp : s.paths[p].subpaths)
      for (size_t q = 0; q < sp.points.size(); ++q, ++i)
        for (int f = 1; f < F; ++f) t[p] = std::max(t[p], std::hypot(pts[f * per + i].x - pts[i].x, pts[f * per + i].y - pts[i].y));
  CHECK(t[0] == 0.0);  // the trousers hold
  CHECK(t[1] > 10.0);  // the sleeves swing
  CHECK(t[2] > 10.0);  // and the hand with them
}

TEST_CASE("a hand hanging at the cuff of a bending sleeve, outside the sweater's box, goes with the cuff") {
  // Trousers, a sweater with its left sleeve out and its right sleeve hanging down to a cuff at
  // y = 100 (x 162..172), and a hand below the cuff: outside the sweater's box, beside its middle.
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">
           <g><path d="M 80 100 L 120 100 L 125 190 L 75 190 Z" fill="#fc0"/></g>
           <g><path d="M 30 40 L 150 40 L 170 60 L 172 100 L 162 100 L 158 65 L 120 60 L 120 100 L 80 100 L 80 55 L 30 55 Z" fill="#00f"/></g>
           <g><path d="M 162 100 L 172 100 L 172 110 L 162 110 Z" fill="#fa8"/></g></svg>)", "sleeve.svg");
  const Rig rig = build_rig(s, {});
  REQUIRE(rig.parts[2].parent == 1);  // the hand hangs from the sweater
  MotionPlan plan = plan_from_prompt(parse_prompt("she is waving her arms"), rig, 1);
  REQUIRE(plan.actions.size() == 1);
  REQUIRE(plan.actions[0].region == Region::Sides);
  const int F = 13;
  const auto pts = animate_plan(s, rig, plan, F);
  const size_t per = pts.size() / F;
  // The sweater's cuff corner (162, 100) and the hand's, which start together.
  auto index_at = [&](int path, Vec2 at) {
    size_t i = 0;
    for (int p = 0; p < path; ++p)
      for (const auto& sp : s.paths[p].subpaths) i += sp.points.size();
    for (const auto& sp : s.paths[path].subpaths)
      for (const Vec2& q : sp.points) {
        if (std::hypot(q.x - at.x, q.y - at.y) < 1e-9) return i;
        ++i;
      }
    return size_t(-1);
  };
  const size_t cuff = index_at(1, {162, 100}), hand = index_at(2, {162, 100});
  REQUIRE(cuff != size_t(-1));
  REQUIRE(hand != size_t(-1));
  double cuff_travel = 0, apart = 0;
  for (int f = 1; f < F; ++f) {
    const Vec2 c = pts[f * per + cuff], h = pts[f * per + hand];
    cuff_travel = std::max(cuff_travel, std::hypot(c.x - 162, c.y - 100));
    apart = std::max(apart, std::hypot(c.x - h.x, c.y - h.y));
  }
  CHECK(cuff_travel > 5.0);  // the sleeve swings
  CHECK(apart < 1.0);        // and the hand stays on its cuff (it stood still before: apart = travel)
}

TEST_CASE("a sway leans the figure's top about its middle; the foot and the lower stem stay planted") {
  // A wine glass: a bowl (y 20-90) on a stem (90-170) on a foot (170-178).
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">
           <g><path d="M 60 20 L 140 20 L 120 90 L 80 90 Z" fill="#c33"/></g>
           <g><rect x="97" y="90" width="6" height="80" fill="#888"/></g>
           <g><rect x="70" y="170" width="60" height="8" fill="#888"/></g></svg>)", "glass.svg");
  const Rig rig = build_rig(s, {});
  MotionPlan plan = plan_from_prompt(parse_prompt("the wine in the glass sways from side to side"), rig, 1);
  REQUIRE(plan.actions.size() == 1);
  CHECK(plan.actions[0].primitive == Primitive::Sway);
  CHECK(plan.actions[0].parts.empty());  // the whole figure
  const int F = 25;
  fit_plan(s, rig, plan, F, 9);
  const auto pts = animate_plan(s, rig, plan, F);
  // The hinge is at 20 + 0.55 * 158 = 106.9: every point at or below it holds, the rim leans.
  double below = 0, rim = 0;
  each_move(pts, F, [&](Vec2 rest, Vec2 m) {
    const double d = std::hypot(m.x, m.y);
    if (rest.y >= 106.9) below = std::max(below, d);
    if (rest.y == 20.0) rim = std::max(rim, d);
  });
  CHECK(below == 0.0);
  CHECK(rim > 6.0);  // about 87 * sin(8 deg) = 12, less the seed's variation
  CHECK(loop_gap(pts, F) < 1e-9);
}

TEST_CASE("a sway the prompt aims at the body turns it about the hips; the legs stay, the arms and head go with it") {
  const Fixture fx("stick_figure.svg");
  const MotionPlan plan = fx.plan("he performs with a rhythmic sway, his body sways subtly");
  // The first clause's sway of the whole figure says the second's again: left out.
  REQUIRE(plan.actions.size() == 1);
  CHECK(plan.actions[0].primitive == Primitive::Swing);
  CHECK(plan.actions[0].parts == std::vector<int>{fx.rig.root});
  REQUIRE(plan.notes.size() == 1);
  CHECK(plan.notes[0] == "'he performs with a rhythmic sway': the prompt aims the same motion at a part elsewhere; the whole figure's left out");
  const auto t = fx.travel(animate_plan(fx.scene, fx.rig, plan, 13), 13);
  for (size_t p = 0; p < fx.scene.paths.size(); ++p) {
    const int part = fx.rig.part_of_path[p];
    const RigBox& b = fx.rig.parts[part].box;
    if (b.y0 >= 118) CHECK(t[p] == 0.0);  // the legs (118-178) stand on the ground
    else CHECK(t[p] > 1.0);               // the torso, the arms and the head sway
  }
  // Without the aimed clause, the whole figure sways (its top leans, the legs' feet stay).
  const MotionPlan whole = fx.plan("he performs with a rhythmic sway");
  REQUIRE(whole.actions.size() == 1);
  CHECK(whole.actions[0].primitive == Primitive::Sway);
}

TEST_CASE("'a surfer rides the waves': the whole figure glides, not a part named after the surfer nor the wave") {
  // A wave behind everything (a backdrop: large, at three edges, painted first), the surfer,
  // his shadow named "shadow_surfer" in the document (an emoji's layer names), his board.
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">
           <g id="wave"><rect x="0" y="100" width="200" height="100" fill="#04c"/></g>
           <g id="surfer"><rect x="80" y="40" width="40" height="100" fill="#c33"/></g>
           <g id="shadow_surfer"><rect x="85" y="100" width="20" height="20" fill="#822"/></g>
           <g id="board"><rect x="50" y="140" width="100" height="10" fill="#ee0"/></g></svg>)", "surfer.svg");
  const SourceNames names = {{s.paths[0].id, {{"/svg/g[1]", "wave"}}}, {s.paths[2].id, {{"/svg/g[3]", "shadow_surfer"}}}};
  const Rig rig = build_rig(s, names);
  REQUIRE(rig.parts[0].name == "wave");
  REQUIRE(rig.parts[0].role == Role::Background);
  REQUIRE(rig.parts[2].name == "shadow_surfer");
  const MotionPlan plan = plan_from_prompt(parse_prompt("A surfer rides the waves."), rig, 1);
  REQUIRE(!plan.actions.empty());
  for (const auto& a : plan.actions) {
    CHECK(a.target == Target::Whole);
    CHECK(a.parts.empty());
  }
  CHECK(plan.not_understood.empty());
  // As the subject, the wave is what moves.
  const MotionPlan roll = plan_from_prompt(parse_prompt("the waves ripple"), rig, 1);
  REQUIRE(!roll.actions.empty());
  CHECK(roll.actions[0].parts == std::vector<int>{0});
}

TEST_CASE("a figure filling its canvas glides when the small splash at the canvas's edge holds still") {
  // A wave behind everything, a surfer on his board, and a splash cut off by the right edge
  // (200 x 200: the margin is 2, the splash reaches 199.5).
  auto scene = [](const char* splash) {
    return read_svg_string(std::string(R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">
           <g><rect x="0" y="100" width="200" height="100" fill="#04c"/></g>
           <g><rect x="60" y="20" width="90" height="150" fill="#c33"/></g>
           <g><rect x="40" y="170" width="120" height="10" fill="#ee0"/></g>
           <g>)") + splash + "</g></svg>", "surfer.svg");
  };
  const int F = 25;
  {
    const Scene s = scene(R"(<rect x="185" y="60" width="14.5" height="10" fill="#fff"/>)");
    const Rig rig = build_rig(s, {});
    REQUIRE(rig.parts[0].role == Role::Background);
    MotionPlan plan = plan_from_prompt(parse_prompt("A surfer rides the waves."), rig, 1);
    REQUIRE(!plan.actions.empty());
    fit_plan(s, rig, plan, F, 9);
    CHECK(plan.warnings.empty());
    CHECK(plan.held == std::vector<int>{3});
    const auto pts = animate_plan(s, rig, plan, F);
    double surfer = 0, splash = 0;
    each_move(pts, F, [&](Vec2 rest, Vec2 m) {
      double& part = rest.x > 180 ? splash : surfer;
      part = std::max(part, std::hypot(m.x, m.y));
      if (rest.x < 199.9) CHECK(rest.x + m.x <= 199.5 + 1e-9);  // (the wave reaches 200 and holds)
    });
    CHECK(splash == 0.0);
    CHECK(surfer > 0.02 * std::hypot(200.0, 200.0));  // visibly: the ranker's 'no motion' had it
  }
  {
    // A board running off the edge is no splash: too large to hold, the figure barely moves.
    const Scene s = scene(R"(<rect x="30" y="150" width="169.5" height="20" fill="#fff"/>)");
    const Rig rig = build_rig(s, {});
    MotionPlan plan = plan_from_prompt(parse_prompt("A surfer rides the waves."), rig, 1);
    fit_plan(s, rig, plan, F, 9);
    CHECK(plan.held.empty());
    CHECK(!plan.warnings.empty());
  }
}

TEST_CASE("a flag ripples from its pole: the pole holds, the free end moves most; a fish has no pole") {
  // A pole (10-14 x 10-190: taller than the cloth is wide, so the figure's long axis is the
  // pole's) and a cloth 14-150 x 20-90.
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">
           <g><rect x="10" y="10" width="4" height="180" fill="#444"/></g>
           <g><path d="M 14 20 L 150 20 L 150 90 L 14 90 Z" fill="#c33"/></g></svg>)", "flag.svg");
  const Rig rig = build_rig(s, {});
  MotionPlan plan = plan_from_prompt(parse_prompt("a flag rippling in the wind"), rig, 1);
  REQUIRE(plan.actions.size() == 1);
  CHECK(plan.actions[0].primitive == Primitive::Undulate);
  CHECK(plan.actions[0].anchored == 1);  // its left
  CHECK(plan.actions[0].why.find("held by a pole at its left") != std::string::npos);
  const int F = 25;
  fit_plan(s, rig, plan, F, 9);
  const auto pts = animate_plan(s, rig, plan, F);
  double pole = 0, free_end = 0;
  each_move(pts, F, [&](Vec2 rest, Vec2 d) {
    CHECK(d.x == 0.0);  // the wave runs across the pole: up and down
    if (rest.x <= 14) pole = std::max(pole, std::fabs(d.y));
    if (rest.x == 150) free_end = std::max(free_end, std::fabs(d.y));
  });
  CHECK(free_end > 3.0);
  CHECK(pole < 0.05 * free_end);
  CHECK(loop_gap(pts, F) < 1e-9);
  // The pole's own points do not move at all (the cloth's edge along it may, a little).
  size_t pole_points = 0;
  for (const auto& sp : s.paths[0].subpaths) pole_points += sp.points.size();
  const size_t per = pts.size() / F;
  double pole_travel = 0;
  for (int f = 0; f < F; ++f)
    for (size_t i = 0; i < pole_points; ++i) pole_travel = std::max(pole_travel, std::hypot(pts[f * per + i].x - pts[i].x, pts[f * per + i].y - pts[i].y));
  CHECK(pole_travel == 0.0);
  // A fish: no thin part at a side, the wave moves both ends.
  const Scene fish = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">
           <g><path d="M 20 100 L 100 70 L 160 100 L 100 130 Z" fill="#08c"/></g>
           <g><path d="M 160 100 L 185 80 L 185 120 Z" fill="#06a"/></g></svg>)", "fish.svg");
  const Rig fr = build_rig(fish, {});
  const MotionPlan swim = plan_from_prompt(parse_prompt("the fish swims"), fr, 1);
  REQUIRE(!swim.actions.empty());
  CHECK(swim.actions[0].primitive == Primitive::Undulate);
  CHECK(swim.actions[0].anchored == 0);
}

TEST_CASE("a flagpole drawn as a thick bar still holds the flag; a tall thin bar inside the figure is no pole") {
  // The pole is 4 wide against a figure 24 wide (a sixth: past kPoleWidth's 5 %), 36 tall, at
  // the left: thin for its length, so the flag ripples from it and it holds still.
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="48" height="48">
           <g><rect x="10" y="2" width="4" height="36" fill="#666"/></g>
           <g><path d="M 12 4 L 34 12 L 12 20 Z" fill="#d24"/></g></svg>)", "thick_pole.svg");
  const Rig rig = build_rig(s, {});
  MotionPlan plan = plan_from_prompt(parse_prompt("the flag ripples in the wind"), rig, 1);
  REQUIRE(plan.actions.size() == 1);
  CHECK(plan.actions[0].anchored == 1);
  const int F = 13;
  fit_plan(s, rig, plan, F, 9);
  CHECK(path_travel(s, animate_plan(s, rig, plan, F), F)[0] == 0.0);  // the pole
  // A bar in the middle of the figure (not starting at a side) is no pole.
  const Scene mid = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="48" height="48">
           <g><rect x="20" y="2" width="4" height="36" fill="#666"/></g>
           <g><path d="M 4 4 L 44 12 L 4 20 Z" fill="#d24"/></g></svg>)", "mid_bar.svg");
  const MotionPlan free = plan_from_prompt(parse_prompt("the flag ripples in the wind"), build_rig(mid, {}), 1);
  REQUIRE(free.actions.size() == 1);
  CHECK(free.actions[0].anchored == 0);
}

TEST_CASE("a bend of an upright figure holds its base and bends most at its top; a fish bends about its middle") {
  // Three stalks 10 wide and 80 tall standing on y = 90: the figure is upright.
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
           <path d="M 20 90 L 30 90 L 30 10 L 20 10 Z" fill="#3a3"/>
           <path d="M 45 90 L 55 90 L 55 10 L 45 10 Z" fill="#3a3"/>
           <path d="M 70 90 L 80 90 L 80 10 L 70 10 Z" fill="#3a3"/></svg>)", "stalks.svg");
  const Rig rig = build_rig(s, {});
  MotionPlan plan = plan_from_prompt(parse_prompt("the stalks bend in the wind"), rig, 1);
  REQUIRE(plan.actions.size() == 1);
  REQUIRE(plan.actions[0].primitive == Primitive::Bend);
  CHECK(plan.actions[0].anchored == 4);
  CHECK(plan.actions[0].why.find("held at its bottom: it bends from there") != std::string::npos);
  const int F = 13;
  fit_plan(s, rig, plan, F, 9);
  const auto pts = animate_plan(s, rig, plan, F);
  double base = 0, top = 0;
  each_move(pts, F, [&](Vec2 rest, Vec2 d) {
    CHECK(d.y == 0.0);  // across the figure's height: sideways
    if (rest.y == 90) base = std::max(base, std::fabs(d.x));
    if (rest.y == 10) top = std::max(top, std::fabs(d.x));
  });
  CHECK(base == 0.0);
  CHECK(top > 8.0);  // the issue's floor: 8 % of the figure's diagonal (about 87)
  CHECK(loop_gap(pts, F) < 1e-9);
  // A fish bends free: named a fish, its ends both move.
  const MotionPlan fish = plan_from_prompt(parse_prompt("the fish bends"), rig, 1);
  REQUIRE(fish.actions.size() == 1);
  CHECK(fish.actions[0].anchored == 0);
}

TEST_CASE("a figure moving on a ground the prompt names leaves the band drawn there still") {
  // A hull and a sail (10-90 x 10-66) on a sea band 0-100 x 70-95 with a crest line along
  // its top (68-72).
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
           <path d="M 0 70 L 100 70 L 100 95 L 0 95 Z" fill="#8cf"/>
           <path d="M 0 70 Q 25 66 50 70 Q 75 74 100 70" fill="none" stroke="#000"/>
           <path d="M 20 55 L 80 55 L 70 66 L 30 66 Z" fill="#a63"/>
           <path d="M 50 10 L 50 52 L 20 52 Z" fill="#ddd"/></svg>)", "boat.svg");
  const Rig rig = build_rig(s, {});
  MotionPlan plan = plan_from_prompt(parse_prompt("the sailboat bobs on the waves"), rig, 1);
  CHECK(plan.ground == "on the waves");
  CHECK(std::find(plan.not_understood.begin(), plan.not_understood.end(), "waves") == plan.not_understood.end());
  const std::vector<char> band = support_paths(s, rig);
  REQUIRE(band.size() == 4);
  CHECK(band == std::vector<char>{1, 1, 0, 0});
  const int F = 13;
  fit_plan(s, rig, plan, F, 9);
  const std::vector<double> travel = path_travel(s, animate_plan(s, rig, plan, F), F);
  CHECK(travel[0] == 0.0);
  CHECK(travel[1] == 0.0);
  CHECK(travel[2] > 1.0);
  CHECK(travel[3] > 1.0);
  // Said without a ground, the sea bobs with the boat (it is part of the figure).
  MotionPlan bare = plan_from_prompt(parse_prompt("the sailboat bobs"), rig, 1);
  CHECK(bare.ground.empty());
  fit_plan(s, rig, bare, F, 9);
  CHECK(path_travel(s, animate_plan(s, rig, bare, F), F)[0] > 1.0);  // the sea
}

TEST_CASE("a compact figure swims with its lower limbs; its head holds; named tentacles drop the swim's slide") {
  // An octopus drawn as one shape, about as wide as tall (160 x 150): no wave along a body.
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">
           <path d="M 60 20 L 140 20 L 140 100 L 180 170 L 20 170 L 60 100 Z" fill="#f78"/></svg>)", "octopus.svg");
  const Rig rig = build_rig(s, {});
  const MotionPlan swim = plan_from_prompt(parse_prompt("an octopus is swimming"), rig, 1);
  REQUIRE(swim.actions.size() == 2);
  CHECK(swim.actions[0].primitive == Primitive::Swing);
  CHECK(swim.actions[0].region == Region::Lower);
  CHECK(swim.actions[0].alternating);
  CHECK(swim.actions[0].why.find("a compact figure: its lower limbs paddle") != std::string::npos);
  CHECK(swim.actions[1].primitive == Primitive::Slide);
  const MotionPlan both = plan_from_prompt(parse_prompt("an octopus is swimming and swaying its tentacles"), rig, 1);
  REQUIRE(both.actions.size() == 2);
  CHECK(both.actions[0].region == Region::Lower);
  CHECK(both.actions[1].region == Region::Sides);
  REQUIRE(both.notes.size() == 1);
  CHECK(both.notes[0] == "the prompt names the limbs that move: the whole-figure swim's slide left out");
  // The head (above the hips at 60 % of the height, y < 110) holds; the arms' ends move.
  const int F = 13;
  const auto pts = animate_plan(s, rig, both, F);
  double head = 0, ends = 0;
  each_move(pts, F, [&](Vec2 rest, Vec2 m) {
    const double d = std::hypot(m.x, m.y);
    if (rest.y < 20 + 0.6 * 150 && rest.x > 60 && rest.x < 140) head = std::max(head, d);
    if (rest.y == 170) ends = std::max(ends, d);
  });
  CHECK(head == 0.0);
  CHECK(ends > 5.0);
}

TEST_CASE("a boxer's body turns into the punches and leans to dodge about the hips; his legs stay planted") {
  const Fixture fx("stick_figure.svg");
  for (const char* prompt : {"the boxer is punching", "he dodges"}) {
    const MotionPlan plan = fx.plan(prompt);
    REQUIRE(!plan.actions.empty());
    const PlannedAction& body = plan.actions.back();
    CHECK(body.primitive == Primitive::Swing);
    CHECK(body.parts == std::vector<int>{fx.rig.root});
    const auto t = fx.travel(animate_plan(fx.scene, fx.rig, plan, 13), 13);
    for (size_t p = 0; p < fx.scene.paths.size(); ++p) {
      const RigBox& b = fx.rig.parts[fx.rig.part_of_path[p]].box;
      if (b.y0 >= 118) CHECK(t[p] == 0.0);  // the legs (118-178)
      else CHECK(t[p] > 1.0);               // the torso, the arms, the head
    }
  }
}

TEST_CASE("the body's turn carries the head upright: it follows its neck without turning") {
  const Fixture fx("stick_figure.svg");
  int head = -1;
  for (size_t g = 0; g < fx.rig.parts.size(); ++g)
    if (fx.rig.parts[g].role == Role::Head && fx.rig.parts[g].parent == fx.rig.root) head = static_cast<int>(g);
  REQUIRE(head >= 0);
  const MotionPlan plan = fx.plan("he dodges");
  REQUIRE(plan.actions.size() == 1);
  REQUIRE(plan.actions[0].parts == std::vector<int>{fx.rig.root});
  const int F = 13;
  const std::vector<Vec2> pts = animate_plan(fx.scene, fx.rig, plan, F);
  const size_t per = pts.size() / F;
  double moved = 0, spread = 0;
  for (size_t p = 0; p < fx.scene.paths.size(); ++p) {
    if (fx.rig.part_of_path[p] != head) continue;
    const size_t i0 = fx.first_point(static_cast<int>(p));
    size_t n = 0;
    for (const auto& sp : fx.scene.paths[p].subpaths) n += sp.points.size();
    for (int f = 1; f < F; ++f) {
      const Vec2 d0 = pts[f * per + i0] - pts[i0];
      moved = std::max(moved, std::hypot(d0.x, d0.y));
      for (size_t i = i0; i < i0 + n; ++i) {
        const Vec2 d = pts[f * per + i] - pts[i];
        spread = std::max(spread, std::hypot(d.x - d0.x, d.y - d0.y));
      }
    }
  }
  CHECK(moved > 1.0);      // it goes with the neck
  CHECK(spread < 1e-9);    // every point of it by the same step: no turn
}

TEST_CASE("a boxer punches with the arm he has thrown out, the other keeps guard; both arms take turns") {
  const Fixture fx("boxer.svg");
  REQUIRE(fx.rig.parts[1].role == Role::UpperLimb);
  REQUIRE(fx.rig.parts[2].role == Role::UpperLimb);
  for (uint32_t seed = 0; seed < 4; ++seed) {
    const MotionPlan plan = fx.plan("the boxer is punching", seed);
    REQUIRE(!plan.actions.empty());
    CHECK(plan.actions[0].parts == std::vector<int>{1});
    const auto t = fx.travel(animate_plan(fx.scene, fx.rig, plan, 13), 13);
    // The guard arm moves only with the body's turn, the thrown arm with it and its own swing.
    CHECK(t[1] > 2 * t[2]);
  }
  const MotionPlan both = fx.plan("his arms are punching");
  REQUIRE(!both.actions.empty());
  CHECK(both.actions[0].parts.size() == 2);
  CHECK(both.actions[0].phase == std::vector<double>{0, 0.5});
  // The same arms, told apart by nothing: a wave picks one by the seed, either.
  const Fixture even("stick_figure.svg");
  std::set<int> picked;
  for (uint32_t seed = 0; seed < 8; ++seed) picked.insert(even.plan("the figure waves", seed).actions[0].parts[0]);
  CHECK(picked.size() == 2);
}

TEST_CASE("a bird flaps its raised wing, not its small beak beside the body") {
  // Body 60-160 x 100-160, a wing raised above its back (tall and thin: an upper limb, not the
  // head), a beak at the left (an upper limb by place, a tenth of the wing's box).
  const Scene s = read_svg_file(data("bird_side.svg"));
  const Rig rig = build_rig(s, {});
  REQUIRE(rig.parts[2].role == Role::UpperLimb);
  const MotionPlan plan = plan_from_prompt(parse_prompt("a bird flies, flapping its wings"), rig, 1);  // no hover's bob
  REQUIRE(plan.actions.size() == 1);
  CHECK(plan.actions[0].parts == std::vector<int>{1});
  const auto pts = animate_plan(s, rig, plan, 13);
  double beak = 0, wing = 0;
  each_move(pts, 13, [&](Vec2 rest, Vec2 m) {
    double& part = rest.x < 62 && rest.y > 105 ? beak : wing;
    part = std::max(part, std::hypot(m.x, m.y));
  });
  CHECK(beak == 0.0);
  CHECK(wing > 10.0);
}

TEST_CASE("a head bobs by turning on its neck: the whole-figure bob aimed at a part swings it") {
  const Fixture fx("stick_figure.svg");
  const MotionPlan plan = fx.plan("he bobs his head");
  REQUIRE(plan.actions.size() == 1);
  const PlannedAction& a = plan.actions[0];
  INFO(a.why);
  CHECK(a.verb == "bob");
  CHECK(a.primitive == Primitive::Swing);
  REQUIRE(a.parts.size() == 1);
  CHECK(fx.rig.parts[a.parts[0]].role == Role::Head);
}

TEST_CASE("a motion too small to see is raised to 8 % of the figure's diagonal, at most twelve times") {
  const Fixture fx("stick_figure.svg");
  // A slight nod: the head turns by about 6 degrees about its neck, its top moving about 4
  // units, under 8 % of the figure's diagonal.
  MotionPlan plan = fx.plan("he nods his head slightly");
  REQUIRE(plan.actions.size() == 1);
  const int F = 49;  // the default clip, 15 keyframes: the turn limit (29 keyframes) is not reached
  const double diag = std::hypot(fx.rig.figure.w(), fx.rig.figure.h());
  auto largest = [&](const MotionPlan& p) {
    double m = 0;
    for (double v : fx.travel(animate_plan(fx.scene, fx.rig, p, F), F)) m = std::max(m, v);
    return m;
  };
  const double before = largest(plan);
  REQUIRE(before < 0.08 * diag);  // the drawing makes the test mean something
  fit_plan(fx.scene, fx.rig, plan, F, 15);
  CHECK(plan.actions[0].scale > 1.0);
  CHECK(plan.actions[0].scale <= 4.0);
  const double after = largest(plan);
  // Aiming kRaiseAim over the floor (a turn's chord grows a little slower than its angle:
  // within 1 %).
  CHECK(after == doctest::Approx(std::min(motion_plan_internal::kRaiseAim * 0.08 * diag, 12 * before)).epsilon(0.01));
  REQUIRE(!plan.notes.empty());
  CHECK(plan.notes[0].find("nod raised to") == 0);
  // A plain motion is left as it is.
  MotionPlan wave = fx.plan("the man waves his right arm");
  fit_plan(fx.scene, fx.rig, wave, F, 15);
  CHECK(wave.scale <= 1.0);
  CHECK(wave.actions[0].scale <= 1.0);
}

TEST_CASE("'a waving flag': a figure held by a pole waves by rippling from it, no region of it swings") {
  const Fixture f("flag.svg");
  MotionPlan plan = f.plan("A waving flag fluttering in the wind.");
  // wave and flutter (arm verbs) find no arm: both are the one ripple from the pole.
  REQUIRE(plan.actions.size() == 1);
  CHECK(plan.actions[0].primitive == Primitive::Undulate);
  CHECK(plan.actions[0].target == Target::Whole);
  CHECK(plan.actions[0].region == Region::None);
  CHECK(plan.actions[0].anchored == 1);
  CHECK(plan.actions[0].why.find("wave has no arms on a figure held by a pole") != std::string::npos);
  const int F = 25;
  fit_plan(f.scene, f.rig, plan, F, 9);
  const auto pts = animate_plan(f.scene, f.rig, plan, F);
  const auto t = f.travel(pts, F);
  CHECK(t[1] > 3.0);           // the cloth's free end moves
  CHECK(t[0] < 0.05 * t[1]);   // the pole holds
  // The same cloth without its pole waves by bending its sides, as any figure without arms.
  const Scene cloth = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">
           <g><path d="M 14 20 L 150 20 L 150 90 L 14 90 Z" fill="#c33"/></g>
           <g><path d="M 14 50 L 150 50 L 150 60 L 14 60 Z" fill="#fff"/></g></svg>)", "cloth.svg");
  const MotionPlan free = plan_from_prompt(parse_prompt("A waving flag."), build_rig(cloth, {}), 1);
  REQUIRE(free.actions.size() == 1);
  CHECK(free.actions[0].primitive == Primitive::Swing);
  CHECK(free.actions[0].region == Region::Sides);
}

TEST_CASE("a ferris wheel's small cabins ride round with the turning wheel, upright") {
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">
           <g><path d="M 95 100 L 105 100 L 130 190 L 70 190 Z" fill="#555"/></g>
           <g><path d="M 40 100 C 40 67 67 40 100 40 C 133 40 160 67 160 100 C 160 133 133 160 100 160 C 67 160 40 133 40 100 Z M 97 45 L 103 45 L 103 155 L 97 155 Z" fill="#d80" fill-rule="evenodd"/></g>
           <g><rect x="154" y="94" width="12" height="12" fill="#0a0"/></g></svg>)", "ferris.svg");
  const Rig rig = build_rig(s, {});
  MotionPlan plan = plan_from_prompt(parse_prompt("the ferris wheel turns slowly"), rig, 1);
  REQUIRE(plan.actions.size() == 1);
  CHECK(plan.actions[0].primitive == Primitive::Spin);
  CHECK(plan.actions[0].parts == std::vector<int>{1});
  const int F = 13;
  const auto pts = animate_plan(s, rig, plan, F);
  const size_t per = pts.size() / F;
  size_t cabin = 0;
  for (size_t p = 0; p < 2; ++p)
    for (const auto& sp : s.paths[p].subpaths) cabin += sp.points.size();
  for (int f = 0; f < F; ++f) {
    const Vec2 a = pts[f * per + cabin], b = pts[f * per + cabin + 1];
    CHECK(b.x - a.x == doctest::Approx(pts[cabin + 1].x - pts[cabin].x));  // upright: no turn
    CHECK(b.y - a.y == doctest::Approx(pts[cabin + 1].y - pts[cabin].y));
  }
  // The cabin hangs from the middle of its top, (160,94): at a quarter of the loop that point
  // has gone a quarter round the centre (100,100), to (94,40) or (106,160), the cabin below it.
  RigBox cb;
  for (size_t i = cabin; i < per; ++i) cb.add(pts[3 * per + i]);
  const Vec2 q{cb.centre().x, cb.y0};
  CHECK(std::hypot(q.x - 100, q.y - 100) == doctest::Approx(std::hypot(60.0, 6.0)).epsilon(1e-6));
  CHECK(std::fabs(q.x - 100) == doctest::Approx(6.0).epsilon(1e-6));
  CHECK(std::hypot(pts[0].x - pts[6 * per].x, pts[0].y - pts[6 * per].y) == 0.0);  // the stand holds
}

TEST_CASE("a ferris wheel with four cabins turns a quarter a loop: spokes about its centre, each cabin upright as one, the stand still") {
  const Fixture fx("ferris.svg");  // paths 0-7 cabins (roof, body), 8 rim, 9-11 spokes and hub, 12-14 stand, 15 shadow
  const MotionPlan plan = fx.plan("the ferris wheel turns slowly");
  REQUIRE(plan.actions.size() == 1);
  const PlannedAction& a = plan.actions[0];
  CHECK(a.primitive == Primitive::Spin);
  CHECK(a.parts == std::vector<int>{fx.rig.part_of_path[8]});
  CHECK(a.amp == doctest::Approx(0.25));  // four riders evenly round it: one spacing a loop
  const int F = 13;
  const auto pts = animate_plan(fx.scene, fx.rig, plan, F);
  const size_t per = pts.size() / F;
  const auto t = fx.travel(pts, F);
  CHECK(t[12] == 0.0);
  CHECK(t[13] == 0.0);
  CHECK(t[14] == 0.0);
  CHECK(t[15] == 0.0);  // the rim's shadow drawn once does not ride
  // The horizontal spoke's end (156,88) turns a quarter about (100,90): to (102,146) or (98,34).
  const Vec2 q = pts[(F - 1) * per + fx.first_point(9) + 3] - pts[fx.first_point(9) + 3];
  const Vec2 end = pts[(F - 1) * per + fx.first_point(9) + 3];
  CHECK(pts[fx.first_point(9) + 3].x == doctest::Approx(156.0));
  CHECK(std::min(std::hypot(end.x - 102, end.y - 146), std::hypot(end.x - 98, end.y - 34)) < 1e-6);
  CHECK(std::hypot(q.x, q.y) > 50.0);
  // Each cabin's roof and body move by one vector in every frame (upright, together).
  for (int c = 0; c < 4; ++c) {
    CHECK(t[2 * c] > 10.0);
    const size_t a0 = fx.first_point(2 * c), a1 = fx.first_point(2 * c + 2);
    for (int f = 0; f < F; ++f) {
      const Vec2 d = pts[f * per + a0] - pts[a0];
      for (size_t i = a0; i < a1; ++i) {
        CHECK(pts[f * per + i].x - pts[i].x == doctest::Approx(d.x));
        CHECK(pts[f * per + i].y - pts[i].y == doctest::Approx(d.y));
      }
    }
  }
}

TEST_CASE("a cabin hanging below the rim at the bottom stays in the canvas when it rides to the top") {
  // A wheel filling its canvas (centre (50,50), radius 45) and a cabin hanging from the rim
  // at its lowest point, inside the wheel's box (the rig hangs it from the wheel): turned with
  // the wheel or carried by its middle, it would stand out above the top.
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
           <g><path d="M 5 50 C 5 25 25 5 50 5 C 75 5 95 25 95 50 C 95 75 75 95 50 95 C 25 95 5 75 5 50 Z M 48 8 L 52 8 L 52 92 L 48 92 Z" fill="#d80" fill-rule="evenodd"/></g>
           <g><rect x="45" y="84" width="10" height="10" fill="#0a0"/></g>
           <g><rect x="78" y="78" width="12" height="12" fill="#00a"/></g></svg>)", "ferris_low.svg");
  const Rig rig = build_rig(s, {});
  MotionPlan plan = plan_from_prompt(parse_prompt("the wheel turns"), rig, 1);
  REQUIRE(plan.actions.size() == 1);
  CHECK(plan.actions[0].parts == std::vector<int>{0});
  const int F = 25;
  const auto pts = animate_plan(s, rig, plan, F);
  const size_t per = pts.size() / F;
  size_t cabin = 0;
  for (const auto& sp : s.paths[0].subpaths) cabin += sp.points.size();
  size_t corner = cabin;
  for (const auto& sp : s.paths[1].subpaths) corner += sp.points.size();
  double top = 1e9;
  for (int f = 0; f < F; ++f)
    for (size_t i = cabin; i < corner; ++i) top = std::min(top, pts[f * per + i].y);
  CHECK(top == doctest::Approx(16.0).epsilon(1e-6));  // its top (50,84) goes round to (50,16)
  for (int f = 0; f < F; ++f) {  // both upright: level edges, their sizes kept; both in the canvas
    RigBox b, c;
    for (size_t i = cabin; i < corner; ++i) b.add(pts[f * per + i]);
    for (size_t i = corner; i < per; ++i) c.add(pts[f * per + i]);
    CHECK(b.w() == doctest::Approx(10.0));
    CHECK(b.h() == doctest::Approx(10.0));
    CHECK(c.w() == doctest::Approx(12.0));
    CHECK(c.y0 >= 0.0);
  }
  // The rig hangs both from the wheel; the one in the box's corner has its middle (84,84)
  // beyond the rim's radius (48 > 45) and rides too, hanging from (84,78).
  CHECK(rig.parts[1].parent == 0);
  CHECK(rig.parts[2].parent == 0);
}

TEST_CASE("a verb's whole-figure accents scale down with its limbs' swing when the turn limit cuts it") {
  // Running: three strides a loop over 9 keyframes turn the legs too far between keyframes, so
  // their swing is cut; the body's bob, the run's accent, is cut by as much (at full size it
  // outweighed the legs of a galloping line-drawn horse).
  const Fixture fx("stick_figure.svg");
  MotionPlan plan = fx.plan("the man runs");
  fit_plan(fx.scene, fx.rig, plan, 49, 9);
  REQUIRE(plan.actions.size() == 3);
  REQUIRE(plan.actions[2].primitive == Primitive::Bob);
  const double limbs = std::min(plan.actions[0].scale, plan.actions[1].scale);
  REQUIRE(limbs < 1);
  CHECK(plan.actions[2].scale == doctest::Approx(limbs));
  CHECK(std::find_if(plan.notes.begin(), plan.notes.end(), [](const std::string& n) { return n.find("with its limbs' swing") != std::string::npos; }) != plan.notes.end());
}

TEST_CASE("arms drawn in one body outline: only the arm lobes bend, about their bases; the hem and the head hold") {
  // A ghost drawn as one outline (y down): its head's top at 100,20, a raised right arm (the
  // viewer's right) out to 175-178,50-56 between its shoulder 140,60 and armpit 145,85, a left
  // arm out to 20-22,92-100 between 60,70 and 58,95, and a scalloped hem whose right corner
  // (172,160) sticks out sideways too, but low and joined to the body along most of its side.
  // An eye inside the body.
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">
           <g><path d="M 100 20 L 130 30 L 140 60 L 175 50 L 178 56 L 145 85 L 150 140 L 172 160 L 160 175
                       L 140 165 L 120 180 L 100 168 L 80 180 L 65 168 L 50 160 L 55 140 L 58 95 L 22 100
                       L 20 92 L 60 70 L 70 30 Z" fill="#eee"/></g>
           <g><path d="M 90 60 L 96 60 L 96 66 L 90 66 Z" fill="#222"/></g></svg>)",
      "ghost.svg");
  const std::vector<ArmLobe> lobes = arm_lobes(s.paths[0]);
  REQUIRE(lobes.size() == 2);
  CHECK(lobes[0].side == -1);
  CHECK(lobes[0].tip.x == doctest::Approx(20).epsilon(0.05));
  CHECK(lobes[1].side == 1);
  CHECK(lobes[1].tip.x > 170);
  // The arm's tip is in its lobe, the body's middle, the hem corner and the head are not.
  CHECK(lobe_depth(lobes[0], {25, 95}) > 0);
  CHECK(lobe_depth(lobes[0], {100, 100}) == 0);
  CHECK(lobe_depth(lobes[1], {170, 160}) == 0);
  CHECK(lobe_depth(lobes[1], {100, 25}) == 0);

  const Rig rig = build_rig(s, {});
  REQUIRE(rig.root == 0);
  CHECK(rig.parts[0].arm_lobes.size() == 2);
  const MotionPlan plan = plan_from_prompt(parse_prompt("the ghost is waving its arms"), rig, 1);
  REQUIRE(plan.actions.size() == 1);
  CHECK(plan.actions[0].region == Region::Sides);
  CHECK(plan.actions[0].lobes.size() == 2);
  const int F = 25;
  const auto pts = animate_plan(s, rig, plan, F);
  const size_t per = pts.size() / F;
  auto travel_at = [&](Vec2 rest) {
    double t = 0;
    for (size_t i = 0; i < per; ++i)
      if (std::hypot(pts[i].x - rest.x, pts[i].y - rest.y) < 1e-6)
        for (int f = 1; f < F; ++f) t = std::max(t, std::hypot(pts[f * per + i].x - rest.x, pts[f * per + i].y - rest.y));
    return t;
  };
  CHECK(travel_at({20, 92}) > 5);    // the left arm's tip
  CHECK(travel_at({178, 56}) > 5);   // the right arm's tip
  CHECK(travel_at({172, 160}) == 0); // the hem's corner
  CHECK(travel_at({100, 20}) == 0);  // the head
  CHECK(travel_at({90, 60}) == 0);   // the eye
  CHECK(loop_gap(pts, F) < 1e-9);
  // One arm asked for: its lobe alone. Limbs (tentacles, petals) reach out all round: the
  // sides bend, not two lobes.
  const MotionPlan left = plan_from_prompt(parse_prompt("the ghost waves its left arm"), rig, 1);
  REQUIRE(left.actions.size() == 1);
  CHECK(left.actions[0].region_side == 1);  // the figure's left, drawn on the viewer's right
  CHECK(left.actions[0].lobes.size() == 2);
  const auto one = animate_plan(s, rig, left, F);
  double right_tip = 0, left_tip = 0;
  for (size_t i = 0; i < per; ++i)
    for (int f = 1; f < F; ++f) {
      const double d = std::hypot(one[f * per + i].x - one[i].x, one[f * per + i].y - one[i].y);
      if (std::hypot(one[i].x - 178, one[i].y - 56) < 1e-6) right_tip = std::max(right_tip, d);
      if (std::hypot(one[i].x - 20, one[i].y - 92) < 1e-6) left_tip = std::max(left_tip, d);
    }
  CHECK(right_tip > 5);
  CHECK(left_tip == 0);
  const MotionPlan limbs = plan_from_prompt(parse_prompt("the ghost sways its limbs"), rig, 1);
  REQUIRE(limbs.actions.size() == 1);
  CHECK(limbs.actions[0].region == Region::Sides);
  // Not the outline's one pair of arms (limbs reach out all round: petals, tentacles); the
  // silhouette's limbs, if any.
  CHECK((limbs.actions[0].lobes.empty() || limbs.actions[0].silhouette));
}

}  // TEST_SUITE

TEST_SUITE("motion") {

TEST_CASE("a tail not drawn as a part of its own: the tail of the figure's silhouette wags, fill and outline together; the head holds") {
  // A dog facing left drawn as one filled body (a box on four legs, a head at the left, a tail
  // rising from its back end at the right), and the tail's outline drawn again as a stroke in
  // another group (the way emoji draw black outlines over fills).
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="240" height="200">
           <g><path d="M 60 80 L 165 80 L 210 32 L 218 40 L 170 92 L 170 150 L 160 150 L 160 115 L 150 115 L 150 150 L 140 150 L 140 115
                       L 90 115 L 90 150 L 80 150 L 80 115 L 70 115 L 70 150 L 60 150 Z
                       M 20 50 L 60 50 L 60 95 L 20 95 Z" fill="#a60"/></g>
           <g><path d="M 165 80 L 210 32 L 218 40 L 170 92" stroke="#000" stroke-width="2" fill="none"/></g></svg>)", "dog.svg");
  const Rig rig = build_rig(s, {});
  bool tail = false;
  for (const ArmLobe& l : rig.limbs) tail = tail || (l.kind == LobeKind::Tail && l.tip.x > 195 && l.tip.y < 55);
  REQUIRE(tail);
  const MotionPlan plan = plan_from_prompt(parse_prompt("the dog wags its tail"), rig, 3);
  REQUIRE(plan.actions.size() == 1);
  INFO(plan.actions[0].why);
  CHECK(plan.actions[0].silhouette);
  const int F = 37;  // not a multiple of the wag's half cycles: no frame lands on rest
  const auto pts = animate_plan(s, rig, plan, F);
  const size_t per = pts.size() / F;
  // Points in order: the body's (head last: its subpath is the second), then the tail stroke's.
  double head = 0, tail_tip = 0, legs = 0;
  for (size_t i = 0; i < per; ++i)
    for (int f = 1; f < F; ++f) {
      const Vec2 r = pts[i], q = pts[f * per + i];
      const double d = std::hypot(q.x - r.x, q.y - r.y);
      if (r.x <= 60) head = std::max(head, d);
      if (r.y >= 140) legs = std::max(legs, d);
      if (std::hypot(r.x - 210, r.y - 32) < 1e-9) tail_tip = std::max(tail_tip, d);
    }
  CHECK(tail_tip > 8);
  CHECK(head == 0);
  CHECK(legs == 0);
}

TEST_CASE("a bird seen from the side: its near wing and the far one rising behind it beat together; the body holds") {
  // An upright body drawn as one path with two wings up from it (the way emoji draw a dove):
  // the near one out to the right, the far one straight up from the shoulders (the skeleton's
  // labels see an upright body's head there).
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">
           <path d="M 70 130 C 70 100 84 80 100 80 C 116 80 130 100 130 130 C 130 160 116 180 100 180 C 84 180 70 160 70 130 Z
                    M 94 90 L 96 15 L 104 15 L 106 90 Z M 108 100 L 168 22 L 176 30 L 124 108 Z" fill="#ccc"/></svg>)", "dove_profile.svg");
  const Rig rig = build_rig(s, {});
  int arms = 0, up = 0;
  for (const ArmLobe& l : rig.limbs) arms += l.kind == LobeKind::Arm, up += l.kind == LobeKind::Head;
  REQUIRE(arms == 1);
  REQUIRE(up == 1);
  const MotionPlan plan = plan_from_prompt(parse_prompt("the bird flaps its wings"), rig, 1);
  REQUIRE(plan.actions.size() == 1);  // the wings named: flapping's bob is left out
  const PlannedAction& a = plan.actions[0];
  INFO(a.why);
  CHECK(a.silhouette);
  CHECK(a.lobes.size() == 2);
  // Not a bird: a figure with one arm raised and a head keeps its head (no pair: the sides bend).
  const MotionPlan man = plan_from_prompt(parse_prompt("the man waves both arms"), rig, 1);
  REQUIRE(!man.actions.empty());
  CHECK(man.actions[0].lobes.size() != 2);
  const int F = 13;
  const auto pts = animate_plan(s, rig, plan, F);
  const size_t per = pts.size() / F;
  double far_tip = 0, near_tip = 0, bottom = 0;
  for (size_t i = 0; i < per; ++i)
    for (int f = 1; f < F; ++f) {
      const Vec2 r = pts[i], q = pts[f * per + i];
      const double d = std::hypot(q.x - r.x, q.y - r.y);
      if (r.y <= 15.5 && r.x < 110) far_tip = std::max(far_tip, d);
      if (r.x >= 168) near_tip = std::max(near_tip, d);
      if (r.y >= 150) bottom = std::max(bottom, d);
    }
  CHECK(far_tip > 8);
  CHECK(near_tip > 8);
  CHECK(bottom == 0);
}

TEST_CASE("a tail with no limb of its own bends at the end away from the head, whatever the seed") {
  // A lying body drawn as one bar (its skeleton has no limbs) and a head above its left half:
  // the far-end bend of the tail is the right end for every seed (by the seed's coin it was
  // the head's end of half the mermaids).
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="240" height="200">
           <g><path d="M 20 100 L 220 100 L 220 140 L 20 140 Z" fill="#a60"/></g>
           <g><path d="M 50 60 L 90 55 L 95 95 L 55 100 Z" fill="#fc9"/></g></svg>)", "lying.svg");
  const Rig rig = build_rig(s, {});
  int head = -1;
  for (size_t i = 0; i < rig.parts.size(); ++i)
    if (rig.parts[i].role == Role::Head) head = static_cast<int>(i);
  REQUIRE(head >= 0);
  for (uint32_t seed = 0; seed < 6; ++seed) {
    const MotionPlan plan = plan_from_prompt(parse_prompt("the mermaid flicks her tail"), rig, seed);
    REQUIRE(plan.actions.size() == 1);
    const PlannedAction& a = plan.actions[0];
    INFO(a.why);
    REQUIRE(a.region == Region::End);
    CHECK(a.direction == 1);
    const int F = 13;
    const auto pts = animate_plan(s, rig, plan, F);
    double left = 0, right = 0;
    each_move(pts, F, [&](Vec2 rest, Vec2 m) {
      double& end = rest.x < 120 ? left : right;
      end = std::max(end, std::hypot(m.x, m.y));
    });
    CHECK(left == 0.0);
    CHECK(right > 8.0);
  }
}

TEST_CASE("a head swivels by turning on its neck and back, not round") {
  const Fixture fx("stick_figure.svg");
  const MotionPlan plan = fx.plan("the owl swivels its head");
  REQUIRE(plan.actions.size() == 1);
  const PlannedAction& a = plan.actions[0];
  INFO(a.why);
  CHECK(a.primitive == Primitive::Swing);
  REQUIRE(a.parts.size() == 1);
  CHECK(fx.rig.parts[a.parts[0]].role == Role::Head);
}

TEST_CASE("'dribbles the ball, bouncing it': the ball, the widest round part, bounces; the player and his round knee hold") {
  const Fixture fx("dribble.svg");
  std::vector<int> round;
  for (size_t i = 0; i < fx.rig.parts.size(); ++i)
    if (fx.rig.parts[i].round) round.push_back(static_cast<int>(i));
  REQUIRE(round.size() == 2);
  const MotionPlan plan = fx.plan("he dribbles the ball, bouncing it off the floor");
  REQUIRE(!plan.actions.empty());  // the two clauses' bounce is one (the same on the same part)
  for (const auto& a : plan.actions) {
    CHECK(a.verb == "bounce");
    CHECK(a.primitive == Primitive::Hop);
    REQUIRE(a.parts.size() == 1);
    CHECK(fx.rig.parts[a.parts[0]].box.w() > 45);  // the ball (50 wide), not the knee (36)
  }
  const auto t = fx.travel(animate_plan(fx.scene, fx.rig, plan, 13), 13);
  CHECK(t[1] > 5);
  CHECK(t[0] == doctest::Approx(0).epsilon(0.001));
  CHECK(t[2] == doctest::Approx(0).epsilon(0.001));
  // Balls, plural: every large round part.
  CHECK(fx.plan("he bounces the balls").actions.at(0).parts.size() == 2);
  // A ball a limb's verb acts on goes with the limb: the arm throws, the ball does not swing alone.
  const MotionPlan thrown = fx.plan("the player throws the ball");
  REQUIRE(!thrown.actions.empty());
  CHECK(thrown.actions[0].verb == "throw");
  CHECK(thrown.actions[0].target == Target::Arms);
}

TEST_CASE("'thrusts his foil forward': forward is the side the arm reaches out to; without the word the seed picks") {
  const Fixture fx("fencer_outline.svg");
  std::set<int> sides, forward;
  for (uint32_t seed = 0; seed < 8; ++seed) {
    const MotionPlan f = fx.plan("the fencer thrusts his foil forward", seed);
    REQUIRE(!f.actions.empty());
    forward.insert(f.actions[0].region_side);
    CHECK(!f.actions[0].lobes.empty());
    sides.insert(fx.plan("the fencer thrusts his foil", seed).actions.at(0).region_side);
  }
  CHECK(forward == std::set<int>{-1});  // the sword arm, at the viewer's left
  CHECK(sides == std::set<int>{-1, 1});
}

}  // TEST_SUITE

TEST_SUITE("motion") {

TEST_CASE("a car drives: its body slides a visible distance inside the canvas and its wheels roll with it") {
  // tests/data/motion/car.svg: a body 120 wide, wheels of radius 15 centred at (70,90) and
  // (130,90), 40 of canvas either side. The drive's shake and whole-turn spin alone left the
  // body where it was (0.6 % of its size); the wheels now turn by the distance over their radius.
  const Fixture fx("car.svg");
  MotionPlan plan = fx.plan("the car drives to the right");
  const int F = 49;
  fit_plan(fx.scene, fx.rig, plan, F, 15);
  const PlannedAction* spin = nullptr;
  const PlannedAction* slide = nullptr;
  for (const auto& a : plan.actions) {
    if (a.primitive == Primitive::Spin) spin = &a;
    if (a.primitive == Primitive::Slide) slide = &a;
  }
  REQUIRE(spin);
  REQUIRE(slide);
  CHECK(spin->rolls);
  CHECK(spin->parts.size() == 2);
  CHECK(slide->direction == 1);  // "to the right"
  // The engine's tremor (a shake of 0.6 % of the height) moves the body but does not roll the
  // wheels: without it, every shift of the body is the slide's.
  for (auto& a : plan.actions)
    if (a.primitive == Primitive::Shake) a.amp = 0;
  const auto pts = animate_plan(fx.scene, fx.rig, plan, F);
  const size_t per = pts.size() / F;
  const double diagonal = std::hypot(120.0, 65.0);  // the figure: x 40-160, y 40-105
  double farthest = 0;
  for (int f = 0; f < F; ++f) {
    const size_t body = fx.first_point(0), wheel = fx.first_point(1);
    const Vec2 shift = pts[f * per + body] - pts[body];
    farthest = std::max(farthest, std::fabs(shift.x));
    for (size_t i = 0; i < per; ++i) {  // nothing leaves the canvas
      CHECK(pts[f * per + i].x >= 0);
      CHECK(pts[f * per + i].x <= 200);
    }
    // The back wheel's centre goes with the body (up to the shake); its spoke's tip (70,77) turns
    // about it by the distance the body went over the radius: clockwise going right.
    const double theta = shift.x / 15;
    const Vec2 centre{70 + shift.x, 90 + shift.y};
    const size_t tip = wheel + fx.scene.paths[1].subpaths[0].points.size();  // the spoke: M 69 77
    const Vec2 spoke_rest = pts[tip] - Vec2{70, 90};
    const Vec2 expect{centre.x + std::cos(theta) * spoke_rest.x - std::sin(theta) * spoke_rest.y,
                      centre.y + std::sin(theta) * spoke_rest.x + std::cos(theta) * spoke_rest.y};
    CHECK(pts[f * per + tip].x == doctest::Approx(expect.x).epsilon(1e-6));
    CHECK(pts[f * per + tip].y == doctest::Approx(expect.y).epsilon(1e-6));
  }
  CHECK(farthest >= 0.08 * diagonal);  // the visible-travel floor (motion_plan_internal.h)
  CHECK(loop_gap(pts, F) < 1e-6);
}

}  // TEST_SUITE

TEST_SUITE("motion") {

TEST_CASE("wheels that look the same at every angle: sent somewhere the figure rolls, else the body bounces on them") {
  // car.svg's wheels each have a spoke: their spin shows, nothing else moves. Without the spokes
  // they are plain discs (a circle as four cubics keeps its radius within 0.03 %): spun in place
  // no pixel would change (the ranker's 'no motion' for every candidate). Sent to the right the
  // car rolls there; sent nowhere the wheels spin in place and the body bounces on them.
  auto plan_for = [](const Scene& scene, const std::string& prompt) {
    const Rig rig = build_rig(scene, {});
    MotionPlan plan = plan_from_prompt(parse_prompt(prompt), rig, 1);
    fit_plan(scene, rig, plan, 25, 9);
    return std::make_pair(rig, plan);
  };
  const Fixture spoked("car.svg");
  {
    const auto [rig, plan] = plan_for(spoked.scene, "the car's wheels spin");
    REQUIRE(plan.actions.size() == 1);
    CHECK(plan.actions[0].primitive == Primitive::Spin);
    CHECK(!plan.actions[0].rolls);
    CHECK(!looks_same_turned(spoked.scene, rig, plan.actions[0].parts));
  }
  Scene plain = spoked.scene;
  for (int w : {1, 2}) plain.paths[w].subpaths.resize(1);  // the spokes taken out
  {
    const auto [rig, plan] = plan_for(plain, "the car's wheels spin to the right");
    REQUIRE(plan.actions.size() == 2);
    CHECK(plan.actions[0].primitive == Primitive::Spin);
    CHECK(plan.actions[0].parts.size() == 2);
    CHECK(looks_same_turned(plain, rig, plan.actions[0].parts));
    CHECK(plan.actions[0].rolls);
    CHECK(plan.actions[1].primitive == Primitive::Slide);
    CHECK(plan.actions[1].parts.empty());
    CHECK(plan.actions[1].direction == 1);
    REQUIRE(!plan.warnings.empty());
    CHECK(plan.warnings[0].find("so the figure rolls with them") != std::string::npos);
    const auto t = path_travel(plain, animate_plan(plain, rig, plan, 25), 25);
    CHECK(t[0] >= 0.08 * std::hypot(120.0, 65.0));  // the body goes a visible distance
  }
  const auto [rig, plan] = plan_for(plain, "the car's wheels spin");
  REQUIRE(plan.actions.size() == 2);
  CHECK(!plan.actions[0].rolls);
  CHECK(plan.actions[1].primitive == Primitive::Bob);
  CHECK(plan.actions[1].parts.empty());
  REQUIRE(!plan.warnings.empty());
  CHECK(plan.warnings[0].find("so the body bounces on them") != std::string::npos);
  // The wheels' points stay on their circles about their resting centres (they spin in place,
  // on the ground); the body's first point bounces and never leaves its column.
  const int F = 25;
  const auto pts = animate_plan(plain, rig, plan, F);
  const size_t per = pts.size() / F;
  double bounce = 0;
  for (int f = 0; f < F; ++f) {
    for (int w : {1, 2}) {
      const RigBox box = rig.parts[rig.part_of_path[w]].box;
      const Vec2 c = box.centre();
      size_t first = 0;
      for (int p = 0; p < w; ++p) first += plain.paths[p].subpaths[0].points.size();
      for (size_t i = 0; i < plain.paths[w].subpaths[0].points.size(); ++i) {
        const Vec2 q = pts[f * per + first + i], r = pts[first + i];
        CHECK(std::hypot(q.x - c.x, q.y - c.y) == doctest::Approx(std::hypot(r.x - c.x, r.y - c.y)).epsilon(1e-6));
      }
    }
    const Vec2 d = pts[f * per] - pts[0];
    CHECK(std::fabs(d.x) < 1e-9);
    bounce = std::max(bounce, std::fabs(d.y));
  }
  // kIdleBounces up-and-downs of kIdleBounce of the figure's height, sampled at the frames.
  double peak = 0;
  for (int f = 0; f < F; ++f) peak = std::max(peak, std::fabs(std::sin(2 * M_PI * kIdleBounces * f / (F - 1.0))));
  CHECK(plan.actions[1].one_sided == 0);
  CHECK(bounce == doctest::Approx(kIdleBounce * rig.figure.h() * peak).epsilon(1e-6));
}

}  // TEST_SUITE

TEST_SUITE("motion") {

TEST_CASE("the figure's own noun is understood: it names who moves; a word the lexicon does not know is listed") {
  const Fixture fx("stick_figure.svg");
  auto listed = [&](const std::string& prompt, const std::string& word) {
    const auto nu = fx.plan(prompt).not_understood;
    return std::find(nu.begin(), nu.end(), word) != nu.end();
  };
  CHECK(!listed("the tiger lashes its tail", "tiger"));
  CHECK(!listed("the dancer waves her arms", "dancer"));
  CHECK(listed("the zorblax waves its arms", "zorblax"));
  CHECK(listed("he waves at the tiger", "tiger"));  // after a preposition: not who moves, no part
}

}  // TEST_SUITE
