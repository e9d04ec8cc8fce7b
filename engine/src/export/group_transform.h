// Group motion as SVG transforms (fit --group-transforms): each group's fitted homography, where
// it is affine, written as <animateTransform> elements instead of being baked into every path's
// keyframe shapes, so a designer can retime or tweak one part.
//
// SMIL's animateTransform has no type="matrix", only translate, rotate, skewX, skewY and scale,
// so an affine map is written as the product translate(tx ty) rotate(θ) skewX(κ) scale(sx sy):
// several animateTransform elements with additive="sum", which SVG post-multiplies in document
// order onto the element's own transform. That product is the QR decomposition of the linear
// part (rotation times an upper-triangular matrix), unique for a non-singular map with sx > 0;
// a mirror shows as sy < 0. The angle is unwrapped from one value to the next (within 180°) so
// the browser's linear interpolation never spins the long way round.
//
// Between keyframes the fitter's motion is the in-betweens' spline (inbetween.h); the group's
// transform parameters are splined the same way at the same times, and each path's residual
// (its points in the group's moving frame: per-path offsets and the displacement field) is what
// remains, so transform times residual equals the baked shape at every written time.
#pragma once

#include <string>
#include <vector>

#include "fit/plan/fit_plan.h"
#include "fit/optimise/motion_model.h"
#include "raster/raster_plan.h"
#include "svgmotion/affine.h"

namespace svgm {

// m = translate(tx ty) rotate(rotate_deg) skewX(skew_x_deg) scale(sx sy), as SVG writes it.
struct TransformParts {
  double tx = 0, ty = 0, rotate_deg = 0, skew_x_deg = 0, sx = 1, sy = 1;
};
TransformParts decompose_affine(const Affine& m);
Affine compose_affine(const TransformParts& p);
// `deg` plus the multiple of 360 that brings it within 180 of `previous`.
double unwrap_degrees(double deg, double previous);

// A homography counts as affine when it departs from its best affine map by no more than this
// anywhere on its group's bounding box (pixels at the fitting size): half a pixel, below what
// the fit resolves. The residual absorbs the difference exactly at the written times either way.
constexpr double kAffineTolerancePx = 0.5;

// The affine map closest to the motion model's homography `th` (motion_model.h) over the pixel
// box (x0, y0)-(x1, y1) (least squares through a 5 x 5 grid of its points), in canvas space
// (`view` maps canvas to the fitting pixels, `origin` and `scale` as the motion model's), and
// the largest distance in pixels between the two on that grid.
struct GroupAffine {
  Affine canvas;
  double projective_px = 0;
};
GroupAffine group_affine(const MotionParams& th, Vec2 origin, double scale, const Affine& view, double x0,
                         double y0, double x1, double y1);

// What the SMIL writer is given: for every fitted path (index into the plan's paths), whether
// its group's motion is written as transforms and, per written value, the group's canvas-space
// affine map (values * plan paths, value-major). The path's `d` values then hold its points
// mapped back through that map.
struct PathMotion {
  int values = 0;
  std::vector<char> as_transform;  // per plan path
  std::vector<Affine> motion;      // values * plan paths
  const Affine& at(int value, int path) const {
    return motion[static_cast<size_t>(value) * as_transform.size() + static_cast<size_t>(path)];
  }
};

// The transform export of one fit: `params` holds K keyframes of every group's 12 motion
// parameters (FitState::params, at the fitting size `width` x `height`, `view` canvas to
// pixels); `key_times`, `frame_times`, `max_inbetweens` and `closed` are what in_between()
// was given for the written points, whose times are `written_times` (checked). Groups whose
// homography is not affine at some keyframe (or is singular) stay baked and are named in
// `baked` with the reason.
struct GroupMotionExport {
  PathMotion paths;
  int transform_groups = 0;
  std::vector<std::string> baked;  // "<group id>: <why>"
};
GroupMotionExport group_motion_export(const FitPlan& fplan, const RasterPlan& plan, const std::vector<float>& params,
                                      int keyframes, const Affine& view, int width, int height,
                                      const std::vector<double>& key_times, const std::vector<double>& frame_times,
                                      int max_inbetweens, bool closed, const std::vector<double>& written_times);

}  // namespace svgm
