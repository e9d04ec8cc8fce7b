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
  return raw_frame_figure(&t.raw[static_cast<size_t>(k) * px * 4], t.width, t.height);
}

RawFigure raw_frame_figure(const float* raw, int width, int height) {
  const size_t px = static_cast<size_t>(width) * height;
  RawFigure f;
  f.background = border_median_rgb(raw, width, height);
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

void compact_raw_frame(CompactRaw& c, const float* raw, int width, int height) {
  const size_t px = static_cast<size_t>(width) * height;
  const RawFigure f = raw_frame_figure(raw, width, height);
  c.border.push_back(f.background);
  c.figure.insert(c.figure.end(), f.figure.begin(), f.figure.end());
  const RgbaImage img = rgba8_image(raw, width, height);
  for (size_t i = 0; i < px; ++i) c.rgb8.insert(c.rgb8.end(), &img.rgba[4 * i], &img.rgba[4 * i + 3]);
}

CompactRaw compact_raw(TargetFrames& t) {
  CompactRaw c;
  if (t.raw.empty()) return c;
  const size_t px = static_cast<size_t>(t.width) * t.height;
  c.rgb8.reserve(static_cast<size_t>(t.keyframes) * px * 3);
  c.figure.reserve(static_cast<size_t>(t.keyframes) * px);
  for (int k = 0; k < t.keyframes; ++k) compact_raw_frame(c, &t.raw[static_cast<size_t>(k) * px * 4], t.width, t.height);
  std::vector<float>().swap(t.raw);
  return c;
}

TargetFrames load_target_compact(const std::filesystem::path& source, int width, int height, TargetOptions options,
                                 CompactRaw& raw) {
  raw = {};
  // Sized up front: growing by doubling would hold up to twice the compact frames.
  const size_t K = options.frames.empty() ? static_cast<size_t>(std::max(options.keyframes, 0)) : options.frames.size();
  const size_t px = static_cast<size_t>(width) * height;
  raw.rgb8.reserve(K * px * 3);
  raw.figure.reserve(K * px);
  options.raw_sink = [&raw, width, height](int, const float* frame) { compact_raw_frame(raw, frame, width, height); };
  return load_target(source, width, height, options);
}

}  // namespace svgm
