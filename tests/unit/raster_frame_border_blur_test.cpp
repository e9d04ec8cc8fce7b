// Taking a soft video's outside blur out of the target's border band (raster/frame_border_blur.h):
// a frame of uniform ink, which a blur padded by reflection (or a scene going on beyond the
// frame) leaves uniform, becomes exactly the zero-padded blur of that ink, the render's model
// (c times the share of the stencil inside the frame, per axis); pixels beyond the stencil's
// radius keep their bits; at the paper's σ nothing changes. The loss's constants and its CPU
// reference take the same correction: their losses agree for a drawing that crosses the border.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <vector>

#include "raster/frame_border_blur.h"
#include "raster/loss_ref.h"
#include "raster/loss_taps.h"
#include "raster_test_support.h"
#include "scene_builders.h"

using namespace svgm;

TEST_SUITE("raster") {

TEST_CASE("frame border blur: uniform ink becomes its zero-padded blur; the inside and σ 1 are untouched") {
  constexpr int W = 30, H = 20;
  const double sigma = 1.8;  // a 1.5-px video blur: sqrt(1 + 1.5²)
  const int R = video_radius(sigma);
  REQUIRE(R == 5);
  const std::vector<double> g = gaussian_stencil(video_sigma(sigma), R);
  auto inside = [&](int i, int n) {  // the share of the stencil inside [0, n) at i
    double s = 0;
    for (int j = -R; j <= R; ++j)
      if (i + j >= 0 && i + j < n) s += g[static_cast<size_t>(j + R)];
    return s;
  };
  const std::array<double, 3> c = {-0.8, -0.5, -0.1};  // ink: the target less white paper
  std::vector<double> d(static_cast<size_t>(W) * H * 3);
  for (size_t i = 0; i < d.size(); ++i) d[i] = c[i % 3];
  std::vector<double> same = d;
  remove_outside_blur(same, W, H, 1.0);
  CHECK(same == d);
  remove_outside_blur(d, W, H, sigma);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      for (int ch = 0; ch < 3; ++ch) {
        const double v = d[3 * (static_cast<size_t>(y) * W + x) + ch];
        CAPTURE(x);
        CAPTURE(y);
        CHECK(v == doctest::Approx(c[ch] * inside(x, W) * inside(y, H)).epsilon(1e-12));
        if (x >= R && x < W - R && y >= R && y < H - R) CHECK(v == c[ch]);
      }
}

TEST_CASE("frame border blur: the kernels' loss and the reference's agree for a drawing across the border") {
  // A disc running off the frame's left edge against a target of uniform ink at the left: the
  // correction changes the target's border band, in Q and in the reference alike.
  const Scene scene = test::scene_of(40, 32, {test::filled(test::circle({2, 16}, 12), {0.2f, 0.3f, 0.7f, 1})});
  const RasterPlan plan = plan_raster(scene, Affine{}, 40, 32);
  const std::vector<double> cp(plan.rest_cp.begin(), plan.rest_cp.end());
  std::vector<float> target(static_cast<size_t>(40) * 32 * 4, 1.f);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 12; ++x) {
      float* t = &target[4 * (static_cast<size_t>(y) * 40 + x)];
      t[0] = 0.25f, t[1] = 0.35f, t[2] = 0.7f;
    }
  for (double sigma : {1.0, 1.8}) {
    CAPTURE(sigma);
    ClRaster r(test::runtime(), plan, 1, sigma, 0);
    r.set_control_points(std::vector<float>(cp.begin(), cp.end()));
    r.set_targets(target);
    const double lc = r.loss_and_gradient(1.f, {1, 1, 1, 1});
    const double lr = ref::blurred_sq_sum(ref::render(plan, cp), target, 40, 32, {1, 1, 1, 1}, sigma) / (40.0 * 32 * 3);
    CHECK(lr > 0);
    CHECK(lc == doctest::Approx(lr).epsilon(1e-4));
  }
}

}  // TEST_SUITE
