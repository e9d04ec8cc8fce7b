// Gradient checks: the OpenCL backward pass against central finite differences of the
// double-precision CPU reference (coverage, compositing, blur and the whole chain), and
// bit-identical repeat runs.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <tuple>

#include "fit/plan/fit_plan.h"
#include "fit/optimise/fitter.h"
#include "opencl/tuning.h"
#include "raster/layer_compositor.h"
#include "raster/loss_ref.h"
#include "raster_test_support.h"
#include "scene_builders.h"

using namespace svgm;
using namespace svgm::test;

namespace {

constexpr float kWeight = 1000.0f;  // the paper's image-loss weight

struct Agreement {
  double cosine = 0, rel_error = 0;
};

Agreement compare(const std::vector<double>& a, const std::vector<double>& b) {
  double ab = 0, aa = 0, bb = 0, dd = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    ab += a[i] * b[i];
    aa += a[i] * a[i];
    bb += b[i] * b[i];
    dd += (a[i] - b[i]) * (a[i] - b[i]);
  }
  return {ab / std::sqrt(aa * bb + 1e-300), std::sqrt(dd / (bb + 1e-300))};
}

// The reference loss of K frames with control points cp (K * n_cp pairs).
double ref_loss(const RasterPlan& plan, const std::vector<double>& cp, const std::vector<float>& targets,
                int K, const std::array<double, 4>& bg, double render_sigma = kLossSigma,
                double chroma_sigma = 0, double chroma_weight = 1) {
  const size_t per_cp = static_cast<size_t>(plan.n_cp) * 2;
  const size_t per_px = static_cast<size_t>(plan.width) * plan.height * 4;
  double sum = 0;
  for (int k = 0; k < K; ++k) {
    const std::vector<double> c(cp.begin() + k * per_cp, cp.begin() + (k + 1) * per_cp);
    const auto img = ref::render(plan, c);
    const std::vector<float> t(targets.begin() + k * per_px, targets.begin() + (k + 1) * per_px);
    sum += ref::blurred_sq_sum(img, t, plan.width, plan.height, bg, render_sigma, chroma_sigma, chroma_weight);
  }
  return kWeight * sum / (static_cast<double>(K) * plan.width * plan.height * 3);
}

struct Case {
  Scene scene;
  std::vector<double> cp;   // K frames of control points
  std::vector<float> targets;
  int K = 2;
};

// Frames are the rest pose perturbed; targets are a different perturbation rendered by the
// reference, so the residual is structured like a fitting problem's.
Case make_case(const Scene& scene, uint32_t seed, int K) {
  Case c;
  c.scene = scene;
  c.K = K;
  const RasterPlan plan = plan_raster(scene, Affine{}, static_cast<int>(scene.width),
                                      static_cast<int>(scene.height));
  std::mt19937 rng(seed);
  std::normal_distribution<double> N(0, 0.7);
  const size_t per_cp = static_cast<size_t>(plan.n_cp) * 2;
  for (int k = 0; k < K; ++k) {
    std::vector<double> frame(plan.rest_cp.begin(), plan.rest_cp.end());
    std::vector<double> target_cp = frame;
    for (size_t i = 0; i + 6 < per_cp; ++i) {  // the 3 padding points stay at 0
      frame[i] += N(rng);
      target_cp[i] += 2 * N(rng);
    }
    c.cp.insert(c.cp.end(), frame.begin(), frame.end());
    const auto t = ref::render(plan, target_cp);
    for (size_t p = 0; p < t.size() / 4; ++p) {  // composite on white, as targets are
      for (int ch = 0; ch < 3; ++ch) c.targets.push_back(static_cast<float>(t[4 * p + ch] + 1.0 - t[4 * p + 3]));
      c.targets.push_back(1.0f);
    }
  }
  return c;
}

