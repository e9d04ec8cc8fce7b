// Encoding rendered frames as a video people can ship, through FFmpeg's libavcodec and
// libavformat: H.264 in an mp4 with its index first ("faststart": a browser starts playing
// before the whole file has arrived), VP9 in WebM, optionally with an alpha channel, or an
// animated WebP (lossless, optionally transparent).
//
// Colour is stated and converted as players expect: BT.709 primaries, transfer and matrix,
// limited ("TV") range, each tagged in the stream and the container, with the RGB -> Y'CbCr
// conversion done with the same BT.709 coefficients (swscale's default is BT.601, which a
// player reading the file as BT.709 shows with shifted colours: white came back 251,253,250).
// Odd sizes are padded on the right and bottom (4:2:0 chroma needs even sides) with white, or
// with transparent pixels for a transparent WebM.
#pragma once

#include <filesystem>
#include <functional>

#include "svgmotion/png_io.h"

namespace svgm {

struct VideoOptions {
  // Constant-rate-factor quality, lower is better: H.264 0..51 (x264's scale), VP9 0..63
  // (libvpx's). -1: kDefaultH264Crf or kDefaultVp9Crf.
  int quality = -1;
  // WebM and WebP only: keep the frames' alpha (VP9 with an alpha channel); otherwise frames are
  // composited over white.
  bool transparent = false;
  // Animated WebP only: play forever (else once). Video containers have no such flag.
  bool loop = true;
};

// Visually near-lossless for flat vector art at a few kB per second (x264's default is 23).
constexpr int kDefaultH264Crf = 20;
// libvpx's constant-quality mode; 31 is the level FFmpeg's VP9 guide suggests for 720p-ish video.
constexpr int kDefaultVp9Crf = 31;
constexpr int kMaxH264Crf = 51;
constexpr int kMaxVp9Crf = 63;

// Writes `frames` frames of frame(i) (8-bit straight RGBA, every frame the size of the first)
// at `fps` to `file`: WebM when its extension is .webm (any case), animated WebP for .webp,
// else mp4. Written to a
// hidden temporary name beside `file` and renamed when complete. Throws svgm::Error
// "<file>: <problem>" (a quality out of range, a missing encoder, a write the disk refused).
void write_video(const std::filesystem::path& file, int frames, double fps,
                 const std::function<RgbaImage(int)>& frame, const VideoOptions& options);

}  // namespace svgm
