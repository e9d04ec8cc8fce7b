// What a figure sits in or on (seat_support.h): in a tub drawn around a bather's lower body
// (tests/data/motion/sit_in_tub.svg) the tub and the shower over it are the seat and the bather
// (body, head, eye) the sitter. "in the tub" names it; the seat stays while the bather sways
// about its own bottom, and goes along when the bather goes somewhere. (The tub's id is "basin": a
// part named "tub" would be the figure's own, no seat.)
#include <doctest/doctest.h>

#include <cmath>

#include "svgmotion/svg_reader.h"
#include "procedural/motion_plan.h"
#include "procedural/prompt_parse.h"
#include "procedural/seat_support.h"
#include "test_paths.h"
#include "wordnet_or_skip.h"

using namespace svgm;

namespace {

const char* kTub = "motion/sit_in_tub.svg";
Scene scene_of(const char* f) { return read_svg_file(svgm::test::data_path(f)); }
Rig rig_of(const char* f, const Scene& s) { return build_rig(s, read_source_names(svgm::test::data_path(f))); }

// The farthest any control point of the paths with id in `ids` moves from rest over the frames.
double moved(const Scene& s, const std::vector<Vec2>& pts, int frames, const std::vector<std::string>& ids) {
  size_t n = 0;
  for (const Path& p : s.paths)
    for (const Subpath& sp : p.subpaths) n += sp.points.size();
  REQUIRE(pts.size() == n * frames);
  double most = 0;
  size_t k = 0;
  for (const Path& p : s.paths)
    for (const Subpath& sp : p.subpaths)
      for (const Vec2& q : sp.points) {
        if (std::find(ids.begin(), ids.end(), p.id) != ids.end())
          for (int f = 0; f < frames; ++f) most = std::max(most, std::hypot(pts[f * n + k].x - q.x, pts[f * n + k].y - q.y));
        ++k;
      }
  return most;
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("a tub drawn around a bather's lower body is the seat; the bather, with its head, the sitter") {
  const Scene s = scene_of(kTub);
  const SeatSupport seat = seat_support(s, rig_of(kTub, s));
  REQUIRE(seat.found);
  for (size_t i = 0; i < s.paths.size(); ++i) {
    const std::string& id = s.paths[i].id;
    CHECK_MESSAGE(seat.seat[i] == (id == "basin" || id == "pipe" || id == "spout"), id);
  }
  // The body's box (x 21-49, y 40-70) and the head's above it (y 22-38).
  CHECK(seat.sitter.x0 == doctest::Approx(21).epsilon(0.01));
  CHECK(seat.sitter.x1 == doctest::Approx(49).epsilon(0.01));
  CHECK(seat.sitter.y0 == doctest::Approx(22).epsilon(0.01));
  CHECK(seat.sitter.y1 == doctest::Approx(70).epsilon(0.01));
}

TEST_CASE("'in the tub' keeps the tub and the shower still while the bather sways; going, the tub goes along") {
  if (!wordnet_or_skip()) return;
  const Scene s = scene_of(kTub);
  const Rig rig = rig_of(kTub, s);
  const MotionPlan plan = plan_from_prompt(parse_prompt("the bather in the tub sways"), rig, 1);
  CHECK(plan.seat == "in the tub");
  CHECK(plan_from_prompt(parse_prompt("the bather sways"), rig, 1).seat.empty());
  const int frames = 9;
  const std::vector<Vec2> pts = animate_plan(s, rig, plan, frames);
  CHECK(moved(s, pts, frames, {"basin", "pipe", "spout"}) < 1e-9);
  const double head = moved(s, pts, frames, {"head"});
  CHECK(head > 2);
  // About the bather's own bottom, inside the tub: the body's lower half moves less than the head.
  CHECK(moved(s, pts, frames, {"body"}) < head);
  // Without the seat the sway leant the whole drawing, tub and shower with it.
  MotionPlan loose = plan;
  loose.seat.clear();
  CHECK(moved(s, animate_plan(s, rig, loose, frames), frames, {"spout"}) > 1);
  // Going somewhere, the seat goes along (how far against the sitter: open, see the h56-perch report).
  const MotionPlan going = plan_from_prompt(parse_prompt("the bather in the tub slides to the right"), rig, 1);
  REQUIRE(going.seat == "in the tub");
  const std::vector<Vec2> gp = animate_plan(s, rig, going, frames);
  CHECK(moved(s, gp, frames, {"basin"}) > 2);
}

}