// Analytic gradient from the kernels and the finite-difference gradient of the reference.
// kernel_cp: the kernels' control points when they are not c.cp rounded to float.
std::pair<std::vector<double>, std::vector<double>> gradients(const Case& c, float* loss_cl = nullptr,
                                                              double* loss_ref = nullptr,
                                                              const std::vector<float>* kernel_cp = nullptr,
                                                              double render_sigma = kLossSigma,
                                                              double chroma_sigma = 0,
                                                              double chroma_weight = 1) {
  const RasterPlan plan = plan_raster(c.scene, Affine{}, static_cast<int>(c.scene.width),
                                      static_cast<int>(c.scene.height));
  ClRaster r(runtime(), plan, c.K, render_sigma, chroma_sigma, chroma_weight);
  r.set_control_points(kernel_cp ? *kernel_cp : std::vector<float>(c.cp.begin(), c.cp.end()));
  r.set_targets(c.targets);
  const std::array<float, 4> white{1, 1, 1, 1};
  const float L = r.loss_and_gradient(kWeight, white);
  if (loss_cl) *loss_cl = L;
  const auto g = r.read_cp_gradient();
  std::vector<double> analytic(g.begin(), g.end());
  const std::array<double, 4> bg{1, 1, 1, 1};
  if (loss_ref) *loss_ref = ref_loss(plan, c.cp, c.targets, c.K, bg, render_sigma, chroma_sigma, chroma_weight);
  std::vector<double> fd(c.cp.size(), 0.0);
  const double h = 1e-5;
  auto cp = c.cp;
  for (size_t i = 0; i < cp.size(); ++i) {
    if (i % (plan.n_cp * 2) >= static_cast<size_t>(plan.n_cp - 3) * 2) continue;  // padding
    const double keep = cp[i];
    cp[i] = keep + h;
    const double up = ref_loss(plan, cp, c.targets, c.K, bg, render_sigma, chroma_sigma, chroma_weight);
    cp[i] = keep - h;
    const double down = ref_loss(plan, cp, c.targets, c.K, bg, render_sigma, chroma_sigma, chroma_weight);
    cp[i] = keep;
    fd[i] = (up - down) / (2 * h);
  }
  return {analytic, fd};
}

}  // namespace

