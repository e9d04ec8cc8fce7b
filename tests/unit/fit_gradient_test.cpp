// Finite-difference checks of the fitter's own kernels, run on the real OpenCL programs:
// the displacement field and the motion model backward (homography parameters with their
// learned centre, field coefficients, free offsets; kernels/field.cl, motion.cl), each
// regulariser's value and gradient (kernels/regularise.cl), and one Adam step (adam.cl).
//
// The oracle is a double-precision host evaluation of the same maths (fit/optimise/motion_model.h's
// apply_motion for the motion, the essays' formulas for the regularisers) differentiated by
// central differences. Tolerances: the kernels are float32 (ε = 6e-8); each gradient term is
// a chain of a few dozen flops and the sums run over at most a few hundred terms, so their
// relative error stays near 1e-6 (measured on PoCL: at most 3e-7). The checks allow 1e-5 of
// the gradient's norm (per parameter kind) and of its largest component per component: ten
// times that, while a wrong term (a sign, a missing factor, a wrong index) is an error of
// order one and even a dropped perspective correction (px ~ 0.05) one of 1e-3.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>
#include <random>
#include <string>

#include "fit/plan/fit_plan.h"
#include "fit/optimise/motion_model.h"
#include "opencl/tuning.h"
#include "raster_test_support.h"
#include "scene_builders.h"

using namespace svgm;
using namespace svgm::test;

namespace {

constexpr int kParams = 12;     // MOTION_PARAMS in kernels/motion.cl
constexpr double kTol = 1e-5;   // relative bound of every check below (see the header)
constexpr int kW = 96, kH = 96;

// Two groups: a curved blob (smooth joints for G1) with a thin bar, and a dot with a
// triangle; the dot and the bar sit close to others (cohesion pairs across paths).
Scene gradient_scene() {
  Path blob = filled(circle({40, 44}, 16), {0.1f, 0.7f, 0.2f, 1});
  Path bar = filled(polygon({{20, 20}, {70, 22}, {70, 24.5}, {20, 22.5}}), {0.1f, 0.2f, 0.8f, 1});
  Path dot = filled(circle({58, 62}, 2.5), {0.8f, 0.1f, 0.1f, 1});
  Path tri = filled(polygon({{55, 66}, {80, 70}, {62, 85}}), {0.5f, 0.5f, 0.1f, 1});
  Scene s = scene_of(kW, kH, {blob, bar, dot, tri});
  s.groups = {{"body", {0, 1}}, {"rest", {2, 3}}};
  s.paths[0].group = s.paths[1].group = 0;
  s.paths[2].group = s.paths[3].group = 1;
  return s;
}

struct Setup {
  RasterPlan raster;
  FitPlan plan;
  ClRuntime& rt = runtime();
  cl::Program* prog = nullptr;
  Setup() {
    const Scene s = gradient_scene();
    raster = plan_raster(s, Affine{}, kW, kH);
    FitPlanOptions o;
    o.field_spacing_px = 12;
    o.cohesion_radius_px = 6;
    plan = plan_fit(s, raster, o);
    // The fitter's program and options (engine/src/fit/optimise/fitter.cpp).
    prog = &rt.program({"field.cl", "motion.cl", "regularise.cl", "adam.cl"},
                       kernel_build_options(raster_tuning(rt.info(), kW)));
  }
  template <class T>
  cl::Buffer buf(const std::vector<T>& v) {
    // At least 16 bytes, copied from a host copy that long (ASan: a 4-byte vector was read for 16).
    std::vector<T> host(v);
    host.resize(std::max(v.size(), (16 + sizeof(T) - 1) / sizeof(T)));
    return cl::Buffer(rt.context(), CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, host.size() * sizeof(T), host.data());
  }
  template <class T>
  void read(const cl::Buffer& b, std::vector<T>& v) {
    rt.queue().enqueueReadBuffer(b, CL_TRUE, 0, v.size() * sizeof(T), v.data());
  }
  void run(cl::Kernel& k, size_t n, size_t frames) {
    rt.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n, frames));
  }
};

