// Blur matching on the rest pose (see blur_match.h).
#include "fit/target/blur_match.h"

#include <array>
#include <cmath>

#include "raster/loss_taps.h"
#include "svgmotion/error.h"

namespace svgm {

namespace {

constexpr double kMaxSigma = 2.0, kStep = 0.05;
// Adopted only when the best σ lowers the rest pose's residual by at least a tenth and the
// first frame is the rest pose at all. Measured on 512-px H.264 non-rigid targets at 256 / 512
// px, best σ, residual ratio and the rest pose's PSNR: blurred σ 1.5 px at 512: 1.25 / 1.85
// (theory sqrt(1 + 0.75²) = 1.25 / sqrt(1 + 1.5²) = 1.80), x0.06-0.14, 50-54 dB (with the
// composed taps of loss_taps.h, bat: 1.25 / 1.70, x0.13 / x0.10, 52 / 48 dB; the same frames
// lossless and not colour-corrected: 1.25 / 1.75, 57 / 61 dB; the H.264 frames not
// colour-corrected: 1.25 / 1.80, denoised or not: the colour correction, not the codec, takes
// 512 px to 1.70, and tests/tools/video_blur_probe.py finds the codec's luma blur 1.50 as
// applied; at 512, searched to 2.5, the best chroma σ is 2.4-2.5 with luma 1.70-1.80, x0.95-0.97, not
// adopted); clean: 1.0 /
// 1.05 (the codec's softness at full size), x1 / x0.86; JPEG quality 20: 1.15 / 1.5, 41-44 dB;
// a first frame shifted 1-2 px (camera shake): 1.2 / 1.8 at x0.94 / x0.83 but 34-36 dB.
constexpr double kMinGain = 0.9;
constexpr double kMinRestPsnr = 38;

}  // namespace

BlurMatch match_render_blur(const RgbaImage& rest, const std::vector<float>& target_rgba) {
  const int W = rest.width, H = rest.height;
  const size_t px = static_cast<size_t>(W) * H;
  if (target_rgba.size() < px * 4) throw Error("internal: blur matching needs a target frame of the render's size");
  std::vector<double> render(px * 3), target(px * 3);
  for (size_t p = 0; p < px; ++p)
    for (int c = 0; c < 3; ++c) {
      // Ink, 1 - colour over white: the paper blurs to ink 0 beyond the frame, as the loss's
      // zero padding does (compared as colours, the padding's falloff at the frame's border
      // differs between two σ and outweighed every edge: a σ 1 blur was matched at 1.15).
      const double a = rest.rgba[4 * p + 3] / 255.0;
      render[3 * p + c] = (1 - rest.rgba[4 * p + c] / 255.0) * a;
      target[3 * p + c] = 1 - target_rgba[4 * p + c];
    }
  const std::vector<double> gt = blur_rgb(target, W, H, loss_stencil(kLossSigma));
  auto residual = [&](double sigma) {
    const std::vector<double> gr = blur_rgb(render, W, H, loss_stencil(sigma));
    double s = 0;
    for (size_t i = 0; i < gr.size(); ++i) s += (gr[i] - gt[i]) * (gr[i] - gt[i]);
    return s;
  };
  BlurMatch m;
  const double base = residual(kLossSigma);
  double best = base;
  for (int i = 1; kLossSigma + i * kStep <= kMaxSigma + 1e-9; ++i) {
    const double s = kLossSigma + i * kStep, r = residual(s);
    if (r < best) best = r, m.best_sigma = s;
  }
  m.residual_ratio = base > 0 ? best / base : 1;
  m.rest_psnr_db = best > 0 ? 10 * std::log10(3.0 * px / best) : 99;
  if (m.residual_ratio <= kMinGain && m.rest_psnr_db >= kMinRestPsnr) m.render_sigma = m.best_sigma;

  // The chroma blur on top of the luma σ just chosen (see blur_match.h). The overall σ is a
  // compromise when only chroma is soft (it blurs sharp luma to meet soft chroma), so the pair
  // is refined by coordinate descent: chroma with luma fixed, luma (1..σ_c) with chroma fixed,
  // chroma again. The pair is adopted by the same rule against the luma-only choice.
  auto pair_residual = [&](double sl, double sc) {
    const std::vector<double> gr = render_blur(render, W, H, sl, sc);
    double s = 0;
    for (size_t i = 0; i < gr.size(); ++i) s += (gr[i] - gt[i]) * (gr[i] - gt[i]);
    return s;
  };
  const double luma_only = m.render_sigma == kLossSigma ? base : residual(m.render_sigma);
  double sl = m.render_sigma, sc = sl, best_c = luma_only;
  auto search_chroma = [&] {
    for (int i = 1; sl + i * kStep <= kMaxSigma + 1e-9; ++i) {
      const double s = sl + i * kStep, r = pair_residual(sl, s);
      if (r < best_c) best_c = r, sc = s;
    }
  };
  search_chroma();
  if (sc != sl) {
    const double keep = sl;
    for (int i = 0; kLossSigma + i * kStep < sc - 1e-9; ++i) {
      const double s = kLossSigma + i * kStep;
      if (s == keep) continue;
      const double r = pair_residual(s, sc);
      if (r < best_c) best_c = r, sl = s;
    }
    if (sl != keep) search_chroma();
  }
  m.best_chroma_sigma = sc;
  m.chroma_luma_sigma = sl;
  m.chroma_residual_ratio = luma_only > 0 ? best_c / luma_only : 1;
  m.chroma_rest_psnr_db = best_c > 0 ? 10 * std::log10(3.0 * px / best_c) : 99;
  m.chroma_sigma = m.render_sigma;
  if (sc != sl && m.chroma_residual_ratio <= kMinGain && m.chroma_rest_psnr_db >= kMinRestPsnr)
    m.render_sigma = sl, m.chroma_sigma = sc;
  return m;
}

}  // namespace svgm
