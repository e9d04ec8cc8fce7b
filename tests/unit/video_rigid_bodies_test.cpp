// Rigid bodies of a procedural motion (geometry/rigid_bodies.h) and what the fitter makes of them
// (fit/plan/motion_groups.h: groups one body carries merge; the bodies' maps become the known motion),
// and the shape overlap the rig hangs parts by (procedural/shape_overlap.h), on hand-made frames.
#include <doctest/doctest.h>

#include <cmath>

#include "fit/plan/motion_groups.h"
#include "svgmotion/svg_reader.h"
#include "geometry/rigid_bodies.h"
#include "procedural/shape_overlap.h"

#include "scene_builders.h"

using namespace svgm;

namespace {

// Three squares in groups of their own, a straight line, and a bar that bends.
const char* kDrawing = R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
  <g id="arm"><path id="sleeve" d="M10 10 L30 10 L30 20 L10 20 Z"/></g>
  <g id="hand"><path id="fist" d="M30 10 L36 10 L36 16 L30 16 Z"/></g>
  <g id="body"><path id="torso" d="M50 50 L70 50 L70 80 L50 80 Z"/></g>
  <path id="stick" d="M30 13 L60 13" stroke="black" fill="none"/>
  <path id="tail" d="M70 80 L90 80 L90 84 L70 84 Z"/></svg>)";

// Frames: sleeve, fist and stick turn by `deg` degrees per frame about (10, 15); the torso
// holds still; one corner of the tail drops while the rest stays (a bend: no affine map does
// that).
std::vector<Vec2> frames_of(const Scene& s, int frames, double deg) {
  std::vector<Vec2> out;
  for (int f = 0; f < frames; ++f) {
    const Affine turn = Affine::translate(10, 15) * Affine::rotate_deg(deg * f) * Affine::translate(-10, -15);
    for (const Path& p : s.paths)
      for (const auto& sp : p.subpaths)
        for (size_t i = 0; i < sp.points.size(); ++i) {
          Vec2 q = sp.points[i];
          if (p.id == "sleeve" || p.id == "fist" || p.id == "stick") q = turn.apply(q);
          if (p.id == "tail" && std::fabs(q.x - 90) < 1e-9 && std::fabs(q.y - 84) < 1e-9) q.y += 2.0 * f;
          out.push_back(q);
        }
  }
  return out;
}


}  // namespace

