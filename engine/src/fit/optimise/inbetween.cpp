// Cubic Hermite in-betweens of the fitted keyframes (see inbetween.h).
#include "fit/optimise/inbetween.h"

#include <algorithm>
#include <cmath>

namespace svgm {

InBetween in_between(const std::vector<double>& points, const std::vector<double>& times,
                     size_t per_key, const std::vector<double>& frames, int max_per_interval,
                     bool closed) {
  const size_t K = times.size();
  InBetween out;
  if (K < 2) {
    out.times = times;
    out.points = points;
    return out;
  }
  // A closed loop ends on its first keyframe's shape.
  std::vector<double> keys = points;
  if (closed)
    std::copy(points.begin(), points.begin() + static_cast<std::ptrdiff_t>(per_key),
              keys.end() - static_cast<std::ptrdiff_t>(per_key));
  const double* P = keys.data();
  // Tangent (per unit of time) at keyframe k: the slope at t_k of the parabola through the
  // keyframes k-1, k, k+1 (Bessel's tangent; Catmull-Rom's for even spacing), one-sided at
  // the ends of an open pass.
  auto tangent = [&](size_t k, size_t i) {
    bool has_a = k > 0 || closed, has_b = k + 1 < K || closed;
    const size_t a = k > 0 ? k - 1 : K - 2, b = k + 1 < K ? k + 1 : 1;
    const double ha = k > 0 ? times[k] - times[a] : times[K - 1] - times[a];
    const double hb = k + 1 < K ? times[b] - times[k] : times[b] - times[0];
    has_a = has_a && ha > 0;
    has_b = has_b && hb > 0;
    const double p = P[k * per_key + i];
    const double da = has_a ? (p - P[a * per_key + i]) / ha : 0, db = has_b ? (P[b * per_key + i] - p) / hb : 0;
    if (has_a && has_b) return (hb * da + ha * db) / (ha + hb);
    return has_a ? da : has_b ? db : 0.0;
  };
  for (size_t k = 0; k < K; ++k) {
    out.times.push_back(times[k]);
    out.points.insert(out.points.end(), P + k * per_key, P + (k + 1) * per_key);
    if (k + 1 == K) break;
    const double t0 = times[k], t1 = times[k + 1], h = t1 - t0;
    if (!(h > 0)) continue;
    std::vector<double> inside;
    for (double f : frames)
      if (f > t0 + 1e-9 && f < t1 - 1e-9) inside.push_back(f);
    if (inside.empty()) continue;
    std::vector<double> pick;
    // `max_per_interval` is for an interval of the mean length; a longer one (keyframes retimed
    // to held frames are spaced unevenly) gets proportionally more, so in-betweens stay as dense
    // in time everywhere and no frame of a long interval is left to the browser's straight line.
    const double mean_h = (times[K - 1] - times[0]) / static_cast<double>(K - 1);
    const double share = mean_h > 0 ? h / mean_h : 1;
    const size_t budget = static_cast<size_t>(std::ceil(std::max(0, max_per_interval) * share - 1e-9));
    const size_t n = std::min(inside.size(), budget);
    if (n == 0) continue;
    for (size_t j = 0; j < n; ++j) pick.push_back(inside[(2 * j + 1) * inside.size() / (2 * n)]);
    for (double f : pick) {
      const double s = (f - t0) / h, s2 = s * s, s3 = s2 * s;
      const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
      out.times.push_back(f);
      for (size_t i = 0; i < per_key; ++i)
        out.points.push_back(h00 * P[k * per_key + i] + h10 * h * tangent(k, i) +
                             h01 * P[(k + 1) * per_key + i] + h11 * h * tangent(k + 1, i));
    }
  }
  return out;
}

}  // namespace svgm
