// The displacement field (kernels/field.cl, plan_fit's field tables): the quadratic B-spline
// weights reproduce constants and linear functions, the plan's two CSR directions agree, the
// forward kernel matches the host evaluation, and the backward kernel is its exact transpose
// (the adjoint identity <W c, g> = <c, Wᵀ g>, which is the finite-difference check of a linear
// map).
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "fit/plan/fit_plan.h"
#include "opencl/runtime.h"
#include "raster_test_support.h"
#include "scene_builders.h"

using namespace svgm;
using namespace svgm::test;

namespace {

// Two groups: a thin ribbon-like bar and a small dot, plus a wide bent shape.
Scene field_scene() {
  Path bar = filled(polygon({{10, 10}, {70, 12}, {70, 13.5}, {10, 11.5}}), {0.1f, 0.2f, 0.8f, 1});
  Path dot = filled(circle({30, 40}, 1.5), {0.8f, 0.1f, 0.1f, 1});
  Path blob = filled(circle({60, 60}, 18), {0.1f, 0.7f, 0.2f, 1});
  Scene s = scene_of(96, 96, {bar, dot, blob});
  s.groups = {{"bar", {0}}, {"rest", {1, 2}}};
  s.paths[0].group = 0;
  s.paths[1].group = 1;
  s.paths[2].group = 1;
  return s;
}

struct FieldSetup {
  RasterPlan raster;
  FitPlan plan;
  explicit FieldSetup(double spacing) {
    const Scene s = field_scene();
    raster = plan_raster(s, Affine{}, 96, 96);
    FitPlanOptions o;
    o.field_spacing_px = spacing;
    plan = plan_fit(s, raster, o);
  }
};

}  // namespace

