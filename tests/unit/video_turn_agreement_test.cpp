// Two turns of the whole figure go the same way first (turn_agreement.h): "hangs ... and swings"
// plans a sway and a rock of the whole figure hung from a bar (tests/data/motion/hang_from_bar.svg),
// and "sways and rocks" the same on a standing figure (stick_figure.svg); in every seed the two
// take one direction and the figure moves at least the floor (8 % of its size), where with
// the ways drawn apart some seeds' turns cancelled to a still figure.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "svgmotion/svg_reader.h"
#include "procedural/motion_plan.h"
#include "procedural/prompt_parse.h"
#include "test_paths.h"
#include "wordnet_or_skip.h"

using namespace svgm;

namespace {

// The farthest any point of the drawing moves from rest over `frames` frames of `plan`.
double farthest(const Scene& s, const Rig& rig, const MotionPlan& plan) {
  const int frames = 17;
  const std::vector<Vec2> pts = animate_plan(s, rig, plan, frames);
  std::vector<Vec2> rest;
  for (const Path& p : s.paths)
    for (const Subpath& sp : p.subpaths) rest.insert(rest.end(), sp.points.begin(), sp.points.end());
  REQUIRE(pts.size() == rest.size() * frames);
  double most = 0;
  for (int f = 0; f < frames; ++f)
    for (size_t i = 0; i < rest.size(); ++i) most = std::max(most, std::hypot(pts[f * rest.size() + i].x - rest[i].x, pts[f * rest.size() + i].y - rest[i].y));
  return most;
}

// For seeds 0-15: the plan of `prompt` on `file` turns the whole figure by a sway and a rock of
// one direction, and some point moves at least 8 % of the figure's diagonal. Returns how many
// seeds' plans had both turns.
int check_turns_agree(const char* file, const char* prompt) {
  const Scene s = read_svg_file(svgm::test::data_path(file));
  const Rig rig = build_rig(s, read_source_names(svgm::test::data_path(file)));
  const double floor = 0.08 * std::hypot(rig.figure.w(), rig.figure.h());
  int both = 0;
  for (uint32_t seed = 0; seed < 16; ++seed) {
    CAPTURE(seed);
    const MotionPlan plan = plan_from_prompt(parse_prompt(prompt), rig, seed);
    const PlannedAction *sway = nullptr, *rock = nullptr;
    for (const PlannedAction& a : plan.actions) {
      if (a.primitive == Primitive::Sway && a.parts.empty()) sway = &a;
      if (a.primitive == Primitive::Rock && a.parts.empty()) rock = &a;
    }
    REQUIRE(sway);
    REQUIRE(rock);
    ++both;
    CHECK(sway->direction == rock->direction);
    CHECK(farthest(s, rig, plan) > floor);
  }
  return both;
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("a figure hung from a bar that sways and swings turns one way about its grip in every seed, never still") {
  if (!wordnet_or_skip()) return;
  CHECK(check_turns_agree("motion/hang_from_bar.svg", "it hangs from the branch and swings slowly") == 16);
}

TEST_CASE("a standing figure that sways and rocks leans one way in every seed, never still") {
  if (!wordnet_or_skip()) return;
  CHECK(check_turns_agree("motion/stick_figure.svg", "he sways and rocks") == 16);
}

}
