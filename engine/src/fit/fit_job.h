// One fit from files to files: the body of `svgmotion fit` and of the opencl fitter plugin.
//
// Reads the SVG (and palette), loads the target, fits with progress and checkpoints, and writes
// animation.svg, animation.json (the same animation as Lottie, export/lottie_writer.h),
// preview.mp4, fit.json and checkpoint.bin into the output folder.
//
// Trust: a loss that diverges (not finite, or above ten times the best seen since the last
// keyframe activation for 50 iterations in a row) rolls back to the last good state and goes on at half the learning rates (at most
// four times). The finished fit then passes the result gate (result_gate.h) or is rejected: it
// is written as animation.failed.svg (no animation.svg; a stale one is removed), fit.json says
// "status": "rejected" with the reasons, and run_fit_job throws svgm::Rejected.
//
// fit.json also keeps the loss every 10 iterations (loss_history) and each keyframe's source
// frame (keyframe_frames), for report.html (report/report_page.h).
//
// Timing: keyframe k is written at the time of the target frame it was fitted to (keyTimes =
// source_index / (N-1), one pass = (N-1) / fps), so frames between keyframes are
// interpolated at the right moments, along a cubic spline through the keyframes sampled at the
// target's frames (inbetween.h) rather than the browser's straight lines; a target whose last
// frame returns to its first closes the loop (the last keyframe is written as the first).
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "fit/optimise/fitter.h"
#include "export/smil_writer.h"