// Central differences of f over the entries `which` of x (step h).
std::vector<double> central_fd(const std::function<double(const std::vector<double>&)>& f,
                               std::vector<double> x, const std::vector<size_t>& which, double h) {
  std::vector<double> g(which.size());
  for (size_t n = 0; n < which.size(); ++n) {
    const size_t i = which[n];
    const double keep = x[i];
    x[i] = keep + h;
    const double up = f(x);
    x[i] = keep - h;
    const double down = f(x);
    x[i] = keep;
    g[n] = (up - down) / (2 * h);
  }
  return g;
}

// Kernel gradient an[which[n]] against fd[n]: norm-relative and per-component bounds.
void check_gradient(const std::string& what, const std::vector<double>& an, const std::vector<double>& fd) {
  REQUIRE(an.size() == fd.size());
  double dd = 0, ff = 0, fmax = 0, emax = 0;
  for (size_t i = 0; i < fd.size(); ++i) {
    dd += (an[i] - fd[i]) * (an[i] - fd[i]);
    ff += fd[i] * fd[i];
    fmax = std::max(fmax, std::abs(fd[i]));
    emax = std::max(emax, std::abs(an[i] - fd[i]));
  }
  const double rel = std::sqrt(dd / ff);
  CAPTURE(what);
  MESSAGE(what << ": " << fd.size() << " entries, |fd| " << std::sqrt(ff) << ", relative error "
               << rel << ", worst component " << emax / fmax << " of the largest");
  CHECK(ff > 1e-6);  // not vacuous
  CHECK(rel < kTol);
  CHECK(emax <= kTol * fmax);
}

template <class T>
std::vector<double> to_double(const std::vector<T>& v) {
  return std::vector<double>(v.begin(), v.end());
}

}  // namespace

