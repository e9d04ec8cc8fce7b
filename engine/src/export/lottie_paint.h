// SVG paint servers as Lottie paint items: linear and radial gradients as a gradient fill (`gf`)
// or gradient stroke (`gs`), with the gradient's geometry at each written value so that it
// follows its shape as the exported SVG draws it (a bounding-box gradient with its box, a
// user-space one with the gradientTransform the SMIL writer animates).
//
// Lottie places a gradient by a start and an end point in the shape's own space (a radial one:
// centre, a point on its circle, and the focal point as a highlight length and angle), with no
// gradient transform. So:
//   - a linear gradient under any affine map stays linear: its start and end are written in
//     canvas space, the end chosen along the colour's steepest direction (exact);
//   - a radial gradient under a similarity stays a circle: written in canvas space (exact);
//   - a radial gradient under any other map is an ellipse: the fill is drawn by the shapes in a
//     group whose transform is the gradient's map, the shapes themselves inside a group with the
//     inverse map (so they land where they were), the map split as rotate-scale-rotate (Lottie
//     transforms have rotation and scale in every player; skew is read differently by some).
//     A stroke cannot be drawn that way (its width would be scaled too): an elliptical gradient
//     stroke is drawn with a circle of the same area and named as approximate;
//   - reflect and repeat spreads are written as pad spreads holding the repeated stops over the
//     range the shape covers (exact for linear gradients and focus-free radial ones).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "export/lottie_json.h"
#include "svgmotion/scene.h"

namespace svgm::lottie {

// A gradient paint over the written values: `values` holds one gradient (static) or one per
// written value, `frames` their frame numbers on the Lottie timeline (same length).
struct GradientTrack {
  std::vector<const Gradient*> values;
  std::vector<double> frames;
  // The compact export (compact_motion.h): only the fewest keys (eased) that place the
  // gradient within `tolerance_px` canvas pixels at every value are written, none when it stays
  // within that of its first value; 0: every value, linear.
  double tolerance_px = 0;
};

// The document as the exported SVG (animation.svg) draws it at each of `times` (seconds): the
// gradients there follow their shapes as the SMIL writer moves them. Empty when `svg` is empty
// or unreadable, or when it does not hold `scene`'s paths with the same paints (the Lottie
// export then keeps each gradient where the document puts it).
std::vector<Scene> sample_exported_svg(const std::filesystem::path& svg, const Scene& scene,
                                       const std::vector<double>& times);

// The fill (or stroke) gradient of scene path `path` over the written values: value i shows
// `samples[sample_of_value[i]]` at frame `frames[i]`; static (the scene's own) without samples.
// Empty when the path's paint is no gradient.
GradientTrack gradient_track(const Scene& scene, const std::vector<Scene>& samples, size_t path, bool stroke,
                             const std::vector<int>& sample_of_value, const std::vector<double>& frames);

// What a path's paint items need besides the path: its gradients (an empty track: a flat
// colour) and the canvas-space control points of each written value (for the range a
// repeating gradient must cover; one entry when static).
struct PaintInputs {
  GradientTrack fill, stroke;
  std::vector<const double*> points;  // each: the path's (x, y) pairs, subpath after subpath
};

// Writes the path's stroke and fill items (stroke first: Lottie draws an earlier item on top,
// SVG the stroke over the fill) after its shape items, which `j` holds from `shapes_begin` to
// its end. An elliptical radial fill regroups the shapes (see above). What cannot be written
// exactly is appended to `approximate` ("radial gradient stroke on #id drawn circular").
void write_paint_items(JsonText& j, size_t shapes_begin, const Path& path, const PaintInputs& in,
                       std::vector<std::string>& approximate);

// The rotate-scale-rotate split of an affine map's linear part (a 2x2 SVD): m = R(rotate1)
// diag(sx, sy) R(rotate2), angles in degrees; sy < 0 for a reflection.
struct RotateScaleRotate {
  double rotate1 = 0, sx = 1, sy = 1, rotate2 = 0;
};
RotateScaleRotate split_affine(const Affine& m);

}  // namespace svgm::lottie
