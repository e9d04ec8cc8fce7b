// The matched blur's program (raster/loss_blur.h): one build of the raster program serves every
// blur but the paper's, its taps, radius, padding and chroma weight read from a kernel argument.
// Built once, it is given blurs of every radius it holds (2 to 8: σ below 1, σ 1 with a chroma
// weight or a chroma σ of its own, and σ 1.05 to 2), and each loss equals the CPU reference's
// (raster/loss_ref.h) and each gradient the reference's finite differences, to float rounding.
// With the taps compiled in, each of these blurs was a program of its own.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "raster/loss_blur.h"
#include "raster/loss_ref.h"
#include "raster/loss_taps.h"
#include "raster_test_support.h"
#include "scene_builders.h"

using namespace svgm;
using namespace svgm::test;

namespace {

constexpr int kW = 44, kH = 36;

struct Blur {
  double sigma, chroma_sigma, chroma_weight;
};

// The reference loss of one frame, as the kernels scale it (weight 1).
double ref_loss(const RasterPlan& plan, const std::vector<double>& cp, const std::vector<float>& target, const Blur& b) {
  return ref::blurred_sq_sum(ref::render(plan, cp), target, kW, kH, {1, 1, 1, 1}, b.sigma, b.chroma_sigma,
                             b.chroma_weight) /
         (kW * kH * 3.0);
}

}  // namespace

TEST_SUITE("raster") {

TEST_CASE("loss blur args: the radius, taps, padding and YCbCr of a blur, as the kernels read them") {
  // σ 1.2: the paper's 5 taps composed with the video's σ sqrt(0.44) cut at 2 a side: radius 4.
  const LossBlurArgs a = loss_blur_args(1.2, 1.2, 1);
  CHECK(a.radius == 4);
  CHECK(a.reflect == 1);
  CHECK(a.ycc == 0);
  const std::vector<double> g = loss_taps(1.2);
  for (int j = 0; j <= kMaxLossRadius; ++j) {
    const float want = j <= 4 ? static_cast<float>(g[static_cast<size_t>(j)]) : 0.f;
    CHECK(a.g[j][0] == want);
    CHECK(a.g[j][1] == want);  // chroma takes the luma taps in RGB
    CHECK(a.g[j][3] == 0.f);
  }
  // A chroma σ of its own: YCbCr, the larger radius (σ 1.35: 5), luma's taps 0 beyond its 4.
  const LossBlurArgs c = loss_blur_args(1.2, 1.35, 0.5);
  CHECK(c.radius == 5);
  CHECK(c.ycc == 1);
  CHECK(c.g[5][0] == 0.f);
  CHECK(c.g[5][1] == static_cast<float>(loss_taps(1.35)[5]));
  CHECK(c.chroma_weight == 0.5f);
  // σ 1 with a chroma weight: the paper's radius, zero padding, on the matched build.
  const LossBlurArgs w = loss_blur_args(1, 1, 0.25);
  CHECK(w.radius == 2);
  CHECK(w.reflect == 0);
  CHECK(loss_blur_options(1, 1, 1).empty());
  CHECK(loss_blur_options(1, 1, 0.25) == " -DLOSS_MATCHED");
  CHECK(loss_blur_options(1.05, 1.05, 1) == " -DLOSS_MATCHED");
}

TEST_CASE("matched blur: one program serves every radius, each loss and gradient the reference's") {
  // A disc off the left edge (reflect padding's border), a translucent triangle; the frame
  // perturbed from rest, the target another perturbation rendered by the reference.
  const Scene scene = scene_of(kW, kH, {filled(circle({3, 15}, 9), {0.9f, 0.2f, 0.1f, 1}),
                                        filled(polygon({{22, 8}, {40, 20}, {27, 31}}), {0.1f, 0.6f, 0.3f, 0.7f})});
  const RasterPlan plan = plan_raster(scene, Affine{}, kW, kH);
  const auto [cp, target] = perturbed_pair(plan, 31);
  const size_t n = static_cast<size_t>(plan.n_cp - 3) * 2;  // the 3 padding points stay at 0
  ClRuntime& rt = runtime();
  const int programs_before = rt.programs_built_from_source() + rt.programs_loaded_from_cache();
  // Radii 2 (σ 0.8; σ 1 with a chroma weight), 3 (1.05), 4 (1.15; 1.2 with chroma 1.1), 5 (1.3;
  // σ 1 with chroma 1.35, zero padding in YCbCr), 6 (1.5), 7 (1.7), 8 (2.0; 1.2 with chroma 2).
  const Blur blurs[] = {{0.8, 0.8, 1},  {1, 1, 0.25},   {1.05, 1.05, 1}, {1.15, 1.15, 1}, {1.2, 1.1, 0.5},
                        {1.3, 1.3, 1},  {1, 1.35, 1},   {1.5, 1.5, 1},   {1.7, 1.7, 0.6}, {2.0, 2.0, 1},
                        {1.2, 2.0, 0.5}};
  for (const Blur& b : blurs) {
    CAPTURE(b.sigma);
    CAPTURE(b.chroma_sigma);
    CAPTURE(b.chroma_weight);
    ClRaster r(rt, plan, 1, b.sigma, b.chroma_sigma, b.chroma_weight);
    r.set_control_points(std::vector<float>(cp.begin(), cp.end()));
    r.set_targets(target);
    const double lc = r.loss_and_gradient(1.f, {1, 1, 1, 1});
    const double lr = ref_loss(plan, cp, target, b);
    CHECK(lr > 0);
    CHECK(lc == doctest::Approx(lr).epsilon(1e-4));
    const std::vector<float> g = r.read_cp_gradient();
    double ab = 0, aa = 0, bb = 0, dd = 0;
    const double h = 1e-5;
    std::vector<double> c = cp;
    for (size_t i = 0; i < n; ++i) {
      const double keep = c[i];
      c[i] = keep + h;
      const double up = ref_loss(plan, c, target, b);
      c[i] = keep - h;
      const double fd = (up - ref_loss(plan, c, target, b)) / (2 * h);
      c[i] = keep;
      ab += g[i] * fd, aa += double{g[i]} * g[i], bb += fd * fd, dd += (g[i] - fd) * (g[i] - fd);
    }
    const double cosine = ab / std::sqrt(aa * bb), rel = std::sqrt(dd / bb);
    MESSAGE("sigma " << b.sigma << " / " << b.chroma_sigma << " weight " << b.chroma_weight << ": cosine " << cosine
                     << ", relative error " << rel);
    CHECK(cosine > 0.99999);
    CHECK(rel < 1e-3);
  }
  // Every one of those blurs ran on the one matched program (this width's; built here, or
  // by an earlier test of this runtime): with the taps compiled in, each was a build.
  CHECK(rt.programs_built_from_source() + rt.programs_loaded_from_cache() - programs_before <= 1);
}

}  // TEST_SUITE
