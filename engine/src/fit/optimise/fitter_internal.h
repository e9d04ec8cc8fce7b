// What the fitter's files share (fitter.cpp sets up and runs the iterations,
// fitter_schedule.cpp activates keyframes and tests for the plateau, fitter_warm_start.cpp
// carries a newly active keyframe toward its target, fitter_state.cpp copies keyframes between
// fits and saves and restores the state): the kernels' layout constants. Not part of the
// engine's interface: include it only from those files.
#pragma once

#include <array>

namespace svgm::fitter_internal {

inline constexpr int kMotionParams = 12;  // MOTION_PARAMS in kernels/motion.cl
inline const std::array<float, 4> kWhite{1, 1, 1, 1};

}  // namespace svgm::fitter_internal
