// Lottie frames through librlottie's C API (see lottie_frames.h).
#include "report/lottie_frames.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#ifdef SVGM_HAVE_RLOTTIE
#include <rlottie_capi.h>
#endif

namespace svgm {

std::optional<LottieFrames> lottie_frames(const std::filesystem::path &json,
                                          int width, int max_frames,
                                          std::string &why_not) {
#ifndef SVGM_HAVE_RLOTTIE
  (void)json, (void)width, (void)max_frames;
  why_not = "this svgmotion was built without librlottie (apt install "
            "librlottie-dev, then rebuild)";
  return std::nullopt;
#else
  Lottie_Animation *anim = lottie_animation_from_file(json.c_str());
  if (!anim) {
    why_not = json.filename().string() + ": librlottie cannot load it";
    return std::nullopt;
  }
  size_t w0 = 0, h0 = 0;
  lottie_animation_get_size(anim, &w0, &h0);
  const size_t total = lottie_animation_get_totalframe(anim);
  const double duration = lottie_animation_get_duration(anim);
  if (w0 == 0 || h0 == 0 || total == 0 || !(duration > 0)) {
    lottie_animation_destroy(anim);
    why_not = json.filename().string() +
              ": no frames to draw (size or duration is 0)";
    return std::nullopt;
  }
  const int w = std::max(1, width);
  const int h = std::max(
      1, static_cast<int>(std::lround(static_cast<double>(h0) * w / w0)));
  const size_t n =
      std::min(total, static_cast<size_t>(std::max(1, max_frames)));
  LottieFrames out;
  out.duration_s = duration;
  out.player = "librlottie";
  std::vector<uint32_t> buf(static_cast<size_t>(w) * h);
  for (size_t i = 0; i < n; ++i) {
    std::fill(buf.begin(), buf.end(), 0u);
    lottie_animation_render(anim, i * total / n, buf.data(),
                            static_cast<size_t>(w), static_cast<size_t>(h),
                            static_cast<size_t>(w) * 4);
    // rlottie writes premultiplied ARGB32 (0xAARRGGBB in native order).
    RgbaImage img{w, h, std::vector<uint8_t>(buf.size() * 4)};
    for (size_t p = 0; p < buf.size(); ++p) {
      const uint32_t v = buf[p];
      const uint32_t a = v >> 24;
      for (int c = 0; c < 3; ++c) {
        const uint32_t pm = v >> (16 - 8 * c) & 0xff;
        img.rgba[4 * p + static_cast<size_t>(c)] = static_cast<uint8_t>(
            a ? std::min<uint32_t>(255, (pm * 255 + a / 2) / a) : 0);
      }
      img.rgba[4 * p + 3] = static_cast<uint8_t>(a);
    }
    out.frames.push_back(std::move(img));
  }
  lottie_animation_destroy(anim);
  return out;
#endif
}

} // namespace svgm
