// Warm-start pieces: the weighted similarity fit recovers a known similarity, composing it
// into a homography equals applying it after the homography, the tracker tells corners from
// edges, the field increment reproduces an affine displacement exactly and leaves untracked
// groups alone, and in a fit a dot that moves across the part it is painted on is carried to
// its new place by the field warm start.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include <unistd.h>

#include "fit/optimise/field_warm_start.h"
#include "fit/plan/fit_plan.h"
#include "fit/target/white_runs.h"
#include "fit/optimise/fitter.h"
#include "fit/optimise/motion_model.h"
#include "fit/optimise/warm_start.h"
#include "known_motion.h"
#include "raster_test_support.h"
#include "scene_builders.h"
#include "svgmotion/target_video.h"

using namespace svgm;
using namespace svgm::test;

// A light square with a dark dot (radius 2.5 px, centred at (26, 30)) painted on it, one part,
// at 64 px.
static Scene square_with_dot() {
  Scene s = scene_of(64, 64, {filled(polygon({{8, 8}, {56, 8}, {56, 56}, {8, 56}}), {0.9f, 0.75f, 0.5f, 1}),
                              filled(circle({26, 30}, 2.5), {0.1f, 0.1f, 0.15f, 1})});
  s.groups = {{"part", {0, 1}}};
  s.paths[0].group = s.paths[1].group = 0;
  return s;
}

TEST_SUITE("fit") {

TEST_CASE("fit_similarity recovers a known similarity, ignoring zero-weight outliers") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(0, 100);
  const double sc = 1.1, ang = 0.3, c = std::cos(ang), s = std::sin(ang);
  std::vector<Vec2> from, to;
  std::vector<double> w;
  for (int i = 0; i < 20; ++i) {
    const Vec2 p{U(rng), U(rng)};
    from.push_back(p);
    to.push_back(Vec2{sc * (c * p.x - s * p.y) + 4, sc * (s * p.x + c * p.y) - 7});
    w.push_back(i % 5 == 0 ? 0.0 : 1.0);
    if (i % 5 == 0) to.back() = to.back() + Vec2{40, -30};  // a broken track, weight 0
  }
  const auto sim = fit_similarity(from, to, w);
  REQUIRE(sim);
  CHECK(sim->scale == doctest::Approx(sc).epsilon(1e-9));
  CHECK(sim->angle == doctest::Approx(ang).epsilon(1e-9));
  CHECK(sim->shift.x == doctest::Approx(4).epsilon(1e-9));
  CHECK(sim->shift.y == doctest::Approx(-7).epsilon(1e-9));
  CHECK_FALSE(fit_similarity({{0, 0}, {1, 1}}, {{0, 0}, {1, 1}}, {1, 1}));  // too few points
}

TEST_CASE("composing a similarity equals applying it after the homography") {
  MotionParams th = identity_params(0.1, -0.2);
  th[0] = 0.05; th[1] = -0.03; th[2] = 0.2; th[3] = 1.1; th[4] = 0.9; th[5] = 0.1; th[6] = -0.05;
  Similarity sim;
  sim.scale = 0.95;
  sim.angle = -0.15;
  sim.shift = {3.5, -2.0};
  MotionParams composed = th;
  const Vec2 o{64, 48};
  const double scale = 64;
  compose_similarity(composed, sim, o, scale);
  const double c = std::cos(sim.angle), s = std::sin(sim.angle);
  for (const Vec2 p : {Vec2{10, 20}, Vec2{100, 80}, Vec2{64, 48}, Vec2{0, 95}}) {
    const Vec2 q = apply_motion(th, p, o, scale);
    const Vec2 want{sim.scale * (c * q.x - s * q.y) + sim.shift.x, sim.scale * (s * q.x + c * q.y) + sim.shift.y};
    const Vec2 got = apply_motion(composed, p, o, scale);
    CHECK(got.x == doctest::Approx(want.x).epsilon(1e-9));
    CHECK(got.y == doctest::Approx(want.y).epsilon(1e-9));
  }
}

