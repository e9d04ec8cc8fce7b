// The fitter's target: the motion video (or folder of numbered PNG frames) reduced to K
// uniformly sampled keyframes at the SVG's render size, each with a foreground mask, a cleaned
// copy (background noise whitened) and a distance field to the foreground.
//
// The fitter compares renders of the SVG against `rgba`, uses `mask`/`sdf` to pull shapes
// towards the figure, and shows `raw` in previews. OpenCV does the decoding, but no OpenCV type
// appears here, so including this header costs nothing.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace svgm {

struct TargetFrames;

struct TargetOptions {
  int keyframes = 15;            // K: uniformly sampled frames, first and last included
  // The source frames to sample instead (increasing, each in 0..N-1; `keyframes` is then their
  // count): the keyframes chosen from the target (fit/optimise/keyframe_choice.h), or frames between
  // them to judge the fit's in-betweens against.
  std::vector<int> frames;
  // A pixel is foreground when a channel differs from the frame's background colour by more
  // than 1 - this; on white, when its darkest channel < this. In (0, 1]. The background is
  // white, or the light colour (channels >= 0.85) that 60% of the border agrees on. Close to white on purpose:
  // drawings have near-white parts (a snowman's #f4ecec body is 0.925), and at 0.9 the cleanup
  // whitened them and containment squeezed them out of the fit; H.264 keeps a white background
  // within a couple of levels of 255, well above 0.97.
  double white_threshold = 0.97;
  double min_component_fraction = 0.02;  // keep components with area >= this * the largest
  // Components covering at least this share of the frame are kept whatever the largest's
  // size; 0: the fraction alone. The fitter sets it to half the drawing's own smallest separate
  // part at rest (smallest_part_share): a scene's figure is so large that 2% of it was more
  // than a whole detached part, and the phoenix's loose flame (359 px of a 32736-px figure at
  // 256) was whitened out of every keyframe, so the fit folded it flat where the video shows it.
  double keep_part_share = 0;
  // Dilation radius of the foreground mask, in pixels: a Euclidean disc of this radius (offsets
  // with dx² + dy² <= r²), so 1 is the 3x3 cross; 0 = no dilation.
  int dilate_px = 1;
  // The drawing's colours (straight RGB in [0, 1]; white is implied). When given, every
  // keyframe is colour-corrected against them before the mask is found (an affine colour map
  // fitted to the frame's flat regions, then flat pixels snapped to their colour;
  // fit/target/colour_correction.h): off-white backgrounds, tints, shading and codec noise.
  std::vector<std::array<float, 3>> palette;
  // Held frames (a clip at a lower frame rate than its container repeats each frame): a keyframe
  // that falls on a repeat is timed at the first frame of its run, where that pose was made.
  bool retime_held_frames = true;
  // Camera shake (the whole frame jittering a pixel or two) removed before sampling: read off
  // the part of the figure that holds still where there is one, else the path of
  // frame-to-frame translations minus its low-pass over time (fit/target/stabilise.h). Off by
  // default: a figure moving in genuine sharp jerks would be smoothed a little.
  bool stabilise = false;
  // The low-pass's standard deviation. Shake is independent from frame to frame, so what the
  // low-pass keeps of it falls as the window grows (bug's 1-2 px jitter, judged from the clean
  // frames: 0.23 px mean left at 256 px with 3 frames, 0.05 px with 12), but the window must
  // follow the figure's own sway, which the measured translation includes: at 12 frames (0.5 s)
  // bug's swinging body was taken for shake (2.4 px "removed", keyframes down to 23 dB at
  // 1024 px); 3 frames (0.125 s at 24 fps) kept it (37.1 dB mean). The low-pass is a local
  // parabola now, which follows a sway's turns: 5 frames (0.2 s) left 0.53-0.59 px (at 512 px)
  // of the non-rigid targets' 1-2 px shake where the straight line over 3 frames left 0.57-0.98.
  double stabilise_sigma_s = 0.2;
  // Codec noise (blocking, ringing, smeared colour) averaged away: each sampled frame becomes
  // the average of itself and its `denoise_radius` neighbours on either side, warped onto it by
  // optical flow, each pixel of a neighbour weighted by how well it agrees (fit/target/temporal_denoise.h).
  // Done at the frames' size, at most twice the target width. 0: the frames as decoded.
  int denoise_radius = 0;
  // Keep the denoised keyframes at the working size in TargetFrames::denoised, for a second
  // load at another width (the refinement's) to reuse instead of decoding and aligning again.
  bool keep_denoised = false;
  // An earlier load of the same source that kept its denoised keyframes: reused when this load
  // has the same working size and keyframes (nothing is decoded); otherwise ignored. Reused, they
  // are taken: each keyframe's is freed from `denoised_from` once this load has stored it, so the
  // two loads never hold every keyframe's together (66 MB for 21 keyframes at 512 px).
  TargetFrames* denoised_from = nullptr;
  // An earlier load of the same source with `stabilise` on (the fit's coarse width, when the
  // refinement loads the clip again at its own): its camera path is reused, not measured twice.
  const TargetFrames* shake_from = nullptr;
  // When set, each keyframe's frame before cleanup (colour-corrected: what `raw` would hold for
  // it) is handed here as soon as the keyframe is cleaned, and the returned `raw` is empty: the
  // load holds one keyframe's floats instead of every keyframe's (16 bytes per pixel and
  // keyframe; 88 MB for 21 keyframes at 512 px). A fit compacts them (fit/target/compact_raw.h).
  std::function<void(int k, const float* raw)> raw_sink;
  // The same for the cleaned frames: each keyframe's `rgba` is handed here as soon as it is
  // cleaned, and the returned `rgba` is empty (its mask and distance field are kept). A fit's
  // refinement packs them as they come (fit/target/white_runs.h): the load never holds every
  // keyframe's floats (88 MB for 21 keyframes at 512 px), nor them and their packed form.
  std::function<void(int k, const float* rgba)> rgba_sink;
};

