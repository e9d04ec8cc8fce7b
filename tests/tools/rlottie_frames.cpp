// Test tool: frames of a Lottie file drawn by librlottie (Samsung's player, Debian's
// librlottie-dev), the second independent player the Lottie export is checked in.
//   rlottie_frames ANIMATION.json WIDTH HEIGHT OUT_PREFIX FRAME...
// writes OUT_PREFIX<i>.png for the i-th FRAME (a frame number of the Lottie timeline; rlottie
// draws whole frames), straight RGBA. Exit 2 when the file cannot be loaded.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "export/lottie_player.h"
#include "svgmotion/png_io.h"

int main(int argc, char** argv) {
  if (argc < 6) {
    std::fprintf(stderr, "usage: rlottie_frames ANIMATION.json WIDTH HEIGHT OUT_PREFIX FRAME...\n");
    return 2;
  }
  std::string why;
  const auto player = svgm::LottiePlayer::open(argv[1], why);
  if (!player) {
    std::fprintf(stderr, "rlottie_frames: %s\n", why.c_str());
    return 2;
  }
  const int w = std::atoi(argv[2]), h = std::atoi(argv[3]);
  try {
    for (int i = 5; i < argc; ++i)
      svgm::write_png(std::string(argv[4]) + std::to_string(i - 5) + ".png",
                      player->draw(static_cast<size_t>(std::atol(argv[i])), w, h));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rlottie_frames: %s\n", e.what());
    return 2;
  }
  return 0;
}
