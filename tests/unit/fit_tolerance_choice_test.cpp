// The compact export's tolerance chosen by rendering (fit/output/tolerance_choice.h): the
// largest step of the ladder whose compact file stays at kCompactTargetDb + kCompactMarginDb of
// the full export at every sampled time, and the temporary candidates removed.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "export/lottie_player.h"
#include "fit/output/tolerance_choice.h"
#include "temp_dir.h"

using namespace svgm;
using svgm::test::TempDir;
namespace fs = std::filesystem;

namespace {

// A light grey square (17 levels from white: a miss is faint, as a compact export's is) moving
// across a 64-unit canvas over 2 s, shifted right by `shift` units.
void write_square(const fs::path& file, double shift) {
  char text[512];
  std::snprintf(text, sizeof text,
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"64\" height=\"64\">"
                "<rect x=\"10\" y=\"20\" width=\"20\" height=\"20\" fill=\"#eeeeee\"><animateTransform "
                "attributeName=\"transform\" type=\"translate\" values=\"%g 0;%g 0\" dur=\"2s\" "
                "repeatCount=\"indefinite\"/></rect></svg>",
                shift, 20 + shift);
  std::ofstream(file) << text;
}

// The same square as a Lottie file (60 frames at 30 fps): its layer's position keyed linearly
// from `shift` to 20 + `shift` units.
void write_lottie_square(const fs::path& file, double shift) {
  char text[1024];
  std::snprintf(text, sizeof text,
                "{\"v\":\"5.7.0\",\"fr\":30,\"ip\":0,\"op\":60,\"w\":64,\"h\":64,\"layers\":[{\"ty\":4,"
                "\"ind\":1,\"ip\":0,\"op\":60,\"st\":0,\"ks\":{\"o\":{\"a\":0,\"k\":100},\"r\":{\"a\":0,\"k\":0},"
                "\"p\":{\"a\":1,\"k\":[{\"t\":0,\"s\":[%g,0,0],\"o\":{\"x\":[0],\"y\":[0]},\"i\":{\"x\":[1],"
                "\"y\":[1]}},{\"t\":60,\"s\":[%g,0,0]}]},\"a\":{\"a\":0,\"k\":[0,0,0]},\"s\":{\"a\":0,\"k\":[100,"
                "100,100]}},\"shapes\":[{\"ty\":\"rc\",\"p\":{\"a\":0,\"k\":[20,30]},\"s\":{\"a\":0,\"k\":[20,20]},"
                "\"r\":{\"a\":0,\"k\":0}},{\"ty\":\"fl\",\"c\":{\"a\":0,\"k\":[0.93333,0.93333,0.93333,1]},"
                "\"o\":{\"a\":0,\"k\":100}}]}]}",
                shift, 20 + shift);
  std::ofstream(file) << text;
}

}  // namespace

