// The target's frames before cleanup kept compact for a fit (see compact_raw.h).
#include "fit/target/compact_raw.h"

#include "fit/target/deflated_bytes.h"
#include "media/preview_video.h"
#include "svgmotion/error.h"

namespace svgm {

namespace {

// Keyframe k of `c`, a target of px pixels per frame, inflated (or it throws).
std::vector<uint8_t> holding(const CompactRaw* c, int k, size_t px) {
  if (!c || k < 0 || static_cast<size_t>(k) >= c->frames.size() || c->pixels != px)
    throw Error("internal: the target holds no frames before cleanup");
  return compact_frame(*c, k);
}

}  // namespace

size_t CompactRaw::bytes() const {
  size_t n = 0;
  for (const auto& f : frames) n += f.size();
  return n;
}

std::vector<uint8_t> compact_frame(const CompactRaw& c, int k) {
  std::vector<uint8_t> out(c.pixels * 4);
  inflate_bytes(c.frames.at(static_cast<size_t>(k)), out.data(), out.size());
  return out;
}

RawFigure raw_figure(const TargetFrames& t, const CompactRaw* c, int k) {
  const size_t px = static_cast<size_t>(t.width) * t.height;
  RawFigure f;
  if (t.raw.empty()) {
    const std::vector<uint8_t> h = holding(c, k, px);
    f.background = c->border[static_cast<size_t>(k)];
    f.figure.assign(h.begin() + static_cast<std::ptrdiff_t>(3 * px), h.end());
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
  const std::vector<uint8_t> h = holding(c, k, px);
  const uint8_t* s = h.data();
  RgbaImage img{t.width, t.height, std::vector<uint8_t>(px * 4, 255)};
  for (size_t i = 0; i < px; ++i)
    for (int ch = 0; ch < 3; ++ch) img.rgba[4 * i + ch] = s[3 * i + ch];
  return img;
}

void compact_raw_frame(CompactRaw& c, const float* raw, int width, int height) {
  const size_t px = static_cast<size_t>(width) * height;
  if (!c.frames.empty() && c.pixels != px) throw Error("internal: compacting frames of another size");
  c.pixels = px;
  const RawFigure f = raw_frame_figure(raw, width, height);
  c.border.push_back(f.background);
  const RgbaImage img = rgba8_image(raw, width, height);
  std::vector<uint8_t> bytes(px * 4);
  for (size_t i = 0; i < px; ++i) std::copy_n(&img.rgba[4 * i], 3, &bytes[3 * i]);
  std::copy(f.figure.begin(), f.figure.end(), bytes.begin() + static_cast<std::ptrdiff_t>(3 * px));
  c.frames.push_back(deflate_bytes(bytes.data(), bytes.size()));
}

CompactRaw compact_raw(TargetFrames& t) {
  CompactRaw c;
  if (t.raw.empty()) return c;
  const size_t px = static_cast<size_t>(t.width) * t.height;
  for (int k = 0; k < t.keyframes; ++k) compact_raw_frame(c, &t.raw[static_cast<size_t>(k) * px * 4], t.width, t.height);
  std::vector<float>().swap(t.raw);
  return c;
}

TargetFrames load_target_compact(const std::filesystem::path& source, int width, int height, TargetOptions options,
                                 CompactRaw& raw) {
  raw = {};
  options.raw_sink = [&raw, width, height](int, const float* frame) { compact_raw_frame(raw, frame, width, height); };
  return load_target(source, width, height, options);
}

}  // namespace svgm
