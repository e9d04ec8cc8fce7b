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
//
// fit_job runs it only when blur matching has seen the video's chroma damaged
// (chroma_calibration_gate, below); a clean video gets 1 without the calibration's seconds.
#pragma once

#include <string>
#include <vector>

#include "fit/target/blur_match.h"
#include "fit/optimise/fitter.h"
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

// Whether the calibration is worth its seconds (3-7 s a fit): only when the video's chroma is
// visibly damaged. Blur matching (fit/target/blur_match.h) has already measured, on the same first
// frame, the luma σ and chroma σ of the loss that best match the video's frame 0 to the rest
// pose (BlurMatch::chroma_luma_sigma, best_chroma_sigma); a codec that damages colour leaves
// the chroma σ well above the luma one. The best pair is used whether blur matching adopted it
// or not: heavy chroma noise keeps the rest pose under blur matching's 38 dB, so the pair is
// not adopted exactly where the damage is worst (the damaged fixture of
// fit_chroma_calibration_test.cpp: 2.0 over 1.05 at 28 dB). Measured at the refinement's
// width, 512 px, the video's own (luma σ, chroma σ): clean H.264 bug 1.05 1.2, parrot 1.05
// 1.2, octopus 1.05 1.15 (excess 0.1-0.15; the calibration kept 1 on all three); JPEG quality
// 20 bug 1.2 2.0, parrot 1.15 2.0, octopus 1.3 1.9 (excess 0.6-0.85; it chose 0.25, 0.25, 1).
// A threshold of 0.4 sits between, at least 0.2 (4 steps of blur matching's 0.05 grid) from
// either side.
//
// The σs are in pixels of the width they were measured at, and a fit without a refinement
// measures only at the fitting width, which may be below the video's: there the damage looks
// smaller (bug, JPEG, 256 px from the 512 px video: 1.05 1.3). So each σ is first taken to the
// video's own width: a blur b (target pixels) beyond the loss's own σ = 1 adds in quadrature,
// σ² = 1 + b², and b scales with the width, so σ_video = sqrt(1 + (σ² - 1) (video / width)²).
// That model predicts the 256 px pairs from the 512 px ones (bug JPEG 1.05 1.34 for 1.05 1.3
// measured; clean 1.01 1.05 for 1.0 1.0), and puts the measured 256 px pairs at excess 0
// (clean bug, parrot, octopus: 1.0 1.0), and 0.75, 0.61, 0.45 (JPEG bug 1.05 1.3, parrot 1.05
// 1.25, octopus 1.1 1.25): the same threshold separates them. Scaling the excess linearly by
// the width instead would put JPEG parrot at the threshold (0.2 x 2) and octopus below it
// (0.15 x 2); a clean pair one grid step apart at 256 px (1.0 1.05) is 0.19 in quadrature.
// At the video's own width the model changes nothing.
constexpr double kChromaExcessThreshold = 0.4;

// σ measured at a stage `width` px wide, as it would be at the video's `source_width` (above).
double sigma_at_source(double sigma, int width, int source_width);

struct ChromaGate {
  bool calibrate = true;
  double excess = 0;     // chroma σ - luma σ at the video's width (both sigma_at_source)
  double threshold = kChromaExcessThreshold;
  int measured_width = 0;  // the stage's width the σs were measured at
  std::string reason;      // why the calibration runs or is skipped, with the figures
};

// The gate on one stage's blur match (BlurMatch::chroma_luma_sigma, best_chroma_sigma; the
// refinement's when there is one, as the video's chroma blocks show at its width, else the
// fitting width's). Calibrate when the excess is at least `threshold` (or not a number).
ChromaGate chroma_calibration_gate(double luma_sigma, double chroma_sigma, int width, int source_width,
                                   double threshold = kChromaExcessThreshold);
// The same on a blur match made at `width` (its best luma and chroma pair).
ChromaGate chroma_calibration_gate(const BlurMatch& match, int width, int source_width,
                                   double threshold = kChromaExcessThreshold);

}  // namespace svgm
