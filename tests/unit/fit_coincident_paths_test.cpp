// Paths with one outline fitted as one (fit/plan/coincident_paths.h): a top-level overlay drawn with
// the outline of the shape under it (offset by a tenth of a unit, as Illustrator's exports do)
// has that shape as its host and shares its fit group; an outline that differs by more than the
// tolerance, a different shape, and a path among others in a group stay where they are.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "fit/plan/coincident_paths.h"
#include "fit/plan/fit_plan.h"
#include "raster/raster_plan.h"
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
  const int base = test::path_index(s, "base"), bevel = test::path_index(s, "bevel"), bevel2 = test::path_index(s, "bevel2");
  const int disc = test::path_index(s, "disc"), copy = test::path_index(s, "copy"), bar = test::path_index(s, "bar");
  const std::vector<int> host = coincident_hosts(s);
  CHECK(host[bevel] == base);
  CHECK(host[bevel2] == base);
  // The disc has an outline of its own, and the copy stays with the bar: its group is a part
  // already.
  for (const int p : {base, disc, copy, bar}) CHECK(host[p] == -1);
  // The fit plan takes them as hosts: the bevels' points move in the screen's group, and the
  // fit has three groups (screen, disc, stand) instead of five. The paths are untouched.
  const RasterPlan raster = plan_raster(s, Affine{}, 100, 100);
  FitPlanOptions opt;
  opt.attach_coincident = true;
  const FitPlan f = plan_fit(s, raster, opt);
  auto group_of = [&](int p) { return f.cp_group[static_cast<size_t>(raster.path_cp_first[static_cast<size_t>(p)])]; };
  CHECK(f.n_groups == 3);
  CHECK(group_of(bevel) == group_of(base));
  CHECK(group_of(bevel2) == group_of(base));
  CHECK(group_of(disc) != group_of(base));
  CHECK(group_of(copy) == group_of(bar));
  CHECK(group_of(copy) != group_of(base));
  opt.attach_coincident = false;
  CHECK(plan_fit(s, raster, opt).n_groups == 5);
}

TEST_CASE("an overlay offset by more than the tolerance is a shape of its own") {
  // 0.8 units is over 0.5% of the canvas: bevel2 keeps its group, bevel still joins.
  const Scene s = read_svg_string(drawing(0.8), "screen.svg");
  const std::vector<int> host = coincident_hosts(s);
  CHECK(host[test::path_index(s, "bevel")] == test::path_index(s, "base"));
  CHECK(host[test::path_index(s, "bevel2")] == -1);
  // Nothing coincides: no host.
  const Scene lone = read_svg_string(R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100"><circle cx="30" cy="30" r="9"/><circle cx="30" cy="30" r="12"/></svg>)", "discs.svg");
  CHECK(coincident_hosts(lone) == std::vector<int>{-1, -1});
}

}  // TEST_SUITE
