// The part rig: names from the document (id, <title>, inkscape:label), roles from geometry
// (root, head, limbs, the figure's own side), pivots where parts attach, the background, round
// parts and repeated elements, limbs drawn as single strokes, on drawings made for these tests
// (tests/data/motion, or inline).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <set>

#include "svgmotion/svg_reader.h"
#include "procedural/part_rig.h"
#include "procedural/stroke_rig.h"
#include "test_paths.h"

using namespace svgm;

namespace {

std::string data(const char* name) { return svgm::test::data_path(std::string("motion/") + name); }

Rig rig_of(const char* name) {
  const Scene s = read_svg_file(data(name));
  return build_rig(s, read_source_names(data(name)));
}

int part_named(const Rig& r, const std::string& name) {
  for (size_t i = 0; i < r.parts.size(); ++i)
    if (r.parts[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace

TEST_SUITE("motion") {

TEST_CASE("name words split ids, labels and camelCase; generic names are no names") {
  CHECK(name_words("upperArm_Right-2") == std::vector<std::string>{"upper", "arm", "right"});
  CHECK(name_words("Left Wing") == std::vector<std::string>{"left", "wing"});
  const Scene s = read_svg_file(data("stick_figure.svg"));
  const SourceNames n = read_source_names(data("stick_figure.svg"));
  // The torso's rect has no id of its own: its group's id names it.
  REQUIRE(n.count(s.paths[0].id) == 1);
  REQUIRE(n.at(s.paths[0].id).size() == 1);
  CHECK(n.at(s.paths[0].id)[0].name == "torso");
  CHECK(n.at(s.paths[0].id)[0].locator == "/svg/g[1]");
  const Rig r = rig_of("stick_figure.svg");
  CHECK(part_named(r, "torso") >= 0);
  CHECK(part_named(r, "left arm") >= 0);
  CHECK(part_named(r, "Right Arm") >= 0);
  CHECK(read_source_names(data("no_such_file.svg")).empty());
}

TEST_CASE("an unnamed bird: body is the root, head above, two wings with mirrored sides") {
  const Rig r = rig_of("bird.svg");
  REQUIRE(r.parts.size() == 4);
  CHECK(r.root == 0);
  CHECK(r.parts[0].role == Role::Root);
  CHECK(r.parts[3].role == Role::Head);
  CHECK(r.parts[1].role == Role::UpperLimb);
  CHECK(r.parts[2].role == Role::UpperLimb);
  // The figure's own side: the wing on the viewer's left is the bird's right.
  CHECK(r.parts[1].side == 1);
  CHECK(r.parts[2].side == -1);
  CHECK(r.parts[1].name == "limb_upper_right");
  CHECK(r.parts[2].name == "limb_upper_left");
  // Pivots where the wings attach: the centroid of the wing's points inside the body's box
  // (70..130 x 95..125 with its control points, plus 1 % of the figure's diagonal): only the
  // wing's inner corner (75,105).
  CHECK(r.parts[1].pivot.x == doctest::Approx(75));
  CHECK(r.parts[1].pivot.y == doctest::Approx(105));
  CHECK(r.parts[2].pivot.x == doctest::Approx(125));
  CHECK(r.parts[1].parent == 0);
  CHECK(r.repeated.empty());
  CHECK(r.figure.x0 == doctest::Approx(20));
  CHECK(r.figure.x1 == doctest::Approx(180));
}

TEST_CASE("a grouper's names (data-name of grouped.svg) name the parts and give their roles") {
  // The bird of bird.svg as a grouper writes it, the wings named by the grouper only (the
  // paths' ids say nothing).
  const Scene s = read_svg_string(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200\" height=\"200\">"
      "<g id=\"group-1\" data-group=\"group-1\" data-name=\"body\"><path id=\"p1\" d=\"M 70 110 C 70 95 130 95 130 110 C 130 125 70 125 70 110 Z\"/></g>"
      "<g id=\"group-2\" data-group=\"group-2\" data-name=\"left wing\"><path id=\"p2\" d=\"M 125 105 L 180 70 L 170 110 Z\"/></g>"
      "<g id=\"group-3\" data-group=\"group-3\" data-name=\"right wing\"><path id=\"p3\" d=\"M 75 105 L 20 70 L 30 110 Z\"/></g>"
      "<g id=\"group-4\" data-group=\"group-4\"><path id=\"p4\" d=\"M 92 80 C 92 70 108 70 108 80 C 108 90 92 90 92 80 Z\"/></g>"
      "</svg>", "grouped.svg");
  std::vector<std::string> names;
  for (const auto& g : s.groups) names.push_back(g.name);
  const Rig r = build_rig(s, {}, names);
  REQUIRE(r.parts.size() == 4);
  CHECK(r.parts[0].name == "body");
  CHECK(r.parts[0].role == Role::Root);
  CHECK(r.parts[1].name == "left wing");
  CHECK(r.parts[1].named);
  CHECK(r.parts[1].side == -1);
  CHECK(r.parts[2].side == 1);
  CHECK(r.parts[2].role == Role::UpperLimb);
  CHECK(r.parts[3].name == "head");  // no name given: its role's
  // Without the names the wings are limbs by geometry only.
  CHECK(build_rig(s, {}).parts[1].name == "limb_upper_left");
}

TEST_CASE("a stick figure: names give the sides, geometry the legs (the figure's own side)") {
  const Rig r = rig_of("stick_figure.svg");
  const int torso = part_named(r, "torso"), left = part_named(r, "left arm"), right = part_named(r, "Right Arm");
  REQUIRE(torso >= 0);
  CHECK(r.root == torso);
  CHECK(r.parts[left].side == -1);
  CHECK(r.parts[right].side == 1);
  CHECK(r.parts[left].role == Role::UpperLimb);
  CHECK(r.parts[left].named);
  // The legs: below the torso's middle; the one drawn on the viewer's left is the right leg.
  CHECK(r.parts[3].role == Role::LowerLimb);
  CHECK(r.parts[3].name == "limb_lower_right");
  CHECK(r.parts[4].name == "limb_lower_left");
  CHECK(r.parts[5].role == Role::Head);
}

TEST_CASE("a scene: background rect, the umbrella as root, six drops with their highlights") {
  const Scene s = read_svg_file(data("rain_scene.svg"));
  const Rig r = build_rig(s, read_source_names(data("rain_scene.svg")));
  int background = 0;
  for (const auto& p : r.parts) background += p.role == Role::Background;
  CHECK(background == 1);
  CHECK(r.parts[0].role == Role::Background);
  CHECK(r.parts[0].why == "large, at the canvas edges, painted first");
  CHECK(r.parts[r.root].name == "canopy");
  REQUIRE(r.repeated.size() == 6);
  for (const auto& e : r.repeated) CHECK(e.size() == 2);  // drop + highlight
  CHECK(r.repeated_why == "6 small paths of similar size");
}

TEST_CASE("arms drawn as shapes of their own in the body's group are limbs; one shape across the body is not") {
  // A grouper merged the raised arms with the shirt: one group of three paths (shirt, the arm
  // on the viewer's left, the arm on the right), the head and the legs groups of their own.
  const char* head = "<g id=\"group-2\" data-group=\"group-2\"><path id=\"p4\" d=\"M 85 30 L 115 30 L 115 60 L 85 60 Z\"/></g>"
                     "<g id=\"group-3\" data-group=\"group-3\"><path id=\"p5\" d=\"M 80 150 L 120 150 L 120 190 L 80 190 Z\"/></g></svg>";
  const std::string top = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200\" height=\"200\">"
                          "<g id=\"group-1\" data-group=\"group-1\"><path id=\"p1\" d=\"M 75 65 L 125 65 L 125 150 L 75 150 Z\"/>";
  const Scene s = read_svg_string(top +
      "<path id=\"p2\" d=\"M 78 75 L 40 20 L 52 14 L 90 70 Z\"/>"
      "<path id=\"p3\" d=\"M 122 75 L 160 20 L 148 14 L 110 70 Z\"/></g>" + head, "arms.svg");
  const Rig r = build_rig(s, {});
  REQUIRE(r.parts.size() == 5);
  // The shirt alone is the root; each arm hangs from it on its own side.
  REQUIRE(r.root >= 0);
  CHECK(r.parts[r.root].box.x0 == doctest::Approx(75));
  CHECK(r.parts[r.root].box.x1 == doctest::Approx(125));
  int arms = 0;
  for (const auto& P : r.parts)
    if (P.role == Role::UpperLimb) {
      ++arms;
      CHECK(P.parent == r.root);
      CHECK(P.side == (P.box.centre().x < 100 ? 1 : -1));
    }
  CHECK(arms == 2);
  // Both arms as one shape with the shoulders (across the shirt's middle): the group stays whole.
  const Scene one = read_svg_string(top +
      "<path id=\"p2\" d=\"M 40 20 L 52 14 L 90 62 L 110 62 L 148 14 L 160 20 L 122 75 L 78 75 Z\"/></g>" + head, "one.svg");
  const Rig r1 = build_rig(one, {});
  CHECK(r1.parts.size() == 3);
}

TEST_CASE("a glove held before the face, grouped with the head, hangs from the arm it lies on") {
  // A boxer in guard: the shirt (root), the head's group holding the face, an eye, the glove
  // beside the face (its middle left of the face's box) and the glove's lacing, an arm reaching
  // up from the shirt to the glove, the legs.
  const std::string top = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200\" height=\"200\">"
                          "<g id=\"group-1\"><path id=\"p1\" d=\"M 75 65 L 125 65 L 125 150 L 75 150 Z\"/></g>"
                          "<g id=\"group-2\"><path id=\"p2\" d=\"M 80 20 L 120 20 L 120 62 L 80 62 Z\"/>"
                          "<path id=\"p3\" d=\"M 90 30 L 96 30 L 96 36 L 90 36 Z\"/>"
                          "<path id=\"p4\" d=\"M 55 40 L 82 40 L 82 68 L 55 68 Z\"/>"
                          "<path id=\"p5\" d=\"M 58 44 L 64 44 L 64 50 L 58 50 Z\"/></g>";
  const std::string arm = "<g id=\"group-3\"><path id=\"p6\" d=\"M 60 62 L 70 62 L 90 105 L 80 105 Z\"/></g>";
  const std::string legs = "<g id=\"group-4\"><path id=\"p7\" d=\"M 80 150 L 120 150 L 120 190 L 80 190 Z\"/></g></svg>";
  const Rig r = build_rig(read_svg_string(top + arm + legs, "guard.svg"), {});
  const int face = r.part_of_path[1], glove = r.part_of_path[3], arm_part = r.part_of_path[5];
  CHECK(r.parts[face].role == Role::Head);
  CHECK(r.part_of_path[2] == face);   // the eye, on the face, stays
  CHECK(glove != face);
  CHECK(r.part_of_path[4] == glove);  // the lacing goes with its glove
  CHECK(r.parts[arm_part].role == Role::UpperLimb);
  CHECK(r.parts[glove].parent == arm_part);
  CHECK(r.parts[glove].role == Role::UpperLimb);
  // With no arm to hold it, the glove stays with the head.
  const Rig alone = build_rig(read_svg_string(top + legs, "no_arm.svg"), {});
  CHECK(alone.part_of_path[3] == alone.part_of_path[1]);
}

TEST_CASE("a round part is a wheel; a stand is not") {
  const Rig r = rig_of("wheel.svg");
  REQUIRE(r.parts.size() == 2);
  CHECK_FALSE(r.parts[0].round);
  CHECK(r.parts[1].round);
}

TEST_CASE("a tall thin part above the body is a raised wing, not the head; a round one is the head") {
  // A bird seen from the side: body 60-160 x 100-160, its beak at the left, one wing raised
  // above its back (95-115 x 20-120: five times as tall as wide).
  const Rig r = rig_of("bird_side.svg");
  REQUIRE(r.root == 0);
  CHECK(r.parts[1].role == Role::UpperLimb);
  CHECK(r.parts[1].why == "above the root, tall and thin (a raised wing or arm)");
  // The same part as wide as tall is the head.
  const Scene h = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">
           <g><path d="M 60 100 L 160 100 L 160 160 L 60 160 Z" fill="#f9c"/></g>
           <g><path d="M 90 60 L 130 60 L 130 105 L 90 105 Z" fill="#e7a"/></g></svg>)", "head.svg");
  const Rig rh = build_rig(h, {});
  CHECK(rh.parts[1].role == Role::Head);
}

TEST_CASE("a wheel drawn in one group with its cabins and stand: its spokes hang from it, each cabin piece is a part, the stand holds") {
  const Rig r = rig_of("ferris.svg");  // paths 0-7 cabins (roof, body), 8 rim, 9-11 spokes and hub, 12-14 stand, 15 shadow
  const int rim = r.part_of_path[8], spokes = r.part_of_path[9], stand = r.part_of_path[12];
  CHECK(r.part_of_path[10] == spokes);
  CHECK(r.part_of_path[11] == spokes);
  CHECK(spokes != rim);
  CHECK(r.parts[spokes].parent == rim);
  CHECK(r.parts[spokes].carried);
  CHECK(r.part_of_path[13] == stand);
  CHECK(r.part_of_path[14] == stand);
  CHECK(r.part_of_path[15] == stand);  // the rim's shadow drawn once is no cabin
  CHECK(stand != rim);
  CHECK(stand != spokes);
  CHECK_FALSE(r.parts[stand].carried);
  std::set<int> cabins;
  for (int p = 0; p < 8; ++p) cabins.insert(r.part_of_path[p]);
  CHECK(cabins.size() == 8);  // the bottom body too: it hangs below the wheel's box, under its roof
  CHECK(cabins.count(stand) == 0);
  CHECK(cabins.count(spokes) == 0);
}

TEST_CASE("a limb drawn as one stroke turns about its end nearest the shoulders or hips, a folded stroke about its fold") {
  // A line drawing: a filled torso 80-120 x 60-140 (the root; shoulders at its top centre
  // 100,60, hips at its bottom 100,140), an arm drawn as a hairpin beside it (down from the
  // shoulder and back, both ends at hip height inside the torso's edge), an arm drawn as one
  // straight stroke from the hand in to the shoulder, a leg drawn from the foot up to the hip.
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">
           <g><path d="M 80 60 L 120 60 L 120 140 L 80 140 Z" fill="#f9c"/></g>
           <g><path d="M 84 110 C 56 40 70 40 80 112" fill="none" stroke="#000" stroke-width="3"/></g>
           <g><path d="M 160 110 C 148 95 134 80 122 66" fill="none" stroke="#000" stroke-width="3"/></g>
           <g><path d="M 92 190 C 93 170 94 150 95 138" fill="none" stroke="#000" stroke-width="3"/></g></svg>)",
      "strokes.svg");
  const Rig r = build_rig(s, {});
  REQUIRE(r.root == 0);
  REQUIRE(r.parts[1].role == Role::UpperLimb);
  REQUIRE(r.parts[2].role == Role::UpperLimb);
  REQUIRE(r.parts[3].role == Role::LowerLimb);
  // The hairpin turns about its fold's tip (its curve's top, t = 0.5: 67.75,57.75), not about
  // its ends' middle (82,111), the centroid of its points in the torso's box.
  CHECK(r.parts[1].pivot.x == doctest::Approx(67.75));
  CHECK(r.parts[1].pivot.y == doctest::Approx(57.75));
  // The straight arm about its shoulder end, the leg about its hip end (not the foot it starts at).
  CHECK(r.parts[2].pivot.x == doctest::Approx(122));
  CHECK(r.parts[2].pivot.y == doctest::Approx(66));
  CHECK(r.parts[3].pivot.x == doctest::Approx(95));
  CHECK(r.parts[3].pivot.y == doctest::Approx(138));
  // Filled or closed paths have no stroke ends: their pivot is found as before.
  CHECK_FALSE(stroke_limb_pivot(s.paths[0], {100, 60}).has_value());
  const Scene f = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">
           <path d="M 160 110 C 148 95 134 80 122 66" fill="#000"/>
           <path d="M 160 110 C 148 95 134 80 122 66 Z" fill="none" stroke="#000"/></svg>)",
      "filled.svg");
  CHECK_FALSE(stroke_limb_pivot(f.paths[0], {100, 60}).has_value());
  CHECK_FALSE(stroke_limb_pivot(f.paths[1], {100, 60}).has_value());
  // An open stroke's end nearest the joint: the same stroke from the hips' side gives its other end.
  const auto hips = stroke_limb_pivot(s.paths[2], {170, 120});
  REQUIRE(hips.has_value());
  CHECK(hips->x == doctest::Approx(160));
  CHECK(hips->y == doctest::Approx(110));
}

