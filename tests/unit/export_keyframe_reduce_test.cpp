// Keyframe reduction (export/keyframe_reduce.h): a linear motion keeps its two ends, a sine keeps
// its extremes, and on random trajectories every sample stays within the tolerance.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "export/keyframe_reduce.h"

using namespace svgm;

namespace {

std::vector<double> uniform_times(size_t n) {
  std::vector<double> t;
  for (size_t i = 0; i < n; ++i) t.push_back(static_cast<double>(i) / (n - 1));
  return t;
}

// The largest distance of the reduced keys' interpolation from any sample.
double worst_error(const ReducedKeys& r, const std::vector<double>& times, const std::vector<double>& values, size_t dim) {
  double worst = 0;
  for (size_t i = 0; i < times.size(); ++i) {
    const std::vector<double> v = keyed_value(r, times, values, dim, i);
    for (size_t k = 0; k + 1 < dim; k += 2)
      worst = std::max(worst, std::hypot(v[k] - values[i * dim + k], v[k + 1] - values[i * dim + k + 1]));
  }
  return worst;
}

}  // namespace

TEST_SUITE("export") {
  TEST_CASE("a linear motion reduces to its two ends, linear") {
    const auto times = uniform_times(49);
    std::vector<double> values;  // two points moving at constant speed
    for (double t : times) values.insert(values.end(), {10 + 30 * t, 5 - 8 * t, -3 + 2 * t, 7 * t});
    const ReducedKeys r = reduce_keyframes(times, values, 4, 0.01, point_error(values, 4, 1.0));
    CHECK(r.keys == std::vector<size_t>{0, 48});
    REQUIRE(r.easing.size() == 1);
    CHECK(r.easing[0].is_linear());
    CHECK(worst_error(r, times, values, 4) < 1e-9);
  }

  TEST_CASE("an eased motion is one segment with its easing") {
    const auto times = uniform_times(25);
    std::vector<double> values;
    for (double t : times) values.insert(values.end(), {20 * (3 * t * t - 2 * t * t * t), 0});
    const ReducedKeys r = reduce_keyframes(times, values, 2, 0.01, point_error(values, 2, 1.0));
    CHECK(r.keys == std::vector<size_t>{0, 24});
    REQUIRE(r.easing.size() == 1);
    CHECK(r.easing[0].y1 == doctest::Approx(0).epsilon(1e-6));
    CHECK(r.easing[0].y2 == doctest::Approx(1).epsilon(1e-6));
  }

  TEST_CASE("a sine keeps its extremes and holds the tolerance") {
    const auto times = uniform_times(49);
    std::vector<double> values;
    for (double t : times) values.insert(values.end(), {10 * std::sin(4 * M_PI * t), 1});
    const double tol = 0.05;
    const ReducedKeys r = reduce_keyframes(times, values, 2, tol, point_error(values, 2, 1.0));
    // Extremes at t = 1/8, 3/8, 5/8, 7/8: samples 6, 18, 30, 42.
    for (size_t e : {6u, 18u, 30u, 42u}) CHECK(std::count(r.keys.begin(), r.keys.end(), e) == 1);
    CHECK(r.keys.size() < 49);
    CHECK(worst_error(r, times, values, 2) <= tol + 1e-12);
    CHECK(r.max_error <= tol + 1e-12);
  }

  TEST_CASE("random trajectories stay within the tolerance, with fewer keys when smooth") {
    std::mt19937 rng(37);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 20; ++trial) {
      const size_t n = 10 + static_cast<size_t>(trial) * 3, dim = 6;
      const auto times = uniform_times(n);
      std::vector<double> values;
      // A smooth drift plus noise whose size varies with the trial.
      const double noise = trial % 2 ? 0.5 : 0.01;
      for (size_t i = 0; i < n; ++i)
        for (size_t k = 0; k < dim; ++k) values.push_back(std::sin(times[i] * (1 + k) / 3.0) + noise * u(rng));
      const double tol = 0.1 + 0.05 * (trial % 3);
      const ReducedKeys r = reduce_keyframes(times, values, dim, tol, point_error(values, dim, 1.0));
      REQUIRE(r.keys.front() == 0);
      REQUIRE(r.keys.back() == n - 1);
      CHECK(worst_error(r, times, values, dim) <= tol + 1e-12);
      if (noise < 0.05) CHECK(r.keys.size() < n / 2);
    }
  }

  TEST_CASE("one sample is one key; a still trajectory two") {
    const std::vector<double> one{0.0}, v1{3, 4};
    CHECK(reduce_keyframes(one, v1, 2, 0.1, point_error(v1, 2, 1)).keys == std::vector<size_t>{0});
    const auto times = uniform_times(10);
    std::vector<double> still;
    for (size_t i = 0; i < 10; ++i) still.insert(still.end(), {1, 2});
    CHECK(reduce_keyframes(times, still, 2, 0.1, point_error(still, 2, 1)).keys == std::vector<size_t>{0, 9});
  }
}
