// The local part of a keyframe's warm start: the displacement-field increment that carries
// each tracked point where the tracks say it went, beyond its group's homography.
//
// A group's homography warm start (warm_start.h) condenses the tracks into one similarity per
// group; a feature that moves against its part (an eye carried off by a face that stretches)
// keeps the previous keyframe's place, and when that is a few pixels off at the fitting size,
// the blurred loss has no gradient to bring it back: it flattens where it is instead (octopus
// on an off-white video: the left eye moved 3.4 px at 256 px between keyframes 2 and 3, was
// lost there and flattened to a line in six keyframes; with keyframes twice as dense, 25, it
// was followed). The tracks say where such features went. This solves, for the field
// coefficients c of every node (kernels/field.cl),
//
//     min  Σ_i w_i ‖Σ_b W_ib c_b − d_i‖²  +  λ Σ_(a,b,c) ‖c_a − 2 c_b + c_c‖²  +  μ Σ_b ‖c_b‖²
//
// with d_i the offset (in the field's own units, before the homography) that takes point i to
// its track, w_i the track's certainty, the field's discrete bending energy (second differences
// of neighbouring nodes, FitPlan::node_bend: zero for every affine field, so a feature's shift
// spreads smoothly into the nodes around it, and where tracked points nearby stay, it stays a
// local bend) and a small ridge that keeps nodes no track reaches at zero. Only tracks whose
// window pins both directions count (PointTracks::isotropy): along a straight edge the tracker
// cannot see motion, and its answer there is noise. x and y are independent and share one
// sparse symmetric positive definite matrix: Eigen's sparse LDLT.
//
// I also tried the bending energy as a regulariser of the fit itself (its own kernel, and nodes
// at the knots inside each part so an eye is tied to the outline around it): it resisted the
// real bends of tentacles more than it held the eye. Octopus on the off-white video, coarse
// fit, mean 256 px PSNR: 47.81 without, 46.82 / 45.16 / 40.86 at weights 0.01 / 0.1 / 1.
#pragma once

#include <optional>
#include <vector>

#include "fit/plan/fit_plan.h"
#include "svgmotion/affine.h"

namespace svgm {

struct FieldTargets {
  std::vector<int> point;       // control points (owning their offset slot) with a track
  std::vector<Vec2> offset;     // d_i: the field offset that would put the point on its track
  std::vector<double> weight;   // w_i > 0
};

// The increment of every node's coefficients ([n_nodes]); all zero when nothing is tracked;
// nothing when the solve fails.
std::optional<std::vector<Vec2>> fit_field_increment(const FitPlan& plan, const FieldTargets& targets, double lambda,
                                      double mu);

}  // namespace svgm
