// Frames of the run's Lottie file (animation.json) drawn by a real Lottie
// player, librlottie (Samsung's, LGPL-2.1, linked from Debian's librlottie0-1
// when the build finds it: the SVGMOTION_WITH_RLOTTIE option), for report.html
// to show the Lottie beside the SVG.
//
// Why frames and not a player in the page: lottie-web (MIT) would have to be
// copied into the page, and the page runs only its own script (its CSP);
// rlottie draws the file as a Lottie player does, so what the page shows is
// what a Lottie player makes of our file, not our own renderer's idea of it.
// Without rlottie the page says so and shows no Lottie pictures.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "svgmotion/png_io.h"

namespace svgm {

struct LottieFrames {
  std::vector<RgbaImage>
      frames;            // evenly over one pass of the animation, straight RGBA
  double duration_s = 0; // of one pass
  std::string player;    // "librlottie"
};

// At most `max_frames` frames at `width` px (height by the file's aspect);
// nothing, with the reason in `why_not`, when rlottie is not built in or cannot
// load the file.
std::optional<LottieFrames> lottie_frames(const std::filesystem::path &json,
                                          int width, int max_frames,
                                          std::string &why_not);

} // namespace svgm