TEST_SUITE("export") {
TEST_CASE("compact tolerance: the largest ladder step that keeps the floor against the full export") {
  TempDir dir;
  const fs::path anim = dir.path / "animation.svg";
  // A compact file that misses by four times the tolerance (1024 px show the 64 canvas units:
  // tolerance / 4 units is 4 x tolerance px at 1024). The square's two vertical edges, 320 px high,
  // at 17 levels: PSNR = 10 log10(1024^2 / (640 d)) + 20 log10(255 / 17) for a miss of d px,
  // 46.6 dB at d = 8 (tolerance 2) and 44.8 at d = 12 (tolerance 3).
  const ToleranceChoice c = choose_compact_tolerance(
      anim, [](const fs::path& f) { write_square(f, 0); },
      [](const fs::path& f, double tolerance_1024) { write_square(f, tolerance_1024 / 4); });
  CHECK(c.tolerance_1024 == 2);
  CHECK(c.worst_db >= kCompactTargetDb + kCompactMarginDb);
  CHECK(c.worst_db < 48);
  // Binary search: 1.1 and 1.5 hold, then 2 holds and 3 does not.
  REQUIRE(c.trials.size() == 4);
  CHECK(c.trials[0].tolerance_1024 == 1.1);
  CHECK(c.trials[3].tolerance_1024 == 3);
  CHECK(c.trials[3].worst_db < kCompactTargetDb + kCompactMarginDb);
  // Nothing holds: the tightest step, with what it measured.
  const ToleranceChoice far = choose_compact_tolerance(
      anim, [](const fs::path& f) { write_square(f, 0); }, [](const fs::path& f, double) { write_square(f, 4); });
  CHECK(far.tolerance_1024 == kToleranceLadder.front());
  CHECK(far.worst_db < kCompactTargetDb);
  // animation.json, which the engine cannot draw, goes two steps tighter (the first at the least).
  CHECK(lottie_tolerance(1.5) == 1.1);
  CHECK(lottie_tolerance(1.25) == 1);
  CHECK(lottie_tolerance(0.5) == 0.25);
  CHECK(lottie_tolerance(0.25) == 0.25);
  CHECK(lottie_tolerance(1.3) == 1.1);
  // The candidates were temporary files beside the animation, all removed.
  CHECK(fs::is_empty(dir.path));
}

TEST_CASE("compact tolerance: the residual shapes' tolerance loosened at the chosen one while the floor holds") {
  TempDir dir;
  const fs::path anim = dir.path / "animation.svg";
  // As above, 2 is chosen; a residual scale s misses by 2 s px at 1024 there (s tolerance / 8
  // units): 2 holds (8 px, 46.6 dB), 3 does not (12 px, 44.8 dB).
  const ToleranceChoice c = choose_compact_tolerance(
      anim, [](const fs::path& f) { write_square(f, 0); },
      [](const fs::path& f, double tolerance_1024) { write_square(f, tolerance_1024 / 4); },
      [](const fs::path& f, double tolerance_1024, double scale) { write_square(f, scale * tolerance_1024 / 8); });
  CHECK(c.tolerance_1024 == 2);
  CHECK(c.residual_scale == 2);
  CHECK(c.worst_db >= kCompactTargetDb + kCompactMarginDb);
  // Four for the tolerance, then scales 2 (held) and 3 (below the floor, the last tried).
  REQUIRE(c.trials.size() == 6);
  CHECK(c.trials[4].residual_scale == 2);
  CHECK(c.trials[5].residual_scale == 3);
  CHECK(c.trials[5].worst_db < kCompactTargetDb + kCompactMarginDb);
  // Without the residual writer only the tolerance is searched.
  const ToleranceChoice plain = choose_compact_tolerance(
      anim, [](const fs::path& f) { write_square(f, 0); },
      [](const fs::path& f, double tolerance_1024) { write_square(f, tolerance_1024 / 4); });
  CHECK(plain.residual_scale == 1);
  CHECK(plain.trials.size() == 4);
  CHECK(fs::is_empty(dir.path));
}

TEST_CASE("compact tolerance of animation.json: measured in the Lottie player, a file rewritten under one name drawn anew") {
  if (!LottiePlayer::available()) {
    MESSAGE("built without librlottie: animation.json is written at lottie_tolerance, nothing to measure");
    CHECK(lottie_drawer() == nullptr);
    return;
  }
  TempDir dir;
  // The player draws what the file holds now: the same name written twice, two pictures (rlottie
  // caches models by key; a path as the key would hand back the first).
  const fs::path probe = dir.path / "probe.json";
  std::string why;
  write_lottie_square(probe, 0);
  const RgbaImage before = LottiePlayer::open(probe, why)->draw(0, 64, 64);
  write_lottie_square(probe, 4);
  const auto player = LottiePlayer::open(probe, why);
  REQUIRE(player);
  CHECK(player->total_frames() == 60);
  const RgbaImage after = player->draw(0, 64, 64);
  // Pixel (12, 30): inside the square at shift 0 (x from 10 to 30), outside it at shift 4.
  const size_t at = 4 * (30 * 64 + 12);
  CHECK(before.rgba[at + 3] == 255);
  CHECK(std::abs(before.rgba[at] - 238) <= 1);  // 0.93333 of 255, rounded or cut
  CHECK(after.rgba[at + 3] == 0);
  CHECK(over_white(after).rgba[at] == 255);
  fs::remove(probe);
  // The same search as animation.svg's, on the player's pictures: the square's edges, drawn by
  // rlottie's own anti-aliasing, give what our render gives within the margin: 2 holds, 3 does not.
  const ToleranceChoice c = choose_compact_tolerance(
      dir.path / "animation.json", [](const fs::path& f) { write_lottie_square(f, 0); },
      [](const fs::path& f, double tolerance_1024) { write_lottie_square(f, tolerance_1024 / 4); }, nullptr,
      lottie_drawer());
  CHECK(c.tolerance_1024 == 2);
  CHECK(c.worst_db >= kCompactTargetDb + kCompactMarginDb);
  CHECK(c.worst_db < 48);
  CHECK(fs::is_empty(dir.path));
}
}  // TEST_SUITE
