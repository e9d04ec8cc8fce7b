// The loss's padding at the frame's border (raster/loss_taps.h, loss_reflects): above the
// paper's σ both blurs pad by reflection. Ink that fills the frame and runs off it on every
// side, against a target of the same ink, costs nothing at a render σ of 1.8 (a 1.5-px video
// blur): with zero padding the render's wider blur faded at the border where the target's
// did not. Drawings crossing the border keep the kernels' loss equal to the CPU reference's
// and the gradient equal to its finite differences, with the plain blur and the per-group one.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "raster/loss_ref.h"
#include "raster/loss_taps.h"
#include "raster_test_support.h"
#include "scene_builders.h"

using namespace svgm;
using namespace svgm::test;

namespace {

constexpr int kW = 40, kH = 32;

// The reference loss of one frame, as the kernels scale it (weight 1).
double ref_loss(const RasterPlan& plan, const std::vector<double>& cp, const std::vector<float>& target, double sl,
                double sc) {
  return ref::blurred_sq_sum(ref::render(plan, cp), target, kW, kH, {1, 1, 1, 1}, sl, sc) / (kW * kH * 3.0);
}

}  // namespace

TEST_SUITE("raster") {

TEST_CASE("reflect-101 indices: mirrored about the edge pixels, the inside unchanged") {
  CHECK(reflect101(-1, 10) == 1);
  CHECK(reflect101(-5, 10) == 5);
  CHECK(reflect101(0, 10) == 0);
  CHECK(reflect101(9, 10) == 9);
  CHECK(reflect101(10, 10) == 8);
  CHECK(reflect101(13, 10) == 5);
  CHECK_FALSE(loss_reflects(1.0));
  CHECK(loss_reflects(1.8));
}

TEST_CASE("loss border: ink filling the frame and running off it costs nothing at a render σ of 1.8") {
  // A rectangle 10 px beyond every side of the frame, in colours a half-float holds exactly,
  // against a target of that colour: the render and the target are the same uniform ink.
  const Rgba ink{0.25f, 0.5f, 0.75f, 1};
  const Scene scene = scene_of(kW, kH, {filled(polygon({{-10, -10}, {kW + 10, -10}, {kW + 10, kH + 10}, {-10, kH + 10}}), ink)});
  const RasterPlan plan = plan_raster(scene, Affine{}, kW, kH);
  const std::vector<double> cp(plan.rest_cp.begin(), plan.rest_cp.end());
  std::vector<float> target(static_cast<size_t>(kW) * kH * 4, 1.f);
  for (size_t p = 0; p < target.size() / 4; ++p) target[4 * p] = 0.25f, target[4 * p + 1] = 0.5f, target[4 * p + 2] = 0.75f;
  for (const auto& [sl, sc] : {std::pair{1.0, 0.0}, std::pair{1.8, 0.0}, std::pair{1.3, 1.9}}) {
    CAPTURE(sl);
    CAPTURE(sc);
    ClRaster r(runtime(), plan, 1, sl, sc);
    r.set_control_points(std::vector<float>(cp.begin(), cp.end()));
    r.set_targets(target);
    // Zero padding left the ink outside G_r's share inside the frame unmatched along the border
    // (G_r's taps against G_t's). The kernels sum Q² and 2Q·E' + E'² in float: what is left is
    // their rounding.
    CHECK(std::fabs(r.loss_and_gradient(1.f, {1, 1, 1, 1})) < 1e-6f);
    CHECK(ref_loss(plan, cp, target, sl, sc) < 1e-20);
  }
}

TEST_CASE("loss border: drawings crossing the border keep the loss and gradient exact with reflect padding") {
  // A disc off the left edge, a translucent triangle off the bottom right corner; the frame
  // perturbed from rest, the target another perturbation rendered by the reference.
  const Scene scene = scene_of(kW, kH, {filled(circle({2, 14}, 9), {0.9f, 0.2f, 0.1f, 1}),
                                        filled(polygon({{24, 18}, {47, 24}, {33, 39}}), {0.1f, 0.6f, 0.3f, 0.7f})});
  const RasterPlan plan = plan_raster(scene, Affine{}, kW, kH);
  const auto [cp, target] = perturbed_pair(plan, 23);
  const size_t n = static_cast<size_t>(plan.n_cp - 3) * 2;  // the 3 padding points stay at 0
  for (const auto& [sl, sc] : {std::pair{1.8, 0.0}, std::pair{1.3, 1.9}}) {
    CAPTURE(sl);
    CAPTURE(sc);
    ClRaster r(runtime(), plan, 1, sl, sc);
    r.set_control_points(std::vector<float>(cp.begin(), cp.end()));
    r.set_targets(target);
    const double lc = r.loss_and_gradient(1.f, {1, 1, 1, 1});
    const double lr = ref_loss(plan, cp, target, sl, sc);
    CHECK(lr > 0);
    CHECK(lc == doctest::Approx(lr).epsilon(1e-4));
    const std::vector<float> g = r.read_cp_gradient();
    double ab = 0, aa = 0, bb = 0, dd = 0;
    const double h = 1e-5;
    std::vector<double> c = cp;
    for (size_t i = 0; i < n; ++i) {
      const double keep = c[i];
      c[i] = keep + h;
      const double up = ref_loss(plan, c, target, sl, sc);
      c[i] = keep - h;
      const double fd = (up - ref_loss(plan, c, target, sl, sc)) / (2 * h);
      c[i] = keep;
      ab += g[i] * fd, aa += double{g[i]} * g[i], bb += fd * fd, dd += (g[i] - fd) * (g[i] - fd);
    }
    const double cosine = ab / std::sqrt(aa * bb), rel = std::sqrt(dd / bb);
    MESSAGE("sigma " << sl << " / " << sc << ": cosine " << cosine << ", relative error " << rel);
    CHECK(cosine > 0.99999);
    CHECK(rel < 1e-3);
  }
}

}  // TEST_SUITE