TEST_SUITE("fit") {

TEST_CASE("motion and field backward match finite differences of the host motion model") {
  Setup s;
  const FitPlan& p = s.plan;
  const int K = 2, n_cp = p.n_cp, G = p.n_groups, nn = p.n_nodes;
  REQUIRE(G == 2);
  REQUIRE(nn > 0);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(-1, 1);
  // Parameters near the identity but exercising every one, the centre included.
  std::vector<float> params(static_cast<size_t>(K) * G * kParams, 0.f);
  for (int kg = 0; kg < K * G; ++kg) {
    float* th = &params[static_cast<size_t>(kg) * kParams];
    const double v[11] = {0.1 * U(rng), 0.1 * U(rng), 0.3 * U(rng), 1 + 0.2 * U(rng), 1 + 0.2 * U(rng),
                          0.1 * U(rng), 0.1 * U(rng), 0.05 * U(rng), 0.05 * U(rng), 0.3 * U(rng),
                          0.3 * U(rng)};
    for (int j = 0; j < 11; ++j) th[j] = static_cast<float>(v[j]);
  }
  std::vector<float> free(static_cast<size_t>(K) * n_cp * 2), coef(static_cast<size_t>(K) * nn * 2),
      gcp(static_cast<size_t>(K) * n_cp * 2, 0.f);
  for (auto& x : free) x = static_cast<float>(U(rng));
  for (auto& x : coef) x = static_cast<float>(2 * U(rng));
  for (int k = 0; k < K; ++k)
    for (int i = 0; i < n_cp; ++i)
      if (p.cp_group[i] >= 0)
        for (int c = 0; c < 2; ++c) gcp[2 * (static_cast<size_t>(k) * n_cp + i) + c] = static_cast<float>(U(rng));
  std::vector<float> rest(s.raster.rest_cp.begin(), s.raster.rest_cp.end());

  const Vec2 origin{0.5 * kW, 0.5 * kH};
  const double scale = 0.5 * kW;
  // J = Σ ∂L/∂x̂ · x̂ over the points of every keyframe, in double: its gradient is what the
  // backward kernels return for the upstream gradient gcp.
  auto offsets_of = [&](const std::vector<double>& fr, const std::vector<double>& cf, int k, int j) {
    Vec2 d{fr[2 * (static_cast<size_t>(k) * n_cp + j)], fr[2 * (static_cast<size_t>(k) * n_cp + j) + 1]};
    for (int e = p.cp_node_first[j]; e < p.cp_node_first[j + 1]; ++e) {
      const size_t b = 2 * (static_cast<size_t>(k) * nn + p.cp_node[e]);
      d = d + Vec2{p.cp_node_w[e] * cf[b], p.cp_node_w[e] * cf[b + 1]};
    }
    return d;
  };
  auto points = [&](const std::vector<double>& th, const std::vector<double>& fr,
                    const std::vector<double>& cf, int k, int i) {
    MotionParams m{};
    const size_t at = (static_cast<size_t>(k) * G + p.cp_group[i]) * kParams;
    for (int j = 0; j < kParams; ++j) m[j] = th[at + j];
    const Vec2 r{s.raster.rest_cp[2 * i], s.raster.rest_cp[2 * i + 1]};
    return apply_motion(m, r + offsets_of(fr, cf, k, p.cp_offset[i]), origin, scale);
  };
  const auto th0 = to_double(params), fr0 = to_double(free), cf0 = to_double(coef);
  auto J = [&](const std::vector<double>& th, const std::vector<double>& fr, const std::vector<double>& cf) {
    double sum = 0;
    for (int k = 0; k < K; ++k)
      for (int i = 0; i < n_cp; ++i) {
        if (p.cp_group[i] < 0) continue;
        const Vec2 x = points(th, fr, cf, k, i);
        const size_t at = 2 * (static_cast<size_t>(k) * n_cp + i);
        sum += gcp[at] * x.x + gcp[at + 1] * x.y;
      }
    return sum;
  };

  // The kernels, chained as in Fitter::fit_iteration.
  auto cp_first = p.cp_node_first, cp_node = p.cp_node, node_first = p.node_cp_first,
       node_cp = p.node_cp, group_first = p.group_first, group_cps = p.group_cps,
       cp_group = p.cp_group, cp_offset = p.cp_offset;
  auto cp_w = p.cp_node_w, node_w = p.node_cp_w;
  std::vector<float> total(free.size(), 0.f), cp(free.size(), 0.f), gparams(params.size(), 0.f),
      goff(free.size(), 0.f), gcoef(coef.size(), 0.f);
  cl::Buffer b_params = s.buf(params), b_free = s.buf(free), b_coef = s.buf(coef), b_total = s.buf(total),
             b_rest = s.buf(rest), b_cpg = s.buf(cp_group), b_cpo = s.buf(cp_offset), b_cp = s.buf(cp),
             b_gf = s.buf(group_first), b_gc = s.buf(group_cps), b_gcp = s.buf(gcp),
             b_gparams = s.buf(gparams), b_goff = s.buf(goff), b_gcoef = s.buf(gcoef),
             b_cpf = s.buf(cp_first), b_cpn = s.buf(cp_node), b_cpw = s.buf(cp_w),
             b_nf = s.buf(node_first), b_ncp = s.buf(node_cp), b_nw = s.buf(node_w);
  const cl_float2 o{{static_cast<float>(origin.x), static_cast<float>(origin.y)}};
  const float sc = static_cast<float>(scale);
  cl::Kernel field(*s.prog, "field_forward"), motion(*s.prog, "motion_forward"),
      motion_back(*s.prog, "motion_backward"), field_back(*s.prog, "field_backward");
  set_args(field, b_free, b_coef, b_cpf, b_cpn, b_cpw, b_total, n_cp, nn);
  set_args(motion, b_params, b_total, b_rest, b_cpg, b_cpo, b_cp, o, sc, n_cp, G);
  set_args(motion_back, b_params, b_total, b_rest, b_cpo, b_gf, b_gc, b_gcp, b_gparams, b_goff, o, sc, n_cp, G);
  set_args(field_back, b_goff, b_nf, b_ncp, b_nw, b_gcoef, n_cp, nn);
  s.run(field, n_cp, K);
  s.run(motion, n_cp, K);
  s.run(motion_back, G, K);
  s.run(field_back, nn, K);
  s.read(b_cp, cp);
  s.read(b_gparams, gparams);
  s.read(b_goff, goff);
  s.read(b_gcoef, gcoef);

  // The forward kernels agree with the host model (the gradient checks below are about the
  // same function).
  double worst = 0;
  for (int k = 0; k < K; ++k)
    for (int i = 0; i < n_cp; ++i)
      if (p.cp_group[i] >= 0) {
        const Vec2 x = points(th0, fr0, cf0, k, i);
        const size_t at = 2 * (static_cast<size_t>(k) * n_cp + i);
        worst = std::max({worst, std::abs(cp[at] - x.x), std::abs(cp[at + 1] - x.y)});
      }
  MESSAGE("forward: worst |x_cl - x_ref| " << worst << " px");
  CHECK(worst < 1e-3);

  // Homography parameters (11 per group and keyframe; the padding slot stays 0).
  std::vector<size_t> which;
  std::vector<double> an;
  for (size_t i = 0; i < params.size(); ++i) {
    if (i % kParams == 11) {
      CHECK(gparams[i] == 0.f);
      continue;
    }
    which.push_back(i);
    an.push_back(gparams[i]);
  }
  check_gradient("homography parameters",
                 an, central_fd([&](const std::vector<double>& th) { return J(th, fr0, cf0); }, th0, which, 1e-6));
  // The learned centre alone (it enters twice, with opposite signs).
  {
    std::vector<size_t> w;
    std::vector<double> a;
    for (size_t i = 0; i < params.size(); ++i)
      if (i % kParams == 9 || i % kParams == 10) {
        w.push_back(i);
        a.push_back(gparams[i]);
      }
    check_gradient("learned centre",
                   a, central_fd([&](const std::vector<double>& th) { return J(th, fr0, cf0); }, th0, w, 1e-6));
  }
  // Free offsets: the slots points own (a closed subpath's closing copy adds into its first
  // point's slot); the other slots get exactly zero.
  which.clear();
  an.clear();
  for (int k = 0; k < K; ++k)
    for (int i = 0; i < n_cp; ++i) {
      const size_t at = 2 * (static_cast<size_t>(k) * n_cp + i);
      if (p.cp_group[i] >= 0 && p.cp_offset[i] == i) {
        for (int c = 0; c < 2; ++c) {
          which.push_back(at + c);
          an.push_back(goff[at + c]);
        }
      } else {
        CHECK(goff[at] == 0.f);
        CHECK(goff[at + 1] == 0.f);
      }
    }
  check_gradient("free offsets",
                 an, central_fd([&](const std::vector<double>& fr) { return J(th0, fr, cf0); }, fr0, which, 1e-5));
  // Field coefficients.
  which.clear();
  for (size_t i = 0; i < coef.size(); ++i) which.push_back(i);
  check_gradient("field coefficients", to_double(gcoef),
                 central_fd([&](const std::vector<double>& cf) { return J(th0, fr0, cf); }, cf0, which, 1e-5));
}

TEST_CASE("regularisers: kernel values match the host formulas and gradients match their finite differences") {
  Setup s;
  const FitPlan& p = s.plan;
  const int K = 2, n_cp = p.n_cp, nj = p.n_joints();
  REQUIRE(p.n_pairs > 0);
  REQUIRE(nj > 0);
  REQUIRE(p.n_coh_pairs > 0);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(-1, 1);
  const float kScale = 0.37f, kMargin = 1.0f;
  // The regularisers add into gradient buffers the image loss has written: start from a known
  // base and subtract it.
  const float kBase = 0.015625f;  // 2^-6: exact, and small enough to cost no precision
  std::vector<float> cp(static_cast<size_t>(K) * n_cp * 2, 0.f), offs(cp.size());
  for (int k = 0; k < K; ++k)
    for (int i = 0; i < n_cp; ++i)
      for (int c = 0; c < 2; ++c) {
        const size_t at = 2 * (static_cast<size_t>(k) * n_cp + i) + c;
        cp[at] = p.cp_group[i] >= 0 ? static_cast<float>(s.raster.rest_cp[2 * i + c] + 0.8 * U(rng)) : 0.f;
        offs[at] = static_cast<float>(1.5 * U(rng));
      }
  const auto cp0 = to_double(cp), offs0 = to_double(offs);
  std::vector<size_t> all(cp.size());
  for (size_t i = 0; i < all.size(); ++i) all[i] = i;
  auto sum = [](const std::vector<float>& v) {
    double t = 0;
    for (float x : v) t += x;
    return t;
  };
  // Kernel gradient minus the base, at the entries `which`.
  auto added = [&](const std::vector<float>& g, const std::vector<size_t>& which) {
    std::vector<double> out;
    for (size_t i : which) out.push_back(static_cast<double>(g[i]) - kBase);
    return out;
  };
  auto nbr_first = p.nbr_first, nbr = p.nbr, coh_first = p.coh_first, coh_nbr = p.coh_nbr,
       joints = p.joints, cp_group = p.cp_group;
  auto nbr_w = p.nbr_w, coh_len = p.coh_len;

  SUBCASE("smoothness") {
    // Σ_pairs w ‖Δ_i − Δ_j‖², pairs from the symmetric lists, each once.
    auto ref = [&](const std::vector<double>& d) {
      double l = 0;
      for (int k = 0; k < K; ++k)
        for (int i = 0; i < n_cp; ++i)
          for (int e = p.nbr_first[i]; e < p.nbr_first[i + 1]; ++e) {
            const int j = p.nbr[e];
            if (j <= i) continue;
            const size_t a = 2 * (static_cast<size_t>(k) * n_cp + i), b = 2 * (static_cast<size_t>(k) * n_cp + j);
            const double dx = d[a] - d[b], dy = d[a + 1] - d[b + 1];
            l += p.nbr_w[e] * (dx * dx + dy * dy);
          }
      return kScale * l;
    };
    std::vector<float> g(cp.size(), kBase), part(static_cast<size_t>(K) * n_cp, 0.f);
    cl::Buffer bo = s.buf(offs), bf = s.buf(nbr_first), bn = s.buf(nbr), bw = s.buf(nbr_w), bg = s.buf(g),
               bp = s.buf(part);
    cl::Kernel k(*s.prog, "smoothness");
    set_args(k, bo, bf, bn, bw, bg, bp, kScale, n_cp);
    s.run(k, n_cp, K);
    s.read(bg, g);
    s.read(bp, part);
    CHECK(sum(part) == doctest::Approx(ref(offs0)).epsilon(1e-5));
    CHECK(ref(offs0) > 0);
    check_gradient("smoothness", added(g, all), central_fd(ref, offs0, all, 1e-5));
  }

  SUBCASE("G1 continuity") {
    auto ref = [&](const std::vector<double>& x) {
      double l = 0;
      for (int k = 0; k < K; ++k)
        for (int j = 0; j < nj; ++j) {
          auto P = [&](int i) {
            const size_t a = 2 * (static_cast<size_t>(k) * n_cp + i);
            return Vec2{x[a], x[a + 1]};
          };
          const Vec2 a = P(p.joints[4 * j + 1]) - P(p.joints[4 * j]);
          const Vec2 b = P(p.joints[4 * j + 2]) - P(p.joints[4 * j + 1]);
          l += 1 - (a.x * b.x + a.y * b.y) / (std::hypot(a.x, a.y) * std::hypot(b.x, b.y));
        }
      return kScale * l;
    };
    std::vector<float> g(cp.size(), kBase), part(static_cast<size_t>(K) * nj, 0.f);
    cl::Buffer bc = s.buf(cp), bj = s.buf(joints), bg = s.buf(g), bp = s.buf(part);
    cl::Kernel k(*s.prog, "g1_continuity");
    set_args(k, bc, bj, bg, bp, kScale, n_cp, nj);
    s.run(k, nj, K);
    s.read(bg, g);
    s.read(bp, part);
    CHECK(sum(part) == doctest::Approx(ref(cp0)).epsilon(1e-4));
    CHECK(ref(cp0) > 0);
    check_gradient("G1 continuity", added(g, all), central_fd(ref, cp0, all, 1e-5));
  }

  SUBCASE("containment") {
    // A distance-like field: positive away from a disc, with ripples so the bilinear cells
    // differ; points scattered over the canvas and a few beyond it (clamped axes, and the
    // distance beyond the canvas added).
    std::vector<float> sdf(static_cast<size_t>(K) * kW * kH);
    for (int k = 0; k < K; ++k)
      for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x)
          sdf[(static_cast<size_t>(k) * kH + y) * kW + x] = static_cast<float>(
              std::hypot(x + 0.5 - 48 - 3 * k, y + 0.5 - 46) - 20 + 1.5 * std::sin(0.7 * x + 0.3 * y));
    std::vector<float> pts = cp;
    for (int k = 0; k < K; ++k)
      for (int i = 0; i < n_cp; ++i) {
        const size_t a = 2 * (static_cast<size_t>(k) * n_cp + i);
        if (p.cp_group[i] < 0) continue;
        pts[a] = static_cast<float>(kW * (0.5 + 0.56 * U(rng)));  // −5 .. 101
        pts[a + 1] = static_cast<float>(kH * (0.5 + 0.56 * U(rng)));
      }
    const auto pts0 = to_double(pts);
    // Margins per point (the fitter's are the margin plus each point's distance at rest).
    std::vector<float> margin(n_cp);
    for (int i = 0; i < n_cp; ++i) margin[i] = static_cast<float>(kMargin + 2 * (1 + U(rng)));
    auto ref = [&](const std::vector<double>& x) {
      double l = 0;
      for (int k = 0; k < K; ++k)
        for (int i = 0; i < n_cp; ++i) {
          if (p.cp_group[i] < 0) continue;
          const size_t a = 2 * (static_cast<size_t>(k) * n_cp + i);
          const double qx = std::clamp(x[a] - 0.5, 0.0, kW - 1.0), qy = std::clamp(x[a + 1] - 0.5, 0.0, kH - 1.0);
          const double beyond = std::hypot(x[a] - 0.5 - qx, x[a + 1] - 0.5 - qy);
          const int x0 = std::min(static_cast<int>(qx), kW - 2), y0 = std::min(static_cast<int>(qy), kH - 2);
          const double fx = qx - x0, fy = qy - y0;
          auto S = [&](int xx, int yy) { return double(sdf[(static_cast<size_t>(k) * kH + yy) * kW + xx]); };
          const double v = (1 - fy) * ((1 - fx) * S(x0, y0) + fx * S(x0 + 1, y0)) +
                           fy * ((1 - fx) * S(x0, y0 + 1) + fx * S(x0 + 1, y0 + 1)) + beyond;
          const double d = v - margin[i];
          if (d > 0) l += d * d;
        }
      return kScale * l;
    };
    std::vector<float> g(cp.size(), kBase), part(static_cast<size_t>(K) * n_cp, 0.f);
    cl::Buffer bc = s.buf(pts), bgr = s.buf(cp_group), bs = s.buf(sdf), bg = s.buf(g), bp = s.buf(part);
    cl::Buffer bm = s.buf(margin);
    cl::Kernel k(*s.prog, "containment");
    set_args(k, bc, bgr, bs, bg, bp, kScale, bm, n_cp, kW, kH);
    s.run(k, n_cp, K);
    s.read(bg, g);
    s.read(bp, part);
    CHECK(sum(part) == doctest::Approx(ref(pts0)).epsilon(1e-4));
    CHECK(ref(pts0) > 0);
    check_gradient("containment", added(g, all), central_fd(ref, pts0, all, 1e-5));
  }

  SUBCASE("cohesion") {
    auto ref = [&](const std::vector<double>& x) {
      double l = 0;
      for (int k = 0; k < K; ++k)
        for (int i = 0; i < n_cp; ++i)
          for (int e = p.coh_first[i]; e < p.coh_first[i + 1]; ++e) {
            const int j = p.coh_nbr[e];
            if (j <= i) continue;
            const size_t a = 2 * (static_cast<size_t>(k) * n_cp + i), b = 2 * (static_cast<size_t>(k) * n_cp + j);
            const double r = std::hypot(x[a] - x[b], x[a + 1] - x[b + 1]) - p.coh_len[e];
            l += r * r;
          }
      return kScale * l;
    };
    std::vector<float> g(cp.size(), kBase), part(static_cast<size_t>(K) * n_cp, 0.f);
    cl::Buffer bc = s.buf(cp), bf = s.buf(coh_first), bn = s.buf(coh_nbr), bl = s.buf(coh_len), bg = s.buf(g),
               bp = s.buf(part);
    cl::Kernel k(*s.prog, "cohesion");
    set_args(k, bc, bf, bn, bl, bg, bp, kScale, n_cp);
    s.run(k, n_cp, K);
    s.read(bg, g);
    s.read(bp, part);
    CHECK(sum(part) == doctest::Approx(ref(cp0)).epsilon(1e-4));
    CHECK(ref(cp0) > 0);
    check_gradient("cohesion", added(g, all), central_fd(ref, cp0, all, 1e-5));
  }
}

