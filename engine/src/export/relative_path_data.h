// The shortest path data of the compact export's animated `d` values: each subpath's start
// absolute ("M x y"), its cubics relative to their start under one implicit "c", numbers without
// a leading zero or a separator before a minus sign. The relative numbers are the differences
// of the absolute coordinates rounded to `decimals` places, taken in whole units of the last
// place, so a player summing them draws exactly the rounded absolute points (no drift along a
// long subpath; a closed subpath's last cubic is absolute, so it ends exactly where it started),
// and every value of an animation has the same commands: SMIL blends two values
// number by number, and a blend of relative numbers is the blend of the absolute points. On the
// bench parrot's twelve residual paths this writes 0.6 of path_data's bytes.
#pragma once

#include <string>

#include "svgmotion/affine.h"
#include "svgmotion/scene.h"

namespace svgm {

// `cp`: the path's control points (canvas space, the subpaths' points in order), mapped into
// the element's coordinates by `to_local`; `decimals` 0..kMaxDecimals.
std::string relative_path_data(const Path& path, const double* cp, const Affine& to_local, int decimals);

}  // namespace svgm
