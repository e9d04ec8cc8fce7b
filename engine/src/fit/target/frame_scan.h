// The target's frames in brief, read before any keyframe is sampled: which frames repeat the
// one before them, and whether the whole frame shakes.
//
// Held frames. A clip made at a lower frame rate than its container's shows each pose several
// times (8 fps in a 24-fps video: every pose three times). Sampled as it is, its keyframes fall
// on repeats and the frames between keyframes are repeats too: the keyframe choice
// (keyframe_choice.h) found the spline "missing" every repeat and made them keyframes, so the
// fit copied the staircase of holds, 1-2 frames behind a motion that goes on (issue 38:
// octopus at 8 fps, held frames 25-30 dB against the true motion, the poses themselves 46-49).
// A repeat carries no pose of its own: the fit is made at the distinct poses, each at the
// time it was made (the first frame of its run), and the frames between are the spline's.
//
// Shake. A hand-held or generated clip whose whole frame jitters by a pixel or two from frame
// to frame (fit/target/stabilise.h removes it; it is costly and off unless asked for). Here it
// is only measured, cheaply: the whole frame's translation from one distinct frame to the next
// (phase correlation of 128-px thumbnails), summed into a path, and how far each point of the
// path lies from the mean of its two neighbours. A motion of the figure, however fast or
// non-rigid, moves that path smoothly (octopus and parrot, non-rigid, 0.05 px at 256; the
// same at 8 fps, 0.25); shake moves it every frame (1-2 px jitter: 0.8-1.8 px).
#pragma once

#include <array>
#include <filesystem>
#include <vector>

#include <opencv2/core.hpp>

namespace svgm {

// A thumbnail pixel (64 px wide, 8-bit grey levels, after area averaging) differing from the
// run's first frame by more than this is a new pose. A codec's re-encoding of a held frame
// moves a few levels (H.264 at 256 px: 1-6); a new pose of an 8-fps clip, tens (67-94).
constexpr double kHeldMaxDiff = 10;

// The path's median distance from its neighbours' mean, at the fitting width, at or above
// which the clip shakes...
constexpr double kShakeMinFitPx = 0.35;
// ...when it is also this large a share of the median step: a fast non-rigid motion wobbles a
// whole-frame registration in proportion to its steps...
constexpr double kShakeMinStepShare = 0.35;
// ...and when the step's translation explains the frame's change: the frame moved by it differs
// from the next by at most this share of what the two frames differ by (median over steps).
// Shake moves the whole frame (1-2 px jitter on the non-rigid bench clips: octopus 0.83 at a
// 256-px video, parrot 0.90 at 512); a figure's own motion bends it (the same clips without
// jitter 1.00-1.01; 6 poses played back and forth 0.99, a loop at 8 fps in one second 0.96),
// and a path sampled that coarsely meets the two bounds above as shake does. The margin is
// thin: a figure that moves rigidly and abruptly (a hop sampled at a few frames) can pass for
// shake, and --no-stabilise is then the user's.
constexpr double kShakeMaxRigidResidual = 0.93;

// A clip at a lower frame rate shows its poses in runs of one length, its cadence (3 at 8 fps
// in 24). Runs of many lengths are a figure that stops now and then: every frame is its own.
// The cadence is the commonest length of the runs before the last, when it is 2 or more and
// at least this share of those runs (at least three) have it.
constexpr double kCadenceMinShare = 0.5;

struct FrameScan {
  int frames = 0;
  std::vector<int> run_start;  // per source frame, the first frame of the run of repeats it is in
  std::vector<int> distinct;   // the frames that start a run (each a pose of its own), increasing
  double jitter_fit_px = 0;    // the path's median distance from its neighbours' mean, fitting px
  double step_fit_px = 0;      // the path's median step between distinct frames, fitting px
  double rigid_residual = 1;   // median over steps: change left once the step's shift is undone
  bool shaking = false;        // jitter_fit_px and its share of the step are both over the bounds
  // The cadence (1: none), and the frames that show a pose of their own: every frame without a
  // cadence; with one, each run's first frame and every cadence-th frame after it in a longer
  // run (the figure held still over several poses stays held), and the last frame (the clip's
  // end is held too, not stretched to).
  int cadence = 1;
  std::vector<int> poses;
  int held() const { return frames - static_cast<int>(distinct.size()); }
  bool collapse() const { return cadence >= 2; }
};

// The cadence of a clip with runs starting at `run_start` (per frame), and its pose frames.
void find_cadence(const std::vector<int>& run_start, FrameScan& scan);

// The run starts of a clip given as 8-bit-level grey thumbnails (CV_32F, one size): frame i
// repeats its run when no pixel differs from the run's first frame by more than `max_diff`.
std::vector<int> held_runs(const std::vector<cv::Mat>& thumbs, double max_diff = kHeldMaxDiff);

// The whole frame's path over `frames` (grey CV_32F thumbnails, one size, ink dark), in
// thumbnail pixels: (0, 0) at the first, then the sum of the phase-correlation steps; and, when
// asked, each step's rigid residual (the mean difference left once the step's shift is undone,
// over the mean difference).
std::vector<std::array<double, 2>> frame_path(const std::vector<cv::Mat>& frames, std::vector<double>* rigid_residual = nullptr);

// The scan's shake figures from a path in fitting pixels and its steps' rigid residuals.
void judge_shake(const std::vector<std::array<double, 2>>& path, const std::vector<double>& rigid_residual, FrameScan& scan);

// Reads every frame of `source` (a video or a PNG folder, as load_target does) at a small size,
// a few dozen at a time, and scans it; `fit_width` is the width the fit works at.
FrameScan scan_frames(const std::filesystem::path& source, int fit_width);

// `keyframes` frames spread evenly over `poses` (all of them when there are fewer), first and
// last included: the keyframes of a clip whose held frames are collapsed.
std::vector<int> spread_over_poses(const std::vector<int>& poses, int keyframes);

}  // namespace svgm
