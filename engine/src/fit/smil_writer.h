// Writing the fitted animation back into the user's own document as SMIL path animation.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "raster/raster_plan.h"
#include "svgmotion/scene.h"

namespace svgm {

struct AnimationTiming {
  int keyframes = 0;
  double duration_s = 2;  // one loop
};

// Writes `out`: the document `source` with every animatable path given
// <animate attributeName="d" values="d_0;...;d_K-1" keyTimes="0;...;1" dur=".." calcMode="linear"
// repeatCount="indefinite"/>, its keyframe shapes in the element's own coordinates (group
// motion baked in, the element's and its ancestors' transforms untouched). Basic shapes (rect,
// circle, ellipse, line, polyline, polygon) become <path> elements with the same id, paint and
// transform, since only paths have a `d`. Shapes drawn through <use> are left static (they
// are shared) and listed in the returned warnings. `points` holds K * plan.n_cp canvas-space
// (x, y) pairs (Fitter::keyframe_points_canvas). Written to a temporary name and renamed.
std::vector<std::string> write_animation_svg(const std::filesystem::path& source,
                                             const Scene& scene, const RasterPlan& plan,
                                             const std::vector<double>& points,
                                             const AnimationTiming& timing,
                                             const std::filesystem::path& out);

// The `d` of one path from its control points (canvas space), mapped into the element's
// coordinates by `to_local`: "M x y C x y x y x y ... Z" per subpath.
std::string path_data(const Path& path, const double* cp, const Affine& to_local);

}  // namespace svgm
