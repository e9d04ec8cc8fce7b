// The motion model on the host, in double precision: the same map as kernels/motion.cl, for
// building known-motion targets, composing warm starts and checking the kernels.
#pragma once

#include <array>

#include "svgmotion/affine.h"

namespace svgm {

// tx, ty, rot, sx, sy, shx, shy, px, py, cx, cy (+ 1 padding): kernels/motion.cl's layout.
using MotionParams = std::array<double, 12>;

MotionParams identity_params(double cx = 0, double cy = 0);

// x̂ = o + s · π(H · [(x − o)/s, 1]) for a point x in pixels, with o the canvas centre
// (origin) and s half the canvas width.
Vec2 apply_motion(const MotionParams& th, Vec2 x, Vec2 origin, double scale);

}  // namespace svgm
