// Keyframe reduction (export/keyframe_reduce.h): a linear motion keeps its two ends, a sine keeps
// its extremes, on random trajectories every sample stays within the tolerance, and so does
// every time between samples, where the full export blends them linearly.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "export/compact_motion.h"
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

// The largest distance, over `steps` times inside every interval between samples, of what the
// reduced keys draw from the linear blend of the two samples (the full export there).
double worst_between(const ReducedKeys& r, const std::vector<double>& times, const std::vector<double>& values,
                     size_t dim, int steps) {
  double worst = 0;
  for (size_t i = 0; i + 1 < times.size(); ++i)
    for (int j = 1; j < steps; ++j) {
      const double u = static_cast<double>(j) / steps, t = times[i] + u * (times[i + 1] - times[i]);
      size_t k = 0;
      while (k + 2 < r.keys.size() && r.keys[k + 1] <= i) ++k;
      const size_t a = r.keys[k], b = r.keys[k + 1];
      const double s = ease(r.easing[k], (t - times[a]) / (times[b] - times[a]));
      for (size_t c = 0; c + 1 < dim; c += 2) {
        double d2 = 0;
        for (size_t q = c; q < c + 2; ++q) {
          const double blend = values[i * dim + q] + u * (values[(i + 1) * dim + q] - values[i * dim + q]);
          const double drawn = values[a * dim + q] + s * (values[b * dim + q] - values[a * dim + q]);
          d2 += (drawn - blend) * (drawn - blend);
        }
        worst = std::max(worst, std::sqrt(d2));
      }
    }
  return worst;
}

}  // namespace

TEST_SUITE("export") {
  TEST_CASE("an easing through every sample that leaves the blend between them is split") {
    // Four samples a third apart lying exactly on the ease-in-out with handles y1 = 0, y2 = 1
    // (s(1/3) = 7/27, s(2/3) = 20/27), 100 px of travel. That one eased segment holds every
    // sample, but at a sixth of the pass the full export draws 100 * 7/54 = 13.0 px where the
    // easing is at 7.4 px: 5.5 px off, with a tolerance of 1. Checking the samples alone kept
    // the two ends ({0, 3}, max_error 0).
    const std::vector<double> times{0, 1.0 / 3, 2.0 / 3, 1};
    const std::vector<double> values{0, 0, 700.0 / 27, 0, 2000.0 / 27, 0, 100, 0};
    const double tol = 1;
    const ReducedKeys r = reduce_keyframes(times, values, 2, tol, point_error(values, 2, 1.0));
    CHECK(r.keys == std::vector<size_t>{0, 1, 2, 3});
    CHECK(r.max_error <= tol);
    CHECK(worst_error(r, times, values, 2) <= tol);
    CHECK(worst_between(r, times, values, 2, 60) <= tol);
  }

  TEST_CASE("a wrapper's turn eased through every value but off between them is split") {
    // A 20 px square about (0, 0) turned 0, 23.3, 66.7 and 90 degrees at values a third apart:
    // the ease-in-out (0, 1) holds every value, but a sixth of the way it is at 6.7 degrees where
    // the values blended are at 11.7: its corners 1.2 px off, with a tolerance of 0.5.
    const std::vector<double> rest{-10, -10, 10, -10, 10, 10, -10, 10};
    const std::vector<double> times{0, 1.0 / 3, 2.0 / 3, 1};
    std::vector<double> trajectory;  // tx ty rotate skew sx sy
    for (double s : {0.0, 7.0 / 27, 20.0 / 27, 1.0}) trajectory.insert(trajectory.end(), {0, 0, 90 * s, 0, 1, 1});
    const SampleError err = wrapper_error(trajectory, rest, Affine{}, Vec2{0, 0}, WrapperForm::Smil);
    const ReducedKeys r = reduce_keyframes(times, trajectory, 6, 0.5, err);
    CHECK(r.keys == std::vector<size_t>{0, 1, 2, 3});
    CHECK(r.max_error <= 0.5);
  }

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
    // Between samples the full export cuts the curve's chords, up to (1/24)^2 / 8 * 120 = 0.026
    // px from it: the tolerance is above that.
    const ReducedKeys r = reduce_keyframes(times, values, 2, 0.05, point_error(values, 2, 1.0));
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
