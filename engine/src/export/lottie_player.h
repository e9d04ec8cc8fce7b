// A Lottie file drawn by a real Lottie player, librlottie (Samsung's, LGPL-2.1, linked from
// Debian's librlottie0-1 when the build finds it: the SVGMOTION_WITH_RLOTTIE option). Two users:
// report.html shows animation.json as a player draws it (report/lottie_frames.h), and the compact
// export measures animation.json's tolerance on the player's own pictures
// (fit/output/tolerance_choice.h), since our renderer draws no Lottie and a player's shapes and
// edges differ from ours by more than the compact export's margin.
//
// Without rlottie `open` says why and nothing is drawn; callers fall back (the report shows no
// Lottie frames, the export writes animation.json a fixed step tighter than animation.svg).
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>

#include "svgmotion/png_io.h"

namespace svgm {

class LottiePlayer {
 public:
  // Whether this build links a Lottie player at all.
  static bool available();
  // Loads `json`; nullptr with the reason in `why_not` when it cannot (no player built in, a
  // file the player rejects, no size or no frames).
  static std::unique_ptr<LottiePlayer> open(const std::filesystem::path& json, std::string& why_not);
  ~LottiePlayer();
  LottiePlayer(const LottiePlayer&) = delete;
  LottiePlayer& operator=(const LottiePlayer&) = delete;

  size_t width() const { return width_; }    // the file's w
  size_t height() const { return height_; }  // the file's h
  size_t total_frames() const { return total_; }
  double duration_s() const { return duration_; }
  // Frame `frame` of the timeline (whole frames, as the player draws them) at width x height,
  // straight (not premultiplied) RGBA.
  RgbaImage draw(size_t frame, int width, int height) const;

 private:
  LottiePlayer() = default;
  void* anim_ = nullptr;  // Lottie_Animation*, opaque here so that users need no rlottie header
  size_t width_ = 0, height_ = 0, total_ = 0;
  double duration_ = 0;
};

// An image composited over white (alpha 255), as the compact export's measure compares renders.
RgbaImage over_white(const RgbaImage& image);

}  // namespace svgm
