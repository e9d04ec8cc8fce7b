// Cubic Hermite in-betweens of the fitted keyframes (see inbetween.h).
#include "fit/inbetween.h"

#include <algorithm>
#include <cmath>

namespace svgm {

InBetween in_between(const std::vector<double>& points, const std::vector<double>& times,
                     size_t per_key, const std::vector<double>& frames, int max_per_interval,
                     bool closed) {
  const size_t K = times.size();
  InBetween out;
  if (K < 2 || max_per_interval <= 0) {
    out.times = times;
    out.points = points;
    return out;
  }
  const double* P = points.data();
  // Tangent (per unit of time) at keyframe k, Catmull-Rom for uneven spacing.
  auto tangent = [&](size_t k, size_t i) {
    size_t a = k, b = k;
    double ta = times[k], tb = times[k];
    if (k > 0) a = k - 1, ta = times[a];
    else if (closed) a = K - 2, ta = times[a] - 1;  // the loop's previous key, one pass earlier
    if (k + 1 < K) b = k + 1, tb = times[b];
    else if (closed) b = 1, tb = times[b] + 1;
    const double dt = tb - ta;
    return dt > 0 ? (P[b * per_key + i] - P[a * per_key + i]) / dt : 0.0;
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
    const size_t n = std::min(inside.size(), static_cast<size_t>(max_per_interval));
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