TEST_CASE("compose_affine: the composed homography is the affine map applied after the group's motion") {
  // A sheared, scaled, turned group (no projective part), then a turn in a slanted plane
  // M R M^-1 (a wheel seen at a slant) about a point: the composition refactored into
  // R · Sh · S with shy = 0 moves every point where the two steps in turn do.
  MotionParams th = identity_params(0.1, -0.2);
  th[0] = 0.05; th[1] = -0.03; th[2] = 0.3; th[3] = 1.2; th[4] = 0.8; th[5] = 0.15; th[6] = -0.1;
  const Affine M{1.4, 0.3, 0.0, 0.7, 0, 0};
  const Vec2 c{70, 40};
  const Affine turn = Affine::translate(c.x, c.y) * M * Affine::rotate_deg(37) * M.inverse() * Affine::translate(-c.x, -c.y);
  MotionParams composed = th;
  const Vec2 o{64, 48};
  const double scale = 64;
  REQUIRE(compose_affine(composed, turn, o, scale));
  CHECK(composed[6] == 0.0);
  for (const Vec2 p : {Vec2{10, 20}, Vec2{100, 80}, Vec2{64, 48}, Vec2{0, 95}}) {
    const Vec2 want = turn.apply(apply_motion(th, p, o, scale));
    const Vec2 got = apply_motion(composed, p, o, scale);
    CHECK(got.x == doctest::Approx(want.x).epsilon(1e-9));
    CHECK(got.y == doctest::Approx(want.y).epsilon(1e-9));
  }
  // A mirroring map (a figure turned round about its vertical axis through x = 70, at 0.4 of its
  // width) composes too: a negative sx, every point where the two steps put it.
  const Affine mirror = Affine::translate(c.x, 0) * Affine::scale(-0.4, 1) * Affine::translate(-c.x, 0);
  MotionParams mirrored = th;
  REQUIRE(compose_affine(mirrored, mirror, o, scale));
  CHECK(mirrored[3] < 0);
  CHECK(mirrored[4] > 0);
  for (const Vec2 p : {Vec2{10, 20}, Vec2{100, 80}, Vec2{64, 48}, Vec2{0, 95}}) {
    const Vec2 want = mirror.apply(apply_motion(th, p, o, scale));
    const Vec2 got = apply_motion(mirrored, p, o, scale);
    CHECK(got.x == doctest::Approx(want.x).epsilon(1e-9));
    CHECK(got.y == doctest::Approx(want.y).epsilon(1e-9));
  }
  // A degenerate map (everything onto a line) is refused, and leaves the parameters as they were.
  MotionParams kept = th;
  CHECK_FALSE(compose_affine(kept, Affine::scale(0, 1), o, scale));
  CHECK(kept == th);
}

TEST_CASE("track_points: a corner's window pins both directions, a straight edge's only one") {
  // A dark square (20..44) on white, 64 x 64.
  const int W = 64, H = 64;
  std::vector<uint8_t> img(W * H, 255);
  for (int y = 20; y < 44; ++y)
    for (int x = 20; x < 44; ++x) img[y * W + x] = 30;
  const auto t = track_points(img, img, W, H, {{20, 20}, {20, 32}, {32, 20}, {32, 32}, {5, 5}});
  MESSAGE("isotropy corner " << t.isotropy[0] << ", left edge " << t.isotropy[1] << ", top edge "
                             << t.isotropy[2] << ", inside " << t.isotropy[3] << ", outside " << t.isotropy[4]);
  CHECK(t.isotropy[0] > 0.5);    // both edges in the window: equal eigenvalues
  CHECK(t.isotropy[1] == 0.0);   // a vertical edge: no vertical gradient at all
  CHECK(t.isotropy[2] == 0.0);
  CHECK(t.isotropy[3] == 0.0);   // flat: no gradient
  CHECK(t.isotropy[4] == 0.0);
  CHECK(t.weight[0] > 0.9);      // the same image: every track stays put and agrees both ways
  CHECK(std::hypot(t.to[0].x - 20, t.to[0].y - 20) < 1e-3);
  // The same measure on its own (the tracker stage's flow path), and off the image: zero.
  const auto iso = window_isotropy(img, W, H, {{20, 20}, {20, 32}, {1e30, 5}, {-500, -500}}, 7);
  CHECK(iso[0] == t.isotropy[0]);
  CHECK(iso[1] == 0.0);
  CHECK(iso[2] == 0.0);
  CHECK(iso[3] == 0.0);
}

