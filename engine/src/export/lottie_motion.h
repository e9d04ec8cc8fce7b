// The compact Lottie export's motion of one path (compact_motion.h, the same analysis and
// keyframe reduction as the compact animation.svg): nothing when the path does not move; a
// moving path's affine motion as its shape group's transform (`tr`: position, anchor at the
// rest shape's centre, rotation, scale, keyed with bezier easing), and its shape keyframed only
// when it changes beyond the tolerance in that moving frame (the residual), at the fewest keys.
//
// Lottie's transform has no skew that every player reads alike, so a motion whose skew moves a
// point by more than the tolerance keeps the skew in the residual shape. The transform is on a
// group holding only the shapes; the paints after it apply in the canvas' frame, so gradients
// keep the placement animation.svg draws and strokes their width, as in the full export.
#pragma once

#include <string>
#include <vector>

#include "export/compact_motion.h"
#include "export/keyframe_reduce.h"

namespace svgm::lottie {

struct CompactPathMotion {
  bool moves = false;     // false: the rest shape, static, identity transform
  bool residual = false;  // the shape is keyframed (its values in `local`, keys in `shape_keys`)
  std::string transform;  // the shapes' group's `tr` item (moving)
  std::vector<Affine> drawn;  // moving: per value, the group's map as players draw it (canvas)
  std::vector<double> local;  // residual: per value, the shape's 2 * count numbers in the group's frame
  ReducedKeys shape_keys;     // residual: the kept values and their easing
  int shape_decimals = 3;     // residual: the coordinates' measured decimals
  double px_per_unit = 1;     // the largest scale of `drawn` (a local unit in canvas pixels)
  size_t transform_keys = 0;  // keys of the transform (moving)
};

// `rest`: the document's control points (canvas, n pairs); `values`: the written values' (n
// pairs each) at pass times `times`, frame `times[i] * frames` on the timeline. `decimals` >= 0
// fixes the decimals of coordinates, -1 measures them (a quarter of the tolerance, as the SVG's).
// The residual shape is written and reduced within `tolerance * residual_scale` (kResidualScales).
CompactPathMotion compact_path_motion(const std::vector<double>& rest, const std::vector<const double*>& values,
                                      const std::vector<double>& times, double frames, double tolerance, int decimals,
                                      double residual_scale = 1);

}  // namespace svgm::lottie
