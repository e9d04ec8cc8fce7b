// Still frames of a video for report.html: the target's keyframes beside the fit, a poster for
// each candidate video. Decoded by OpenCV (FFmpeg), scaled to a thumbnail width.
#pragma once

#include <filesystem>
#include <vector>

#include "svgmotion/png_io.h"

namespace svgm {

// Frames `indices` (0-based, any order, repeats allowed) of the video `file`, each `width` px
// wide (height by the frame's aspect; a frame narrower than that is kept at its size). An index
// past the end gives the last frame. Throws svgm::Error "<file>: not a readable video".
std::vector<RgbaImage> video_frames(const std::filesystem::path& file, const std::vector<int>& indices, int width);

// The number of frames, counted by decoding. Throws like video_frames.
int video_frame_count(const std::filesystem::path& file);

}  // namespace svgm
