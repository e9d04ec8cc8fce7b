// In-between shapes: the fitted keyframes joined by a smooth curve in time, sampled at the
// target's own frames between them.
//
// A browser interpolates SMIL `values` linearly, so with 15 keyframes over 49 frames a motion
// that curves in time (a swing, a wave) cuts its corners between keyframes, and the in-between
// frames lag the target by several dB. Instead of leaving that to the browser, the export
// evaluates a cubic Hermite spline through the keyframes (Bessel tangents: the slope of the
// parabola through keyframes k-1, k, k+1, which is Catmull-Rom's for even spacing and exact for
// quadratic motion at uneven spacing; one-sided at the ends, wrapping around for a closed
// loop) at the times of the target frames between them, and writes those
// as extra values. Every fitted keyframe is kept exactly; the browser's linear interpolation
// then only spans one frame.
#pragma once

#include <cstddef>
#include <vector>

namespace svgm {

struct InBetween {
  std::vector<double> times;   // increasing, in [0, 1]; the keyframes' times among them
  std::vector<double> points;  // times.size() * per_key numbers
};

// `points`: K * per_key numbers (keyframe k's control points); `times`: K increasing key times
// in [0, 1]; `frames`: the times of the target's frames (the candidates for in-betweens);
// at most `max_per_interval` frames (evenly chosen) are added between two keyframes the mean
// interval apart, proportionally more (rounded up) between two further apart.
// `closed`: the motion returns to its start and goes on through it; the last keyframe is
// written as the first one's shape.
InBetween in_between(const std::vector<double>& points, const std::vector<double>& times,
                     std::size_t per_key, const std::vector<double>& frames, int max_per_interval,
                     bool closed);

}  // namespace svgm
