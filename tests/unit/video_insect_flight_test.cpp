// Light things that go about in the air (issue 35): an insect's flight read as a buzz's dart with
// its wings beating (self_movers.h's insect_flight), a carried flight's body raised to
// kCarriedTravel of the figure's size, not the visible floor (motion_fit.cpp), and room on the
// canvas for a figure the prompt carries about (travel_words.h, pipeline/canvas_room.h). On
// drawings made for these tests: bird.svg (a body, a head and two wings, 160 x 51 in a 200
// canvas) and bee_room.svg (the same, 60 x 38).
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "pipeline/canvas_room.h"
#include "procedural/motion_plan.h"
#include "procedural/motion_plan_internal.h"
#include "procedural/prompt_parse.h"
#include "procedural/self_movers.h"
#include "procedural/travel_words.h"
#include "svgmotion/svg_reader.h"

#include "motion_drawing.h"
using namespace svgm;
using svgm::test::Drawing;
using svgm::motion_plan_internal::kCarriedTravel;

namespace {

double diagonal(const Rig& rig) { return std::hypot(rig.figure.w(), rig.figure.h()); }

// Whether `plan` moves the whole figure by a primitive `p` of verb `verb`, and beats the wings
// (a swing of the arms) by that verb.
bool has_whole(const MotionPlan& plan, Primitive p, const char* verb) {
  for (const PlannedAction& a : plan.actions)
    if (a.target == Target::Whole && a.parts.empty() && a.primitive == p && a.verb == verb) return true;
  return false;
}
bool beats_wings(const MotionPlan& plan, const char* verb) {
  for (const PlannedAction& a : plan.actions)
    if (a.target == Target::Arms && a.primitive == Primitive::Swing && a.verb == verb) return true;
  return false;
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("insect flight: an insect that flits, zips, flutters by or flies about darts about with its wings beating") {
  const Drawing d("bird.svg");
  for (const char* prompt : {"the mosquito flits around", "the fly zips around", "the butterfly flutters by",
                             "the beetle flies about, wings beating"}) {
    INFO(prompt);
    const MotionPlan plan = plan_from_prompt(parse_prompt(prompt), d.rig, 1);
    // Read as they were: flutter's wing beat in place, move's slide with the wings still, fly's
    // wing beat with its bob left out for the named wings.
    CHECK(has_whole(plan, Primitive::Slide, "buzz"));
    CHECK(has_whole(plan, Primitive::Bob, "buzz"));
    CHECK(beats_wings(plan, "buzz"));
  }
}

TEST_CASE("insect flight: a flutter of the wings beats them in place, a crawl crawls, and a bird's flight is its own") {
  const Drawing d("bird.svg");
  const MotionPlan wings = plan_from_prompt(parse_prompt("the butterfly flutters its wings"), d.rig, 1);
  CHECK(beats_wings(wings, "flutter"));
  for (const PlannedAction& a : wings.actions) CHECK(a.verb != "buzz");
  const ParsedPrompt crawl = parse_prompt("the ladybird crawls up the stem");
  REQUIRE(crawl.clauses.size() == 1);
  REQUIRE(crawl.clauses[0].verbs.size() == 1);
  CHECK(insect_flight(crawl.clauses[0].verbs[0], crawl.clauses[0], crawl.clauses[0].verb_words[0])->name == "move");
  const ParsedPrompt bird = parse_prompt("the sparrow flies about");
  REQUIRE(bird.clauses.size() == 1);
  REQUIRE(!bird.clauses[0].verbs.empty());
  CHECK(insect_flight(bird.clauses[0].verbs[0], bird.clauses[0], bird.clauses[0].verb_words[0])->name == "fly");
}

TEST_CASE("insect flight: a buzz's dart is raised to kCarriedTravel of the figure's size, past the floor, where the canvas has room") {
  {
    // bee_room.svg: a bee 60 x 38 in a 200 canvas, room all round: nothing cuts the raise.
    const Drawing d("bee_room.svg");
    MotionPlan plan = plan_from_prompt(parse_prompt("the bee buzzes about"), d.rig, 1);
    const int F = 49;
    fit_plan(d.scene, d.rig, plan, F, 9);
    // The body (path 0) moves by the dart alone, raised to kCarriedTravel (kRaiseAim over it),
    // then cut only with every action by the plan's scale. Raised to the floor, 8.6 %.
    const double body = d.travel(plan, F)[0];
    CHECK(plan.scale >= 0.8);
    CHECK(body >= kCarriedTravel * diagonal(d.rig) * plan.scale * (1 - 1e-6));
  }
}

TEST_CASE("insect flight: a figure across 80 % of its canvas gets room when the prompt carries it about in the air") {
  CHECK(carries_figure_about(parse_prompt("the drone hovers, its rotors whirring")));
  CHECK(carries_figure_about(parse_prompt("the balloon drifts to the right on the breeze")));
  CHECK(carries_figure_about(parse_prompt("the mosquito flits around")));
  CHECK_FALSE(carries_figure_about(parse_prompt("the butterfly flutters its wings")));
  CHECK_FALSE(carries_figure_about(parse_prompt("the man waves his right arm")));
  // A 100 x 100 canvas; a body from 10 to 90 both ways (80 %: under kFillsCanvas, over kTravelFills).
  const Scene scene = read_svg_string(R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">
    <rect x="10" y="10" width="80" height="80" fill="red"/></svg>)",
                                      "t.svg");
  char why[200] = "";
  CHECK(auto_room(scene, "the drone hovers", why, sizeof why) == kAutoRoom);
  CHECK(std::string(why) == "the prompt carries the figure about in the air and it spans 80 % of its canvas's width");
  CHECK(auto_room(scene, "the balloon floats", nullptr, 0) == kAutoRoom);
  CHECK(auto_room(scene, "the lamp glows", nullptr, 0) == 0);
  CHECK(auto_room(scene, "the butterfly flutters its wings", nullptr, 0) == 0);
}

}  // TEST_SUITE
