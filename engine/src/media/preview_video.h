// Preview videos of a fit: each video frame is a row of panels (say, target | render |
// overlay) side by side, written as an H.264 mp4 that any browser or player shows.
//
// Panels are 8-bit straight RGBA (svgm::RgbaImage, the renderer's and PNG writer's format);
// alpha is composited over white, since previews are about ink on paper. Float images (such as
// TargetFrames::raw) convert with rgba8_image.
#pragma once

#include <filesystem>
#include <functional>
#include <vector>

#include "svgmotion/png_io.h"

namespace svgm {

// panel_image(frame, panel) returns panel `panel` of video frame `frame`. Every panel of a frame
// has the same height; panel p has the same size in every frame. Panels are requested in order
// (frame 0 panels 0..P-1, frame 1 ...), one frame at a time, so a long preview never holds more
// than one frame in memory.
using PreviewPanelFn = std::function<RgbaImage(int frame, int panel)>;

// Writes `frames` frames at `fps` to `file` through media/video_encoder.h: H.264 in an mp4
// (faststart, BT.709-tagged, which media/video_decoder.h reads back with the same matrix), or VP9
// in WebM for a file named .webm. Odd frame sizes are padded with white on the right/bottom
// (4:2:0 chroma needs even sides). Written to a hidden temporary name in the same folder and
// renamed when complete, so a failure never leaves a partial file. Throws svgm::Error
// "<file>: <problem>"; a write the disk refuses is named as such ("<file>: cannot write: No
// space left on device").
void write_preview_video(const std::filesystem::path& file, int frames, int panels,
                         const PreviewPanelFn& panel_image, double fps);

// The same with every image at hand: panels[p][k] is panel p of frame k (all panels[p] the
// same length).
void write_preview_video(const std::filesystem::path& file,
                         const std::vector<std::vector<RgbaImage>>& panels, double fps);

// Straight float RGBA in [0,1] (width*height*4, row-major) to 8-bit, clamped and rounded.
RgbaImage rgba8_image(const float* rgba, int width, int height);

}  // namespace svgm
