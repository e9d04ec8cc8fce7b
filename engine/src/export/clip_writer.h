// Writing rendered frames as a clip: an mp4 (H.264) or WebM (VP9, alpha optional) video
// (video_encoder.h), an animated GIF (gif_writer.h), or a numbered PNG sequence (frames/%04d.png). Used by
// `svgmotion render ANIMATION.svg -o clip.mp4|.webm|.gif|frames/%04d.png`.
#pragma once

#include <functional>
#include <string>

#include "svgmotion/png_io.h"

namespace svgm {

enum class ClipFormat { Still, Sequence, Mp4, Webm, Gif, Webp };

// What an output name asks for, by its extension (any case): .png a still image, or a frame
// sequence when the name holds one frame-number field (%d, %4d or %04d; %% is a literal %);
// .mp4, .webm, .gif, .webp (animated WebP) a clip. Throws svgm::Error naming `out` for anything else, or a pattern
// with no, several or another kind of % field.
ClipFormat clip_format(const std::string& out);

// The name of frame `i` in a sequence pattern (the field replaced by the number, zero-padded
// to its width when it says %0N; %% becomes %).
std::string sequence_name(const std::string& pattern, int i);

// What a clip keeps beside its frames.
struct ClipOptions {
  int quality = -1;          // a video's CRF (video_encoder.h); -1 the codec's default
  bool transparent = false;  // the frames' alpha kept: PNG, GIF (binary alpha), WebM, WebP
};

// Writes `frames` frames at `fps`: frame(i) is called in order (a GIF calls it twice per frame,
// see gif_writer.h). `loop`: the clip repeats (a GIF loops forever; a video has no such flag).
// Without options.transparent, video and GIF frames are composited over white; an mp4 cannot
// be transparent (svgm::Error).
// A sequence creates its folder when missing and writes frame i as sequence_name(out, i), each
// file atomically; the other formats write one file atomically. Throws svgm::Error.
void write_clip(const std::string& out, ClipFormat format, int frames, double fps, bool loop,
                const std::function<RgbaImage(int)>& frame, const ClipOptions& options = {});

}  // namespace svgm
