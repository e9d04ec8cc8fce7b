// Per-path motion analysis of the compact exports (see compact_motion.h).
#include "export/compact_motion.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace svgm {

double compact_tolerance(double canvas_width, double canvas_height) {
  return kCompactTolerance1024 * std::max(canvas_width, canvas_height) / 1024.0;
}

namespace {

// The least-squares affine map from points `from` to `to` (n pairs each); a translation when
// the points span no area (a line, a lone point), where an affine map is not determined.
Affine fit_affine(const std::vector<double>& from, const double* to) {
  const size_t n = from.size() / 2;
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  Eigen::Vector3d bx = Eigen::Vector3d::Zero(), by = Eigen::Vector3d::Zero();
  double cx = 0, cy = 0, tx = 0, ty = 0;
  for (size_t i = 0; i < n; ++i) {
    cx += from[2 * i], cy += from[2 * i + 1], tx += to[2 * i], ty += to[2 * i + 1];
  }
  cx /= std::max<size_t>(n, 1), cy /= std::max<size_t>(n, 1), tx /= std::max<size_t>(n, 1), ty /= std::max<size_t>(n, 1);
  // Centred coordinates keep the normal equations well conditioned far from the origin.
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d r(from[2 * i] - cx, from[2 * i + 1] - cy, 1);
    m += r * r.transpose();
    bx += r * (to[2 * i] - tx);
    by += r * (to[2 * i + 1] - ty);
  }
  Eigen::Matrix2d s = m.topLeftCorner<2, 2>();
  if (n < 3 || s.determinant() < 1e-9 * std::max(1.0, s.trace() * s.trace()))
    return Affine::translate(tx - cx, ty - cy);
  const Eigen::Vector3d ax = m.ldlt().solve(bx), ay = m.ldlt().solve(by);
  // x' = ax0 (x - cx) + ax1 (y - cy) + ax2 + tx
  Affine a{ax(0), ay(0), ax(1), ay(1), 0, 0};
  a.e = tx + ax(2) - ax(0) * cx - ax(1) * cy;
  a.f = ty + ay(2) - ay(0) * cx - ay(1) * cy;
  return a;
}

}  // namespace

PartMotion analyse_part_motion(const std::vector<double>& rest, const std::vector<const double*>& values,
                               double tolerance, double residual_tolerance) {
  PartMotion out;
  const size_t n = rest.size() / 2;
  double moved = 0;
  for (const double* v : values)
    for (size_t i = 0; i < n; ++i)
      moved = std::max(moved, std::hypot(v[2 * i] - rest[2 * i], v[2 * i + 1] - rest[2 * i + 1]));
  if (moved <= tolerance) return out;
  out.moves = true;
  for (const double* v : values) {
    const Affine a = fit_affine(rest, v);
    out.affine.push_back(a);
    for (size_t i = 0; i < n; ++i) {
      const Vec2 p = a.apply({rest[2 * i], rest[2 * i + 1]});
      out.affine_miss_px = std::max(out.affine_miss_px, std::hypot(p.x - v[2 * i], p.y - v[2 * i + 1]));
    }
  }
  out.residual = out.affine_miss_px > (residual_tolerance > 0 ? residual_tolerance : tolerance);
  return out;
}

Affine wrapper_map(const double* p, Vec2 c, WrapperForm form) {
  const Affine linear = compose_affine({0, 0, p[2], form == WrapperForm::Smil ? p[3] : 0, p[4], p[5]});
  if (form == WrapperForm::Lottie)
    return Affine::translate(c.x + p[0], c.y + p[1]) * linear * Affine::translate(-c.x, -c.y);
  const Affine rotate_about = Affine::translate(c.x, c.y) * Affine::rotate_deg(p[2]) * Affine::translate(-c.x, -c.y);
  return Affine::translate(p[0], p[1]) * rotate_about * compose_affine({0, 0, 0, p[3], p[4], p[5]});
}