TEST_CASE("one Adam step matches the formula in double precision; inactive keyframes stay put") {
  Setup s;
  // 4 keyframes of 7 elements: keyframe 0 below `first`, keyframe 1 not active (t = 0),
  // keyframes 2 and 3 at steps 3 and 1 (bias correction far from and at its largest).
  const int per = 7, K = 4, first = 1;
  const float lr = 1e-3f, eps = 1e-6f;  // the paper's learning rate and epsilon
  // The paper's settings (β1 = β2 = 0.9), and distinct betas so that a swapped one shows.
  for (const auto& betas : {std::pair{0.9f, 0.9f}, std::pair{0.8f, 0.99f}}) {
    // Named copies: clang before 16 cannot capture structured bindings (CAPTURE is a lambda).
    const float b1 = betas.first, b2 = betas.second;
    CAPTURE(b1);
    CAPTURE(b2);
    std::vector<int> steps{5, 0, 3, 1};
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> U(-1, 1);
    std::vector<float> theta(K * per), grad(K * per), m(K * per), v(K * per);
    for (int i = 0; i < K * per; ++i) {
      theta[i] = static_cast<float>(2 * U(rng));
      grad[i] = static_cast<float>(i % 5 == 0 ? 1e-4 * U(rng) : 3 * U(rng));  // some tiny ones
      m[i] = static_cast<float>(0.5 * U(rng));
      v[i] = static_cast<float>(0.5 * (1 + U(rng)));
    }
    const auto theta0 = theta, m0 = m, v0 = v;
    // Each keyframe's bias-correction denominators (Fitter::upload_steps computes them in
    // float; rounded from double here, within the bounds below either way).
    std::vector<cl_float2> bias;
    for (int t : steps)
      bias.push_back(t > 0 ? cl_float2{{static_cast<float>(1 - std::pow(double(b1), t)),
                                        static_cast<float>(1 - std::pow(double(b2), t))}}
                           : cl_float2{{0, 0}});
    cl::Buffer bt = s.buf(theta), bg = s.buf(grad), bm = s.buf(m), bv = s.buf(v), bs = s.buf(bias);
    cl::Kernel k(*s.prog, "adam");
    set_args(k, bt, bg, bm, bv, bs, per, first, lr, b1, b2, eps, K * per);
    s.rt.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(round_up(K * per, 64)));
    s.read(bt, theta);
    s.read(bm, m);
    s.read(bv, v);
    int checked = 0;
    for (int i = 0; i < K * per; ++i) {
      const int kf = i / per, t = steps[kf];
      CAPTURE(i);
      if (kf < first || t <= 0) {
        CHECK(theta[i] == theta0[i]);
        CHECK(m[i] == m0[i]);
        CHECK(v[i] == v0[i]);
        continue;
      }
      const double g = grad[i];
      const double mi = double(b1) * m0[i] + (1 - double(b1)) * g;
      const double vi = double(b2) * v0[i] + (1 - double(b2)) * g * g;
      const double step = double(lr) * (mi / (1 - std::pow(double(b1), t))) /
                          (std::sqrt(vi / (1 - std::pow(double(b2), t))) + double(eps));
      const double want = theta0[i] - step;
      // m and v: a few float roundings of their two terms (m's may cancel, so the bound is on
      // the terms); θ: the step to 1e-5 of the step made of those terms, plus θ's own rounding.
      const double mterms = std::abs(double(b1) * m0[i]) + std::abs((1 - double(b1)) * g);
      CHECK(std::abs(m[i] - mi) <= 1e-6 * mterms);
      CHECK(std::abs(v[i] - vi) <= 1e-6 * std::abs(vi));
      const double step_terms = double(lr) * (mterms / (1 - std::pow(double(b1), t))) /
                                (std::sqrt(vi / (1 - std::pow(double(b2), t))) + double(eps));
      CHECK(std::abs(theta[i] - want) <= 1e-5 * step_terms + 2.4e-7 * std::abs(want));
      CHECK(std::abs(step) > 0);
      ++checked;
    }
    CHECK(checked == 2 * per);
  }
}

}  // TEST_SUITE
