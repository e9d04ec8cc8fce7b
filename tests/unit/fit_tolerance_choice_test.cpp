// The compact export's tolerance chosen by rendering (fit/output/tolerance_choice.h): the
// largest step of the ladder whose compact file stays at kCompactTargetDb + kCompactMarginDb of
// the full export at every sampled time, and the temporary candidates removed.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

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
}  // TEST_SUITE