std::vector<double> wrapper_trajectory(const std::vector<Affine>& affine, const Affine& parent_to_canvas, Vec2 c,
                                       WrapperForm form) {
  const Affine to_parent = parent_to_canvas.inverse();
  std::vector<double> out;
  TransformParts prev;
  for (size_t v = 0; v < affine.size(); ++v) {
    const Affine m = to_parent * affine[v] * parent_to_canvas;
    TransformParts p = decompose_affine(m);
    if (v > 0) {
      p.rotate_deg = unwrap_degrees(p.rotate_deg, prev.rotate_deg);
      p.skew_x_deg = unwrap_degrees(p.skew_x_deg, prev.skew_x_deg);
    }
    prev = p;
    // The translation that, with the rotation about c, gives m: SMIL t = m(0) - c + R c
    // (m's own translation is m(0)); Lottie t = m(c) - c.
    Vec2 t;
    if (form == WrapperForm::Lottie) {
      t = m.apply(c) - c;
    } else {
      const Vec2 rc = Affine::rotate_deg(p.rotate_deg).apply(c);
      t = Vec2{m.e, m.f} - c + rc;
    }
    out.insert(out.end(), {t.x, t.y, p.rotate_deg, p.skew_x_deg, p.sx, p.sy});
  }
  return out;
}

Vec2 rest_centre(const std::vector<double>& rest, const Affine& parent_to_canvas) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (size_t k = 0; k + 1 < rest.size(); k += 2) {
    x0 = std::min(x0, rest[k]), x1 = std::max(x1, rest[k]);
    y0 = std::min(y0, rest[k + 1]), y1 = std::max(y1, rest[k + 1]);
  }
  if (rest.empty()) return {};
  return parent_to_canvas.inverse().apply({0.5 * (x0 + x1), 0.5 * (y0 + y1)});
}

Vec2 motion_pivot(const std::vector<Affine>& affine, const std::vector<double>& rest, const Affine& parent_to_canvas) {
  if (rest.empty()) return {};
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (size_t k = 0; k + 1 < rest.size(); k += 2) {
    x0 = std::min(x0, rest[k]), x1 = std::max(x1, rest[k]);
    y0 = std::min(y0, rest[k + 1]), y1 = std::max(y1, rest[k + 1]);
  }
  const Eigen::Vector2d c0(0.5 * (x0 + x1), 0.5 * (y0 + y1));
  // m(P) - P = (L - I) P + b: minimise the sum of its squares plus lambda |P - c0|^2.
  Eigen::Matrix2d n = Eigen::Matrix2d::Zero();
  Eigen::Vector2d r = Eigen::Vector2d::Zero();
  for (const Affine& m : affine) {
    Eigen::Matrix2d a;
    a << m.a - 1, m.c, m.b, m.d - 1;
    const Eigen::Vector2d b(m.e, m.f);
    n += a.transpose() * a;
    r -= a.transpose() * b;
  }
  const double lambda = 1e-4 * n.trace() / 2 + 1e-12;
  n += lambda * Eigen::Matrix2d::Identity();
  r += lambda * c0;
  Eigen::Vector2d p = n.ldlt().solve(r);
  const double reach = 4 * std::max(1.0, std::hypot(x1 - x0, y1 - y0));
  if (!p.allFinite()) p = c0;
  if ((p - c0).norm() > reach) p = c0 + reach * (p - c0).normalized();
  return parent_to_canvas.inverse().apply({p.x(), p.y()});
}

SampleError wrapper_error(const std::vector<double>& trajectory, const std::vector<double>& rest,
                          const Affine& parent_to_canvas, Vec2 c, WrapperForm form) {
  const Affine to_parent = parent_to_canvas.inverse();
  return [&trajectory, &rest, parent_to_canvas, to_parent, c, form](size_t i, double u, const double* approx) {
    // Between values: the two values' numbers blended, what keeping both as keys draws (the
    // full export's blend of the points cuts a turn's chord there; keyframe_reduce.h).
    double blend[6];
    for (size_t k = 0; k < 6; ++k)
      blend[k] = trajectory[6 * i + k] + (u > 0 ? u * (trajectory[6 * (i + 1) + k] - trajectory[6 * i + k]) : 0);
    const Affine exact = parent_to_canvas * wrapper_map(blend, c, form) * to_parent;
    const Affine drawn = parent_to_canvas * wrapper_map(approx, c, form) * to_parent;
    double worst = 0;
    for (size_t k = 0; k + 1 < rest.size(); k += 2) {
      const Vec2 a = exact.apply({rest[k], rest[k + 1]}), b = drawn.apply({rest[k], rest[k + 1]});
      worst = std::max(worst, std::hypot(a.x - b.x, a.y - b.y));
    }
    return worst;
  };
}

