// Warm-start pieces: the weighted similarity fit recovers a known similarity, and composing it
// into a homography equals applying it after the homography.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "fit/motion_model.h"
#include "fit/warm_start.h"

using namespace svgm;

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

}  // TEST_SUITE