TEST_SUITE("raster") {

TEST_CASE("loss: the kernels' blurred MSE equals the reference's") {
  const Case c = make_case(scene_of(40, 32, {filled(circle({20, 16}, 9), {0.9f, 0.2f, 0.1f, 1}),
                                             filled(polygon({{3, 4}, {30, 6}, {14, 28}}), {0.1f, 0.3f, 0.8f, 0.6f})}),
                           7, 2);
  float lc = 0;
  double lr = 0;
  gradients(c, &lc, &lr);
  CHECK(lr > 0);
  CHECK(lc == doctest::Approx(lr).epsilon(1e-4));
}

// The loss's blurs (raster.cl's residual output along x, loss.cl's blur_y_loss_rows along y) add
// each tap only inside the drawing's row extents, and skip the per-tap tests where every tap is
// inside. A disc reaching past the frame's top and bottom, a thin sliver and a lone dot give rows
// whose extents differ from their neighbours' (taps partly outside on one side or both, rows
// within the radius of the frame's edges, a row of one pixel): the kernels' loss equals the
// reference's for the plain, a wider and a per-group chroma blur.
TEST_CASE("loss: rows whose blur taps fall partly outside the drawing's extents") {
  const Case c = make_case(scene_of(72, 48, {filled(circle({36, 24}, 30), {0.9f, 0.2f, 0.1f, 1}),
                                             filled(polygon({{2, 10}, {70, 12}, {2, 13}}), {0.1f, 0.3f, 0.8f, 0.6f}),
                                             filled(polygon({{66, 3}, {67.5f, 3}, {67.5f, 4}}), {0.1f, 0.7f, 0.2f, 1})}),
                           19, 2);
  const RasterPlan plan = plan_raster(c.scene, Affine{}, 72, 48);
  const std::array<double, 4> bg{1, 1, 1, 1};
  for (const auto& [sl, sc] : {std::pair{1.0, 0.0}, std::pair{1.4, 0.0}, std::pair{1.0, 1.6}}) {
    CAPTURE(sl);
    CAPTURE(sc);
    ClRaster r(runtime(), plan, c.K, sl, sc);
    r.set_control_points(std::vector<float>(c.cp.begin(), c.cp.end()));
    r.set_targets(c.targets);
    const float lc = r.loss_and_gradient(kWeight, {1, 1, 1, 1});
    const double lr = ref_loss(plan, c.cp, c.targets, c.K, bg, sl, sc);
    CHECK(lr > 0);
    // The float sums over this larger drawing are 2.5e-5 off the double reference, before and
    // after the tests were taken out of the taps (the same bits).
    CHECK(lc == doctest::Approx(lr).epsilon(1e-4));
  }
}

TEST_CASE("gradient of overlapping opaque and translucent fills matches finite differences") {
  const Case c = make_case(scene_of(40, 32, {filled(circle({20, 16}, 9), {0.9f, 0.2f, 0.1f, 1}),
                                             filled(polygon({{3, 4}, {30, 6}, {14, 28}}), {0.1f, 0.3f, 0.8f, 0.6f})}),
                           11, 2);
  const auto [an, fd] = gradients(c);
  const Agreement a = compare(an, fd);
  MESSAGE("cosine " << a.cosine << ", relative error " << a.rel_error);
  CHECK(a.cosine > 0.99999);
  CHECK(a.rel_error < 1e-3);
}

// A scene whose circle is painted with a linear gradient (red to blue across the canvas) under
// a translucent triangle with a radial one (opaque white at its centre to transparent green):
// the kernels read the draws' paint images (RasterPlan::paint).
Scene gradient_scene() {
  Scene s = scene_of(40, 32, {filled(circle({20, 16}, 9), {0.5f, 0.f, 0.5f, 1}),
                              filled(polygon({{3, 4}, {30, 6}, {14, 28}}), {0.5f, 0.9f, 0.5f, 0.8f})});
  Gradient lin;
  lin.p1 = {0, 0};
  lin.p2 = {40, 0};
  lin.stops = {{0, {1, 0, 0, 1}}, {1, {0, 0, 1, 1}}};
  Gradient rad;
  rad.radial = true;
  rad.center = rad.focal = {15, 12};
  rad.r = 14;
  rad.stops = {{0, {1, 1, 1, 1}}, {1, {0, 0.8f, 0, 0}}};
  rad.opacity = 0.8f;
  s.gradients = {lin, rad};
  s.paths[0].fill_gradient = 0;
  s.paths[1].fill_gradient = 1;
  return s;
}

TEST_CASE("gradient paints: the kernels composite the paint images, and the gradient matches finite differences") {
  const Scene scene = gradient_scene();
  const RasterPlan plan = plan_raster(scene, Affine{}, 40, 32);
  REQUIRE(plan.draws.size() == 2);
  CHECK(plan.draws[0].paint == 0);
  CHECK(plan.draws[1].paint == 1);
  // The paint image is the gradient at pixel centres: pixel (3, 16) has t = 3.5 / 40.
  const float* px = &plan.paint[4 * (16 * 40 + 3)];
  CHECK(px[0] == doctest::Approx(1 - 3.5 / 40).epsilon(1e-6));
  CHECK(px[2] == doctest::Approx(3.5 / 40).epsilon(1e-6));
  // The forward pass against the reference, and the CPU compositor (which paints gradients its
  // own way) at the rest pose.
  const std::vector<float> cl = render_cl(scene);
  const std::vector<double> ref = render_ref(scene);
  const std::vector<float> lc = composite_layers(scene, render_size(scene, 40));
  double worst_ref = 0, worst_lc = 0;
  for (size_t i = 0; i < cl.size(); ++i) {
    worst_ref = std::max(worst_ref, std::abs(cl[i] - ref[i]));
    worst_lc = std::max(worst_lc, static_cast<double>(std::abs(cl[i] - lc[i])));
  }
  MESSAGE("largest difference: reference " << worst_ref << ", layer compositor " << worst_lc);
  CHECK(worst_ref < 1e-5);
  CHECK(worst_lc < 1e-5);
  // The circle's centre is the gradient's colour there, not the draw's flat colour.
  CHECK(cl[4 * (16 * 40 + 24) + 0] == doctest::Approx(1 - 24.5 / 40).epsilon(1e-5));  // right of the triangle
  const Case c = make_case(scene, 5, 2);
  const auto [an, fd] = gradients(c);
  const Agreement a = compare(an, fd);
  MESSAGE("cosine " << a.cosine << ", relative error " << a.rel_error);
  CHECK(a.cosine > 0.99999);
  CHECK(a.rel_error < 1e-3);
}

// Blur matching (raster/loss_taps.h): the render blurred wider than the target. The loss and
// its gradient follow the reference with the same two blurs, and a target that is the
// render blurred by the extra amount scores far less than with the paper's blur alone.
TEST_CASE("blur matching: a wider render blur keeps the loss and gradient exact") {
  const Case c = make_case(scene_of(40, 32, {filled(circle({20, 16}, 9), {0.9f, 0.2f, 0.1f, 1}),
                                             filled(polygon({{3, 4}, {30, 6}, {14, 28}}), {0.1f, 0.3f, 0.8f, 0.6f})}),
                           11, 2);
  float lc = 0;
  double lr = 0;
  const auto [an, fd] = gradients(c, &lc, &lr, nullptr, 1.4);
  CHECK(lr > 0);
  CHECK(lc == doctest::Approx(lr).epsilon(1e-4));
  double lr1 = 0;
  gradients(c, nullptr, &lr1);
  CHECK(std::abs(lr - lr1) > 1e-3 * lr1);  // the wider blur is in effect
  const Agreement a = compare(an, fd);
  MESSAGE("render sigma 1.4: cosine " << a.cosine << ", relative error " << a.rel_error);
  CHECK(a.cosine > 0.99999);
  CHECK(a.rel_error < 1e-3);
}

// The paper is blurred as the target is, whatever the render's σ (kernels/loss.cl, Q): a
// drawing with nothing in the frame against a blank page has loss 0 at a wider render blur and
// a chroma blur of its own. With the render's blur on the paper too, zero padding left a band
// along the border (1 - (B 1) against 1 - (G_t 1)) that no pose could fit.
TEST_CASE("blur matching: nothing drawn against a blank page costs nothing at any render blur") {
  Case c = make_case(scene_of(40, 32, {filled(circle({20, 16}, 9), {0.9f, 0.2f, 0.1f, 1})}), 5, 2);
  const RasterPlan plan = plan_raster(c.scene, Affine{}, 40, 32);
  std::fill(c.targets.begin(), c.targets.end(), 1.f);
  for (size_t i = 0; i < c.cp.size(); ++i) c.cp[i] += 500;  // the disc far outside the frame
  for (const auto& [sl, sc] : {std::pair{1.0, 0.0}, std::pair{1.4, 0.0}, std::pair{1.3, 1.9}}) {
    CAPTURE(sl);
    CAPTURE(sc);
    ClRaster r(runtime(), plan, c.K, sl, sc);
    r.set_control_points(std::vector<float>(c.cp.begin(), c.cp.end()));
    r.set_targets(c.targets);
    CHECK(std::fabs(r.loss_and_gradient(kWeight, {1, 1, 1, 1})) < 1e-12f);
    CHECK(ref_loss(plan, c.cp, c.targets, c.K, {1, 1, 1, 1}, sl, sc) == 0);
  }
}

// Chroma blur matching (raster/loss_taps.h, render_blur): luma blurred at the render σ,
// chroma in YCbCr at its own. The kernels' loss follows the reference's per-group blur and the
// gradient its finite differences, with the chroma blur wider than luma's radius (1 / 1.6: radii
// 2 and 4) and both widened (1.3 / 1.9). A chroma σ equal to the render σ is today's loss, bit
// for bit.
TEST_CASE("chroma blur matching: a softer chroma blur keeps the loss and gradient exact") {
  const Case c = make_case(scene_of(40, 32, {filled(circle({20, 16}, 9), {0.9f, 0.2f, 0.1f, 1}),
                                             filled(polygon({{3, 4}, {30, 6}, {14, 28}}), {0.1f, 0.6f, 0.3f, 0.7f})}),
                           13, 2);
  for (const auto& [sl, sc] : {std::pair{1.0, 1.6}, std::pair{1.3, 1.9}}) {
    CAPTURE(sl);
    CAPTURE(sc);
    float lc = 0;
    double lr = 0, lr_plain = 0;
    const auto [an, fd] = gradients(c, &lc, &lr, nullptr, sl, sc);
    gradients(c, nullptr, &lr_plain, nullptr, sl);
    CHECK(lr > 0);
    // The kernels read Q = bg·(B 1) − G_t ∗ T stored as halves (kernels/loss.cl), within 2^-11
    // of the reference's: the loss agrees to 1e-4 (2e-5 measured), not to float rounding.
    CHECK(lc == doctest::Approx(lr).epsilon(1e-4));
    CHECK(std::abs(lr - lr_plain) > 1e-3 * lr_plain);  // the chroma blur is in effect
    const Agreement a = compare(an, fd);
    MESSAGE("luma sigma " << sl << ", chroma sigma " << sc << ": cosine " << a.cosine << ", relative error " << a.rel_error);
    CHECK(a.cosine > 0.99999);
    CHECK(a.rel_error < 1e-3);
  }
  // σ_c = σ: the plain build, the same bits as without a chroma σ.
  for (double s : {1.0, 1.4}) {
    float l0 = 0, l1 = 0;
    const auto g0 = gradients(c, &l0, nullptr, nullptr, s).first;
    const auto g1 = gradients(c, &l1, nullptr, nullptr, s, s).first;
    CHECK(l0 == l1);
    CHECK(g0 == g1);
  }
}

TEST_CASE("chroma weight: chroma residuals count w times, luma fully; the loss and gradient stay exact") {
  // The red disc and the green triangle differ in luma and chroma. With the plain blur and with
  // a chroma blur of its own, the kernels' weighted loss equals the reference's and the
  // gradient its finite differences; the weight changes the loss (it is in effect).
  const Case c = make_case(scene_of(40, 32, {filled(circle({20, 16}, 9), {0.9f, 0.2f, 0.1f, 1}),
                                             filled(polygon({{3, 4}, {30, 6}, {14, 28}}), {0.1f, 0.6f, 0.3f, 0.7f})}),
                           17, 2);
  for (const auto& [sl, sc, w] : {std::tuple{1.0, 0.0, 0.3}, std::tuple{1.2, 0.0, 0.6}, std::tuple{1.0, 1.6, 0.25}}) {
    CAPTURE(sl);
    CAPTURE(sc);
    CAPTURE(w);
    float lc = 0;
    double lr = 0, lr_plain = 0;
    const auto [an, fd] = gradients(c, &lc, &lr, nullptr, sl, sc, w);
    gradients(c, nullptr, &lr_plain, nullptr, sl, sc);
    CHECK(lr > 0);
    // Q is stored as halves (as above): 1e-4, not float rounding (2.7e-5 measured at σ 1.2,
    // whose taps reach 4 px since they are the paper's composed with the video's, loss_taps.h).
    CHECK(lc == doctest::Approx(lr).epsilon(1e-4));
    CHECK(lr < 0.999 * lr_plain);  // the chroma part of the residual counts less
    const Agreement a = compare(an, fd);
    MESSAGE("sigma " << sl << "/" << sc << ", weight " << w << ": cosine " << a.cosine << ", relative error " << a.rel_error);
    CHECK(a.cosine > 0.99999);
    CHECK(a.rel_error < 1e-3);
  }
  // The metric by hand: a pure luma residual (along y = (.299, .587, .114)) counts fully, a pure
  // chroma one (y·e = 0) w times.
  const double w = 0.25;
  const std::vector<double> luma{0.299, 0.587, 0.114}, chroma{0.587, -0.299, 0};
  const auto ml = chroma_metric(luma, w), mc = chroma_metric(chroma, w);
  for (int i = 0; i < 3; ++i) {
    CHECK(ml[i] == doctest::Approx(luma[i]).epsilon(1e-12));
    CHECK(mc[i] == doctest::Approx(w * chroma[i]).epsilon(1e-12));
  }
}

TEST_CASE("gradient on random scenes: curves, evenodd, opacity, off-canvas, tiny and huge shapes") {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> U(0, 1);
  for (int trial = 0; trial < 6; ++trial) {
    const double W = 36, H = 30;
    std::vector<Path> paths;
    const int n = 2 + trial % 3;
    for (int i = 0; i < n; ++i) {
      Subpath sp;
      sp.closed = true;
      // Centres may sit off the canvas; radii from tiny (0.4 px) to huge (3x the canvas).
      const double cx = -8 + (W + 16) * U(rng), cy = -8 + (H + 16) * U(rng);
      const double r = i == 0 && trial == 4 ? 0.4 : i == 0 && trial == 5 ? 90 : 4 + 10 * U(rng);
      const int segs = 3 + static_cast<int>(rng() % 3);
      sp.points.push_back({cx + r, cy});
      for (int k = 1; k <= segs; ++k) {
        const double a0 = 2 * M_PI * (k - 1) / segs, a1 = 2 * M_PI * k / segs;
        const double rr = r * (0.6 + 0.8 * U(rng));
        sp.points.push_back({cx + rr * std::cos(a0 + 0.4), cy + rr * std::sin(a0 + 0.4)});
        sp.points.push_back({cx + rr * std::cos(a1 - 0.4), cy + rr * std::sin(a1 - 0.4)});
        sp.points.push_back({cx + r * std::cos(a1), cy + r * std::sin(a1)});
      }
      if (trial == 3 && i == 1) sp.points[4] = sp.points[3] + Vec2{1e-4, 0};  // nearly degenerate
      const Rgba col{static_cast<float>(U(rng)), static_cast<float>(U(rng)),
                     static_cast<float>(U(rng)), static_cast<float>(0.4 + 0.6 * U(rng))};
      Path p = filled(sp, col, U(rng) < 0.4 ? FillRule::EvenOdd : FillRule::NonZero);
      p.opacity = static_cast<float>(0.6 + 0.4 * U(rng));
      paths.push_back(p);
    }
    const Case c = make_case(scene_of(W, H, paths), 100 + trial, 2);
    const auto [an, fd] = gradients(c);
    const Agreement a = compare(an, fd);
    CAPTURE(trial);
    MESSAGE("trial " << trial << ": cosine " << a.cosine << ", relative error " << a.rel_error);
    CHECK(a.cosine > 0.99999);
    CHECK(a.rel_error < 1e-3);
  }
}

TEST_CASE("gradient through strokes with every join and cap matches finite differences") {
  const LineJoin joins[] = {LineJoin::Miter, LineJoin::Bevel, LineJoin::Round, LineJoin::MiterClip};
  const LineCap caps[] = {LineCap::Butt, LineCap::Square, LineCap::Round, LineCap::Round};
  for (int t = 0; t < 4; ++t) {
    // An open curve with a corner, a closed curved stroke over a fill, and a thin polyline.
    Subpath open;
    open.points = {{4.3, 20.2}, {8.1, 6.3}, {14.7, 5.2}, {17.4, 12.6}, {19.2, 17.1}, {25.5, 19.4}, {31.2, 8.3}};
    Path a = stroked(open, 2.6, joins[t], caps[t], {0.8f, 0.1f, 0.1f, 1});
    a.stroke.miter_limit = t == 3 ? 1.3 : 4;
    Path b = filled(circle({20.4, 15.3}, 6.2), {0.2f, 0.6f, 0.2f, 0.8f});
    b.has_stroke = true;
    b.stroke.color = {0.1f, 0.1f, 0.7f, 0.9f};
    b.stroke.width = 1.7;
    b.stroke.join = joins[(t + 1) % 4];
    b.stroke.cap = LineCap::Butt;
    b.stroke.miter_limit = 4;
    Path c = stroked(polygon({{6.2, 25.1}, {14.3, 22.4}, {9.9, 27.7}, {30.3, 26.2}}, false), 1.1,
                     joins[(t + 2) % 4], caps[(t + 1) % 4], {0.3f, 0.3f, 0.3f, 1});
    const Case cs = make_case(scene_of(36, 30, {b, a, c}), 300 + t, 2);
    const auto [an, fd] = gradients(cs);
    const Agreement ag = compare(an, fd);
    CAPTURE(t);
    MESSAGE("strokes " << t << ": cosine " << ag.cosine << ", relative error " << ag.rel_error);
    CHECK(ag.cosine > 0.99999);
    CHECK(ag.rel_error < 1e-3);
  }
}

TEST_CASE("two runs of the backward pass give identical bits") {
  const Case c = make_case(scene_of(40, 32, {filled(circle({20, 16}, 9), {0.9f, 0.2f, 0.1f, 1}),
                                             filled(polygon({{3, 4}, {30, 6}, {14, 28}}), {0.1f, 0.3f, 0.8f, 0.6f})}),
                           5, 3);
  auto run = [&] {
    const RasterPlan plan = plan_raster(c.scene, Affine{}, 40, 32);
    ClRaster r(runtime(), plan, c.K);
    r.set_control_points(std::vector<float>(c.cp.begin(), c.cp.end()));
    r.set_targets(c.targets);
    r.loss_and_gradient(kWeight, {1, 1, 1, 1});
    return r.read_cp_gradient();
  };
  const auto a = run(), b = run();
  REQUIRE(a.size() == b.size());
  CHECK(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
  double norm = 0;
  for (float v : a) norm += v * v;
  CHECK(norm > 0);
}

TEST_CASE("a band's tape from the forward pass and from the backward pass's replay give the same bits") {
  // raster_taped hands each band's tape to raster_backward through a pool; a band that does
  // not fit it is replayed by raster_backward itself. Pool capacities: the default, none (every
  // band replays), and 400 entries (5 of the 9 bands fit, the rest replay). An integer-aligned
  // rectangle puts marked pixels (edges on pixel boundaries) on the tape too.
  const Case c = make_case(scene_of(40, 48, {filled(polygon({{4, 8}, {24, 8}, {24, 24}, {4, 24}}), {0.2f, 0.7f, 0.3f, 1}),
                                             filled(circle({20, 24}, 11), {0.9f, 0.2f, 0.1f, 1}),
                                             filled(polygon({{3, 4}, {36, 6}, {14, 44}}), {0.1f, 0.3f, 0.8f, 0.6f})}),
                           7, 3);
  const RasterPlan plan = plan_raster(c.scene, Affine{}, 40, 48);
  ClRaster r(runtime(), plan, c.K);
  r.set_control_points(std::vector<float>(c.cp.begin(), c.cp.end()));
  r.set_targets(c.targets);
  const int bands = c.K * 3;  // 48 rows in bands of 16
  auto run = [&](int pool, int misses) {
    if (pool >= 0) r.set_tape_pool_capacity(pool);
    const float loss = r.loss_and_gradient(kWeight, {1, 1, 1, 1});
    std::vector<float> g = r.read_cp_gradient();
    g.push_back(loss);
    const int m = r.tape_pool_misses();
    MESSAGE("pool " << pool << ": " << m << " bands replayed");
    CAPTURE(pool);
    if (misses >= 0) CHECK(m == misses);
    else CHECK((m > 0 && m < bands));
    return g;
  };
  const auto taped = run(-1, 0), replayed = run(0, bands), mixed = run(400, -1), regrown = run(-1, 0);
  REQUIRE(taped.size() == replayed.size());
  CHECK(std::memcmp(taped.data(), replayed.data(), taped.size() * sizeof(float)) == 0);
  CHECK(std::memcmp(taped.data(), mixed.data(), taped.size() * sizeof(float)) == 0);
  CHECK(std::memcmp(taped.data(), regrown.data(), taped.size() * sizeof(float)) == 0);
  CHECK(r.tape_overflow() == 0);
  double norm = 0;
  for (size_t i = 0; i + 1 < taped.size(); ++i) norm += taped[i] * taped[i];
  CHECK(norm > 0);
}

}  // TEST_SUITE

// Edges exactly on pixel boundaries (kernels/raster_backward.cl, "Edges on pixel boundaries"):
// the loss has a kink there, central differences of the reference converge to the mean of
// the one-sided derivatives, and the kernels must give that mean, not the dead zero of pixels
// whose winding integral is an integer. The frames are the rest pose itself, so every edge of
// the integer-aligned shapes stays on its boundary; the targets are perturbed as in make_case.
namespace {

Case make_aligned_case(const Scene& scene, uint32_t seed, int K) {
  Case c = make_case(scene, seed, K);
  const RasterPlan plan = plan_raster(scene, Affine{}, static_cast<int>(scene.width),
                                      static_cast<int>(scene.height));
  c.cp.clear();
  for (int k = 0; k < K; ++k) c.cp.insert(c.cp.end(), plan.rest_cp.begin(), plan.rest_cp.end());
  return c;
}

// The control points of the rest pose as the fitter computes them: through motion_forward
// (kernels/motion.cl) at identity homographies, in float, so integer coordinates come out
// within a few rounding steps of the canvas scale. The centres are moved off the centroids
// (the fitter learns them; the map stays the identity), which makes that rounding show.
std::vector<float> rest_through_motion(const Scene& scene, int K) {
  const RenderSize size = render_size(scene, static_cast<int>(scene.width));
  const RasterPlan plan = plan_raster(scene, size.view, size.width, size.height);
  const FitPlan fplan = plan_fit(scene, plan, FitPlanOptions{});
  ClRuntime& rt = runtime();
  cl::Program& prog = rt.program({"field.cl", "motion.cl", "regularise.cl", "adam.cl"},
                                 kernel_build_options(raster_tuning(rt.info(), size.width)));
  cl::Kernel motion(prog, "motion_forward");
  auto params = identity_motion(fplan, plan, size);
  for (int g = 0; g < fplan.n_groups; ++g) {  // kernels/motion.cl: parameters 9, 10 are the centre
    params[12 * g + 9] += 0.3141593f;
    params[12 * g + 10] -= 0.2718282f;
  }
  std::vector<float> offsets(static_cast<size_t>(plan.n_cp) * 2, 0.f), cp(offsets.size(), 0.f);
  std::vector<float> rest(plan.rest_cp.begin(), plan.rest_cp.end());
  auto group = fplan.cp_group, slot = fplan.cp_offset;
  auto& ctx = rt.context();
  auto buf = [&](auto& v) {
    using T = typename std::decay_t<decltype(v)>::value_type;
    return cl::Buffer(ctx, CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, std::max<size_t>(v.size() * sizeof(T), 16),
                      v.data());
  };
  cl::Buffer bp = buf(params), bo = buf(offsets), br = buf(rest), bg = buf(group), bs = buf(slot), bc = buf(cp);
  const cl_float2 origin{{0.5f * size.width, 0.5f * size.height}};
  set_args(motion, bp, bo, br, bg, bs, bc, origin, 0.5f * size.width, plan.n_cp, fplan.n_groups);
  rt.queue().enqueueNDRangeKernel(motion, cl::NullRange, cl::NDRange(plan.n_cp, 1));
  rt.queue().enqueueReadBuffer(bc, CL_TRUE, 0, cp.size() * sizeof(float), cp.data());
  std::vector<float> out;
  for (int k = 0; k < K; ++k) out.insert(out.end(), cp.begin(), cp.end());
  return out;
}

// The same bounds as the gradient checks above; the gradient at the aligned control points is
// not small (the check is not vacuous).
void check_aligned(const Scene& scene, uint32_t seed, const std::string& what,
                   bool through_motion = false) {
  const Case c = make_aligned_case(scene, seed, 2);
  std::vector<float> kernel_cp;
  if (through_motion) {
    kernel_cp = rest_through_motion(scene, c.K);
    double off = 0;
    for (size_t i = 0; i < kernel_cp.size(); ++i) off = std::max(off, std::abs(kernel_cp[i] - c.cp[i]));
    MESSAGE(what << ": the motion model moves the rest pose by up to " << off << " px");
    CHECK(off > 0);  // the rounding this case is about is there
  }
  const auto [an, fd] = gradients(c, nullptr, nullptr, through_motion ? &kernel_cp : nullptr);
  const Agreement a = compare(an, fd);
  double norm = 0;
  for (double v : fd) norm += v * v;
  CAPTURE(what);
  MESSAGE(what << ": cosine " << a.cosine << ", relative error " << a.rel_error << ", |fd| "
               << std::sqrt(norm));
  CHECK(std::sqrt(norm) > 1e-3);
  CHECK(a.cosine > 0.99999);
  CHECK(a.rel_error < 1e-3);
}

}  // namespace

TEST_SUITE("raster") {

TEST_CASE("gradient at edges on pixel boundaries: integer-aligned rectangles, both windings") {
  // Opaque nonzero rectangle (clockwise on screen), a translucent counter-clockwise one over
  // it sharing the column x = 20, and an evenodd one whose bottom edge y = 16 is the boundary
  // of the 16-row bands.
  const Path a = filled(polygon({{6, 5}, {20, 5}, {20, 19}, {6, 19}}), {0.9f, 0.2f, 0.1f, 1});
  const Path b = filled(polygon({{20, 9}, {20, 27}, {33, 27}, {33, 9}}), {0.1f, 0.3f, 0.8f, 0.6f});
  const Path e = filled(polygon({{11, 2}, {27, 2}, {27, 16}, {11, 16}}), {0.2f, 0.7f, 0.3f, 0.7f},
                        FillRule::EvenOdd);
  check_aligned(scene_of(40, 32, {a, b, e}), 41, "rectangles");
}

TEST_CASE("gradient at edges on pixel boundaries after the fitter's motion model at rest") {
  // The fitter's rest pose leaves integer coordinates a rounding step off the boundary; the
  // kernel must still see the edges on it (SNAP_REL in kernels/raster_backward.cl).
  const Path a = filled(polygon({{6, 5}, {20, 5}, {20, 19}, {6, 19}}), {0.9f, 0.2f, 0.1f, 1});
  const Path b = filled(polygon({{20, 9}, {20, 27}, {33, 27}, {33, 9}}), {0.1f, 0.3f, 0.8f, 0.6f});
  check_aligned(scene_of(40, 32, {a, b}), 59, "rectangles through the motion model", true);
}

TEST_CASE("gradient at edges on the canvas border") {
  // Left edge on x = 0, bottom on y = H, right on x = W and top on y = 0.
  const Path a = filled(polygon({{0, 20}, {12, 20}, {12, 32}, {0, 32}}), {0.9f, 0.2f, 0.1f, 1});
  const Path b = filled(polygon({{27, 0}, {40, 0}, {40, 13}, {27, 13}}), {0.1f, 0.3f, 0.8f, 0.8f});
  check_aligned(scene_of(40, 32, {a, b}), 43, "canvas border");
}

TEST_CASE("gradient at vertices on pixel corners: a diamond and a triangle through lattice points") {
  const Path a = filled(polygon({{20, 3}, {29, 12}, {20, 21}, {11, 12}}), {0.9f, 0.2f, 0.1f, 1});
  const Path b = filled(polygon({{8, 14}, {30, 29}, {8, 29}}), {0.1f, 0.3f, 0.8f, 0.7f});
  check_aligned(scene_of(40, 32, {a, b}), 47, "pixel corners");
}

TEST_CASE("gradient at stroke outlines on pixel boundaries: butt and square caps, miter corner") {
  // Width 2 about integer centre lines: every outline edge lies on a pixel boundary.
  Path a = stroked(polygon({{5, 6}, {30, 6}, {30, 26}}, false), 2, LineJoin::Miter, LineCap::Butt,
                   {0.8f, 0.1f, 0.1f, 1});
  Path b = stroked(polygon({{9, 12}, {9, 28}}, false), 2, LineJoin::Bevel, LineCap::Square,
                   {0.1f, 0.3f, 0.8f, 0.7f});
  check_aligned(scene_of(40, 32, {a, b}), 53, "strokes");
}

}  // TEST_SUITE
