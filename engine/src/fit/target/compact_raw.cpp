// The target's frames before cleanup kept compact for a fit (see compact_raw.h).
#include "fit/target/compact_raw.h"

#include <algorithm>
#include <cmath>

#include "media/preview_video.h"
#include "svgmotion/error.h"

namespace svgm {

RawFigure raw_figure(const TargetFrames& t, int k) {
  const size_t px = static_cast<size_t>(t.width) * t.height;
  RawFigure f;
  if (t.raw.empty()) {
    const TargetFrames::CompactRaw& c = t.raw_compact;
    if (c.figure.size() < (static_cast<size_t>(k) + 1) * px) throw Error("internal: the target holds no frames before cleanup");
    f.background = c.border[static_cast<size_t>(k)];
    const auto at = c.figure.begin() + static_cast<std::ptrdiff_t>(static_cast<size_t>(k) * px);
    f.figure.assign(at, at + static_cast<std::ptrdiff_t>(px));
    return f;
  }
  const float* raw = &t.raw[static_cast<size_t>(k) * px * 4];
  f.background = border_median_rgb(raw, t.width, t.height);
  f.figure.resize(px);
  for (size_t i = 0; i < px; ++i) f.figure[i] = differs_from(raw[4 * i], raw[4 * i + 1], raw[4 * i + 2], f.background);
  return f;
}

RgbaImage raw_image(const TargetFrames& t, int k) {
  const size_t px = static_cast<size_t>(t.width) * t.height;
  if (!t.raw.empty()) return rgba8_image(&t.raw[static_cast<size_t>(k) * px * 4], t.width, t.height);
  const std::vector<uint8_t>& rgb8 = t.raw_compact.rgb8;
  if (rgb8.size() < (static_cast<size_t>(k) + 1) * px * 3) throw Error("internal: the target holds no frames before cleanup");
  RgbaImage img{t.width, t.height, std::vector<uint8_t>(px * 4, 255)};
  const uint8_t* s = &rgb8[static_cast<size_t>(k) * px * 3];
  for (size_t i = 0; i < px; ++i)
    for (int c = 0; c < 3; ++c) img.rgba[4 * i + c] = s[3 * i + c];  // A stays 255: raw's A is 1
  return img;
}

void compact_raw(TargetFrames& t) {
  if (t.raw.empty()) return;
  const size_t px = static_cast<size_t>(t.width) * t.height;
  TargetFrames::CompactRaw c;
  c.rgb8.reserve(static_cast<size_t>(t.keyframes) * px * 3);
  c.figure.reserve(static_cast<size_t>(t.keyframes) * px);
  for (int k = 0; k < t.keyframes; ++k) {
    RawFigure f = raw_figure(t, k);
    c.border.push_back(f.background);
    c.figure.insert(c.figure.end(), f.figure.begin(), f.figure.end());
    const RgbaImage img = raw_image(t, k);
    for (size_t i = 0; i < px; ++i) c.rgb8.insert(c.rgb8.end(), &img.rgba[4 * i], &img.rgba[4 * i + 3]);
  }
  t.raw_compact = std::move(c);
  std::vector<float>().swap(t.raw);
}

}  // namespace svgm
