// The eye cue (procedural/eye_cue.h): a small dark round element near one end of an animal
// seen from the side marks its head, and the silhouette skeleton's head and tail labels follow
// it. On rigs made by hand (which elements count as an eye) and on a drawing made for the test
// (eye_tail.svg: a thin tail ending in a round tuft wider than the snout, which the skeleton's
// tip rule takes for the head).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "procedural/eye_cue.h"
#include "procedural/limb_qualifiers.h"
#include "procedural/motion_plan.h"
#include "procedural/part_locator.h"
#include "procedural/skeleton_lobes.h"

#include "motion_drawing.h"
using namespace svgm;
using svgm::test::Drawing;

namespace {

RigElement blob(double x0, double y0, double x1, double y1, double l) { return svgm::test::box_element(x0, y0, x1, y1, l); }

// A figure 200 x 100 from (0, 0) whose body is a light element over all of it.
Rig side_figure() {
  Rig rig;
  rig.figure.add(Vec2{0, 0});
  rig.figure.add(Vec2{200, 100});
  rig.elements = {blob(0, 0, 200, 100, 0.8)};
  return rig;
}

ArmLobe limb(LobeKind kind, double tx, double ty) {
  ArmLobe l;
  l.kind = kind;
  l.pivot = {100, 50};
  l.tip = {tx, ty};
  return l;
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("eye cue: a small dark round element near one end is the eye; the head is on its side") {
  Rig rig = side_figure();
  rig.elements.push_back(blob(20, 20, 28, 28, 0.1));  // 8 px: 0.04 of the figure's 200, at x 24 (0.12)
  EyeCue eye = find_eye(rig);
  CHECK(eye.side == -1);
  CHECK(eye.count == 1);
  CHECK(eye.at.x == doctest::Approx(24));
  CHECK(eye.at.y == doctest::Approx(24));
  CHECK(eye.why == "its eye (1 small dark round element at 0.12,0.24 of the figure)");
  // A nostril at the same end joins it.
  rig.elements.push_back(blob(4, 40, 8, 44, 0.2));
  eye = find_eye(rig);
  CHECK(eye.side == -1);
  CHECK(eye.count == 2);
}

TEST_CASE("eye cue: no end is shown by two eyes at both ends, light or large or long or low blobs, or one at the middle") {
  auto side_with = [](std::vector<RigElement> more) {
    Rig rig = side_figure();
    rig.elements.insert(rig.elements.end(), more.begin(), more.end());
    return find_eye(rig).side;
  };
  CHECK(side_with({blob(20, 20, 28, 28, 0.1), blob(172, 20, 180, 20 + 8, 0.1)}) == 0);  // a face from the front, spots
  CHECK(side_with({blob(20, 20, 28, 28, 0.6)}) == 0);    // light: a highlight
  CHECK(side_with({blob(10, 10, 40, 40, 0.1)}) == 0);    // 30 px: 0.15 of the figure, a patch
  CHECK(side_with({blob(20, 20, 40, 24, 0.1)}) == 0);    // 20 x 4: a stripe
  CHECK(side_with({blob(20, 80, 28, 88, 0.1)}) == 0);    // at 0.84 of the height: a hoof
  CHECK(side_with({blob(96, 20, 104, 28, 0.1)}) == 0);   // at the middle
  CHECK(side_with({blob(170, 20, 178, 28, 0.1)}) == 1);  // the same eye at the right end
}

TEST_CASE("eye cue: the skeleton's head and tail labels follow the eye; facing says so") {
  Rig rig = side_figure();
  rig.elements.push_back(blob(170, 20, 178, 28, 0.1));  // the eye at the right
  rig.limbs = {limb(LobeKind::Head, 10, 40), limb(LobeKind::Tail, 195, 30), limb(LobeKind::Leg, 30, 100),
               limb(LobeKind::Head, 110, 0)};  // a head limb up at the middle keeps its label
  const EyeCue eye = find_eye(rig);
  REQUIRE(eye.side == 1);
  CHECK(relabel_by_eye(rig, eye) == 2);
  CHECK(rig.limbs[0].kind == LobeKind::Tail);
  CHECK(rig.limbs[1].kind == LobeKind::Head);
  CHECK(rig.limbs[2].kind == LobeKind::Leg);
  CHECK(rig.limbs[3].kind == LobeKind::Head);
  rig.eye_side = eye.side;
  std::string why;
  CHECK(facing_side(rig, &why) == 1);
  CHECK(why == "its eye");
  // No eye: nothing changes.
  CHECK(relabel_by_eye(rig, EyeCue{}) == 0);
}

TEST_CASE("eye cue: a limb belongs to the end its base leaves, when that is off the middle: antennae swept back stay the head's") {
  Rig rig = side_figure();
  rig.elements.push_back(blob(170, 20, 178, 28, 0.1));  // the eye at the right
  auto from = [](LobeKind kind, Vec2 pivot, Vec2 tip) {
    ArmLobe l;
    l.kind = kind;
    l.pivot = pivot;
    l.tip = tip;
    return l;
  };
  rig.limbs = {from(LobeKind::Tail, {165, 15}, {15, 5}),    // antennae: from the head back past the tail's end
               from(LobeKind::Head, {30, 40}, {150, 2}),    // a tail curled forward over the back
               from(LobeKind::Tail, {105, 50}, {10, 60})};  // a base at the middle: by its tip, a tail still
  const EyeCue eye = find_eye(rig);
  REQUIRE(eye.side == 1);
  CHECK(relabel_by_eye(rig, eye) == 2);
  CHECK(rig.limbs[0].kind == LobeKind::Head);
  CHECK(rig.limbs[1].kind == LobeKind::Tail);
  CHECK(rig.limbs[2].kind == LobeKind::Tail);
}

TEST_CASE("eye cue: an animal whose round-tufted tail the skeleton reads as its head flicks its tail, not its snout") {
  Drawing d("eye_tail.svg");
  REQUIRE(d.rig.parts.size() == 1);
  // Read in the drawing's own colours (the pipeline's svg is recoloured; it gives the original).
  Scene recoloured = d.scene;
  for (Path& p : recoloured.paths) p.fill = Rgba{0.9f, 0.9f, 0.2f, 1};  // no dark left: no eye
  CHECK(apply_eye_cue(d.rig, d.scene, recoloured).side == 0);
  CHECK(d.rig.eye_side == 0);
  CHECK(apply_eye_cue(d.rig, d.scene, d.scene).side == -1);
  CHECK(d.rig.eye_side == -1);
  // The skeleton alone takes the wider tuft at the right for the head.
  bool head_right = false;
  for (const ArmLobe& l : skeleton_lobes(d.scene, {0, 1})) head_right = head_right || (l.kind == LobeKind::Head && l.tip.x > 180);
  CHECK(head_right);
  // With the eye, the rig's limb at the right is the tail and the one at the left the head.
  int tails = 0, heads = 0;
  for (const ArmLobe& l : d.rig.limbs) {
    tails += l.kind == LobeKind::Tail && l.tip.x > 180;
    heads += l.kind == LobeKind::Head && l.tip.x < 30;
  }
  CHECK(tails == 1);
  CHECK(heads == 1);
  const MotionPlan plan = plan_from_prompt(parse_prompt("the squirrel flicks its tail"), d.rig, 1);
  REQUIRE(!plan.actions.empty());
  // How far the body path's points at the tuft (x > 185) and at the snout (x < 40) travel.
  const int F = 13;
  const std::vector<Vec2> pts = animate_plan(d.scene, d.rig, plan, F);
  const size_t per = pts.size() / F;
  double tuft = 0, snout = 0;
  size_t i = 0;
  for (const auto& sp : d.scene.paths[0].subpaths)
    for (const Vec2& q : sp.points) {
      for (int f = 1; f < F; ++f) {
        const double m = std::hypot(pts[f * per + i].x - pts[i].x, pts[f * per + i].y - pts[i].y);
        if (q.x > 185) tuft = std::max(tuft, m);
        if (q.x < 40) snout = std::max(snout, m);
      }
      ++i;
    }
  CHECK(tuft > 10.0);
  CHECK(snout == 0.0);
  CHECK(d.travel(plan)[1] == 0.0);  // the eye
}

TEST_CASE("eye cue: ears are looked for at the eye's end; a raised tail at the other is none") {
  Rig rig = side_figure();
  rig.elements.push_back(blob(20, 20, 28, 28, 0.1));   // the eye, left
  rig.elements.push_back(blob(150, -40, 175, 5, 0.7));  // a raised tail sticking up at the right
  rig.elements.push_back(blob(30, -22, 48, 5, 0.7));    // a smaller ear above the eye
  for (RigElement& e : rig.elements) rig.figure.add(e.box);
  const EyeCue eye = find_eye(rig);
  REQUIRE(eye.side == -1);
  LocatedPart ears = locate_part(rig, PartShape::Ears);
  CHECK(ears.lobes.size() == 2);  // without the eye: the tail and the ear, the tail first
  rig.eye_side = eye.side;
  rig.eye = eye.at;
  ears = locate_part(rig, PartShape::Ears);
  REQUIRE(ears.lobes.size() == 1);
  CHECK(ears.lobes[0].tip.x < 50);
}

}