TEST_CASE("a sketched wheel: one stroke round an oval is a loop; its plane turns it in place") {
  // An ellipse with semi-axes 30 (x) and 15 (y) about (100, 150), drawn as three of its four
  // quarter cubics (kappa 0.5523) and most of the fourth: an open stroke that winds 0.9 turn.
  // An S-shaped stroke (its turns cancel) and a hairpin (half a turn) are no loops.
  const double k = 0.5523;
  char d[512];
  std::snprintf(d, sizeof d,
                "M 130 150 C 130 %g %g 135 100 135 C %g 135 70 %g 70 150 C 70 %g %g 165 100 165 C %g 165 126 160 127 157",
                150 - 15 * k, 100 + 30 * k, 100 - 30 * k, 150 - 15 * k, 150 + 15 * k, 100 - 30 * k, 100 + 30 * k);
  auto stroke = [](const std::string& path_d) {
    Scene s = read_svg_string("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200\" height=\"200\"><path d=\"" + path_d +
                                  "\" fill=\"none\" stroke=\"#000\"/></svg>",
                              "stroke.svg");
    return s.paths.at(0);
  };
  const Path wheel = stroke(d);
  CHECK(is_loop_stroke(wheel));
  CHECK_FALSE(is_loop_stroke(stroke("M 20 20 C 60 0 60 60 100 40 C 140 20 140 80 180 60")));  // S
  CHECK_FALSE(is_loop_stroke(stroke("M 84 110 C 56 40 70 40 80 112")));                          // hairpin
  // The plane: M R M^-1 keeps every point of the ellipse on the ellipse (x/30)^2 + (y/15)^2 = 1
  // about its centre, where R alone (a turn in the drawing's plane) takes (30, 0) to (0, 30),
  // twice as far out as the ellipse reaches there.
  const Affine M = loop_plane(wheel);
  CHECK(M.det() == doctest::Approx(1).epsilon(1e-9));
  const Affine turn = M * Affine::rotate_deg(90) * M.inverse();
  for (double a = 0; a < 6.28; a += 0.5) {
    const Vec2 q = turn.apply({30 * std::cos(a), 15 * std::sin(a)});
    const double on = (q.x / 30) * (q.x / 30) + (q.y / 15) * (q.y / 15);
    CHECK(on == doctest::Approx(1).epsilon(0.03));  // the stroke's gap makes its moments an ellipse's within 3 %
  }
}