struct TargetFrames {
  int width = 0, height = 0, keyframes = 0;
  int source_frames = 0;          // frames in the video / folder
  int source_width = 0, source_height = 0;  // the frames' own size, before resizing
  double fps = 24;                // from the video (folders, or videos without a rate: 24)
  // Source frame of each keyframe: round(k * (N-1) / (K-1)), or the first frame of the run of
  // identical frames it falls in (TargetOptions::retime_held_frames).
  std::vector<int> source_index;
  int held_frames = 0;            // frames that repeat the one before (video sources)
  int colour_corrected = 0;       // keyframes whose colours were corrected
  double max_shake_px = 0;        // largest shake removed from a keyframe, target pixels
  std::string shake_model;        // how shake was told from motion (ShakeEstimate::model)
  std::vector<std::array<double, 2>> frame_shake;  // every source frame's shake, its own pixels
  double still_share = 0;         // the still part's share of the first frame's edges
  bool shake_loop = false;        // the clip is a loop and its shake was told round it
  double denoise_seconds = 0;     // spent averaging keyframes with their neighbours (denoise_radius)
  // With TargetOptions::keep_denoised: the denoised keyframes before shake removal, RGB float at
  // the working size (H*W*3 floats per keyframe, each kept deflated by byte planes: the twemoji
  // dog's 34 at 512 px were 107 MB as floats, held through the keyed load; a load that reuses
  // them inflates and frees each as it goes), and the frame each was decoded from (before
  // retiming).
  int denoised_width = 0, denoised_height = 0;
  std::vector<std::vector<uint8_t>> denoised;
  std::vector<int> denoised_frame;
  // K*H*W*4, row-major per keyframe: the cleaned target, straight RGB in [0,1], A = 1; pixels
  // outside the dilated mask are exactly white (1, 1, 1).
  std::vector<float> rgba;
  std::vector<float> raw;     // K*H*W*4: the resized frames before cleanup (A = 1)
  std::vector<uint8_t> mask;  // K*H*W: 1 = foreground (after the component filter + dilation)
  // K*H*W: Euclidean distance in pixels from the pixel centre to the nearest foreground pixel
  // centre (0 inside the mask). A keyframe without foreground holds width + height everywhere.
  std::vector<float> sdf;
};

// What a source holds, without decoding more than needed to count: the native frame size,
// the number of frames (counted by reading, since containers' frame counts can be wrong) and
// the frame rate (24 for folders or when the container has none).
struct TargetInfo {
  int width = 0, height = 0, frames = 0;
  double fps = 24;
};

// `source`: a video file (mp4, webm, avi, mov: whatever FFmpeg's libavformat reads) or a
// folder of numbered PNG frames, ordered by the last number in each name (000.png,
// frame_12.png). PNGs with alpha are composited over white. Throws svgm::Error
// "<path>: <problem>" for a missing/unreadable source, a folder without PNGs or with PNGs that
// are unnumbered, numbered alike, unreadable or of different sizes.
TargetInfo probe_target(const std::filesystem::path& source);

// Reads `source` (as above) and samples options.keyframes frames uniformly, resized to
// width x height (cv::INTER_AREA when neither side grows, INTER_LINEAR otherwise; the aspect is
// the caller's business). Foreground per keyframe: a channel differs from the background (see
// TargetOptions::white_threshold) by more than 1 - white_threshold, 8-connected
// components with area >= max(4, min(min_component_fraction * largest, keep_part_share * the
// frame)) kept, and so is any smaller one those enclose (not reachable from the frame's border
// without crossing them: a detail inside the figure, not a stray mark), dilated by dilate_px.
// A video is read twice (once to count, once keeping only the sampled frames), so memory stays
// at K frames whatever the video's length. Throws svgm::Error "<path>: <problem>", including
// "has N frames, fewer than the K keyframes asked for".
// The share of the frame covered by the smallest separate part (8-connected ink component,
// ink as load_target finds it on white) of `rgba8` (8-bit RGBA, opaque, width x height) that
// has at least 4 pixels; 0 when there is none.
double smallest_part_share(const std::vector<uint8_t>& rgba8, int width, int height, double white_threshold);

// Per-channel median of a frame's border pixels (straight RGBA floats, width x height): the
// background colour of a frame whose figure does not cover most of its border.
std::array<float, 3> border_median_rgb(const float* rgba, int width, int height);

TargetFrames load_target(const std::filesystem::path& source, int width, int height,
                         const TargetOptions& options = {});

// Every frame of `source` (as above), decoded once in order and handed to `visit` with its index
// and its pixels resized to width x height as straight RGBA floats: what load_target keeps as
// `raw` for a sampled frame without denoising or stabilising. One frame is held at a time, so a
// scan of a long clip costs one decode of it and one frame of memory (load_target, asked for
// batches of frames, decodes the clip from its start for each batch).
void for_each_target_frame(const std::filesystem::path& source, int width, int height,
                           const std::function<void(int index, const float* rgba)>& visit);

}  // namespace svgm
