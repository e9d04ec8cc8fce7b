// Blur matching (fit/blur_match.h): the render σ of the loss found from the rest pose. A first
// frame that is the render itself keeps the paper's σ; one blurred by a Gaussian of σ_b is
// matched near sqrt(1 + σ_b²) (the two blurs compose); one shifted by two pixels (not the rest
// pose) is not matched by blurring.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "fit/blur_match.h"

using namespace svgm;

namespace {

constexpr int kW = 64, kH = 48;

// Ink coverage of a disc (centre 24, 22, radius 9) and a 2-px bar (x 40..42, y 8..40), 8x8
// supersampled: anti-aliased edges like a render's.
double ink(double x, double y) {
  const bool disc = (x - 24) * (x - 24) + (y - 22) * (y - 22) < 81;
  const bool bar = x >= 40 && x < 42 && y >= 8 && y < 40;
  return disc || bar ? 1 : 0;
}

std::vector<double> coverage(double dx) {
  std::vector<double> c(static_cast<size_t>(kW) * kH);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      double s = 0;
      for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 8; ++i) s += ink(x + (i + 0.5) / 8 - dx, y + (j + 0.5) / 8);
      c[static_cast<size_t>(y) * kW + x] = s / 64;
    }
  return c;
}

// A true Gaussian blur (radius 4σ, normalised, clamped at the border).
std::vector<double> gaussian(const std::vector<double>& in, double sigma) {
  const int r = static_cast<int>(std::ceil(4 * sigma));
  std::vector<double> g(static_cast<size_t>(2 * r + 1));
  double sum = 0;
  for (int j = -r; j <= r; ++j) sum += g[static_cast<size_t>(j + r)] = std::exp(-0.5 * j * j / (sigma * sigma));
  for (double& v : g) v /= sum;
  auto at = [&](const std::vector<double>& a, int x, int y) {
    return a[static_cast<size_t>(std::clamp(y, 0, kH - 1)) * kW + std::clamp(x, 0, kW - 1)];
  };
  std::vector<double> tmp(in.size()), out(in.size());
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      double s = 0;
      for (int j = -r; j <= r; ++j) s += g[static_cast<size_t>(j + r)] * at(in, x + j, y);
      tmp[static_cast<size_t>(y) * kW + x] = s;
    }
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      double s = 0;
      for (int j = -r; j <= r; ++j) s += g[static_cast<size_t>(j + r)] * at(tmp, x, y + j);
      out[static_cast<size_t>(y) * kW + x] = s;
    }
  return out;
}

// Dark blue ink over white: the rest render (8-bit, straight alpha) and a target frame.
RgbaImage render_of(const std::vector<double>& cov) {
  RgbaImage im{kW, kH, std::vector<uint8_t>(static_cast<size_t>(kW) * kH * 4)};
  for (size_t p = 0; p < cov.size(); ++p) {
    im.rgba[4 * p] = 20, im.rgba[4 * p + 1] = 40, im.rgba[4 * p + 2] = 160;
    im.rgba[4 * p + 3] = static_cast<uint8_t>(std::lround(255 * cov[p]));
  }
  return im;
}

std::vector<float> frame_of(const std::vector<double>& cov) {
  std::vector<float> f(cov.size() * 4, 1.f);
  const double ink_rgb[3] = {20 / 255.0, 40 / 255.0, 160 / 255.0};
  for (size_t p = 0; p < cov.size(); ++p)
    for (int c = 0; c < 3; ++c) f[4 * p + c] = static_cast<float>(ink_rgb[c] * cov[p] + (1 - cov[p]));
  return f;
}

}  // namespace

TEST_SUITE("fit") {

TEST_CASE("blur matching: a sharp first frame keeps the paper's blur") {
  const auto cov = coverage(0);
  const BlurMatch m = match_render_blur(render_of(cov), frame_of(cov));
  CHECK(m.render_sigma == 1);
  CHECK(m.best_sigma == 1);
  CHECK(m.rest_psnr_db > 45);
}

TEST_CASE("blur matching: a blurred first frame is matched by the composed blur") {
  const auto cov = coverage(0);
  for (double sb : {0.75, 1.0}) {
    const BlurMatch m = match_render_blur(render_of(cov), frame_of(gaussian(cov, sb)));
    CAPTURE(sb);
    CAPTURE(m.best_sigma);
    CAPTURE(m.residual_ratio);
    CHECK(m.render_sigma == m.best_sigma);  // adopted
    CHECK(std::abs(m.render_sigma - std::sqrt(1 + sb * sb)) <= 0.1);
    CHECK(m.residual_ratio < 0.5);
  }
}

TEST_CASE("blur matching: a first frame that is not the rest pose is not blurred to fit") {
  const BlurMatch m = match_render_blur(render_of(coverage(0)), frame_of(coverage(2)));
  CAPTURE(m.best_sigma);
  CAPTURE(m.residual_ratio);
  CHECK(m.render_sigma == 1);
}

}  // TEST_SUITE
