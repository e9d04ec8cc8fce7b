// The target's frames before cleanup (TargetFrames::raw) in the form a fit needs once they are
// loaded: the preview shows them in 8 bits and the result gate reads which pixels differ from
// the frame's background, so a fit keeps those (4 bytes per pixel) instead of float RGBA (16;
// 94 MB for 30 keyframes at 512 px). Both read the compact form exactly as they read `raw`:
// the preview's bytes and the gate's verdict are the same bits.
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

// Keyframe k's figure as the gate sees it, from `raw` or from its compact form.
struct RawFigure {
  std::array<float, 3> background{1, 1, 1};  // border_median_rgb of the frame
  std::vector<uint8_t> figure;               // H*W, 1 = differs_from(background)
};
RawFigure raw_figure(const TargetFrames& t, int k);

// Keyframe k before cleanup as 8-bit RGBA (rgba8_image of `raw`'s frame, or its compact form).
RgbaImage raw_image(const TargetFrames& t, int k);

// Replaces t.raw by t.raw_compact (nothing when raw is already empty). Nothing that reads
// `raw` itself may run on `t` after this (the ranker plugins do, on their own loads).
void compact_raw(TargetFrames& t);

}  // namespace svgm
