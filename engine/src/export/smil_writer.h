// Writing the fitted animation back into the user's own document as SMIL path animation.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "export/group_transform.h"
#include "raster/raster_plan.h"
#include "svgmotion/scene.h"

namespace svgm {

// How the animation repeats: `loop` (forever, from the start again), `once` (plays once and
// holds the last pose) or `mirror` (forever, forwards then backwards).
enum class LoopMode { Loop, Once, Mirror };
// "loop" / "once" / "mirror" -> the mode; throws svgm::Error naming `what` otherwise.
LoopMode parse_loop_mode(const std::string& text, const std::string& what);
const char* loop_mode_name(LoopMode m);

// Decimal places of the exported coordinates (stages.fitter.precision, fit --precision): 3 is
// 1/1000 of a user unit, well below a pixel at any sensible size; fewer make smaller files
// (1/100 of a unit is still a hundredth of a pixel in a drawing whose unit is a pixel).
constexpr int kDefaultDecimals = 3;
constexpr int kMaxDecimals = 6;  // beyond a float's precision for coordinates of thousands

struct AnimationTiming {
  int keyframes = 0;
  // The time of each keyframe as a fraction of one pass, from 0 to 1 and increasing: the times
  // of the target frames it was fitted to (empty: uniform k / (K-1)).
  std::vector<double> key_times;
  double duration_s = 2;  // one pass
  LoopMode loop = LoopMode::Loop;
  // The target ends where it began: the last keyframe is written as the first one, so the loop
  // restarts without a jump.
  bool close_loop = false;
};

// One pass of the animation as written: the keyframe shown at each value (seq, indices into the
// keyframes), its time as a fraction of the pass (times, 0 to 1, increasing) and the pass's
// length. 0..K-1 (a closed loop shows keyframe 0's shape in the last place); a mirror goes on
// back to 0 over twice the duration. Every exporter (SMIL, Lottie) writes this same pass.
struct AnimationPass {
  std::vector<int> seq;
  std::vector<double> times;
  double duration_s = 0;
};
AnimationPass animation_pass(const AnimationTiming& timing);

struct ExportMap;

// What every animation writer (SMIL, Lottie) checks of its inputs: K >= 1 keyframes of the
// plan's points, key times per keyframe, an export map covering the document, decimals in
// 0..kMaxDecimals. Throws svgm::Error("internal: ...").
void check_animation_inputs(const Scene& scene, const RasterPlan& plan, const std::vector<double>& points,
                            const AnimationTiming& timing, const ExportMap* map, int decimals);

// How the fitted paths map onto the document written into (when it is not the fitted SVG
// itself): fitted_of[i] is the fitted path (index into the plan's paths) drawn by the
// document's path i, or -1 to leave it static; `order`, when not empty, is the paint order to
// apply (back to front, indices into the document's paths; see document_order.h).
struct ExportMap {
  std::vector<int> fitted_of;
  std::vector<int> order;
};

// Writes `out`: the document `source` with every animatable path given
// <animate attributeName="d" values="d_0;...;d_K-1" keyTimes=".." dur=".." calcMode="linear"
// repeatCount="indefinite"/>, its keyframe shapes in the element's own coordinates (group
// motion baked in, the element's and its ancestors' transforms untouched). Basic shapes (rect,
// circle, ellipse, line, polyline, polygon) become <path> elements with the same id, paint and
// transform, since only paths have a `d`. Shapes drawn through <use> are left static (they
// are shared) and listed in the returned warnings. `points` holds K * plan.n_cp canvas-space
// (x, y) pairs (Fitter::keyframe_points_canvas). `scene` is `source` as read; without a `map`
// it is also the fitted scene. Coordinates are rounded to `decimals` places (0..kMaxDecimals).
// Written to a temporary name and renamed.
// With `motion` (group_transform.h; its values are the timing's keyframes), a path whose group
// moves as a transform gets <animateTransform attributeName="transform" additive="sum"> children
// (translate, rotate, skewX, scale; those that stay the identity are left out) with the same
// timing, and its `d` values hold its points in that moving frame (no <animate> when they do not
// change at `decimals` places).
std::vector<std::string> write_animation_svg(const std::filesystem::path& source,
                                             const Scene& scene, const RasterPlan& plan,
                                             const std::vector<double>& points,
                                             const AnimationTiming& timing,
                                             const std::filesystem::path& out,
                                             const ExportMap* map = nullptr,
                                             int decimals = kDefaultDecimals,
                                             const PathMotion* motion = nullptr);

// The compact export (export/compact_motion.h), the default: a path that does not move is left
// as the document has it; a moving one is wrapped in a new <g> whose additive animateTransforms
// (translate, rotate, skewX, scale) carry its affine motion, the element itself untouched (an
// edit of its `d` or of the group's transform shows in playback), and gets an <animate
// attributeName="d"> only for what the affine map misses beyond the tolerance. Each animation
// keeps the fewest keyframes within the tolerance (keyframe_reduce.h), with keySplines easing,
// and numbers at the fewest decimals that keep it (`decimals` >= 0: that many for coordinates).
struct CompactExport {
  double tolerance_px = 0;  // canvas pixels; 0: compact_tolerance(the canvas)
  int decimals = -1;        // coordinates' decimal places; -1: measured
  double residual_scale = 1;  // the residual `d`'s tolerance: tolerance_px times this (kResidualScales)
};
struct CompactStats {
  int still = 0, transformed = 0, residual = 0;  // paths
  int pivoted = 0, centred = 0;  // transformed paths turned about their motion's pivot or rest centre
  size_t values = 0, keys = 0;                   // written values per animation, before and after
};
std::vector<std::string> write_compact_animation_svg(const std::filesystem::path& source, const Scene& scene,
                                                     const RasterPlan& plan, const std::vector<double>& points,
                                                     const AnimationTiming& timing, const std::filesystem::path& out,
                                                     const ExportMap* map, const CompactExport& options,
                                                     CompactStats* stats = nullptr);

// The `d` of one path from its control points (canvas space), mapped into the element's
// coordinates by `to_local`: "M x y C x y x y x y ... Z" per subpath, numbers rounded to
// `decimals` places.
std::string path_data(const Path& path, const double* cp, const Affine& to_local,
                      int decimals = kDefaultDecimals);

}  // namespace svgm
