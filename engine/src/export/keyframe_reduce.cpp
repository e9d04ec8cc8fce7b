// Keyframe reduction (see keyframe_reduce.h).
#include "export/keyframe_reduce.h"

#include <algorithm>
#include <cmath>

namespace svgm {

namespace {

// The two Bernstein terms of the easing that carry y1 and y2, and the fixed x^3.
double b1(double x) { return 3 * (1 - x) * (1 - x) * x; }
double b2(double x) { return 3 * (1 - x) * x * x; }

// The easing that best maps the segment's time fractions xs to the interpolation parameters ss
// (least squares over y1, y2 in [0, 1]; the clamped variable's partner refitted alone).
Easing fit_easing(const std::vector<double>& xs, const std::vector<double>& ss) {
  double a11 = 0, a12 = 0, a22 = 0, r1 = 0, r2 = 0;
  for (size_t i = 0; i < xs.size(); ++i) {
    const double p = b1(xs[i]), q = b2(xs[i]), r = ss[i] - xs[i] * xs[i] * xs[i];
    a11 += p * p, a12 += p * q, a22 += q * q, r1 += p * r, r2 += q * r;
  }
  Easing e;
  const double det = a11 * a22 - a12 * a12;
  if (xs.empty() || std::fabs(det) < 1e-12 * std::max(1.0, a11 * a22)) return e;
  e.y1 = (a22 * r1 - a12 * r2) / det;
  e.y2 = (a11 * r2 - a12 * r1) / det;
  if (e.y1 < 0 || e.y1 > 1) {
    e.y1 = std::clamp(e.y1, 0.0, 1.0);
    e.y2 = a22 > 0 ? (r2 - a12 * e.y1) / a22 : e.y2;
  }
  if (e.y2 < 0 || e.y2 > 1) {
    e.y2 = std::clamp(e.y2, 0.0, 1.0);
    e.y1 = a11 > 0 ? std::clamp((r1 - a12 * e.y2) / a11, 0.0, 1.0) : e.y1;
  }
  return e;
}

struct Segment {
  Easing easing;
  double max_error = 0;
  size_t worst = 0;  // the sample nearest the time it misses most
};

// Segment [a, b]: the eased interpolation's fit and its largest error over the samples inside
// and the times checked between every two samples from a to b.
Segment fit_segment(const std::vector<double>& times, const std::vector<double>& values, size_t dim, size_t a,
                    size_t b, const SampleError& error) {
  Segment seg;
  if (b <= a) return seg;
  const double* va = &values[a * dim];
  const double* vb = &values[b * dim];
  const double duration = times[b] - times[a];
  if (b > a + 1) {
    double span = 0;
    for (size_t k = 0; k < dim; ++k) span += (vb[k] - va[k]) * (vb[k] - va[k]);
    std::vector<double> xs, ss;
    for (size_t i = a + 1; i < b; ++i) {
      // The interpolation parameter that brings the line a-b closest to sample i.
      double dot = 0;
      const double* vi = &values[i * dim];
      for (size_t k = 0; k < dim; ++k) dot += (vi[k] - va[k]) * (vb[k] - va[k]);
      xs.push_back((times[i] - times[a]) / duration);
      ss.push_back(span > 0 ? dot / span : xs.back());
    }
    seg.easing = fit_easing(xs, ss);
  }
  // Every sample inside and every checked time between samples (sample i and u of the way to
  // i + 1), as the eased keys a and b draw it.
  std::vector<double> approx(dim);
  auto worst_of = [&](const Easing& e, size_t* at) {
    double worst = -1;
    for (size_t i = a; i < b; ++i)
      for (int j = i == a ? 1 : 0; j < kBetweenChecks; ++j) {
        const double u = static_cast<double>(j) / kBetweenChecks;
        const double t = times[i] + u * (times[i + 1] - times[i]);
        const double s = ease(e, duration > 0 ? (t - times[a]) / duration : 0);
        for (size_t k = 0; k < dim; ++k) approx[k] = va[k] + s * (vb[k] - va[k]);
        const double err = error(i, u, approx.data());
        if (err > worst) {
          worst = err;
          // Split at the sample nearest that time, one inside the segment.
          *at = std::clamp(u <= 0.5 ? i : i + 1, a + 1, b > a + 1 ? b - 1 : a + 1);
        }
      }
    return std::max(worst, 0.0);
  };
  // Linear unless the easing is measurably better: plain keyTimes are the simplest file.
  size_t at_eased = a, at_linear = a;
  const double linear = worst_of(Easing{}, &at_linear);
  const double eased = seg.easing.is_linear() ? linear : worst_of(seg.easing, &at_eased);
  if (linear <= eased) {
    seg.easing = Easing{};
    seg.max_error = linear;
    seg.worst = at_linear;
  } else {
    seg.max_error = eased;
    seg.worst = at_eased;
  }
  return seg;
}

}  // namespace

bool Easing::is_linear() const { return std::fabs(y1 - 1.0 / 3) < 1e-9 && std::fabs(y2 - 2.0 / 3) < 1e-9; }

double ease(const Easing& e, double x) { return b1(x) * e.y1 + b2(x) * e.y2 + x * x * x; }

SampleError point_error(const std::vector<double>& values, size_t dim, double px_per_unit) {
  return [&values, dim, px_per_unit](size_t i, double u, const double* approx) {
    const double* v = &values[i * dim];
    const double* w = u > 0 ? v + dim : v;
    double worst = 0;
    for (size_t k = 0; k + 1 < dim; k += 2)
      worst = std::max(worst, std::hypot(approx[k] - (v[k] + u * (w[k] - v[k])),
                                         approx[k + 1] - (v[k + 1] + u * (w[k + 1] - v[k + 1]))));
    return worst * px_per_unit;
  };
}

ReducedKeys reduce_keyframes(const std::vector<double>& times, const std::vector<double>& values, size_t dim,
                             double tolerance, const SampleError& error) {
  ReducedKeys r;
  const size_t n = times.size();
  if (n == 0) return r;
  if (n == 1) {
    r.keys = {0};
    return r;
  }
  // Douglas-Peucker: split at the worst sample until every segment holds.
  std::vector<char> keep(n, 0);
  keep[0] = keep[n - 1] = 1;
  std::vector<std::pair<size_t, size_t>> todo{{0, n - 1}};
  while (!todo.empty()) {
    const auto [a, b] = todo.back();
    todo.pop_back();
    const Segment s = fit_segment(times, values, dim, a, b, error);
    if (s.max_error <= tolerance || s.worst <= a || s.worst >= b) continue;
    keep[s.worst] = 1;
    todo.push_back({a, s.worst});
    todo.push_back({s.worst, b});
  }
  for (size_t i = 0; i < n; ++i)
    if (keep[i]) r.keys.push_back(i);
  // Merge: a key whose neighbours' one eased segment still holds every sample goes.
  for (size_t k = 1; k + 1 < r.keys.size();) {
    if (fit_segment(times, values, dim, r.keys[k - 1], r.keys[k + 1], error).max_error <= tolerance)
      r.keys.erase(r.keys.begin() + static_cast<std::ptrdiff_t>(k));
    else
      ++k;
  }
  for (size_t k = 0; k + 1 < r.keys.size(); ++k) {
    const Segment s = fit_segment(times, values, dim, r.keys[k], r.keys[k + 1], error);
    r.easing.push_back(s.easing);
    r.max_error = std::max(r.max_error, s.max_error);
  }
  return r;
}

std::vector<double> keyed_value(const ReducedKeys& r, const std::vector<double>& times,
                                const std::vector<double>& values, size_t dim, size_t i) {
  return keyed_at(r, times, values, dim, times[i]);
}

std::vector<double> keyed_at(const ReducedKeys& r, const std::vector<double>& times, const std::vector<double>& values,
                             size_t dim, double t) {
  size_t k = 0;
  while (k + 2 < r.keys.size() && times[r.keys[k + 1]] <= t) ++k;
  std::vector<double> out(values.begin() + static_cast<std::ptrdiff_t>(r.keys[k] * dim),
                          values.begin() + static_cast<std::ptrdiff_t>((r.keys[k] + 1) * dim));
  if (r.keys.size() < 2) return out;
  const size_t a = r.keys[k], b = r.keys[k + 1];
  const double s = ease(r.easing[k], std::clamp((t - times[a]) / (times[b] - times[a]), 0.0, 1.0));
  for (size_t j = 0; j < dim; ++j) out[j] += s * (values[b * dim + j] - values[a * dim + j]);
  return out;
}

}  // namespace svgm