namespace {

// A disc (group "disc") and a small square apart from it (group "box"), 96 x 96 pixels.
FitPlan two_part_plan(RasterPlan& raster) {
  Scene s = scene_of(96, 96, {filled(circle({40, 44}, 20), {0.2f, 0.5f, 0.8f, 1}),
                              filled(polygon({{78, 10}, {88, 10}, {88, 20}, {78, 20}}), {0.8f, 0.2f, 0.1f, 1})});
  s.groups = {{"disc", {0}}, {"box", {1}}};
  s.paths[0].group = 0;
  s.paths[1].group = 1;
  raster = plan_raster(s, Affine{}, 96, 96);
  FitPlanOptions o;
  o.field_spacing_px = 8;
  return plan_fit(s, raster, o);
}

}  // namespace

TEST_CASE("fit_field_increment: an affine displacement is reproduced exactly, untracked groups stay at zero") {
  RasterPlan raster;
  const FitPlan plan = two_part_plan(raster);
  REQUIRE(plan.n_nodes > 0);
  // Every point of the disc asks for an affine displacement; the box has no tracks.
  auto want = [](double x, double y) { return Vec2{0.05 * x - 0.02 * y + 3, 0.03 * x + 0.04 * y - 2}; };
  FieldTargets t;
  for (int i = 0; i < plan.n_cp; ++i)
    if (plan.cp_group[i] == 0 && plan.cp_offset[i] == i) {
      t.point.push_back(i);
      t.offset.push_back(want(raster.rest_cp[2 * i], raster.rest_cp[2 * i + 1]));
      t.weight.push_back(1.0);
    }
  // With a vanishing ridge the affine field is the exact minimiser: zero misfit, zero bending.
  const auto solved = fit_field_increment(plan, t, 1.0, 1e-9);
  REQUIRE(solved);
  const std::vector<Vec2>& c = *solved;
  double worst = 0;
  for (size_t j = 0; j < t.point.size(); ++j) {
    const int i = t.point[j];
    Vec2 got;
    for (int e = plan.cp_node_first[i]; e < plan.cp_node_first[i + 1]; ++e)
      got = got + plan.cp_node_w[e] * c[plan.cp_node[e]];
    worst = std::max(worst, std::hypot(got.x - t.offset[j].x, got.y - t.offset[j].y));
  }
  MESSAGE("largest misfit of the affine field: " << worst << " px");
  CHECK(worst < 1e-5);
  for (int i = 0; i < plan.n_cp; ++i)
    if (plan.cp_group[i] == 1)
      for (int e = plan.cp_node_first[i]; e < plan.cp_node_first[i + 1]; ++e) {
        CHECK(c[plan.cp_node[e]].x == 0.0);
        CHECK(c[plan.cp_node[e]].y == 0.0);
      }
  // One point pulled 4 px, every other point of the disc tracked in place: the pull is a local
  // bend, so the pulled point gets part of the way, and the disc's far side does not move.
  FieldTargets one = t;
  for (size_t j = 0; j < one.point.size(); ++j) one.offset[j] = j == 0 ? Vec2{4, 0} : Vec2{};
  const auto solved1 = fit_field_increment(plan, one, 1.0, 1e-3);
  REQUIRE(solved1);
  const std::vector<Vec2>& c1 = *solved1;
  auto field_at = [&](int i) {
    Vec2 d;
    for (int e = plan.cp_node_first[i]; e < plan.cp_node_first[i + 1]; ++e) d = d + plan.cp_node_w[e] * c1[plan.cp_node[e]];
    return d;
  };
  const Vec2 p0{raster.rest_cp[2 * one.point[0]], raster.rest_cp[2 * one.point[0] + 1]};
  double far_move = 0, far_dist = 0;
  for (int i : one.point) {
    const double dist = std::hypot(raster.rest_cp[2 * i] - p0.x, raster.rest_cp[2 * i + 1] - p0.y);
    if (dist > far_dist) far_dist = dist, far_move = std::hypot(field_at(i).x, field_at(i).y);
  }
  MESSAGE("a lone pull of 4 px moves its point " << field_at(one.point[0]).x << " px, the point " << far_dist
                                                 << " px away " << far_move << " px");
  CHECK(field_at(one.point[0]).x > 0.5);
  CHECK(field_at(one.point[0]).x < 4.0);
  CHECK(far_move < 0.05);
}

