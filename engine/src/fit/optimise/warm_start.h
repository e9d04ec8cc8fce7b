// The warm start of a newly activated keyframe: point tracks from the previous keyframe's
// render to the new target frame (pyramidal Lucas-Kanade, OpenCV), with forward-backward
// consistency as the certainty, condensed per group into a similarity that is composed into
// the copied homography. The fitter keeps whichever of copied and tracked fits better.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "fit/optimise/motion_model.h"
#include "svgmotion/affine.h"

namespace svgm {

struct PointTracks {
  std::vector<Vec2> to;         // tracked positions
  std::vector<double> weight;   // 0 (lost) .. 1 (forward and backward agree exactly)
  // How well the window around each point pins both directions of its motion: the smaller
  // over the larger eigenvalue of its structure tensor in the previous image (0 on a straight
  // edge, where only the motion across the edge is seen: the aperture problem; 0 where flat).
  std::vector<double> isotropy;
};

// PointTracks::isotropy of windows of radius r (pixels) centred at `at` in an 8-bit grey image
// (central differences; 0 for a point off the image or flat there).
std::vector<double> window_isotropy(const std::vector<uint8_t>& image, int width, int height,
                                   const std::vector<Vec2>& at, int r);

// prev and next: 8-bit grey images of width x height. Points in pixels (centres at +0.5).
PointTracks track_points(const std::vector<uint8_t>& prev, const std::vector<uint8_t>& next,
                         int width, int height, const std::vector<Vec2>& from);

struct Similarity {
  double scale = 1, angle = 0;
  Vec2 shift;  // y = scale · R(angle) · x + shift
};

// Weighted least-squares similarity from → to (Umeyama 1991); nothing when fewer than 3 points
// carry weight or the points are degenerate.
std::optional<Similarity> fit_similarity(const std::vector<Vec2>& from, const std::vector<Vec2>& to,
                                         const std::vector<double>& weight);

// Applies a pixel-space similarity after the homography `th` (origin, scale: the normalisation
// of kernels/motion.cl). Exact when th has no projective part, otherwise an approximation.
void compose_similarity(MotionParams& th, const Similarity& s, Vec2 origin, double scale);

// Applies a pixel-space affine map after the homography `th`, as compose_similarity. The
// result is refactored into kernels/motion.cl's R · Sh · S with shy = 0 (a QR factorisation of
// the linear part). A known motion of a wheel seen at a slant (a turn in its own tilted plane)
// is affine, not a similarity. A mirroring map (a figure turned round, its back shown) gives a
// negative sx. False, th untouched, when th has a projective part or the map is degenerate.
bool compose_affine(MotionParams& th, const Affine& m, Vec2 origin, double scale);

}  // namespace svgm