TEST_SUITE("motion") {

TEST_CASE("paths one map moves in every frame share a rigid body; a bending path has none") {
  const Scene s = read_svg_string(kDrawing, "bodies.svg");
  const RigidBodies rb = rigid_bodies(s, frames_of(s, 5, 7.0), 5, 1e-6);
  const int sleeve = rb.body[test::path_index(s, "sleeve")], fist = rb.body[test::path_index(s, "fist")];
  const int stick = rb.body[test::path_index(s, "stick")], torso = rb.body[test::path_index(s, "torso")];
  CHECK(sleeve == 0);  // numbered by first path
  CHECK(fist == sleeve);
  CHECK(stick == sleeve);  // a straight line cannot determine a map, but the arm's carries it
  CHECK(torso == 1);       // held still: the identity's body
  CHECK(rb.body[test::path_index(s, "tail")] == -1);
  REQUIRE(rb.maps.size() == 2);
  REQUIRE(rb.maps[0].size() == 5);
  // The arm's map at frame 3 is the turn by 21 degrees about (10, 15).
  const Affine want = Affine::translate(10, 15) * Affine::rotate_deg(21) * Affine::translate(-10, -15);
  const Affine& got = rb.maps[0][3];
  CHECK(got.a == doctest::Approx(want.a).epsilon(1e-9));
  CHECK(got.b == doctest::Approx(want.b).epsilon(1e-9));
  CHECK(got.e == doctest::Approx(want.e).epsilon(1e-9));
  CHECK(got.f == doctest::Approx(want.f).epsilon(1e-9));
  const Affine& still = rb.maps[1][4];  // the torso's: the identity
  CHECK(std::fabs(still.a - 1) + std::fabs(still.b) + std::fabs(still.c) + std::fabs(still.d - 1) + std::fabs(still.e) +
            std::fabs(still.f) < 1e-9);
}

TEST_CASE("groups one moving body carries merge into one; still and bending paths keep theirs") {
  const Scene s = read_svg_string(kDrawing, "bodies.svg");
  const std::vector<Vec2> pts = frames_of(s, 5, 7.0);
  const RigidBodies rb = rigid_bodies(s, pts, 5, 1e-6);
  nlohmann::json paths = nlohmann::json::array();
  for (size_t p = 0; p < s.paths.size(); ++p)
    paths.push_back({{"id", s.paths[p].id}, {"body", rb.body[p]}, {"max_travel", s.paths[p].id == "torso" ? 0.0 : 3.0}});
  const nlohmann::json report{{"paths", paths}};
  std::vector<std::string> notes;
  const Scene out = merge_groups_by_body(s, report, &notes);
  // arm + hand + the stick (the reader gives a top-level path a group of its own) become the
  // arm's group; the body and the bending tail keep theirs.
  REQUIRE(s.groups.size() == 5);
  REQUIRE(out.groups.size() == 3);
  CHECK(out.groups[0].id == "arm");
  CHECK(out.groups[0].paths == std::vector<int>{test::path_index(s, "sleeve"), test::path_index(s, "fist"), test::path_index(s, "stick")});
  CHECK(out.groups[1].id == "body");
  CHECK(out.groups[2].paths == std::vector<int>{test::path_index(s, "tail")});
  CHECK(out.paths[static_cast<size_t>(test::path_index(s, "stick"))].group == 0);
  CHECK(out.paths[static_cast<size_t>(test::path_index(s, "tail"))].group == 2);
  REQUIRE(notes.size() == 1);
  CHECK(notes[0] == "arm: 3 groups the target moves as one rigid body fit as one (with hand, stick)");
  // No bodies in the report: the scene as it was.
  const Scene same = merge_groups_by_body(s, nlohmann::json{{"paths", nlohmann::json::array()}}, nullptr);
  CHECK(same.groups.size() == s.groups.size());
}

TEST_CASE("the known motion reads each body's maps and matches paths by id") {
  const Scene s = read_svg_string(kDrawing, "bodies.svg");
  nlohmann::json paths = nlohmann::json::array();
  for (const Path& p : s.paths) paths.push_back({{"id", p.id}, {"body", p.id == "torso" ? 1 : p.id == "tail" ? -1 : 0}});
  const nlohmann::json report{{"paths", paths},
                              {"bodies", {{{1, 0, 0, 1, 0, 0}, {1, 0, 0, 1, 2.5, -1}}, {{1, 0, 0, 1, 0, 0}, {1, 0, 0, 1, 0, 0}}}}};
  const KnownMotion k = known_motion(s, report);
  REQUIRE(k.maps.size() == 2);
  CHECK(k.maps[0][1].apply({10, 10}) == Vec2{12.5, 9});
  CHECK(k.body[static_cast<size_t>(test::path_index(s, "fist"))] == 0);
  CHECK(k.body[static_cast<size_t>(test::path_index(s, "torso"))] == 1);
  CHECK(k.body[static_cast<size_t>(test::path_index(s, "tail"))] == -1);
  // A report about another drawing (a path it does not name) gives no known motion.
  nlohmann::json other = report;
  other["paths"].erase(0);
  CHECK(known_motion(s, other).body.empty());
  // The chosen candidate's own maps and bodies (this one moves the tail with the fist's body and
  // holds the fist still); a candidate the report does not list gives none.
  nlohmann::json chosen = report;
  nlohmann::json path_body = nlohmann::json::array();
  for (const Path& p : s.paths) path_body.push_back(p.id == "fist" ? 1 : p.id == "tail" ? 0 : p.id == "torso" ? 1 : 0);
  chosen["candidates"] = {{{"name", "00.mp4"}}, {{"name", "01.mp4"}, {"path_body", path_body}, {"bodies", {{{1, 0, 0, 1, 0, 0}, {1, 0, 0, 1, -3, 0}}, {{1, 0, 0, 1, 0, 0}, {1, 0, 0, 1, 0, 0}}}}}};
  const KnownMotion c = known_motion(s, chosen, "01.mp4");
  REQUIRE(c.maps.size() == 2);
  CHECK(c.maps[0][1].apply({10, 10}) == Vec2{7, 10});
  CHECK(c.body[static_cast<size_t>(test::path_index(s, "fist"))] == 1);
  CHECK(c.body[static_cast<size_t>(test::path_index(s, "tail"))] == 0);
  CHECK(known_motion(s, chosen, "02.mp4").body.empty());
  CHECK(known_motion(s, chosen, "00.mp4").body.empty());  // listed, but without its bodies
  // A malformed map: none either.
  nlohmann::json bad = report;
  bad["bodies"][0][1] = {1, 0, 0};
  CHECK(known_motion(s, bad).body.empty());
}

TEST_CASE("shapes overlap by the area both cover, not by their boxes") {
  const Scene s = read_svg_string(R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
    <path id="a" d="M0 0 L40 0 L40 40 L0 40 Z"/>
    <path id="b" d="M20 20 L60 20 L60 60 L20 60 Z"/>
    <path id="diag" d="M0 100 L2 100 L100 2 L100 0 Z"/>
    <path id="ring" d="M0 0 L40 0 L40 40 L0 40 Z M10 10 L10 30 L30 30 L30 10 Z"/></svg>)", "shapes.svg");
  const PartShape a = part_shape(s, {0}), b = part_shape(s, {1}), diag = part_shape(s, {2}), ring = part_shape(s, {3});
  // a and b share the square 20..40: 400. The grid estimate over that square is exact here.
  CHECK(shape_overlap(a, b) == doctest::Approx(400));
  // The thin diagonal's box holds all of a; its shape crosses a's far corner only.
  CHECK(shape_overlap(a, diag) < 40);
  // The ring's hole (drawn the other way round) is not covered: 1600 - 400.
  CHECK(shape_overlap(a, ring) == doctest::Approx(1200).epsilon(0.02));
  CHECK(shape_contains(ring, {5, 5}));
  CHECK_FALSE(shape_contains(ring, {20, 20}));
}

}  // TEST_SUITE
