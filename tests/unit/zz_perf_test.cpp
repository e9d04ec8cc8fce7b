#include <doctest/doctest.h>
#include <chrono>
#include <cstdio>
#include "raster_test_support.h"
#include "scene/synthetic_scene.h"
using namespace svgm; using namespace svgm::test;
TEST_CASE("perf" * doctest::skip()) {
  for (int n : {3, 30}) {
  Scene s = synthetic_blobs(n, 256, 7);
  RasterPlan plan = plan_raster(s, Affine{}, 256, 256);
  static ClRuntime prt("auto", true);
  ClRaster r(prt, plan, 15); r.set_rest_pose();
  r.forward(ClRaster::Output::Float, {1,1,1,1});
  auto img = r.read_image(); for (auto& v : img) v = 1.0f;
  r.set_targets(img);
  double best = 1e9;
  for (int rep = 0; rep < 6; ++rep) {
    auto t0 = std::chrono::steady_clock::now(); r.loss_and_gradient(1000, {1,1,1,1});
    best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now()-t0).count());
  }
  printf("paths %d lines %d iter %.3f ms\n", n, plan.n_lines, best);
  for (auto& [nm, ms] : r.kernel_times()) printf("  %s %.3f\n", nm.c_str(), ms);
  }
}
