// Region bends through the as-rigid-as-possible mesh (procedural/region_bend.h), on a drawing
// made here: a sweater drawn as one shape with long sleeves, and a red band (a cuff) lying across
// the left sleeve where the bend's ramp is, in the sweater's group. Waving the arms bends the
// sleeves: the band must bend with them, neither cut nor squeezed, the mesh must not fold, the
// still body must stay; and a bend asked so far that its mesh folds must be caught and made smaller.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <utility>

#include "geometry/curve_samples.h"
#include "procedural/motion_plan.h"
#include "svgmotion/svg_reader.h"

using namespace svgm;

namespace {

// Skirt (group 1), sweater with sleeves from x 20 to 180 (group 2) and the band x 55..61 across
// the left sleeve (y 40..60), sticking out 2 units above and below it.
const char* kSweater = R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">
  <g><path d="M 85 120 L 115 120 L 120 190 L 80 190 Z" fill="#fc0"/></g>
  <g><path d="M 20 40 L 180 40 L 180 60 L 110 60 L 110 120 L 90 120 L 90 60 L 20 60 Z" fill="#00f"/>
     <path d="M 80 38 L 86 38 L 86 62 L 80 62 Z" fill="#f00"/></g></svg>)";

constexpr int kFrames = 25;

// The first control point of path `path` in animate_plan's order.
size_t first_point_of(const Scene& s, int path) {
  size_t i = 0;
  for (int p = 0; p < path; ++p)
    for (const auto& sp : s.paths[p].subpaths) i += sp.points.size();
  return i;
}

// Every control point of the scene (one frame of animate_plan).
size_t all_points(const Scene& s) { return first_point_of(s, static_cast<int>(s.paths.size())); }

