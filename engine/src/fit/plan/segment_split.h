// Long Bézier segments split before fitting, so a warped outline can bend where it bends.
//
// The fitter moves a drawing's own control points. A long cubic (a trouser leg's inner edge
// drawn as one segment, a kite string, a background's side) can only take the shapes a single
// cubic has, and a video's non-rigid motion bends it into an S that no single cubic draws:
// woman_wave fitted to a non-rigid target left the inner edge of a bent leg straight across
// the gap between the legs (worst keyframe at 1024 px 33.95 dB, boundary F 0.935). De
// Casteljau's construction splits a cubic at any t into two that draw exactly the same curve,
// so splitting costs nothing at rest and gives the fit the points the motion needs (the same
// drawing with every segment longer than 4 % of the canvas split in two: 36.67 dB, F 0.970).
//
// The split is decided once, on the scene as read, as a plan (pieces per segment), and the
// same plan is applied to whatever document the animation is written into, so the written
// paths have exactly the fitted structure. At rest every written path draws what the
// original drew; its `d` has more segments.
#pragma once

#include <vector>

#include "svgmotion/scene.h"

namespace svgm {

// pieces[path][subpath][segment] >= 1.
using SplitPlan = std::vector<std::vector<std::vector<int>>>;

// Each cubic segment whose control polygon is longer than `max_length` (canvas units) is cut
// into ceil(length / max_length) pieces of equal parameter, at most `max_pieces`.
// max_length <= 0: no segment is split.
SplitPlan plan_segment_split(const Scene& scene, double max_length, int max_pieces = 4);

// The path with its segments cut as `pieces` says (one entry per subpath, one per segment);
// exact: the pieces draw the original curve. Throws svgm::Error("internal: ...") when the
// plan does not fit the path's structure.
Path split_path(const Path& path, const std::vector<std::vector<int>>& pieces);

// Every path of `scene` split by its entry of `plan` (plan.size() == scene.paths.size()).
Scene split_scene(const Scene& scene, const SplitPlan& plan);

// Control points added by `plan` (for the log).
int added_points(const SplitPlan& plan);

}  // namespace svgm
