// The chroma weight read off the video's first frame (`fit --chroma-weight auto`).
//
// The loss can count an error of chroma alone W times against one of luma (kernels/loss.cl's
// loss_metric, FitOptions::chroma_weight). On heavily compressed video, whose codec keeps
// colour at a quarter of the resolution and quantises it hard, W < 1 stops the fit chasing
// colour noise (bug +1.0 dB at 0.25, parrot +0.6); on a drawing whose parts differ by hue more
// than by brightness it blinds the fit to their borders (octopus -2.1). Which it is depends on
// the drawing and the video together, so it is measured, not guessed.
//
// The measurement needs no ground truth: the first frame of the target shows the drawing at
// rest (FitOptions::pin_rest_keyframe), so a fit of that one frame should stay exactly at rest.
// Fitting a still target (frame 0, as the fitter has it after colour correction, blur
// matching and stabilisation, repeated over a few unpinned keyframes), every keyframe
// drifts from rest only as far as the video's noise pulls it through the loss; the weight under
// which it drifts least is the one whose loss trusts what in the video is signal. Measured
// against full fits judged on clean frames, the still-frame ordering agreed with the whole
// video's on JPEG-damaged bug, parrot (0.25 best) and octopus (1 best), and every weight tied
// on clean videos. Drift is the mean squared RGB difference between the fitted keyframes'
// render and the render at rest (our own renderer), over the canvas.
//
// A weight below 1 is chosen only when it drifts clearly less than 1 does (ChromaCalibration
// Options::margin): a tie within noise keeps 1, so a clean video is fitted exactly as with
// `--chroma-weight 1`. Anything that fails falls back to 1 with a note, never an error.
#pragma once

#include <string>
#include <vector>

#include "fit/fitter.h"
#include "opencl/runtime.h"
#include "svgmotion/scene.h"
#include "svgmotion/target_video.h"

namespace svgm {

// The budget is what still told the weights apart on the measured videos (below) at the least
// cost: 3 keyframes (2 free) and 50 refinement iterations order them as 5 keyframes and 75 did,
// in 4-5 s instead of 8-10 (the coarse stage converges within its 300). Without the
// refinement's stage the weights were not told apart (bug, JPEG: 40.8, 40.8, 44.7 x1e-6 at
// 256 px; the damage shows at 512), and 2 keyframes with 100 refinement iterations once took a
// clean video's noise for a 23% gain.
struct ChromaCalibrationOptions {
  std::vector<double> weights = {1, 0.5, 0.25};  // the candidates; 1 first, the fallback
  int keyframes = 3;     // of the still target: the pinned rest pose and the free copies
  int iterations = 300;  // per candidate, at the fitting width (at most the fit's own)
  int fine_iterations = 50;  // per candidate, at the refinement's width (at most the fit's own)
  // A weight below 1 is chosen only when its drift is below (1 - margin) times the drift at 1
  // and below it by more than min_gain. Measured drift at 1 and the best below 1 (x1e-6):
  // JPEG quality 20, bug 49.0 -> 38.2 (0.25), parrot 68.5 -> 50.6 (0.25), octopus 18.9 -> 25.9
  // (none); clean, bug 4.71 -> 4.25, parrot 9.90 -> 10.3, octopus 4.39 -> 4.41: gains of 18-26%
  // and 11-18e-6 where the whole fit gains 0.6-1 dB, at most 10% and 0.5e-6 where it gains
  // nothing.
  double margin = 0.15;
  double min_gain = 3e-6;
};

struct ChromaCandidate {
  double weight = 1;
  double drift = 0;     // mean squared RGB difference from the rest render, [0, 1] units
  // RMS control-point displacement from rest, pixels of the last stage's width (recorded; it
  // did not order the weights as the fits' quality did: clean parrot 0.140, 0.124, 0.117 px).
  double drift_px = 0;
};

struct ChromaCalibration {
  double chosen = 1;
  std::vector<ChromaCandidate> candidates;
  std::string note;  // why it fell back to 1 (empty when the measurement chose)
  double seconds = 0;
};

// One stage of the fit the calibration mirrors: its target (keyframe 0 is used) and options
// (blur matching's σs, held groups; chroma_weight is replaced by each candidate).
struct ChromaStage {
  const TargetFrames* target = nullptr;
  FitOptions options;
};

// `coarse`: the fit at the fitting width; `fine`: its refinement (fit_job.h refine_width),
// or none. Never throws: a failure returns chosen = 1 with `note` set.
ChromaCalibration calibrate_chroma_weight(ClRuntime& rt, const Scene& scene, const ChromaStage& coarse,
                                          const ChromaStage* fine, const ChromaCalibrationOptions& options = {});

// The still target: keyframe 0 of `target` repeated `keyframes` times.
TargetFrames still_target(const TargetFrames& target, int keyframes);

}  // namespace svgm
