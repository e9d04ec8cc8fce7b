// librlottie's C API behind LottiePlayer (see lottie_player.h).
#include "export/lottie_player.h"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <functional>
#include <string>
#include <vector>

#ifdef SVGM_HAVE_RLOTTIE
#include <rlottie_capi.h>
#endif

namespace svgm {

bool LottiePlayer::available() {
#ifdef SVGM_HAVE_RLOTTIE
  return true;
#else
  return false;
#endif
}

std::unique_ptr<LottiePlayer> LottiePlayer::open(const std::filesystem::path& json, std::string& why_not) {
#ifndef SVGM_HAVE_RLOTTIE
  (void)json;
  why_not = "this svgmotion was built without librlottie (apt install librlottie-dev, then rebuild)";
  return nullptr;
#else
  std::ifstream in(json, std::ios::binary);
  if (!in) {
    why_not = json.string() + ": cannot read it";
    return nullptr;
  }
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // rlottie caches every model it parses under a key (the path, for lottie_animation_from_file)
  // and hands the cached one back for the same key: a file written again under the same name
  // (the tolerance search's candidates) would be drawn as it was first read. A key made of the
  // content's hash and length changes with the content.
  const std::string key = std::to_string(std::hash<std::string>{}(text)) + "-" + std::to_string(text.size());
  Lottie_Animation* anim = lottie_animation_from_data(text.c_str(), key.c_str(), json.parent_path().c_str());
  if (!anim) {
    why_not = json.filename().string() + ": librlottie cannot load it";
    return nullptr;
  }
  std::unique_ptr<LottiePlayer> p(new LottiePlayer);
  p->anim_ = anim;
  lottie_animation_get_size(anim, &p->width_, &p->height_);
  p->total_ = lottie_animation_get_totalframe(anim);
  p->duration_ = lottie_animation_get_duration(anim);
  if (p->width_ == 0 || p->height_ == 0 || p->total_ == 0 || !(p->duration_ > 0)) {
    why_not = json.filename().string() + ": no frames to draw (size or duration is 0)";
    return nullptr;
  }
  return p;
#endif
}

LottiePlayer::~LottiePlayer() {
#ifdef SVGM_HAVE_RLOTTIE
  if (anim_) lottie_animation_destroy(static_cast<Lottie_Animation*>(anim_));
#endif
}

RgbaImage LottiePlayer::draw(size_t frame, int width, int height) const {
  const int w = std::max(1, width), h = std::max(1, height);
  RgbaImage img{w, h, std::vector<uint8_t>(static_cast<size_t>(w) * h * 4)};
#ifdef SVGM_HAVE_RLOTTIE
  std::vector<uint32_t> buf(static_cast<size_t>(w) * h, 0u);
  lottie_animation_render(static_cast<Lottie_Animation*>(anim_), frame, buf.data(), static_cast<size_t>(w),
                          static_cast<size_t>(h), static_cast<size_t>(w) * 4);
  // rlottie writes premultiplied ARGB32 (0xAARRGGBB in native order).
  for (size_t p = 0; p < buf.size(); ++p) {
    const uint32_t v = buf[p], a = v >> 24;
    for (int c = 0; c < 3; ++c) {
      const uint32_t pm = v >> (16 - 8 * c) & 0xff;
      img.rgba[4 * p + static_cast<size_t>(c)] = static_cast<uint8_t>(a ? std::min<uint32_t>(255, (pm * 255 + a / 2) / a) : 0);
    }
    img.rgba[4 * p + 3] = static_cast<uint8_t>(a);
  }
#else
  (void)frame;
#endif
  return img;
}

RgbaImage over_white(const RgbaImage& image) {
  RgbaImage out = image;
  for (size_t i = 0; i < out.rgba.size(); i += 4) {
    const int a = out.rgba[i + 3];
    for (size_t c = 0; c < 3; ++c) out.rgba[i + c] = static_cast<uint8_t>((out.rgba[i + c] * a + 255 * (255 - a) + 127) / 255);
    out.rgba[i + 3] = 255;
  }
  return out;
}

}  // namespace svgm
