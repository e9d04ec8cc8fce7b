// Colour quantisation for GIF through FFmpeg's libavfilter: one palette for the whole clip from
// `palettegen` over every frame, then each frame mapped to it by `paletteuse` (Floyd-Steinberg
// error diffusion: deterministic, so still areas before a change keep their indices and a
// GIF's frame differencing finds them).
//
// Why FFmpeg's: it is the quantiser people compare GIFs against (`ffmpeg -vf
// "split[a][b];[a]palettegen[p];[b][p]paletteuse"`), FFmpeg is already a dependency (OpenCV's
// video back end), and a median cut on a 5-bit histogram with error diffusion keeps gradients
// free of banding where a nearest-colour map does not.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "svgmotion/png_io.h"

namespace svgm {

class PaletteQuantiser {
 public:
  // `transparent`: pixels with alpha < 128 map to the palette's transparent index; otherwise
  // every frame is composited over white first. One palette index is always reserved as
  // transparent (GIF frame differencing marks unchanged pixels with it). `name` names the
  // output in errors. Throws svgm::Error "<name>: <problem>".
  PaletteQuantiser(int width, int height, bool transparent, std::string name);
  ~PaletteQuantiser();
  PaletteQuantiser(const PaletteQuantiser&) = delete;
  PaletteQuantiser& operator=(const PaletteQuantiser&) = delete;

  // Pass 1: every frame of the clip, in order (only its colour statistics are kept).
  void gather(const RgbaImage& frame);
  // Ends pass 1: the palette as 0xAARRGGBB (256 entries; unused ones are 0).
  const std::array<uint32_t, 256>& palette();
  // The reserved transparent index (alpha 0 in the palette).
  int transparent_index() const { return transparent_index_; }
  // Pass 2: maps the frames in order; `out(indices)` receives each frame's width*height palette
  // indices, in order, possibly a frame or two after its map() call (the filter buffers); finish()
  // hands over the rest.
  void map(const RgbaImage& frame, const std::function<void(const std::vector<uint8_t>&)>& out);
  void finish(const std::function<void(const std::vector<uint8_t>&)>& out);

 private:
  struct Graph;
  struct SourceSpec;
  std::unique_ptr<Graph> build_graph(const std::vector<SourceSpec>& specs, const char* filter) const;
  [[noreturn]] void fail(const std::string& problem, int av_error = 0) const;
  void push(Graph& g, int input, const RgbaImage* frame);

  int width_, height_;
  bool transparent_;
  std::string name_;
  std::unique_ptr<Graph> gen_, use_;
  std::array<uint32_t, 256> palette_{};
  int transparent_index_ = -1;
  int64_t pts_ = 0;
};

}  // namespace svgm
