// The target's frames before cleanup (TargetFrames::raw) in the form a fit needs once they are
// loaded: the preview shows them in 8 bits and the result gate reads which pixels differ from
// the frame's background, so a fit keeps those (4 bytes per pixel, held deflated: a few per cent
// of that on a drawing's paper) instead of float RGBA (16; 94 MB for 30 keyframes at 512 px).
// Both read the compact form exactly as they read `raw`: the preview's bytes and the gate's
// verdict are the same bits.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "svgmotion/png_io.h"
#include "svgmotion/target_video.h"

namespace svgm {

// The result gate's figure: a pixel differing from the frame's background (the median of its
// border) by more than this in some channel (fit/output/result_gate.h).
inline constexpr float kFigureContrast = 0.1f;

inline bool differs_from(float r, float g, float b, const std::array<float, 3>& background) {
  return std::max({std::fabs(r - background[0]), std::fabs(g - background[1]), std::fabs(b - background[2])}) >
         kFigureContrast;
}

// A target's `raw` once compacted (compact_raw), for its K keyframes of H x W pixels. Each
// keyframe's bytes are held deflated (deflated_bytes.h): they are read once each, at the end of
// a fit, and the 4 bytes per pixel and keyframe (36 MB for 34 keyframes at 512 px) deflate to a
// few per cent on a drawing's white paper and flat colours.
struct CompactRaw {
  size_t pixels = 0;  // H*W, per keyframe
  // K: keyframe k's rgb8 (H*W*3: rgba8_image's rounding; its A is 255, raw's is 1), then its
  // figure (H*W: 1 = differs_from the keyframe's border median), deflated.
  std::vector<std::vector<uint8_t>> frames;
  std::vector<std::array<float, 3>> border;  // K: border_median_rgb of each keyframe
  size_t keyframes() const { return frames.size(); }
  size_t bytes() const;
};
// Keyframe k of `c` inflated: rgb8 (3 per pixel), then figure (1 per pixel).
std::vector<uint8_t> compact_frame(const CompactRaw& c, int k);

// Keyframe k's figure as the gate sees it, from t.raw, or from `c` when t.raw is empty.
struct RawFigure {
  std::array<float, 3> background{1, 1, 1};  // border_median_rgb of the frame
  std::vector<uint8_t> figure;               // H*W, 1 = differs_from(background)
};
RawFigure raw_figure(const TargetFrames& t, const CompactRaw* c, int k);
// The same of one frame before cleanup (straight RGBA floats, width x height).
RawFigure raw_frame_figure(const float* raw, int width, int height);

// Keyframe k before cleanup as 8-bit RGBA: rgba8_image of t.raw's frame, or from `c`.
RgbaImage raw_image(const TargetFrames& t, const CompactRaw* c, int k);

// Moves t.raw into its compact form (t.raw is empty afterwards; an empty form when it already
// was). Nothing that reads `raw` itself may run on `t` after this (the ranker plugins do, on
// their own loads).
CompactRaw compact_raw(TargetFrames& t);
// Appends one keyframe's frame before cleanup (straight RGBA floats, width x height) to `c`, as
// compact_raw does for each: a load with TargetOptions::raw_sink compacts keyframe by keyframe.
void compact_raw_frame(CompactRaw& c, const float* raw, int width, int height);

// load_target with its `raw` compacted into `raw` keyframe by keyframe as the load cleans each
// (TargetOptions::raw_sink): the returned target's `raw` is empty, and the load never holds
// every keyframe's floats at once. `raw` ends as compact_raw would have made it.
TargetFrames load_target_compact(const std::filesystem::path& source, int width, int height, TargetOptions options,
                                 CompactRaw& raw);

}  // namespace svgm
