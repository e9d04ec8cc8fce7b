// Writing the fitted animation as Lottie (bodymovin JSON, animation.json), the format of app and
// web motion players (lottie-web, rlottie, ThorVG, Qt Lottie).
//
// It is fed the same data as the SMIL writer (smil_writer.h): the document's scene, the fitted
// control points per written value and the timing, so both files show the same shapes at the
// same times. The structure, chosen for what players draw most faithfully:
//   - one shape layer per path (named by its id), in the document's paint order (Lottie lists
//     the topmost layer first), holding one group with the path's subpaths (`sh`, keyframed
//     when the path was fitted, static otherwise), then its stroke (`st`: colour, opacity,
//     width, cap, join, miter limit, dashes), then its fill (`fl`: colour, opacity, rule 1
//     nonzero / 2 evenodd): a stroke listed before the fill is drawn over it, as SVG paints it;
//     gradient paints as `gs`/`gf` following their shapes (lottie_paint.h);
//   - the element's opacity as the layer's; group opacity, clip-paths and masks as
//     precompositions and track mattes (lottie_compositing.h);
//   - each of the document's top-level groups as a null layer with the identity transform,
//     parent of its paths' layers: it changes nothing drawn (the motion is baked into the path
//     keyframes, as a homography is no Lottie transform), and gives an editor one handle to move
//     or retime a part;
//   - coordinates in canvas pixels (the SVG's size after its viewBox mapping), `w` x `h` the
//     canvas; keyframes at frame time x fps, linear in between (SMIL's calcMode="linear"
//     interpolates the same numbers), a mirror written forwards then backwards;
//   - compact (LottieOptions::compact, the default of fit and export): still paths static, a
//     moving one's affine motion on its shape group's transform, the residual shape and every
//     property at the fewest eased keys (lottie_motion.h).
// Lottie has no loop flag: players loop by default (lottie-web's `loop: true`); "once" is
// noted in `meta.d` and must be asked of the player. What Lottie cannot draw is named in one
// warning (lottie_unsupported.h).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "export/smil_writer.h"
#include "raster/raster_plan.h"
#include "svgmotion/scene.h"

namespace svgm {

struct LottieOptions {
  double fps = 30;                  // the timeline's frame rate (the target video's)
  int decimals = kDefaultDecimals;  // decimal places of coordinates and widths (canvas pixels); compact: -1 measured
  std::string name;                 // the animation's `nm` (the document's file name)
  // The SMIL export of the same animation (animation.svg), when written: gradients are placed
  // as it draws them at each keyframe, following their shapes (lottie_paint.h). Without it
  // they stay where the document puts them.
  std::filesystem::path exported_svg;
  // When set, write_lottie also writes the .lottie archive here (dotlottie.h).
  std::filesystem::path dotlottie;
  // The compact export (lottie_motion.h, compact_motion.h): a path that does not move is
  // static; a moving one's affine motion is its shape group's transform (`tr`), its shape
  // keyframed only for what remains, gradients in that moving frame; every property at the
  // fewest keys within the tolerance, with bezier easing. `decimals` < 0: measured.
  bool compact = false;
  double tolerance_px = 0;  // canvas pixels; 0: compact_tolerance(the canvas)
  double residual_scale = 1;  // the residual shapes' tolerance: tolerance_px times this (kResidualScales)
};

struct LottieDocument {
  std::string json;
  std::vector<std::string> warnings;  // without a file name in front
};

// The Lottie JSON of the animation: `scene` is the document (every visible path is written,
// the fitted ones keyframed), `points` holds timing.keyframes * plan.n_cp canvas-space (x, y)
// pairs, `map` (optional) says which fitted path each document path shows and the paint order
// (smil_writer.h). Throws svgm::Error on inconsistent input (an internal error).
LottieDocument lottie_animation(const Scene& scene, const RasterPlan& plan,
                                const std::vector<double>& points, const AnimationTiming& timing,
                                const LottieOptions& options, const ExportMap* map = nullptr);

// Writes lottie_animation(...) to `out` (temporary name, then renamed); returns its warnings
// as lines naming `out`.
std::vector<std::string> write_lottie(const std::filesystem::path& out, const Scene& scene,
                                      const RasterPlan& plan, const std::vector<double>& points,
                                      const AnimationTiming& timing, const LottieOptions& options,
                                      const ExportMap* map = nullptr);

}  // namespace svgm