// The band's corners at frame f: its on-curve points 0, 3, 6, 9 (lines are cubics of 3 points).
std::vector<Vec2> band_corners(const Scene& s, const std::vector<Vec2>& pts, int f, int band) {
  const size_t n = all_points(s), at = static_cast<size_t>(f) * n + first_point_of(s, band);
  return {pts[at], pts[at + 3], pts[at + 6], pts[at + 9]};
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("a band across a waving sleeve bends with it: not cut, not squeezed, the mesh unfolded, the body still") {
  const Scene s = read_svg_string(kSweater, "sweater.svg");
  const Rig rig = build_rig(s, {});
  MotionPlan plan = plan_from_prompt(parse_prompt("she is waving her arms"), rig, 1);
  REQUIRE(plan.actions.size() == 1);
  REQUIRE(plan.actions[0].region == Region::Sides);
  std::vector<BendFold> folds;
  const std::vector<Vec2> pts = animate_plan(s, rig, plan, kFrames, &folds);
  REQUIRE(folds.size() == 1);
  CHECK(folds[0].meshed);
  CHECK(folds[0].flipped == 0);
  CHECK(folds[0].min_area_ratio > 0.25);  // 0.34: the armpit, inside the bend
  // The same bits again (the mesh and its factorisation remembered the second time).
  CHECK(animate_plan(s, rig, plan, kFrames) == pts);
  const int band = 2;
  const std::vector<Vec2> rest = band_corners(s, pts, 0, band);
  CHECK(rest[0].x == 80);  // frame 0 is the rest pose, exactly
  CHECK(rest[2].y == 62);
  // The band's top edge (corners 0 -> 1) and bottom edge (3 -> 2), each 6 long at rest: the
  // inside and the outside of the bend. Their lengths' extremes over the frames.
  double shortest = 1e9, longest = 0, moved = 0;
  for (int f = 0; f < kFrames; ++f) {
    const std::vector<Vec2> c = band_corners(s, pts, f, band);
    moved = std::max(moved, std::hypot(c[0].x - rest[0].x, c[0].y - rest[0].y));
    for (const auto& [i, j] : {std::pair<int, int>{0, 1}, {3, 2}}) {
      // Each edge keeps its direction along the sleeve (its corners stay in order)...
      CHECK((c[j].x - c[i].x) * (rest[j].x - rest[i].x) + (c[j].y - c[i].y) * (rest[j].y - rest[i].y) > 0);
      const double len = std::hypot(c[j].x - c[i].x, c[j].y - c[i].y) / 6;
      shortest = std::min(shortest, len);
      longest = std::max(longest, len);
    }
    CHECK(shoelace(c) * shoelace(rest) > 0);
  }
  CHECK(moved > 5);  // the band moved with the sleeve
  // ... and its length: bent point by point (the closed form, before the mesh), the band's top
  // edge shrank to 0.42 of its length and its bottom edge grew to 2.03 (its top-left corner
  // passed its top-right one sideways: a notch); through the mesh, 0.83 and 1.27.
  CHECK(shortest > 0.7);
  CHECK(longest < 1.4);
  // The body's bottom (the still core) stays where it is: within the mesh's soft handles' error.
  const size_t body = first_point_of(s, 1) + 12;  // (110, 120)
  for (int f = 0; f < kFrames; ++f) {
    const Vec2 q = pts[static_cast<size_t>(f) * all_points(s) + body];
    CHECK(std::hypot(q.x - 110, q.y - 120) < 0.05);
  }
}

TEST_CASE("a sleeve swung so far that its mesh folds is caught: fit_plan makes it smaller, or bends it in closed form") {
  const Scene s = read_svg_string(kSweater, "sweater.svg");
  const Rig rig = build_rig(s, {});
  // 90 degrees folds the armpit at full size and unfolds at 0.64 of it (above kMinUnfoldScale).
  MotionPlan plan = plan_from_prompt(parse_prompt("she is waving her arms"), rig, 1);
  REQUIRE(plan.actions.size() == 1);
  plan.actions[0].amp = 90;
  std::vector<BendFold> folds;
  animate_plan(s, rig, plan, kFrames, &folds);
  REQUIRE(folds.size() == 1);
  CHECK(folds[0].flipped > 0);
  CHECK(folds[0].frame > 0);
  fit_plan(s, rig, plan, kFrames, 15);
  bool noted = false;
  for (const std::string& n : plan.notes) noted = noted || n.find("its bend folds its shape") != std::string::npos;
  CHECK(noted);
  CHECK_FALSE(plan.actions[0].closed_form);
  animate_plan(s, rig, plan, kFrames, &folds);
  CHECK(folds[0].meshed);
  CHECK(folds[0].flipped == 0);
  CHECK(folds[0].min_area_ratio >= 0.05);  // kPinchArea
  // 170 degrees: the sleeves swing over the body, and the mesh folds until under half the size
  // (the drawing's parts would only overlap there): the bend keeps its size in closed form.
  MotionPlan over = plan_from_prompt(parse_prompt("she is waving her arms"), rig, 1);
  over.actions[0].amp = 170;
  fit_plan(s, rig, over, kFrames, 15);
  CHECK(over.actions[0].closed_form);
  bool closed_noted = false;
  for (const std::string& n : over.notes) closed_noted = closed_noted || n.find("bent in closed form") != std::string::npos;
  CHECK(closed_noted);
  animate_plan(s, rig, over, kFrames, &folds);
  CHECK_FALSE(folds[0].meshed);
}

TEST_CASE("a patch lying inside a waving sleeve, across its bend, moves rigidly; the band sticking out of it still bends") {
  // The sweater with a patch (76..88 x 44..56) drawn on the left sleeve where the bend's ramp
  // is, inside its fill, after it; the band (80..86, 2 units out of the sleeve above and below)
  // lies across the sleeve and is no shape the sleeve carries.
  const Scene s = read_svg_string(R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">
  <g><path d="M 85 120 L 115 120 L 120 190 L 80 190 Z" fill="#fc0"/></g>
  <g><path d="M 20 40 L 180 40 L 180 60 L 110 60 L 110 120 L 90 120 L 90 60 L 20 60 Z" fill="#00f"/>
     <path d="M 80 38 L 86 38 L 86 62 L 80 62 Z" fill="#f00"/>
     <path d="M 76 44 L 88 44 L 88 56 L 76 56 Z" fill="#0f0"/></g></svg>)", "patched.svg");
  const Rig rig = build_rig(s, {});
  MotionPlan plan = plan_from_prompt(parse_prompt("she is waving her arms"), rig, 1);
  REQUIRE(plan.actions.size() == 1);
  REQUIRE(plan.actions[0].region == Region::Sides);
  const std::vector<Vec2> pts = animate_plan(s, rig, plan, kFrames);
  const std::vector<Vec2> rest = band_corners(s, pts, 0, 3), band_rest = band_corners(s, pts, 0, 2);
  double moved = 0, band_longest = 0;
  for (int f = 0; f < kFrames; ++f) {
    const std::vector<Vec2> c = band_corners(s, pts, f, 3);
    moved = std::max(moved, std::hypot(c[0].x - rest[0].x, c[0].y - rest[0].y));
    // Every distance between two corners of the patch is the one at rest.
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        CHECK(std::hypot(c[j].x - c[i].x, c[j].y - c[i].y) ==
              doctest::Approx(std::hypot(rest[j].x - rest[i].x, rest[j].y - rest[i].y)).epsilon(1e-9));
    const std::vector<Vec2> b = band_corners(s, pts, f, 2);
    band_longest = std::max(band_longest, std::hypot(b[2].x - b[3].x, b[2].y - b[3].y) / 6);
  }
  CHECK(moved > 5);             // the patch moved with the sleeve
  CHECK(band_longest > 1.05);   // the band across the bend bends (its outer edge grows)
  CHECK(band_rest[0].x == 80);
}

}  // TEST_SUITE