TEST_CASE("a line drawing: the longest central stroke is the root, strokes alongside it the body, limbs hang where their ends touch") {
  // A stick figure drawn as open strokes only (a sketch): a torso stroke 100,60-100,140 and a
  // second torso stroke drawn alongside it, a head arc above, an arm from the shoulder and a
  // forearm drawn on from the arm's hand, a leg from the hip and a stroke drawn down the back of
  // the leg whose lower end meets the leg at the foot (its upper end touches nothing).
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="220">
           <g>
             <path d="M 100 60 C 100 87 100 113 100 140" fill="none" stroke="#000" stroke-width="3"/>
             <path d="M 96 65 C 96 90 97 110 97 135" fill="none" stroke="#000" stroke-width="3"/>
             <path d="M 90 45 C 90 25 106 25 106 45" fill="none" stroke="#000" stroke-width="3"/>
           </g>
           <g>
             <path d="M 104 64 C 120 76 135 88 150 100" fill="none" stroke="#000" stroke-width="3"/>
             <path d="M 150 101 C 160 103 170 105 180 106" fill="none" stroke="#000" stroke-width="3"/>
           </g>
           <g>
             <path d="M 103 142 C 110 160 118 178 125 195" fill="none" stroke="#000" stroke-width="3"/>
             <path d="M 118 150 C 120 165 122 180 124 193" fill="none" stroke="#000" stroke-width="3"/>
           </g></svg>)",
      "sketch.svg");
  const Rig r = build_rig(s, {});
  // Each stroke is a part of its own (the groups join strokes of different limbs).
  REQUIRE(r.parts.size() == 7);
  for (size_t i = 0; i < r.parts.size(); ++i) REQUIRE(r.part_of_path[i] == static_cast<int>(i));
  CHECK(r.root == 0);
  // The torso stroke alongside the root is the body: a detail hanging from the root.
  CHECK(r.parts[1].role == Role::Detail);
  CHECK(r.parts[1].parent == 0);
  CHECK(r.parts[2].role == Role::Head);
  // The arm hangs from the root (its box overlaps nothing larger) and turns about its shoulder end.
  CHECK(r.parts[3].role == Role::UpperLimb);
  CHECK(r.parts[3].parent == 0);
  CHECK(r.parts[3].pivot.x == doctest::Approx(104));
  CHECK(r.parts[3].pivot.y == doctest::Approx(64));
  // The forearm (an upper limb too: its middle is beside the body's upper half) touches the
  // arm's curve at the hand with its end: it hangs from the arm.
  CHECK(r.parts[4].parent == 3);
  CHECK(r.parts[4].chain_top == 3);
  // The leg turns about its hip end; the stroke down its back meets it at the foot and hangs from it.
  CHECK(r.parts[5].role == Role::LowerLimb);
  CHECK(r.parts[5].parent == 0);
  CHECK(r.parts[5].pivot.x == doctest::Approx(103));
  CHECK(r.parts[5].pivot.y == doctest::Approx(142));
  CHECK(r.parts[6].parent == 5);
  // A filled path makes the drawing no line drawing: the rules for shapes hold.
  CHECK(is_line_drawing(s));
  CHECK_FALSE(is_line_drawing(read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">
           <path d="M 80 60 L 120 60 L 120 140 L 80 140 Z" fill="#f9c"/>
           <path d="M 84 110 C 56 40 70 40 80 112" fill="none" stroke="#000"/>
           <path d="M 160 110 C 148 95 134 80 122 66" fill="none" stroke="#000"/>
           <path d="M 92 190 C 93 170 94 150 95 138" fill="none" stroke="#000"/></svg>)",
      "mixed.svg")));
  // Lengths and curve boxes are the curve's, not the handles'.
  CHECK(stroke_length(s.paths[0]) == doctest::Approx(80).epsilon(0.001));
  const RigBox hb = stroke_box(s.paths[2]);
  CHECK(hb.y0 == doctest::Approx(30));  // the arc's top at t = 0.5 (its handles stand at 25)
}

}  // TEST_SUITE
