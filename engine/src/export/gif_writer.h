// Writing an animated GIF (GIF89a) of rendered frames: one palette for the whole clip, frame
// differencing, LZW.
//
// Colours are FFmpeg's palettegen/paletteuse (palette_quantiser.h): the palette is shared by
// every frame so a flat colour never flickers as the animation loops, and paletteuse's error
// diffusion keeps gradients from banding. Each frame then draws only the rectangle that changed, with
// unchanged pixels transparent (see GifFrames in the .cpp). The container and its LZW coder are
// our own: ~150 lines of the format, where FFmpeg's GIF muxer would fix timing and disposal
// for us in ways a transparent animation cannot use.
#pragma once

#include <filesystem>
#include <functional>

#include "svgmotion/png_io.h"

namespace svgm {

// frame(i) returns frame i (8-bit straight RGBA); it is called twice per frame (once to gather
// colours, once to encode), so no frame is held in memory. `transparent`: pixels with alpha
// below 128 are transparent in the GIF and the rest opaque (GIF has no partial alpha); else
// every frame is composited over white.
// Frame i is shown from round(100 i / fps) to round(100 (i+1) / fps) hundredths of a second
// (GIF's unit), so the whole clip lasts frames / fps to the hundredth. `loop`: repeat forever
// (the NETSCAPE2.0 extension), else play once. Written to a temporary name and renamed.
// Throws svgm::Error "<file>: <problem>".
void write_gif(const std::filesystem::path& file, int frames, double fps,
               const std::function<RgbaImage(int)>& frame, bool loop, bool transparent = false);

}  // namespace svgm