int measured_decimals(const std::vector<double>& values, size_t dim, const std::vector<size_t>& keys,
                      const SampleError& error, double budget, size_t first, size_t count, int max_decimals) {
  std::vector<double> rounded(dim);
  for (int d = 0; d < max_decimals; ++d) {
    const double f = std::pow(10.0, d);
    double worst = 0;
    for (size_t k : keys) {
      std::copy(values.begin() + static_cast<std::ptrdiff_t>(k * dim),
                values.begin() + static_cast<std::ptrdiff_t>((k + 1) * dim), rounded.begin());
      for (size_t j = first; j < first + count; ++j) rounded[j] = std::round(rounded[j] * f) / f;
      worst = std::max(worst, error(k, 0, rounded.data()));
    }
    if (worst <= budget) return d;
  }
  return max_decimals;
}

size_t WrapperKeys::key_count() const {
  size_t n = 0;
  for (const ReducedKeys& c : channel) n += c.keys.size();
  return n;
}

std::vector<double> wrapper_keyed_at(const WrapperKeys& w, const std::vector<double>& times, double t) {
  std::vector<double> out(6, 0.0);
  for (size_t c = 0; c < kWrapperChannels; ++c) {
    const std::vector<double> v = keyed_at(w.channel[c], times, w.trajectory, 6, t);
    for (size_t j = 0; j < kChannelSize[c]; ++j) out[kChannelAt[c] + j] = v[kChannelAt[c] + j];
  }
  return out;
}

namespace {

// Channel c's numbers of a trajectory of 6 per value.
std::vector<double> channel_numbers(const std::vector<double>& trajectory, size_t c) {
  std::vector<double> out;
  for (size_t v = 0; v + 5 < trajectory.size(); v += 6)
    out.insert(out.end(), trajectory.begin() + static_cast<std::ptrdiff_t>(v + kChannelAt[c]),
               trajectory.begin() + static_cast<std::ptrdiff_t>(v + kChannelAt[c] + kChannelSize[c]));
  return out;
}

// Channel c's error: its numbers `approx` with the other channels at the exact blend, so each
// channel is measured by what it alone moves the rest points.
SampleError channel_error(const std::vector<double>& exact, const SampleError& error, size_t c) {
  return [&exact, &error, c](size_t i, double u, const double* approx) {
    double full[6];
    for (size_t k = 0; k < 6; ++k)
      full[k] = exact[6 * i + k] + (u > 0 ? u * (exact[6 * (i + 1) + k] - exact[6 * i + k]) : 0);
    for (size_t j = 0; j < kChannelSize[c]; ++j) full[kChannelAt[c] + j] = approx[j];
    return error(i, u, full);
  };
}

// Calls f(i, u, t) at every value and at the kBetweenChecks - 1 times checked between two.
template <typename F>
void for_checked_times(const std::vector<double>& times, F&& f) {
  for (size_t i = 0; i < times.size(); ++i)
    for (int j = 0; j < (i + 1 < times.size() ? kBetweenChecks : 1); ++j) {
      const double u = static_cast<double>(j) / kBetweenChecks;
      f(i, u, u > 0 ? times[i] + u * (times[i + 1] - times[i]) : times[i]);
    }
}

// Channel c's keys within `budget`: one constant (each number's midrange) when that holds,
// else the reduction's. The constant is written into row 0 of `trajectory`.
ReducedKeys channel_keys(std::vector<double>& trajectory, const std::vector<double>& exact, const SampleError& error,
                         const std::vector<double>& times, size_t c, double budget) {
  const size_t n = kChannelSize[c], at = kChannelAt[c];
  const std::vector<double> numbers = channel_numbers(exact, c);
  const SampleError err = channel_error(exact, error, c);
  double constant[2];
  for (size_t j = 0; j < n; ++j) {
    double lo = 1e300, hi = -1e300;
    for (size_t v = j; v < numbers.size(); v += n) lo = std::min(lo, numbers[v]), hi = std::max(hi, numbers[v]);
    constant[j] = 0.5 * (lo + hi);
  }
  double worst = 0;
  for_checked_times(times, [&](size_t i, double u, double) { worst = std::max(worst, err(i, u, constant)); });
  if (worst <= budget) {
    for (size_t j = 0; j < n; ++j) trajectory[at + j] = constant[j];
    ReducedKeys one;
    one.keys = {0};
    one.max_error = worst;
    return one;
  }
  ReducedKeys r = reduce_keyframes(times, numbers, n, budget, err);
  for (size_t j = 0; j < n; ++j) trajectory[at + j] = exact[at + j];
  return r;
}

}  // namespace

