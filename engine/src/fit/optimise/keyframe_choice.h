// Keyframes from the target: where the spline through the fitted keyframes does not predict
// the frames between them, those frames become keyframes too.
//
// A fit is made at K keyframes spread evenly over the clip, and the frames between them are
// written as a cubic spline through the keyframes (inbetween.h). On a clip whose consecutive
// frames differ a lot (a low frame rate, a fast move, a pose played back and forth) the spline
// cannot know what happened between two keyframes: issue 38 measured 25-30 dB there while the
// keyframes scored 49-60. So after the first fit every frame between keyframes is rendered at
// the spline's shape and compared with its own target frame by the loss the fitter uses
// (measure_spline_frames); the frames it misses clearly (choose_keyframes) become keyframes,
// each starting from the fitted keyframe whose target looks most like its own frame
// (closest_sources), within a budget that keeps long clips from fitting every frame.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "opencl/runtime.h"
#include "raster/raster_plan.h"
#include "svgmotion/render_size.h"
#include "svgmotion/target_video.h"

namespace svgm {

// When a frame between keyframes counts as not predicted by the spline. dB are of the loss's
// blurred mean squared error (the fitter's image loss over its weight: 10 log10(1 / MSE) of the
// σ-blurred render against the σ-blurred, cleaned target frame).
struct KeyframeRule {
  // A frame at or above this is predicted well enough whatever its keyframes score. The loss's
  // blur takes 3-5 dB off a few-pixel misfit, so 46 here is about 41-43 dB unblurred at the
  // fitting width (issue 38's bar: every frame >= 40 dB at 256 px).
  double good_db = 46;
  // Below good_db, a frame is missed when it scores this much worse than the worse of its two
  // keyframes: a spline that follows the motion loses a little between keyframes (smooth
  // known-motion targets: 0.5-2 dB), one that misses it loses tens of dB.
  double margin_db = 4;
};

struct KeyframeChoice {
  std::vector<int> frames;  // the keyframes (source frames, increasing): the old and the added
  std::vector<int> added;   // the frames added, increasing
  std::vector<int> missed;  // every frame the rule found missed (added or not: the budget)
  int worst_frame = -1;     // the lowest-scoring frame between keyframes, and its dB
  double worst_db = 0;
  std::string reason;       // "" when nothing was added; else why, for the terminal and fit.json
};

// `keys`: the keyframes' source frames (increasing) and `key_db` their scores; `frames` the
// frames between them that were judged (any order) and `frame_db` their scores; `budget`: the
// most keyframes the fit may have (no more are added beyond it; the worst-scoring missed frames
// come first). Pure: no device, no files.
KeyframeChoice choose_keyframes(const std::vector<int>& keys, const std::vector<double>& key_db,
                                const std::vector<int>& frames, const std::vector<double>& frame_db, int budget,
                                const KeyframeRule& rule = {});

// The default budget for a clip of `source_frames` fitted with `keyframes`: every frame of a
// short clip, at most twice the keyframes asked for (a 24-frame clip at 15 may take all 24; a
// 200-frame one at most 30, so the fit's cost stays in proportion).
int default_keyframe_budget(int keyframes, int source_frames);

// The score (dB, as KeyframeRule) of each frame in `frames` (source frames, none a keyframe)
// when drawn at the spline through the keyframes: `key_points` are K * per_key canvas
// coordinates (Fitter::keyframe_points_canvas), `key_times` their times in [0, 1], `closed` the
// export's loop closing. `load(frames)` loads those frames as the fit's targets are loaded
// (cleaned, at the fitting size; at most `batch` at a time, so memory stays bounded); they are
// rendered with `plan` at `size` through a loss with the fitter's blur and chroma settings.
struct SplineLoss {
  double render_sigma = 1, chroma_sigma = 0, chroma_weight = 1;
  float w_image = 1000;
  int batch = 8;
};
std::vector<double> measure_spline_frames(ClRuntime& rt, const RasterPlan& plan, const RenderSize& size,
                                          const std::vector<double>& key_points, const std::vector<double>& key_times,
                                          bool closed, int source_frames, const std::vector<int>& frames,
                                          const std::function<TargetFrames(const std::vector<int>&)>& load,
                                          const SplineLoss& loss);

// For each keyframe of `next` (the new keyframe set, a superset of `prev`), the index in `prev`
// of the keyframe to start from: itself where it was a keyframe, else the one whose cleaned
// target frame (`prev_target`, `next_target`: K * H * W * 4 floats each) differs least from its
// own (a pose played back and forth returns to one a keyframe already has).
std::vector<int> closest_sources(const std::vector<int>& prev, const TargetFrames& prev_target,
                                 const std::vector<int>& next, const TargetFrames& next_target);

// dB of a keyframe's image loss as read from the fitter (each weighted w_image and divided by the
// `frames` the loss was taken over: ClRaster::read_frame_losses).
double loss_db(float loss, int frames, float w_image);

}  // namespace svgm
