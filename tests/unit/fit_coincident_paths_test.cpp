// Paths with one outline fitted as one (fit/coincident_paths.h): a top-level overlay drawn with
// the outline of the shape under it (offset by a tenth of a unit, as Illustrator's exports do)
// joins that shape's group; an outline that differs by more than the tolerance, a different
// shape, and a path among others in a group stay where they are.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "fit/coincident_paths.h"
#include "svgmotion/svg_reader.h"

#include "scene_builders.h"

using namespace svgm;

namespace {

// A rounded screen (a group of its own), its two bevel overlays as top-level paths, a disc, and
// a group holding a copy of the screen's outline with a bar. Canvas 100: tolerance 0.5.
std::string drawing(double overlay_dx) {
  const std::string screen = "M10,10 H90 A5,5 0 0 1 95,15 V60 A5,5 0 0 1 90,65 H10 A5,5 0 0 1 5,60 V15 A5,5 0 0 1 10,10 Z";
  const std::string shifted = "M" + std::to_string(10 + overlay_dx) + ",10 H" + std::to_string(90 + overlay_dx) + " A5,5 0 0 1 " +
                              std::to_string(95 + overlay_dx) + ",15 V60 A5,5 0 0 1 " + std::to_string(90 + overlay_dx) +
                              ",65 H" + std::to_string(10 + overlay_dx) + " A5,5 0 0 1 " + std::to_string(5 + overlay_dx) +
                              ",60 V15 A5,5 0 0 1 " + std::to_string(10 + overlay_dx) + ",10 Z";
  return R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">)"
         R"(<g id="screen"><path id="base" fill="#222" d=")" + screen + R"("/></g>)"
         R"(<path id="bevel" fill="#bbb" opacity="0.3" d=")" + screen + R"("/>)"
         R"(<path id="bevel2" fill="#bbb" opacity="0.3" d=")" + shifted + R"("/>)"
         R"(<circle id="disc" cx="50" cy="80" r="10"/>)"
         R"(<g id="stand"><path id="copy" fill="#444" d=")" + screen + R"("/><rect id="bar" x="45" y="65" width="10" height="30"/></g>)"
         R"(</svg>)";
}


}  // namespace

TEST_SUITE("fit") {

TEST_CASE("overlays with the outline of the shape they cover are fitted in its group") {
  const Scene s = read_svg_string(drawing(0.1), "screen.svg");
  REQUIRE(s.paths.size() == 6);
  REQUIRE(s.groups.size() == 5);  // screen, bevel, bevel2, disc (each a part of its own), stand
  std::vector<std::string> notes;
  const Scene out = merge_coincident_paths(s, &notes);
  const int base = test::path_index(out, "base"), bevel = test::path_index(out, "bevel"), bevel2 = test::path_index(out, "bevel2");
  const int disc = test::path_index(out, "disc"), copy = test::path_index(out, "copy"), bar = test::path_index(out, "bar");
  REQUIRE(out.groups.size() == 3);  // the bevels' own groups are gone
  CHECK(out.groups[0].id == "screen");
  CHECK(out.groups[0].paths == std::vector<int>{base, bevel, bevel2});
  for (const int p : {base, bevel, bevel2}) CHECK(out.paths[p].group == 0);
  // The disc keeps its own group, and the copy stays with the bar: its group is a part already.
  CHECK(out.groups[1].paths == std::vector<int>{disc});
  CHECK(out.groups[2].id == "stand");
  CHECK(out.groups[2].paths == std::vector<int>{copy, bar});
  CHECK(out.paths[copy].group == 2);
  REQUIRE(notes.size() == 1);
  CHECK(notes[0] == "screen: bevel, bevel2 fit with base, whose outline they share");
  // The paths themselves are untouched.
  for (size_t i = 0; i < s.paths.size(); ++i) CHECK(out.paths[i].subpaths[0].points.size() == s.paths[i].subpaths[0].points.size());
}

TEST_CASE("an overlay offset by more than the tolerance is a shape of its own") {
  // 0.8 units is over 0.5% of the canvas: bevel2 keeps its group, bevel still joins.
  const Scene s = read_svg_string(drawing(0.8), "screen.svg");
  std::vector<std::string> notes;
  const Scene out = merge_coincident_paths(s, &notes);
  REQUIRE(out.groups.size() == 4);
  CHECK(out.groups[0].paths == std::vector<int>{test::path_index(out, "base"), test::path_index(out, "bevel")});
  CHECK(out.groups[1].paths == std::vector<int>{test::path_index(out, "bevel2")});
  REQUIRE(notes.size() == 1);
  CHECK(notes[0] == "screen: bevel fit with base, whose outline it shares");
  // Nothing coincides: the scene comes back as it was.
  const Scene lone = read_svg_string(R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100"><circle cx="30" cy="30" r="9"/><circle cx="30" cy="30" r="12"/></svg>)", "discs.svg");
  std::vector<std::string> none;
  const Scene same = merge_coincident_paths(lone, &none);
  CHECK(none.empty());
  CHECK(same.groups.size() == lone.groups.size());
}

}  // TEST_SUITE
