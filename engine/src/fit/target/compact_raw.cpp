// The target's frames before cleanup kept compact for a fit (see compact_raw.h).
#include "fit/target/compact_raw.h"

#include "media/preview_video.h"
#include "svgmotion/error.h"

namespace svgm {

namespace {

// `c` holds keyframe k of a target of px pixels per frame (or it throws).
const CompactRaw& holding(const CompactRaw* c, int k, size_t px) {
  if (!c || c->figure.size() < (static_cast<size_t>(k) + 1) * px || c->rgb8.size() < (static_cast<size_t>(k) + 1) * px * 3)
    throw Error("internal: the target holds no frames before cleanup");
  return *c;
}

}  // namespace

RawFigure raw_figure(const TargetFrames& t, const CompactRaw* c, int k) {
  const size_t px = static_cast<size_t>(t.width) * t.height;
  RawFigure f;
  if (t.raw.empty()) {
    const CompactRaw& h = holding(c, k, px);
    f.background = h.border[static_cast<size_t>(k)];
    const auto at = h.figure.begin() + static_cast<std::ptrdiff_t>(static_cast<size_t>(k) * px);
    f.figure.assign(at, at + static_cast<std::ptrdiff_t>(px));
    return f;
  }
  const float* raw = &t.raw[static_cast<size_t>(k) * px * 4];
  f.background = border_median_rgb(raw, t.width, t.height);
  f.figure.resize(px);
  for (size_t i = 0; i < px; ++i) f.figure[i] = differs_from(raw[4 * i], raw[4 * i + 1], raw[4 * i + 2], f.background);
  return f;
}

RgbaImage raw_image(const TargetFrames& t, const CompactRaw* c, int k) {
  const size_t px = static_cast<size_t>(t.width) * t.height;
  if (!t.raw.empty()) return rgba8_image(&t.raw[static_cast<size_t>(k) * px * 4], t.width, t.height);
  const uint8_t* s = &holding(c, k, px).rgb8[static_cast<size_t>(k) * px * 3];
  RgbaImage img{t.width, t.height, std::vector<uint8_t>(px * 4, 255)};
  for (size_t i = 0; i < px; ++i)
    for (int ch = 0; ch < 3; ++ch) img.rgba[4 * i + ch] = s[3 * i + ch];
  return img;
}

CompactRaw compact_raw(TargetFrames& t) {
  CompactRaw c;
  if (t.raw.empty()) return c;
  const size_t px = static_cast<size_t>(t.width) * t.height;
  c.rgb8.reserve(static_cast<size_t>(t.keyframes) * px * 3);
  c.figure.reserve(static_cast<size_t>(t.keyframes) * px);
  for (int k = 0; k < t.keyframes; ++k) {
    const RawFigure f = raw_figure(t, nullptr, k);
    c.border.push_back(f.background);
    c.figure.insert(c.figure.end(), f.figure.begin(), f.figure.end());
    const RgbaImage img = raw_image(t, nullptr, k);
    for (size_t i = 0; i < px; ++i) c.rgb8.insert(c.rgb8.end(), &img.rgba[4 * i], &img.rgba[4 * i + 3]);
  }
  std::vector<float>().swap(t.raw);
  return c;
}

}  // namespace svgm
