// Writing an animated GIF (GIF89a) of rendered frames: one palette for the whole clip, LZW.
//
// Why our own encoder: OpenCV (our video library) cannot write GIF, FFmpeg's GIF encoder is
// only reachable through its command-line tool or a filter graph, and giflib would be one more
// dependency for the ~150 lines of the format's own LZW coder. The palette is shared by every
// frame so a flat colour never flickers as the animation loops: the drawing's colours exactly
// when the clip has at most 256 of them, otherwise a weighted median cut of every frame's
// colours (large flat areas pull their box's mean to their own colour). No dithering: vector
// art is flat colour, and dither noise would crawl from frame to frame.
#pragma once

#include <filesystem>
#include <functional>

#include "svgmotion/png_io.h"

namespace svgm {

// frame(i) returns frame i (8-bit RGBA, composited over white where not opaque); it is called
// twice per frame (once to gather colours, once to encode), so no frame is held in memory.
// Frame i is shown from round(100 i / fps) to round(100 (i+1) / fps) hundredths of a second
// (GIF's unit), so the whole clip lasts frames / fps to the hundredth. `loop`: repeat forever
// (the NETSCAPE2.0 extension), else play once. Written to a temporary name and renamed.
// Throws svgm::Error "<file>: <problem>".
void write_gif(const std::filesystem::path& file, int frames, double fps,
               const std::function<RgbaImage(int)>& frame, bool loop);

}  // namespace svgm
