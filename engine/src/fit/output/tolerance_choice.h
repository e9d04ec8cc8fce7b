// The compact export's tolerance chosen by measurement, per drawing: the largest tolerance on a
// short ladder whose compact animation.svg, rendered at 1024 px (the drawing's larger side) at
// ten times of one pass, stays within kCompactTargetDb of the full per-frame export of the same
// fit at every one of them. A fixed tolerance is either too tight for a jittery fit on a small
// canvas (the bundled man: 88 kB of Lottie at a quarter pixel, 57 dB, where 1.25 pixels keep
// 34 kB above the target; at 1.5 it falls to 44.8 dB) or too loose for a drawing with thin, fast parts (the bench
// kite and bug drop to 40-42 dB at one pixel).
//
// animation.svg is drawn by the engine's own renderer (raster/render_image.h), animation.json by
// the Lottie player the build links (librlottie, export/lottie_player.h), each file measured on
// its own: the same tolerance draws differently in the two (animation.json keeps the skew in its
// residual shapes and rounds in canvas pixels; on the bundled man's fit of session 41,
// animation.svg at 1 px held 46.7 dB and animation.json at 1 px 46.4 dB, at 1.25 px 44.2 and
// 44.7 dB). Candidates are written to temporary files beside the animation and removed. Without
// a player animation.json is written two ladder steps tighter than animation.svg's tolerance
// (lottie_tolerance), which held on every drawing measured but wrote the man's 58 kB where its
// own measure writes 34 kB.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <vector>

#include "svgmotion/png_io.h"

namespace svgm {

// PSNR (RGB over white, dB) every sampled time of the compact export keeps against the full one.
constexpr double kCompactTargetDb = 45;
// The measured floor asked of our render: players draw a little differently from it (librlottie
// and the SMIL render of the same compact file differ by up to about 0.5 dB on the man).
constexpr double kCompactMarginDb = 1;
// Tolerances tried, pixels at 1024 px, increasing; the first is taken when none holds the target.
inline const std::vector<double> kToleranceLadder = {0.25, 0.5, 0.75, 1, 1.1, 1.25, 1.5, 2, 3};
// Times sampled over one pass, and the size they are rendered at (the larger side).
constexpr int kToleranceTimes = 10;
constexpr int kToleranceRenderPx = 1024;

struct ToleranceTrial {
  double tolerance_1024 = 0;
  double worst_db = 0;  // the lowest PSNR over the sampled times (stops at the first below target)
  double residual_scale = 1;  // the residual shapes' tolerance, a multiple of tolerance_1024
};
struct ToleranceChoice {
  double tolerance_1024 = 0;
  double worst_db = 0;  // of the chosen tolerance and residual scale (infinity: identical renders)
  double residual_scale = 1;  // kResidualScales (compact_motion.h); 1 when not searched
  std::vector<ToleranceTrial> trials;  // in the order tried
};

// Draws one kind of export file (animation.svg, animation.json) at the measure's sampled times:
// kToleranceTimes times (k + 0.5) / kToleranceTimes of one pass, kToleranceRenderPx on the
// larger side, opaque over white. Made from the full export, whose clock and size it takes, and
// which it holds loaded until the next load().
class ExportDrawer {
 public:
  virtual ~ExportDrawer() = default;
  virtual size_t count() const = 0;
  virtual void load(const std::filesystem::path& file) = 0;  // the file drawn next
  virtual RgbaImage draw(size_t k) = 0;                       // at the k-th time (k < count())
};
using DrawerMaker = std::function<std::unique_ptr<ExportDrawer>(const std::filesystem::path& full)>;
// animation.svg by the engine's own renderer (raster/render_image.h), at the times of its SMIL
// clock.
DrawerMaker svg_drawer();
// animation.json by the Lottie player (export/lottie_player.h) at whole frames
// floor((k + 0.5) / kToleranceTimes * frames), as tests/bench/compact_psnr.sh draws it; nullptr
// when this build has no player.
DrawerMaker lottie_drawer();

// `write_full(path)` writes the full export, `write_compact(path, tolerance_1024)` a compact one,
// both as the file `beside` names would be written (the temporary candidates go next to it, with
// its extension), and `draw` draws them. Binary search over kToleranceLadder (the error grows
// with the tolerance): three or four compact candidates, each stopped at its first time below
// target. Then, when `write_residual(path, tolerance_1024, scale)` is given and a tolerance held,
// the residual shapes' tolerance is loosened at the chosen one along kResidualScales while the
// floor holds (one or two more candidates: the residual moves few pixels, the transform the
// whole part). Throws svgm::Error when a candidate cannot be written or read back.
ToleranceChoice choose_compact_tolerance(
    const std::filesystem::path& beside, const std::function<void(const std::filesystem::path&)>& write_full,
    const std::function<void(const std::filesystem::path&, double)>& write_compact,
    const std::function<void(const std::filesystem::path&, double, double)>& write_residual = nullptr,
    const DrawerMaker& draw = svg_drawer());

// The tolerance animation.json is written at for animation.svg's `svg_tolerance_1024` when no
// Lottie player is built in to measure it (lottie_drawer): the ladder step kLottieStepsBelow below it (the first step at the least; a tolerance off the
// ladder counts from the largest step below it). Two since each transform channel is keyed on
// its own (compact_motion.h): librlottie drew the man's animation.json at 1.25 px at 44.7 dB
// of the full JSON where animation.svg at 1.5 px held 46.3 dB by our render; at 1.1 px 45.6 dB.
constexpr size_t kLottieStepsBelow = 2;
double lottie_tolerance(double svg_tolerance_1024);

// PSNR of two renders of the same size (RGB, 8-bit, dB; infinity when identical).
double render_psnr(const RgbaImage& a, const RgbaImage& b);

}  // namespace svgm
