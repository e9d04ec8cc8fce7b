// Small shapes a bending region carries move rigidly (issue 35: "a small shape lying on a moving
// part moves with the part that carries it, not bent across or notched").
//
// A region bend (region_bend.h) moves every point of the paths it bends by the mesh under it: an
// eye on a nodding head, a spot on a giraffe's bending neck, a shell drawn on a body take the
// mesh's deformation point by point, and where the bend's band crosses them they are stretched
// on one side and squeezed on the other (motion.json's rigid bodies counted such paths in 15 of
// the suite's 86 runs). Here a closed subpath that lies inside the fill of another bent path
// painted before it (all its on-curve points within that fill), and is small beside the bent
// part (its box's diagonal at most kCarriedShare of the part's), is a shape carried by the bend:
// in every frame its points take the best rigid motion (rotation and translation, least squares)
// of their bent positions, and the line art riding on it (detail_binding.h) with them. A limb
// drawn as a subpath of its own reaching out of the body is not inside another fill: it bends.
#pragma once

#include <cstddef>
#include <vector>

#include "svgmotion/scene.h"

namespace svgm {

inline constexpr double kCarriedShare = 0.25;

// `bend_size[p]`: the diagonal of the part whose region bend moves path p point by point (0: no
// bend moves it); `rides_on[p][k]`: the path whose motion point k of path p takes, or -1 (its
// own; detail_binding.h, may be empty for a path). Returns the carried shapes, each as the
// indices of its points within one frame (animate_plan's layout: the paths' subpaths' points in
// order).
std::vector<std::vector<size_t>> carried_shapes(const Scene& scene, const std::vector<double>& bend_size,
                                                const std::vector<std::vector<int>>& rides_on);

// Each shape's points in each of `frames` frames of `pts` replaced by the best rigid motion of
// their rest positions (the scene's) onto them.
void keep_carried_rigid(const Scene& scene, const std::vector<std::vector<size_t>>& shapes, int frames, std::vector<Vec2>& pts);

}  // namespace svgm
