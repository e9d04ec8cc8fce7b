// Does the target video start at the drawing's rest pose? (see rest_start.h)
#include "fit/target/rest_start.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "raster/loss_taps.h"
#include "svgmotion/error.h"

namespace svgm {

RgbaImage blur_rest_as_target(const RgbaImage& rest, double render_sigma) {
  if (!(render_sigma > kLossSigma)) return rest;
  // The video's blur beyond the render's: G_r ∗ render = G_1 ∗ video with video = G_e ∗ render
  // gives σ_r² = 1 + σ_e² (Gaussians compose in quadrature).
  const double se = std::sqrt(render_sigma * render_sigma - kLossSigma * kLossSigma);
  const int R = static_cast<int>(std::ceil(3 * se));
  std::vector<double> g(static_cast<size_t>(2 * R + 1));
  double sum = 0;
  for (int j = -R; j <= R; ++j) sum += g[static_cast<size_t>(j + R)] = std::exp(-0.5 * j * j / (se * se));
  for (double& v : g) v /= sum;
  const int W = rest.width, H = rest.height;
  const size_t px = static_cast<size_t>(W) * H;
  // Ink over white (1 - colour), so the zero padding beyond the frame is white paper.
  std::vector<double> ink(px * 3);
  for (size_t p = 0; p < px; ++p)
    for (int c = 0; c < 3; ++c) ink[3 * p + c] = (1 - rest.rgba[4 * p + c] / 255.0) * (rest.rgba[4 * p + 3] / 255.0);
  const std::vector<double> b = blur_rgb(ink, W, H, g);
  RgbaImage out{W, H, std::vector<uint8_t>(px * 4, 255)};
  for (size_t p = 0; p < px; ++p)
    for (int c = 0; c < 3; ++c)
      out.rgba[4 * p + c] = static_cast<uint8_t>(std::lround(255 * std::clamp(1 - b[3 * p + c], 0.0, 1.0)));
  return out;
}

RestStart judge_rest_start(const RgbaImage& rest_sharp, const TargetFrames& target, double white_threshold,
                           int dilate_px, double min_iou, double render_sigma) {
  RestStart r;
  const RgbaImage rest = blur_rest_as_target(rest_sharp, render_sigma);
  const int W = target.width, H = target.height;
  const size_t px = static_cast<size_t>(W) * H;
  if (rest.width != W || rest.height != H || rest.rgba.size() < px * 4 || target.mask.size() < px || target.keyframes < 1 ||
      target.source_index.empty() || target.source_index.front() != 0)
    return r;  // nothing to compare (or keyframe 0 is not the first frame): keep the pin
  // The rest render's foreground as the target's mask finds ink on white (its darkest channel
  // below the threshold), dilated by the same Euclidean disc.
  std::vector<uint8_t> ink(px, 0), fg(px, 0);
  for (size_t i = 0; i < px; ++i) {
    const uint8_t* c = &rest.rgba[4 * i];
    const double a = c[3] / 255.0;
    const double dark = std::min({c[0], c[1], c[2]}) / 255.0 * a + (1 - a);
    ink[i] = dark < white_threshold;
  }
  const int d = std::max(0, dilate_px);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      bool on = false;
      for (int dy = -d; dy <= d && !on; ++dy)
        for (int dx = -d; dx <= d && !on; ++dx) {
          const int u = x + dx, v = y + dy;
          on = dx * dx + dy * dy <= d * d && u >= 0 && v >= 0 && u < W && v < H && ink[static_cast<size_t>(v) * W + u];
        }
      fg[static_cast<size_t>(y) * W + x] = on;
    }
  size_t both = 0, either = 0;
  for (size_t i = 0; i < px; ++i) {
    const bool a = fg[i], b = target.mask[i];
    both += a && b;
    either += a || b;
  }
  r.iou = either ? static_cast<double>(both) / either : 1.0;
  r.at_rest = r.iou >= min_iou;
  return r;
}

}  // namespace svgm