TEST_SUITE("fit") {

TEST_CASE("quadratic B-spline weights: partition of unity and linear precision") {
  for (double u : {-0.49, 0.0, 0.3, 0.5, 0.51, 1.7, 2.25, 7.499}) {
    int j0;
    double w[3];
    quadratic_bspline_weights(u, &j0, w);
    CAPTURE(u);
    CHECK(w[0] + w[1] + w[2] == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(w[0] * j0 + w[1] * (j0 + 1) + w[2] * (j0 + 2) == doctest::Approx(u).epsilon(1e-12));
    for (double x : w) CHECK(x >= 0.0);
  }
}

TEST_CASE("field plan: every owned point has 9 weights summing to 1, both CSR directions agree") {
  const FieldSetup f(8.0);
  REQUIRE(f.plan.n_nodes > 0);
  REQUIRE(f.plan.node_pos.size() == 2u * f.plan.n_nodes);
  double total_fwd = 0, total_back = 0;
  for (int i = 0; i < f.plan.n_cp; ++i) {
    const int n = f.plan.cp_node_first[i + 1] - f.plan.cp_node_first[i];
    if (f.plan.cp_group[i] < 0 || f.plan.cp_offset[i] != i) {
      CHECK(n == 0);
      continue;
    }
    CHECK(n == 9);
    double sum = 0;
    for (int e = f.plan.cp_node_first[i]; e < f.plan.cp_node_first[i + 1]; ++e) sum += f.plan.cp_node_w[e];
    CHECK(sum == doctest::Approx(1.0).epsilon(1e-6));
    total_fwd += sum;
  }
  for (float w : f.plan.node_cp_w) total_back += w;
  CHECK(total_back == doctest::Approx(total_fwd).epsilon(1e-6));
  // Nodes belong to one group: the bar's and the dot's points never share a node.
  for (int b = 0; b < f.plan.n_nodes; ++b) {
    const int g = f.plan.cp_group[f.plan.node_cp[f.plan.node_cp_first[b]]];
    for (int e = f.plan.node_cp_first[b]; e < f.plan.node_cp_first[b + 1]; ++e)
      CHECK(f.plan.cp_group[f.plan.node_cp[e]] == g);
  }
  // Without a spacing there is no field.
  const FieldSetup none(0.0);
  CHECK(none.plan.n_nodes == 0);
  CHECK(none.plan.cp_node.empty());
}

TEST_CASE("field kernels: an affine field is reproduced exactly, backward is the transpose") {
  const FieldSetup f(8.0);
  const FitPlan& p = f.plan;
  const int K = 2, n_cp = p.n_cp, nn = p.n_nodes;
  ClRuntime& rt = runtime();
  cl::Program& prog = rt.program({"field.cl"}, "");
  cl::Kernel fwd(prog, "field_forward"), back(prog, "field_backward");
  auto& ctx = rt.context();
  auto buf = [&](auto& v) {
    using T = typename std::decay_t<decltype(v)>::value_type;
    return cl::Buffer(ctx, CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, std::max<size_t>(v.size() * sizeof(T), 16),
                      v.data());
  };
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> U(-1.f, 1.f);

  // Keyframe 0: coefficients of an affine map A x + t at the knots; free offsets zero.
  // Keyframe 1: random coefficients and random free offsets.
  const double A[4] = {0.03, -0.02, 0.05, 0.01}, t[2] = {1.5, -0.7};
  std::vector<float> coef(static_cast<size_t>(K) * nn * 2), free(static_cast<size_t>(K) * n_cp * 2, 0.f);
  for (int b = 0; b < nn; ++b) {
    const double x = p.node_pos[2 * b], y = p.node_pos[2 * b + 1];
    coef[2 * b] = static_cast<float>(A[0] * x + A[1] * y + t[0]);
    coef[2 * b + 1] = static_cast<float>(A[2] * x + A[3] * y + t[1]);
  }
  for (size_t j = 2u * nn; j < coef.size(); ++j) coef[j] = U(rng);
  for (size_t j = 2u * n_cp; j < free.size(); ++j) free[j] = U(rng);
  std::vector<float> out(free.size(), 0.f);
  auto cp_first = p.cp_node_first;
  auto cp_node = p.cp_node;
  auto cp_w = p.cp_node_w;
  auto node_first = p.node_cp_first;
  auto node_cp = p.node_cp;
  auto node_w = p.node_cp_w;
  cl::Buffer free_b = buf(free), coef_b = buf(coef), out_b = buf(out), cpf = buf(cp_first), cpn = buf(cp_node),
             cpw = buf(cp_w), nf = buf(node_first), ncp = buf(node_cp), nw = buf(node_w);
  set_args(fwd, free_b, coef_b, cpf, cpn, cpw, out_b, n_cp, nn);
  rt.queue().enqueueNDRangeKernel(fwd, cl::NullRange, cl::NDRange(n_cp, K));
  rt.queue().enqueueReadBuffer(out_b, CL_TRUE, 0, out.size() * sizeof(float), out.data());
  for (int i = 0; i < n_cp; ++i) {
    if (p.cp_group[i] < 0 || p.cp_offset[i] != i) continue;
    const double x = f.raster.rest_cp[2 * i], y = f.raster.rest_cp[2 * i + 1];
    CAPTURE(i);
    CHECK(out[2 * i] == doctest::Approx(A[0] * x + A[1] * y + t[0]).epsilon(1e-4));
    CHECK(out[2 * i + 1] == doctest::Approx(A[2] * x + A[3] * y + t[1]).epsilon(1e-4));
  }
  // Keyframe 1 against the host evaluation of the same sums.
  for (int i = 0; i < n_cp; ++i) {
    double dx = free[2 * (n_cp + i)], dy = free[2 * (n_cp + i) + 1];
    for (int e = p.cp_node_first[i]; e < p.cp_node_first[i + 1]; ++e) {
      dx += p.cp_node_w[e] * coef[2 * (nn + p.cp_node[e])];
      dy += p.cp_node_w[e] * coef[2 * (nn + p.cp_node[e]) + 1];
    }
    CHECK(out[2 * (n_cp + i)] == doctest::Approx(dx).epsilon(1e-5));
    CHECK(out[2 * (n_cp + i) + 1] == doctest::Approx(dy).epsilon(1e-5));
  }

  // Adjoint: with zero free offsets, <W c, g> must equal <c, Wᵀ g> for random c and g.
  std::vector<float> zero(free.size(), 0.f), g(free.size()), gc(coef.size(), 0.f);
  for (auto& x : coef) x = U(rng);
  for (int i = 0; i < n_cp; ++i)  // points without weights get no gradient from the field
    for (int k = 0; k < K; ++k) {
      g[2 * (k * n_cp + i)] = U(rng);
      g[2 * (k * n_cp + i) + 1] = U(rng);
    }
  cl::Buffer zb = buf(zero), cb = buf(coef), gb = buf(g), gcb = buf(gc);
  set_args(fwd, zb, cb, cpf, cpn, cpw, out_b, n_cp, nn);
  rt.queue().enqueueNDRangeKernel(fwd, cl::NullRange, cl::NDRange(n_cp, K));
  set_args(back, gb, nf, ncp, nw, gcb, n_cp, nn);
  rt.queue().enqueueNDRangeKernel(back, cl::NullRange, cl::NDRange(nn, K));
  rt.queue().enqueueReadBuffer(out_b, CL_TRUE, 0, out.size() * sizeof(float), out.data());
  rt.queue().enqueueReadBuffer(gcb, CL_TRUE, 0, gc.size() * sizeof(float), gc.data());
  double lhs = 0, rhs = 0, scale = 0;
  for (size_t j = 0; j < out.size(); ++j) {
    lhs += double(out[j]) * g[j];
    scale += std::abs(double(out[j]) * g[j]);
  }
  for (size_t j = 0; j < gc.size(); ++j) rhs += double(coef[j]) * gc[j];
  MESSAGE("<Wc, g> = " << lhs << ", <c, W'g> = " << rhs);
  CHECK(std::abs(lhs - rhs) < 1e-5 * scale);
  CHECK(scale > 1.0);  // the check is not vacuous
}

}  // TEST_SUITE