TEST_CASE("field warm start: a dot moving across the part it sits on is carried to its new place") {
  // A light square with a dark dot painted on it, one part. Between the two keyframes the
  // square stays and the dot moves 5 px (at the 64 px fitting size; its radius is 2.5 px).
  // Without the warm start (FitOptions::track off) the fit chases the dot with the whole
  // part's homography: the square drifted 6.7 px in these 150 iterations. With it, the field
  // carries the dot and the square stays.
  Scene s = square_with_dot();
  const int K = 2;
  const Vec2 shift{4, 3};
  const auto dir = std::filesystem::temp_directory_path() / ("svgm_fieldws_" + std::to_string(::getpid()));
  const auto truth = write_known_motion(s, 64, K, [](int, int) { return identity_params(); },
                                        [&](int k, Vec2 q) { return std::hypot(q.x - 26, q.y - 30) < 6 ? k * shift : Vec2{}; },
                                        dir);
  TargetOptions to;
  to.keyframes = K;
  const TargetFrames target = load_target(dir, 64, 64, to);
  std::filesystem::remove_all(dir);
  FitOptions fo;
  fo.iterations = 150;
  Fitter fitter(runtime(), s, target, fo);
  while (!fitter.done()) fitter.step();
  CHECK(fitter.field_warm_starts_tried == 1);
  CHECK(fitter.field_warm_starts_kept == 1);
  const auto pts = fitter.keyframe_points_canvas();
  const RasterPlan& plan = fitter.raster_plan();
  Vec2 centre, want;
  const int first = plan.path_cp_first[1], n = plan.path_cp_count[1];
  for (int i = first; i < first + n; ++i) {
    centre = centre + Vec2{pts[(plan.n_cp + i) * 2], pts[(plan.n_cp + i) * 2 + 1]};
    want = want + Vec2{truth[1][2 * i], truth[1][2 * i + 1]};
  }
  const double err = std::hypot(centre.x - want.x, centre.y - want.y) / n;
  // The square has nothing to follow: it stays where it was.
  double square = 0;
  for (int i = plan.path_cp_first[0]; i < plan.path_cp_first[0] + plan.path_cp_count[0]; ++i)
    if (truth[1][2 * i] != 0 || truth[1][2 * i + 1] != 0)
      square = std::max(square, std::hypot(pts[(plan.n_cp + i) * 2] - truth[1][2 * i], pts[(plan.n_cp + i) * 2 + 1] - truth[1][2 * i + 1]));
  MESSAGE("the square's largest drift " << square << " px");
  CHECK(square < 0.5);
  MESSAGE("the dot's centre is " << err << " px from its target place (it moved " << std::hypot(shift.x, shift.y) << ")");
  CHECK(err < 0.5);
}

TEST_CASE("a fitter reading packed targets a frame at a time fits as one given the whole clip, warm starts included") {
  // `bench fit` keeps its target packed (fit/target/white_runs.h) and hands the fitter a frame
  // reader (Fitter::read_targets_from): the loss's constants and each keyframe's warm start
  // read the frames from the runs. Three keyframes, so two warm starts read the target.
  Scene s = square_with_dot();
  const int K = 3;
  const auto dir = std::filesystem::temp_directory_path() / ("svgm_packedws_" + std::to_string(::getpid()));
  write_known_motion(s, 64, K, [](int k, int) { MotionParams p = identity_params(); p[0] = 0.03f * k; return p; },
                     [&](int k, Vec2 q) { return std::hypot(q.x - 26, q.y - 30) < 6 ? k * Vec2{3, 2} : Vec2{}; }, dir);
  TargetOptions to;
  to.keyframes = K;
  const TargetFrames whole = load_target(dir, 64, 64, to);
  std::filesystem::remove_all(dir);
  TargetFrames bare = whole;
  std::vector<float> floats = whole.rgba;
  const WhiteRuns packed = pack_white_runs(floats);
  bare.rgba.clear();
  FitOptions fo;
  fo.iterations = 120;
  Fitter a(runtime(), s, whole, fo);
  Fitter b(runtime(), s, bare, fo);
  const size_t px = 64 * 64;
  b.read_targets_from([&packed, px](int k, float* out) { unpack_white_runs_range(packed, k * px, px, out); });
  while (!a.done()) a.step();
  while (!b.done()) b.step();
  CHECK(a.iteration() == b.iteration());
  CHECK(a.active_keyframes() == K);
  CHECK(a.field_warm_starts_tried == b.field_warm_starts_tried);
  CHECK(a.keyframe_points_canvas() == b.keyframe_points_canvas());
  CHECK(a.keyframe_losses() == b.keyframe_losses());
}

}  // TEST_SUITE