WrapperKeys wrapper_keys(const std::vector<Affine>& affine, const Affine& parent_to_canvas, const std::vector<double>& rest,
                         const std::vector<double>& times, double tolerance, int decimals, Vec2 centre, WrapperForm form) {
  WrapperKeys w;
  w.trajectory = wrapper_trajectory(affine, parent_to_canvas, centre, form);
  const std::vector<double> exact = w.trajectory;
  const SampleError err = wrapper_error(exact, rest, parent_to_canvas, centre, form);
  // The composed transform's largest miss, every channel as its keys draw it.
  auto composed_error = [&] {
    double worst = 0;
    for_checked_times(times, [&](size_t i, double u, double t) {
      worst = std::max(worst, err(i, u, wrapper_keyed_at(w, times, t).data()));
    });
    return worst;
  };
  // Each channel's own error adds to the others' in the composed transform; the budgets start at
  // the whole tolerance (one channel moving: the others are exact) and shrink until the sum holds.
  // Rounds: 0.8 of the tolerance over the miss each, at least halving the budgets within six.
  double budget = tolerance;
  bool held = false;
  for (int round = 0; round < 6 && !held; ++round) {
    for (size_t c = 0; c < kWrapperChannels; ++c) w.channel[c] = channel_keys(w.trajectory, exact, err, times, c, budget);
    const double miss = composed_error();
    held = miss <= tolerance;
    budget *= std::clamp(0.8 * tolerance / std::max(miss, 1e-300), 0.25, 0.9);
  }
  // Shared keys: the whole transform reduced at once, within the tolerance by construction. Kept
  // when they write fewer numbers (a time and the channel's numbers per key, a channel that never
  // changes at the shared keys written once), e.g. when the channels all turn at the same times.
  const ReducedKeys shared = reduce_keyframes(times, exact, 6, tolerance, err);
  size_t own_numbers = 0, shared_numbers = 0;
  for (size_t c = 0; c < kWrapperChannels; ++c) {
    own_numbers += w.channel[c].keys.size() * (kChannelSize[c] + 1);
    bool changes = false;
    for (size_t k : shared.keys)
      for (size_t j = 0; j < kChannelSize[c]; ++j)
        changes = changes || exact[6 * k + kChannelAt[c] + j] != exact[6 * shared.keys[0] + kChannelAt[c] + j];
    shared_numbers += (changes ? shared.keys.size() : 1) * (kChannelSize[c] + 1);
  }
  if (!held || shared_numbers <= own_numbers) {
    w.trajectory = exact;
    for (ReducedKeys& c : w.channel) c = shared;
  }
  // Rounding is measured against the written numbers (exact at every kept key, a constant's
  // midrange), with the tolerance of the finest use (a path without a residual keeps its motion
  // within `tolerance`; the budgets are shares of it).
  const std::vector<double> written = w.trajectory;
  const SampleError round_err = wrapper_error(written, rest, parent_to_canvas, centre, form);
  const int max_decimals = 8;
  auto places = [&](size_t c, double share) {
    return measured_decimals(written, 6, w.channel[c].keys, round_err, share, kChannelAt[c], kChannelSize[c], max_decimals);
  };
  w.translate_decimals = decimals >= 0 ? decimals : places(kTranslate, tolerance / 4);
  w.rotate_decimals = places(kRotate, tolerance / 8);
  w.skew_decimals = places(kSkew, tolerance / 8);
  w.scale_decimals = places(kScale, tolerance / 8);
  const int channel_places[kWrapperChannels] = {w.translate_decimals, w.rotate_decimals, w.skew_decimals, w.scale_decimals};
  for (size_t c = 0; c < kWrapperChannels; ++c) {
    const double f = std::pow(10.0, channel_places[c]);
    for (size_t k : w.channel[c].keys)
      for (size_t j = 0; j < kChannelSize[c]; ++j) {
        double& x = w.trajectory[6 * k + kChannelAt[c] + j];
        x = std::round(x * f) / f;
        if (x == 0) x = 0;  // no "-0"
      }
  }
  const Affine to_parent = parent_to_canvas.inverse();
  for (size_t v = 0; v < affine.size(); ++v) {
    const std::vector<double> p = wrapper_keyed_at(w, times, times[v]);
    w.drawn.push_back(parent_to_canvas * wrapper_map(p.data(), centre, form) * to_parent);
  }
  return w;
}

}  // namespace svgm
