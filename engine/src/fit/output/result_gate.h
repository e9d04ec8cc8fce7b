// The result gate: whether a finished fit may be handed to the user as animation.svg.
//
// An optimiser always returns something; a user must never receive an exploded drawing as a
// success. After the fit, every keyframe is judged on two counts:
//  - fidelity: the fit's render against the cleaned target it was fitted to (PSNR over the
//    whole frame), and the IoU of the figure in the fit and in the target, the figure being the
//    pixels that differ by more than 0.1 from the target frame's background colour (median of
//    its border), so a drifting off-white background counts as background;
//  - geometry: every control point within half a canvas of the canvas (a fit that throws
//    points far outside has diverged), and no path whose bounding-box diagonal grew more than
//    `max_growth` times, or shrank below `min_shrink` of, its rest size beyond what the target's
//    foreground did between keyframe 0 and this one (a target that zooms in may grow paths),
//    unless the grown path's pixels show what the target shows there (min_shown of its
//    coverage within 0.2 of the target: a warp may stretch one feature, an eye pulled into a
//    line, while the figure as a whole keeps its size; an exploded path covers background).
// The thresholds are loose on purpose: they separate broken results (noise targets, motions
// that leave the frame, diverged fits: PSNR well under 15 dB, points canvases away) from weak
// but honest ones (a good fit scores 35-50 dB, IoU > 0.95; a figure left at rest against a
// moving target about 20 dB), so the gate never vetoes a fit a user would keep.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "raster/raster_plan.h"
#include "svgmotion/scene.h"
#include "svgmotion/target_video.h"

namespace svgm {

struct CompactRaw;

// A filled path whose enclosed area falls below this share of keyframe 0's is folded flat.
inline constexpr double kFoldedArea = 0.1;

struct GateOptions {
  double min_psnr_db = 15;
  double min_iou = 0.5;
  double max_outside = 0.5;  // points may lie this fraction of the canvas size outside it
  double max_growth = 4;     // path bbox diagonal / rest, relative to the target's own change
  double min_shown = 0.75;   // ...unless this share of the grown path shows what the target shows
  double min_shrink = 0.2;
};

struct GateVerdict {
  bool passed = true;
  std::vector<std::string> reasons;  // one line each, "keyframe k: ..."
  std::vector<std::string> waived;   // growth let through because the target shows it
  // Not reasons to reject, but what a user should look at: a filled path folded flat (its
  // enclosed area under kFoldedArea of keyframe 0's while the target's figure keeps at least
  // half its size), one line per path naming its keyframes. A shape folded edge-on keeps its
  // box, so the shrink check above does not see it; the drawing shows a part vanishing.
  std::vector<std::string> warnings;
  std::vector<double> psnr_db, iou;  // per keyframe
};

// `renders`: K premultiplied RGBA float frames at the target's size (Fitter::render_keyframes);
// `points`: K * plan.n_cp canvas-space (x, y) pairs (Fitter::keyframe_points_canvas);
// `scene`: the fitted scene (rest pose, canvas space); `view`: canvas -> target pixels.
GateVerdict judge_fit(const TargetFrames& target, const std::vector<float>& renders,
                      const std::vector<double>& points, const RasterPlan& plan, const Scene& scene,
                      const Affine& view, const GateOptions& options = {});
// The same with keyframe k's render made when it is judged (`render(k)`: H * W * 4 floats, as
// Fitter::render_keyframe), so one keyframe's render exists at a time.
GateVerdict judge_fit(const TargetFrames& target, const std::function<std::vector<float>(int)>& render,
                      const std::vector<double>& points, const RasterPlan& plan, const Scene& scene,
                      const Affine& view, const GateOptions& options = {});
// The same for a target whose `raw` a fit has compacted into `raw` (fit/target/compact_raw.h):
// the same verdict, to the bit, as from the float frames. `cleaned`, when given, writes keyframe
// k's cleaned frame (H * W RGBA floats, what target.rgba holds for it) to its second argument:
// for a target whose rgba its holder keeps packed (fit/target/white_runs.h), read a keyframe at
// a time instead of whole (16 bytes per pixel and keyframe: 142 MB for 34 keyframes at 512 px).
using CleanedFrameReader = std::function<void(int k, float* rgba)>;
GateVerdict judge_fit(const TargetFrames& target, const CompactRaw* raw,
                      const std::function<std::vector<float>(int)>& render, const std::vector<double>& points,
                      const RasterPlan& plan, const Scene& scene, const Affine& view, const GateOptions& options = {},
                      const CleanedFrameReader& cleaned = {});

nlohmann::json gate_json(const GateVerdict& v, const GateOptions& o);

}  // namespace svgm
