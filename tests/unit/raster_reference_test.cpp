// The OpenCL rasteriser against the double-precision CPU reference on random scenes: overlapping
// paths, opacity, both fill rules, curves, strokes with every join and cap, partly off canvas.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "raster_test_support.h"
#include "scene_builders.h"

using namespace svgm;
using namespace svgm::test;

namespace {

Scene random_scene(uint32_t seed, int w, int h) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> X(-10, w + 10), Y(-10, h + 10), U(0, 1);
  std::vector<Path> paths;
  const int n = 3 + static_cast<int>(rng() % 5);
  for (int i = 0; i < n; ++i) {
    Subpath sp;
    sp.closed = U(rng) < 0.7;
    sp.points.push_back({X(rng), Y(rng)});
    const int segs = 1 + static_cast<int>(rng() % 5);
    for (int s = 0; s < 3 * segs; ++s) sp.points.push_back({X(rng), Y(rng)});
    const Rgba col{static_cast<float>(U(rng)), static_cast<float>(U(rng)),
                   static_cast<float>(U(rng)), static_cast<float>(0.3 + 0.7 * U(rng))};
    Path p;
    if (U(rng) < 0.5) {
      p = filled(sp, col, U(rng) < 0.5 ? FillRule::EvenOdd : FillRule::NonZero);
    } else {
      p = stroked(sp, 0.5 + 6 * U(rng), static_cast<LineJoin>(rng() % 4),
                  static_cast<LineCap>(rng() % 3), col);
      p.stroke.miter_limit = 1 + 5 * U(rng);
    }
    p.opacity = static_cast<float>(0.5 + 0.5 * U(rng));
    paths.push_back(p);
  }
  return scene_of(w, h, paths);
}

}  // namespace

TEST_SUITE("raster") {

TEST_CASE("kernels agree with the CPU reference on random scenes to 1e-4 per channel") {
  for (uint32_t seed = 1; seed <= 12; ++seed) {
    const Scene s = random_scene(seed, 48, 40);
    const auto cl = render_cl(s);
    const auto rf = render_ref(s);
    REQUIRE(cl.size() == rf.size());
    double worst = 0;
    size_t at = 0;
    for (size_t i = 0; i < cl.size(); ++i)
      if (std::fabs(cl[i] - rf[i]) > worst) { worst = std::fabs(cl[i] - rf[i]); at = i; }
    CAPTURE(seed);
    CAPTURE(at / 4 % 48);
    CAPTURE(at / 4 / 48);
    CHECK(worst < 1e-4);
    CHECK(alpha_sum(rf) > 0);  // the scene is not empty
  }
}

TEST_CASE("two runs of the kernels give identical bits") {
  const Scene s = random_scene(99, 64, 48);
  const auto a = render_cl(s, 3), b = render_cl(s, 3);
  CHECK(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
}

TEST_CASE("read_image_frame reads one frame of read_image, and only one frame's bytes") {
  // The fitter's warm start reads the previous keyframe alone: the whole clip was 88 MB of a
  // 21-keyframe 512 px fit's peak memory.
  const Scene s = random_scene(7, 40, 32);
  const RasterPlan plan = plan_raster(s, Affine{}, 40, 32);
  ClRaster r(runtime(), plan, 3);
  std::vector<float> cp;
  for (int k = 0; k < 3; ++k)  // three different frames: each moved k px to the right
    for (size_t i = 0; i < plan.rest_cp.size(); i += 2) {
      cp.push_back(plan.rest_cp[i] + static_cast<float>(k));
      cp.push_back(plan.rest_cp[i + 1]);
    }
  r.set_control_points(cp);
  r.forward();
  const auto all = r.read_image();
  const size_t frame = 40 * 32 * 4;
  for (int k = 0; k < 3; ++k) {
    const auto one = r.read_image_frame(k);
    REQUIRE(one.size() == frame);
    CHECK(std::memcmp(one.data(), all.data() + k * frame, frame * sizeof(float)) == 0);
  }
  CHECK(std::memcmp(all.data(), all.data() + frame, frame * sizeof(float)) != 0);  // the frames differ
  CHECK_THROWS(r.read_image_frame(3));
}

}  // TEST_SUITE
