// Fewest keyframes for a sampled motion: which of a trajectory's samples to keep, and the easing
// curve between two kept ones, so that what a player interpolates stays within a tolerance of
// every dropped sample. Used by the compact SMIL and Lottie exports (compact_export.h).
//
// A trajectory is n samples of a vector of d numbers (control points, transform parameters) at
// increasing times. A player draws, between kept keys a and b at the time fraction x, the
// numbers v_a + s (v_b - v_a) with s = ease(x) (SMIL calcMode="spline" keySplines; Lottie's "o"
// and "i" handles). The reduction is Douglas-Peucker in time: the segment [first, last] is
// tried with the easing fitted to its samples; the sample it misses most splits it, until every
// sample is within the tolerance; then neighbouring segments are merged where one eased segment
// still holds every sample. The error of a sample is the caller's (`SampleError`), in pixels of
// the drawing.
//
// What the keys replace is not only the samples: the full export draws every time between two
// samples too, blending them linearly, and a player shows those times (the tolerance's measure
// renders ten times of a pass, which mostly fall between samples). An eased curve through every
// sample can leave that blend by far more than the tolerance between them (an ease-in-out
// through samples a third of a segment apart misses the straight line between the first two by
// over 5 % of its travel). So each segment is also measured at kBetweenChecks - 1 times evenly
// inside every interval of samples it replaces, against the two samples' numbers blended there
// (what keeping both as keys draws), and is split at the nearest sample when it misses. For
// points that blend is the full export's; for a transform's numbers it turns along an arc where
// the full export's blend of the points cuts the chord, a gap no choice of keys at samples
// closes (it shrinks with the square of the angle turned between two values).
//
// The easing is a cubic Bezier from (0,0) to (1,1) with handles (1/3, y1) and (2/3, y2): its x
// is then the time fraction itself, so ease(x) = 3(1-x)^2 x y1 + 3(1-x) x^2 y2 + x^3, linear in
// (y1, y2) and fitted by least squares to the samples' best interpolation parameters. y1, y2
// stay in [0, 1] (SMIL requires it), which spans linear (1/3, 2/3), ease-in, ease-out and
// ease-in-out (0, 1: smoothstep).
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

namespace svgm {

struct Easing {
  double y1 = 1.0 / 3, y2 = 2.0 / 3;  // linear
  bool is_linear() const;
};
// s at the time fraction x in [0, 1].
double ease(const Easing& e, double x);

// How far (pixels of the drawing) the interpolated numbers `approx` (d of them) draw from
// samples i and i + 1's numbers blended linearly at the fraction u in [0, 1) of the way between
// them (u = 0: sample i itself; u > 0 only for i + 1 < n).
using SampleError = std::function<double(size_t i, double u, const double* approx)>;
// Times checked per interval between two samples: kBetweenChecks - 1 evenly inside it (a
// quarter, a half and three quarters of the way; a cubic's gap from a straight line between its
// ends is largest near the middle).
constexpr int kBetweenChecks = 4;
// The usual error: the numbers are (x, y) pairs of points, in units that are `px_per_unit`
// pixels, blended linearly between samples; the largest distance of a point from the blend's.
SampleError point_error(const std::vector<double>& values, size_t dim, double px_per_unit);

struct ReducedKeys {
  std::vector<size_t> keys;    // indices of the kept samples, increasing, first and last included
  std::vector<Easing> easing;  // per segment between kept keys (keys.size() - 1)
  double max_error = 0;        // the largest error of any sample or time between, as the keys draw it
};

// Reduces `values` (n samples x dim, row-major) at `times` (n, increasing) to the fewest keys
// this method finds within `tolerance` of every sample and of the checked times between
// samples. n >= 1; one sample keeps one key.
ReducedKeys reduce_keyframes(const std::vector<double>& times, const std::vector<double>& values, size_t dim,
                             double tolerance, const SampleError& error);

// The numbers the reduced keys draw at sample time times[i] (dim of them), as a player does.
std::vector<double> keyed_value(const ReducedKeys& r, const std::vector<double>& times,
                                const std::vector<double>& values, size_t dim, size_t i);
// The same at any time t (held at the first and last keys outside them).
std::vector<double> keyed_at(const ReducedKeys& r, const std::vector<double>& times, const std::vector<double>& values,
                             size_t dim, double t);

}  // namespace svgm
