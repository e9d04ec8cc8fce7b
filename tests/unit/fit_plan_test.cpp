// plan_fit's grouping of small paths (FitPlanOptions::attach_small_px): a dot alone in its
// scene group joins the group of the path it sits on; a dot beside everything, a large path
// and a path in a real (multi-path) group keep their own.
#include <doctest/doctest.h>

#include "fit/plan/fit_plan.h"
#include "scene_builders.h"

using namespace svgm;
using namespace svgm::test;

TEST_SUITE("fit") {

TEST_CASE("fit plan: small paths move with the path they sit on") {
  Path face = filled(circle({30, 30}, 20), {0.9f, 0.7f, 0.6f, 1});
  Path freckle = filled(circle({25, 28}, 1), {0.6f, 0.3f, 0.2f, 1});      // on the face
  Path speck = filled(circle({58, 58}, 1), {0.1f, 0.1f, 0.1f, 1});        // on nothing
  Path eye_a = filled(circle({38, 24}, 1.2), {0, 0, 0, 1});               // on the face, but
  Path eye_b = filled(circle({22, 24}, 1.2), {0, 0, 0, 1});               // grouped together
  Scene s = scene_of(64, 64, {face, freckle, speck, eye_a, eye_b});
  s.groups = {{"face", {0}}, {"freckle", {1}}, {"speck", {2}}, {"eyes", {3, 4}}};
  s.paths[0].group = 0;
  s.paths[1].group = 1;
  s.paths[2].group = 2;
  s.paths[3].group = s.paths[4].group = 3;
  const RasterPlan raster = plan_raster(s, Affine{}, 64, 64);
  auto group_of = [&](const FitPlan& f, int path) { return f.cp_group[raster.path_cp_first[path]]; };

  FitPlanOptions o;
  const FitPlan apart = plan_fit(s, raster, o);
  CHECK(apart.n_groups == 4);
  CHECK(group_of(apart, 1) != group_of(apart, 0));

  o.attach_small_px = 4;  // the dots are 2-2.4 px, the face 40 px
  const FitPlan f = plan_fit(s, raster, o);
  CHECK(f.n_groups == 3);
  CHECK(group_of(f, 1) == group_of(f, 0));  // the freckle follows the face
  CHECK(group_of(f, 2) != group_of(f, 0));  // the speck sits on nothing
  CHECK(group_of(f, 3) == group_of(f, 4));  // the eyes keep their own group
  CHECK(group_of(f, 3) != group_of(f, 0));
}

}  // TEST_SUITE