namespace svgm {

// More in-betweens than this add nothing a viewer sees (targets have a few frames per keyframe).
constexpr int kMaxInbetweens = 16;
// Codec noise: each keyframe averaged with this many flow-aligned neighbours on either side
// (fit/target/temporal_denoise.h), and the most `fit --denoise` / stages.fitter.denoise accept.
constexpr int kDefaultDenoiseRadius = 2;
constexpr int kMaxDenoiseRadius = 4;

struct FitJob {
  std::filesystem::path svg, target, out;
  std::optional<std::filesystem::path> palette;
  std::optional<std::filesystem::path> tracks;  // tracks.json of the tracker stage
  // The procedural video stage's report (motion.json): groups it moves apart are fitted as
  // several (motion_groups.h).
  std::optional<std::filesystem::path> motion;
  // The candidate video the ranker chose ("01.mp4"), whose known motion warm-starts the fit
  // (motion_groups.h known_motion); empty: the report's first.
  std::string motion_candidate;
  // The document the animation is written into (default: svg). The fitter plugin fits the
  // pipeline's working copy (layered.svg) and exports into the user's own input.svg: paths are
  // matched by id and the working copy's paint order is applied (document_order.h).
  std::optional<std::filesystem::path> export_into;
  std::string export_name;  // how messages name export_into (the user's path, not the run copy)
  LoopMode loop = LoopMode::Loop;
  // Smooth in-between shapes written per keyframe interval, at the target's frames there
  // (inbetween.h); 0 leaves the in-betweens to the browser's linear interpolation.
  int inbetweens = 3;  // fit --inbetweens, stages.fitter.inbetweens (0..kMaxInbetweens)
  // Decimal places of the exported coordinates (animation.svg in the element's units,
  // animation.json in canvas pixels).
  // -1: measured, the fewest that keep the compact export's tolerance (kDefaultDecimals for
  // the full export).
  int decimals = -1;
  // The compact export (smil_writer.h write_compact_animation_svg), the default; false: every
  // written value of every path, as before (fit --full, stages.fitter.compact: false).
  bool compact = true;
  // Each group's motion, where affine, as <animateTransform> elements on its paths, with the
  // paths' `d` values in the group's moving frame (group_transform.h); false: baked into `d`.
  bool group_transforms = false;  // fit --group-transforms, stages.fitter.group_transforms
  // Segments longer than this fraction of the canvas's larger side are split (exactly) before
  // fitting, so the motion can bend them (segment_split.h); 0: the paths keep their own
  // segments. fit --max-segment, stages.fitter.max_segment.
  double max_segment = 0.04;
  bool gate = true;  // false: write animation.svg even when the result gate rejects the fit
  // Progress: when set, called about twice a second with the fraction done and a short note,
  // instead of the progress line on stderr.
  std::function<void(double fraction, const std::string& note)> progress;
  FitOptions options;
  int keyframes = 15;
  // Keyframes from the target (keyframe_choice.h): after the fit at `keyframes`, the frames the
  // spline between keyframes does not predict become keyframes too, up to this many in all.
  // -1: automatic (default_keyframe_budget: every frame of a short clip, at most twice
  // `keyframes`); `keyframes` or fewer: none are added. fit --max-keyframes,
  // stages.fitter.max_keyframes.
  int max_keyframes = -1;
  // Keyframe 0 pinned to the drawing's rest pose (true), fitted like any other (false), or
  // decided from the video's first frame against the rest pose (unset, the default;
  // rest_start.h). fit --start rest|free|auto, stages.fitter.start.
  std::optional<bool> start_at_rest;
  int width = 256;
  // Coarse-to-fine: after the whole coarse fit, `refine_share` x iterations more refine every
  // keyframe at this width, with the target read again at that size (the regularisers scaled
  // to weigh the same geometry: FitOptions::refined_at). -1: automatic, the default (twice the
  // fitting width, or the video's own width if smaller, when the video is at least 1.5x the
  // fitting width); 0: off. What is one or two pixels wide at 256 px is seen at 512: measured
  // on 512-px H.264 non-rigid targets judged at 1024 px, worst keyframe without -> with:
  // octopus 41.34 -> 43.46 dB, parrot 37.94 -> 41.67, bug 42.93 -> 44.72; 250 extra
  // iterations at 512 px did as well as 500. (Taking the refinement's iterations from the
  // coarse fit instead cost octopus an eye in its most bent keyframes: 38.5 dB.)
  int refine_width = -1;
  double refine_share = 0.125;
  // Colour-correct every keyframe against the drawing's colours (target_video.h).
  bool colour_correction = true;
  // Match the video's blur, measured on the rest pose, in the loss (fit/target/blur_match.h).
  bool blur_matching = true;
  // How much a residual of chroma alone counts in the loss against one of luma (kernels/
  // loss.cl's loss_metric), in (0, 1]; 1: the plain squared error.
  double chroma_weight = 1;
  // Choose chroma_weight from the video's first frame instead (fit/target/chroma_calibration.h):
  // `svgmotion fit`'s default; the pipeline's fitter keeps 1.
  bool chroma_weight_auto = false;
  // Remove camera shake from the video before sampling it (target_video.h): always (true),
  // never (false), or when the target shakes (unset, the default: fit/target/frame_scan.h).
  // fit --stabilise / --no-stabilise, stages.fitter.stabilise.
  std::optional<bool> stabilise;
  // Average each sampled frame with this many flow-aligned neighbours on either side
  // (TargetOptions::denoise_radius; 0: off).
  int denoise_radius = kDefaultDenoiseRadius;
  double mask_threshold = 0.97;
  bool resume = false;
  // `svgmotion fit`: claim `out` as a run directory and hold its lock (run/run_directory.h)
  // before writing there; `force` takes a non-empty folder that is not one. The pipeline's
  // fitter leaves this off: its run holds the lock.
  bool claim_out = false;
  bool force = false;
  // Resume from out/checkpoint.bin when it holds an unfinished fit of exactly this problem
  // (the pipeline's fitter after a Ctrl-C); otherwise fit from the start.
  bool resume_unfinished = false;
  bool quiet = false;
  std::string device = "auto";
};

// Runs the fit; returns 0 when done, 130 when `interrupted()` stopped it early (the outputs are
// written either way). Throws svgm::Error on bad input, svgm::Rejected when the gate rejects.
int run_fit_job(const FitJob& job, const std::function<bool()>& interrupted);

}  // namespace svgm
