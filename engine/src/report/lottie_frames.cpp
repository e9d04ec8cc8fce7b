// Lottie frames for report.html through the Lottie player (see lottie_frames.h).
#include "report/lottie_frames.h"

#include <algorithm>
#include <cmath>

#include "export/lottie_player.h"

namespace svgm {

std::optional<LottieFrames> lottie_frames(const std::filesystem::path &json,
                                          int width, int max_frames,
                                          std::string &why_not) {
  const auto player = LottiePlayer::open(json, why_not);
  if (!player)
    return std::nullopt;
  const size_t total = player->total_frames();
  const int w = std::max(1, width);
  const int h = std::max(
      1, static_cast<int>(std::lround(static_cast<double>(player->height()) *
                                      w / player->width())));
  const size_t n =
      std::min(total, static_cast<size_t>(std::max(1, max_frames)));
  LottieFrames out;
  out.duration_s = player->duration_s();
  out.player = "librlottie";
  for (size_t i = 0; i < n; ++i)
    out.frames.push_back(player->draw(i * total / n, w, h));
  return out;
}

} // namespace svgm
