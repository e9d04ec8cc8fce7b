// Repeated elements (procedural/repeated_elements.h) on drawings made here: drops drawn as the
// subpaths of one path fall one by one while the cloud above them holds; snowflakes drawn as
// three crossing lines each are one element each; a drop's fill and its outline drawn as two
// paths are one element; a ring's hole stays with its ring.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "svgmotion/svg_reader.h"
#include "procedural/motion_plan.h"
#include "procedural/repeated_elements.h"

using namespace svgm;

namespace {

// A cloud (path 0) and six drops as six closed contours of path 1 (each a diamond, 4 wide and 6
// tall, in two rows), on a 100 x 100 canvas.
const char* kRain = R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
  <path fill="#ddd" d="M 10 10 L 90 10 L 90 40 L 10 40 Z"/>
  <path fill="#5ad" d="M 20 50 L 22 53 L 20 56 L 18 53 Z M 50 50 L 52 53 L 50 56 L 48 53 Z M 80 50 L 82 53 L 80 56 L 78 53 Z
                       M 35 62 L 37 65 L 35 68 L 33 65 Z M 65 62 L 67 65 L 65 68 L 63 65 Z M 50 70 L 52 73 L 50 76 L 48 73 Z"/>
</svg>)";

// How far each subpath's points get from frame 0 (the largest over its points and frames).
std::vector<std::vector<double>> subpath_travel(const Scene& s, const std::vector<Vec2>& pts, int F) {
  const size_t per = pts.size() / F;
  std::vector<std::vector<double>> out;
  size_t i = 0;
  for (const auto& p : s.paths) {
    out.emplace_back();
    for (const auto& sp : p.subpaths) {
      double m = 0;
      for (size_t q = 0; q < sp.points.size(); ++q, ++i)
        for (int f = 1; f < F; ++f) m = std::max(m, std::hypot(pts[f * per + i].x - pts[i].x, pts[f * per + i].y - pts[i].y));
      out.back().push_back(m);
    }
  }
  return out;
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("drops drawn as the subpaths of one path are elements of their own and fall apart from each other") {
  const Scene s = read_svg_string(kRain, "rain.svg");
  const Rig rig = build_rig(s, {});
  REQUIRE(rig.repeated.size() == 6);
  for (size_t e = 0; e < rig.repeated.size(); ++e) {
    REQUIRE(rig.repeated[e].size() == 1);
    CHECK(rig.repeated[e][0].path == 1);
  }
  std::vector<int> subs;
  for (const auto& e : rig.repeated) subs.push_back(e[0].subpath);
  std::sort(subs.begin(), subs.end());
  CHECK(subs == std::vector<int>{0, 1, 2, 3, 4, 5});
  CHECK(rig.repeated_why == "6 small shapes of similar size (the subpaths of a path drawing several)");

  MotionPlan plan = plan_from_prompt(parse_prompt("rain pours from the cloud"), rig, 1);
  REQUIRE(!plan.actions.empty());
  CHECK(plan.actions[0].primitive == Primitive::Fall);
  CHECK(plan.actions[0].target == Target::Repeated);
  const int F = 25;
  fit_plan(s, rig, plan, F, 9);
  const auto pts = animate_plan(s, rig, plan, F);
  const auto t = subpath_travel(s, pts, F);
  CHECK(t[0][0] == 0.0);  // the cloud holds
  for (double d : t[1]) CHECK(d > 3.0);  // every drop falls
  // Two drops of one path in different phases: their first points' heights differ over time.
  REQUIRE(s.paths[0].subpaths[0].points.size() == 13);  // the cloud: four segments
  const size_t per = pts.size() / F, a = 13, b = 13 + 13;  // drops 0 and 1 (13 points each)
  double differ = 0;
  for (int f = 0; f < F; ++f)
    differ = std::max(differ, std::fabs((pts[f * per + a].y - pts[a].y) - (pts[f * per + b].y - pts[b].y)));
  CHECK(differ > 1.0);
}

TEST_CASE("snowflakes of three crossing lines are one element each; a fill and its outline are one element") {
  // Three flakes (a vertical and two diagonal strokes each) under a cloud; the cloud is big.
  const Scene flakes = read_svg_string(R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
    <path fill="#ddd" d="M 10 10 L 90 10 L 90 40 L 10 40 Z"/>
    <g stroke="#000" stroke-width="1.5" fill="none">
      <line x1="20" y1="50" x2="20" y2="60"/><line x1="16" y1="57" x2="24" y2="53"/><line x1="24" y1="57" x2="16" y2="53"/>
      <line x1="50" y1="60" x2="50" y2="70"/><line x1="46" y1="67" x2="54" y2="63"/><line x1="54" y1="67" x2="46" y2="63"/>
      <line x1="80" y1="52" x2="80" y2="64"/><line x1="75" y1="61" x2="85" y2="55"/><line x1="85" y1="61" x2="75" y2="55"/>
    </g></svg>)", "snow.svg");
  const RepeatedElements r = find_repeated_elements(flakes, {});
  REQUIRE(r.elements.size() == 3);
  for (const auto& e : r.elements) {
    REQUIRE(e.size() == 3);
    // The three lines of one flake are drawn one after another.
    CHECK(e[1].path == e[0].path + 1);
    CHECK(e[2].path == e[0].path + 2);
    CHECK(e[0].subpath == -1);
  }
  CHECK(r.why == "3 small paths of similar size");

  // Three drops, each a fill and its outline (paths 2k and 2k+1): one element of two paths each.
  const Scene drops = read_svg_string(R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
    <rect x="20" y="50" width="5" height="8" fill="#5ad"/><rect x="20" y="50" width="5" height="8" fill="none" stroke="#000"/>
    <rect x="50" y="50" width="5" height="8" fill="#5ad"/><rect x="50" y="50" width="5" height="8" fill="none" stroke="#000"/>
    <rect x="80" y="50" width="5" height="8" fill="#5ad"/><rect x="80" y="50" width="5" height="8" fill="none" stroke="#000"/>
    </svg>)", "drops.svg");
  const RepeatedElements d = find_repeated_elements(drops, {});
  REQUIRE(d.elements.size() == 3);
  for (const auto& e : d.elements) {
    REQUIRE(e.size() == 2);
    CHECK(e[0].path % 2 == 0);
    CHECK(e[1].path == e[0].path + 1);
  }
}

TEST_CASE("snowflakes drift: every motion of the verb is the elements', the cloud holds") {
  const Scene s = read_svg_string(kRain, "rain.svg");
  const Rig rig = build_rig(s, {});
  MotionPlan plan = plan_from_prompt(parse_prompt("snowflakes drift down from the cloud"), rig, 1);
  REQUIRE(plan.actions.size() == 2);  // float: a bob and a rock
  for (const auto& a : plan.actions) CHECK(a.target == Target::Repeated);
  const int F = 25;
  fit_plan(s, rig, plan, F, 9);
  const auto t = subpath_travel(s, animate_plan(s, rig, plan, F), F);
  CHECK(t[0][0] == 0.0);  // the cloud (it rocked with the whole figure)
  for (double d : t[1]) CHECK(d > 0.5);
}

TEST_CASE("a path's pieces: a contour inside another's box belongs to it (a ring's hole, a highlight)") {
  const Scene s = read_svg_string(R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
    <path d="M 10 10 L 30 10 L 30 30 L 10 30 Z M 15 15 L 15 25 L 25 25 L 25 15 Z M 60 10 L 80 10 L 80 30 L 60 30 Z"/>
    </svg>)", "rings.svg");
  const auto pieces = subpath_pieces(s.paths[0]);
  REQUIRE(pieces.size() == 2);
  CHECK(pieces[0] == std::vector<int>{0, 1});
  CHECK(pieces[1] == std::vector<int>{2});
}

}  // TEST_SUITE
