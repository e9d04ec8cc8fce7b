// The cohesion regulariser (kernels/regularise.cl) and its pairs (plan_fit): the pairs are
// symmetric and join points of different paths that touch at rest, the kernel's value is
// zero at rest and under a rotation, and its gradient matches central finite differences of
// its own value on the real OpenCL kernel.
#include <doctest/doctest.h>

#include <cmath>
#include <numeric>
#include <random>

#include "fit/plan/fit_plan.h"
#include "opencl/runtime.h"
#include "raster_test_support.h"
#include "scene_builders.h"

using namespace svgm;
using namespace svgm::test;

namespace {

// A thin ribbon (1.5 px) lying on a body, and a small dot on the body: three groups.
struct CohesionSetup {
  RasterPlan raster;
  FitPlan plan;
  CohesionSetup() {
    Path body = filled(polygon({{10, 10}, {60, 10}, {60, 50}, {10, 50}}), {0.9f, 0.1f, 0.1f, 1});
    Path ribbon = filled(polygon({{12, 20}, {58, 20}, {58, 21.5}, {12, 21.5}}), {0.1f, 0.1f, 0.1f, 1});
    Path dot = filled(circle({30, 40}, 1.2), {1, 1, 1, 1});
    Scene s = scene_of(64, 64, {body, ribbon, dot});
    s.groups = {{"body", {0}}, {"ribbon", {1}}, {"dot", {2}}};
    for (int i = 0; i < 3; ++i) s.paths[i].group = i;
    raster = plan_raster(s, Affine{}, 64, 64);
    FitPlanOptions o;
    o.cohesion_radius_px = 4;
    plan = plan_fit(s, raster, o);
  }
};

// Runs the cohesion kernel on one frame of points; returns the loss, fills the gradient.
double run_cohesion(const FitPlan& p, const std::vector<float>& cp, float scale, std::vector<float>* grad) {
  ClRuntime& rt = runtime();
  cl::Program& prog = rt.program({"regularise.cl"}, "");
  cl::Kernel k(prog, "cohesion");
  auto& ctx = rt.context();
  auto buf = [&](auto v) {
    using T = typename decltype(v)::value_type;
    return cl::Buffer(ctx, CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, std::max<size_t>(v.size() * sizeof(T), 16),
                      v.data());
  };
  const int n = p.n_cp;
  std::vector<float> g(2 * n, 0.f), part(n, 0.f);
  cl::Buffer cpb = buf(cp), fb = buf(p.coh_first), nb = buf(p.coh_nbr), lb = buf(p.coh_len), gb = buf(g),
             pb = buf(part);
  set_args(k, cpb, fb, nb, lb, gb, pb, scale, n);
  rt.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n, 1));
  rt.queue().enqueueReadBuffer(pb, CL_TRUE, 0, part.size() * sizeof(float), part.data());
  if (grad) {
    grad->resize(2 * n);
    rt.queue().enqueueReadBuffer(gb, CL_TRUE, 0, grad->size() * sizeof(float), grad->data());
  }
  return std::accumulate(part.begin(), part.end(), 0.0);
}

}  // namespace

TEST_SUITE("fit") {

TEST_CASE("cohesion pairs: symmetric, within the radius, across paths") {
  const CohesionSetup s;
  const FitPlan& p = s.plan;
  REQUIRE(p.n_coh_pairs > 0);
  CHECK(static_cast<int>(p.coh_nbr.size()) == 2 * p.n_coh_pairs);
  int across = 0;
  for (int i = 0; i < p.n_cp; ++i)
    for (int e = p.coh_first[i]; e < p.coh_first[i + 1]; ++e) {
      const int j = p.coh_nbr[e];
      CHECK(p.coh_len[e] < 4.0f);
      CHECK(p.coh_len[e] > 0.0f);
      CHECK(p.cp_offset[i] == i);
      CHECK(p.cp_offset[j] == j);
      bool back = false;  // j lists i with the same length
      for (int f = p.coh_first[j]; f < p.coh_first[j + 1]; ++f) back |= p.coh_nbr[f] == i && p.coh_len[f] == p.coh_len[e];
      CHECK(back);
      across += p.cp_group[i] != p.cp_group[j];
    }
  CHECK(across > 0);  // the ribbon and the dot are tied to the body under them
  // Both sides of the 1.5 px ribbon are paired with each other.
  const int r0 = s.raster.path_cp_first[1], rn = s.raster.path_cp_count[1];
  bool sides = false;
  for (int i = r0; i < r0 + rn; ++i)
    for (int e = p.coh_first[i]; e < p.coh_first[i + 1]; ++e) {
      const int j = p.coh_nbr[e];
      if (j >= r0 && j < r0 + rn && std::abs(s.raster.rest_cp[2 * i + 1] - s.raster.rest_cp[2 * j + 1]) > 1.0f)
        sides = true;
    }
  CHECK(sides);
}

TEST_CASE("cohesion kernel: zero at rest and under a rotation, gradient matches finite differences") {
  const CohesionSetup s;
  const FitPlan& p = s.plan;
  const std::vector<float> rest = s.raster.rest_cp;
  std::vector<float> g;
  CHECK(run_cohesion(p, rest, 1.f, &g) == doctest::Approx(0.0).epsilon(1e-9));
  std::vector<float> rot(rest.size());
  const double a = 0.3;
  for (size_t i = 0; i < rest.size(); i += 2) {
    rot[i] = static_cast<float>(std::cos(a) * rest[i] - std::sin(a) * rest[i + 1] + 3);
    rot[i + 1] = static_cast<float>(std::sin(a) * rest[i] + std::cos(a) * rest[i + 1] - 2);
  }
  CHECK(run_cohesion(p, rot, 1.f, nullptr) < 1e-6 * p.n_coh_pairs);

  // A random deformation: analytic gradient against central differences of the loss.
  std::mt19937 rng(3);
  std::normal_distribution<float> N(0.f, 0.4f);
  std::vector<float> x = rest;
  for (auto& v : x) v += N(rng);
  const float scale = 0.7f;
  const double l0 = run_cohesion(p, x, scale, &g);
  CHECK(l0 > 0.01);
  const double h = 1e-2;
  int checked = 0;
  double worst = 0;
  for (int i = 0; i < p.n_cp; ++i) {
    if (p.coh_first[i + 1] == p.coh_first[i]) continue;
    for (int c = 0; c < 2; ++c) {
      std::vector<float> xp = x, xm = x;
      xp[2 * i + c] += static_cast<float>(h);
      xm[2 * i + c] -= static_cast<float>(h);
      const double fd = (run_cohesion(p, xp, scale, nullptr) - run_cohesion(p, xm, scale, nullptr)) / (2 * h);
      CAPTURE(i);
      CAPTURE(c);
      CHECK(g[2 * i + c] == doctest::Approx(fd).epsilon(2e-2).scale(1e-3));
      worst = std::max(worst, std::abs(g[2 * i + c] - fd));
      ++checked;
    }
  }
  MESSAGE("cohesion: " << checked << " gradient entries checked, worst |analytic - fd| " << worst);
  CHECK(checked > 20);
}

}  // TEST_SUITE
