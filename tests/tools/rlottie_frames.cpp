// Test tool: frames of a Lottie file drawn by librlottie (Samsung's player, Debian's
// librlottie-dev), the second independent player the Lottie export is checked in.
//   rlottie_frames ANIMATION.json WIDTH HEIGHT OUT_PREFIX FRAME...
// writes OUT_PREFIX<i>.png for the i-th FRAME (a frame number of the Lottie timeline; rlottie
// draws whole frames), straight RGBA. Exit 2 when the file cannot be loaded.
#include <rlottie_capi.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "svgmotion/png_io.h"

int main(int argc, char** argv) {
  if (argc < 6) {
    std::fprintf(stderr, "usage: rlottie_frames ANIMATION.json WIDTH HEIGHT OUT_PREFIX FRAME...\n");
    return 2;
  }
  Lottie_Animation* anim = lottie_animation_from_file(argv[1]);
  if (!anim) {
    std::fprintf(stderr, "rlottie_frames: %s: rlottie cannot load it\n", argv[1]);
    return 2;
  }
  const int w = std::atoi(argv[2]), h = std::atoi(argv[3]);
  std::vector<uint32_t> buf(static_cast<size_t>(w) * h);
  try {
    for (int i = 5; i < argc; ++i) {
      std::fill(buf.begin(), buf.end(), 0u);
      lottie_animation_render(anim, static_cast<size_t>(std::atol(argv[i])), buf.data(), static_cast<size_t>(w),
                              static_cast<size_t>(h), static_cast<size_t>(w) * 4);
      // rlottie writes premultiplied ARGB32 (0xAARRGGBB in native order).
      svgm::RgbaImage img{w, h, std::vector<uint8_t>(static_cast<size_t>(w) * h * 4)};
      for (size_t p = 0; p < buf.size(); ++p) {
        const uint32_t v = buf[p];
        const int a = v >> 24;
        for (int c = 0; c < 3; ++c) {
          const int pm = v >> (16 - 8 * c) & 0xff;
          img.rgba[4 * p + c] = static_cast<uint8_t>(a ? std::min(255, (pm * 255 + a / 2) / a) : 0);
        }
        img.rgba[4 * p + 3] = static_cast<uint8_t>(a);
      }
      svgm::write_png(std::string(argv[4]) + std::to_string(i - 5) + ".png", img);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rlottie_frames: %s\n", e.what());
    lottie_animation_destroy(anim);
    return 2;
  }
  lottie_animation_destroy(anim);
  return 0;
}
