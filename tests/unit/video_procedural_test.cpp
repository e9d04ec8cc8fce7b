// The procedural video provider's motion library: prompt words to motions, the chosen part
// moves while the rest holds still, loops start and end at rest, seeds vary the candidates.
#include <doctest/doctest.h>

#include <cmath>

#include "svgmotion/svg_reader.h"
#include "video/procedural_motion.h"

using namespace svgm;

TEST_SUITE("fit") {

TEST_CASE("prompts map to motions by their words; unknown prompts idle with a note") {
  std::string note;
  CHECK(motion_for_prompt("The man waves his right arm", &note) == "wave");
  CHECK(note.empty());
  CHECK(motion_for_prompt("a bird flapping its wings", &note) == "fly");
  CHECK(motion_for_prompt("A balloon floating in the air.", &note) == "sway");
  CHECK(motion_for_prompt("the dog wags its tail", &note) == "wag");
  CHECK(motion_for_prompt("a heart beating", &note) == "pulse");
  CHECK(motion_for_prompt("Running fast", &note) == "run");
  CHECK(motion_for_prompt("nothing happens", &note) == "idle");
  CHECK(note == "no motion word in the prompt; using a gentle idle motion");
  CHECK(motion_for_prompt("show him", &note) == "idle");  // "how" inside a word is not "ho..."
}

TEST_CASE("a wave moves one arm around its shoulder, the body holds still, the loop closes") {
  const Scene s = read_svg_file(std::string(SVGM_TEST_DATA) + "/examples/man.svg");
  const int F = 25;
  ProceduralMotion info;
  const auto pts = animate_scene(s, "wave", F, 3, &info);
  const size_t per = pts.size() / F;
  REQUIRE(per * F == pts.size());
  REQUIRE(info.parts.size() == 1);
  const std::string moved = s.groups[info.parts[0]].id;
  CHECK((moved == "arm_right" || moved == "arm_left"));
  double still = 0, arm = 0, loop = 0;
  size_t i = 0;
  for (const auto& p : s.paths)
    for (const auto& sp : p.subpaths)
      for (size_t q = 0; q < sp.points.size(); ++q, ++i) {
        double m = 0;
        for (int f = 0; f < F; ++f) m = std::max(m, std::hypot(pts[f * per + i].x - pts[i].x, pts[f * per + i].y - pts[i].y));
        (s.groups[p.group].id == moved ? arm : still) = std::max(s.groups[p.group].id == moved ? arm : still, m);
        loop = std::max(loop, std::hypot(pts[(F - 1) * per + i].x - pts[i].x, pts[(F - 1) * per + i].y - pts[i].y));
      }
  CHECK(still == 0.0);
  CHECK(arm > 20.0);     // user units of the 512-unit drawing
  CHECK(loop < 1e-6);    // the last frame is the first: the video loops
  // Another seed: another amplitude or phase, same kind of motion.
  const auto other = animate_scene(s, "wave", F, 4, nullptr);
  double differ = 0;
  for (size_t k = 0; k < pts.size(); ++k) differ = std::max(differ, std::hypot(pts[k].x - other[k].x, pts[k].y - other[k].y));
  CHECK(differ > 1.0);
  // Deterministic.
  const auto again = animate_scene(s, "wave", F, 3, nullptr);
  CHECK(again == pts);
}

TEST_CASE("a side named in the prompt picks the arm whose group is named for that side") {
  CHECK(side_for_prompt("The man waves his right arm") == 1);
  CHECK(side_for_prompt("wave with the LEFT hand") == -1);
  CHECK(side_for_prompt("a bright wave") == 0);  // "right" inside a word is not the side
  CHECK(side_for_prompt("left and right") == 0);
  const Scene s = read_svg_file(std::string(SVGM_TEST_DATA) + "/examples/man.svg");
  for (uint32_t seed = 0; seed < 6; ++seed) {
    ProceduralMotion r, l;
    animate_scene(s, "wave", 9, seed, &r, 1);
    animate_scene(s, "wave", 9, seed, &l, -1);
    REQUIRE(r.parts.size() == 1);
    REQUIRE(l.parts.size() == 1);
    CHECK(s.groups[r.parts[0]].id == "arm_right");
    CHECK(s.groups[l.parts[0]].id == "arm_left");
  }
}

TEST_CASE("a wave with no arm where a figure has one still moves something") {
  // The largest max point displacement over the frames.
  auto travel = [](const std::vector<Vec2>& pts, int F) {
    const size_t per = pts.size() / F;
    double m = 0;
    for (int f = 1; f < F; ++f)
      for (size_t i = 0; i < per; ++i) m = std::max(m, std::hypot(pts[f * per + i].x - pts[i].x, pts[f * per + i].y - pts[i].y));
    return m;
  };
  // A body and one part hanging below it: no side part, no head.
  const Scene two = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
           <g id="body"><rect x="30" y="10" width="40" height="50" fill="#f00"/></g>
           <g id="tail"><rect x="45" y="60" width="10" height="30" fill="#00f"/></g></svg>)", "two.svg");
  ProceduralMotion info;
  const auto pts = animate_scene(two, "wave", 9, 1, &info);
  REQUIRE(info.parts.size() == 1);
  CHECK(two.groups[info.parts[0]].id == "tail");
  CHECK(travel(pts, 9) > 1.0);
  // One group only: the whole drawing sways.
  const Scene one = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
           <rect x="30" y="10" width="40" height="50" fill="#f00"/></svg>)", "one.svg");
  ProceduralMotion solo;
  const auto moved = animate_scene(one, "wave", 9, 1, &solo);
  CHECK(solo.parts.empty());
  CHECK(travel(moved, 9) > 1.0);
}

}  // TEST_SUITE
