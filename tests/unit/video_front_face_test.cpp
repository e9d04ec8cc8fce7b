// A figure seen from the front (procedural/front_face.h): a pair of eye-like marks level with each
// other and mirrored about the figure's middle. Its tail is not drawn, so "wags its tail" wags the
// whole figure (motion_plan.cpp) instead of bending the far end of its box (a dog's face bent an
// ear). On rigs made by hand (which pairs count) and on plain_face.svg, a round face with two
// eyes, against a side view with one eye.
#include <doctest/doctest.h>

#include <string>

#include "procedural/eye_cue.h"
#include "procedural/front_face.h"
#include "procedural/motion_plan.h"
#include "procedural/prompt_parse.h"
#include "svgmotion/svg_reader.h"
#include "motion_drawing.h"
#include "test_paths.h"

using namespace svgm;

namespace {

RigElement mark(double x0, double y0, double x1, double y1, double l) { return svgm::test::box_element(x0, y0, x1, y1, l); }

// A light figure 200 x 200 from (0, 0).
Rig face_rig() {
  Rig rig;
  rig.figure.add(Vec2{0, 0});
  rig.figure.add(Vec2{200, 200});
  rig.elements = {mark(0, 0, 200, 200, 0.8)};
  return rig;
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("front face: two dark marks level and mirrored about the middle are a face seen from the front") {
  Rig rig = face_rig();
  CHECK_FALSE(front_face(rig).seen);  // no eyes
  rig.elements.push_back(mark(60, 70, 76, 86, 0.1));    // middle (68, 78)
  rig.elements.push_back(mark(124, 70, 140, 86, 0.1));  // middle (132, 78): the pair's middle 100, 64 apart (0.32)
  FrontFace f = front_face(rig);
  REQUIRE(f.seen);
  CHECK(f.left.x == doctest::Approx(68));
  CHECK(f.right.x == doctest::Approx(132));
  CHECK(f.why == "a pair of eye-like marks level at 0.34,0.39 and 0.66,0.39 of the figure");
  // One 14 px lower (0.07 of the height, over kFacePairLevel's 0.06): no pair.
  rig.elements.back() = mark(124, 84, 140, 100, 0.1);
  CHECK_FALSE(front_face(rig).seen);
  // Both on the right of the middle (a side view's eye and a nostril): their middle is 0.2 off.
  rig.elements = {mark(0, 0, 200, 200, 0.8), mark(124, 70, 140, 86, 0.1), mark(164, 70, 180, 86, 0.1)};
  CHECK_FALSE(front_face(rig).seen);
  // Light marks are no eyes (eye_like: luma at most kEyeDark).
  rig.elements = {mark(0, 0, 200, 200, 0.8), mark(60, 70, 76, 86, 0.9), mark(124, 70, 140, 86, 0.9)};
  CHECK_FALSE(front_face(rig).seen);
  // Of two pairs, the smaller: the eyes, not a dog's dark ear insides above them.
  rig.elements = {mark(0, 0, 200, 200, 0.8), mark(30, 10, 52, 32, 0.1), mark(148, 10, 170, 32, 0.1), mark(60, 70, 76, 86, 0.1),
                  mark(124, 70, 140, 86, 0.1)};
  f = front_face(rig);
  REQUIRE(f.seen);
  CHECK(f.left.x == doctest::Approx(68));
}

TEST_CASE("front face: 'wags its tail' on a face seen from the front wags the whole figure; a side view's tail still bends") {
  auto plan_of = [](const char* file, const char* prompt) {
    const Scene s = read_svg_file(svgm::test::data_path(std::string("motion/") + file));
    Rig rig = build_rig(s, read_source_names(svgm::test::data_path(std::string("motion/") + file)));
    apply_eye_cue(rig, s, s);  // the eyes' lightness, as the procedural provider reads it
    return plan_from_prompt(parse_prompt(prompt), rig, 1);
  };
  const MotionPlan face = plan_of("plain_face.svg", "the dog wags its tail");
  REQUIRE(face.actions.size() == 1);
  CHECK(face.actions[0].verb == "wag");
  CHECK(face.actions[0].target == Target::Whole);
  CHECK(face.actions[0].region == Region::None);
  CHECK(face.actions[0].why.find("no tail drawn: the figure is seen from the front (a pair of eye-like marks level at") != std::string::npos);
  CHECK(face.warnings.empty());
  // The same words on a side view (one eye): the far end of the body, away from the eye, bends.
  const MotionPlan side = plan_of("eye_tail.svg", "the dog wags its tail");
  REQUIRE_FALSE(side.actions.empty());
  CHECK(side.actions[0].target == Target::Tail);
  CHECK(side.actions[0].why.find("no tail drawn") == std::string::npos);
}

}  // TEST_SUITE
