// The loss's separable blurs on the host (see loss_taps.h): the plain one and the per-group
// YCbCr one of chroma blur matching.
#include "raster/loss_taps.h"

namespace svgm {

std::vector<double> blur_rgb(const std::vector<double>& in, int W, int H, const std::vector<double>& g) {
  const int R = static_cast<int>(g.size() / 2);
  auto at = [W](int x, int y, int c) { return 3 * (static_cast<size_t>(y) * W + x) + c; };
  std::vector<double> tmp(in.size()), out(in.size());
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      for (int c = 0; c < 3; ++c) {
        double s = 0;
        for (int j = -R; j <= R; ++j)
          if (x + j >= 0 && x + j < W) s += g[static_cast<size_t>(j + R)] * in[at(x + j, y, c)];
        tmp[at(x, y, c)] = s;
      }
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      for (int c = 0; c < 3; ++c) {
        double s = 0;
        for (int j = -R; j <= R; ++j)
          if (y + j >= 0 && y + j < H) s += g[static_cast<size_t>(j + R)] * tmp[at(x, y + j, c)];
        out[at(x, y, c)] = s;
      }
  return out;
}

std::vector<double> render_blur(const std::vector<double>& in, int W, int H, double sigma, double chroma_sigma,
                                bool adjoint) {
  if (chroma_sigma == sigma) return blur_rgb(in, W, H, loss_stencil(sigma));
  // Into the blur's coordinates: A (forward) or A⁻ᵀ (adjoint); out: A⁻¹ or Aᵀ.
  auto into = [&](int i, int j) { return adjoint ? kYccInv[j][i] : kYcc[i][j]; };
  auto out_of = [&](int i, int j) { return adjoint ? kYcc[j][i] : kYccInv[i][j]; };
  const size_t px = in.size() / 3;
  std::vector<double> f(in.size());
  for (size_t p = 0; p < px; ++p)
    for (int i = 0; i < 3; ++i) {
      double s = 0;
      for (int j = 0; j < 3; ++j) s += into(i, j) * in[3 * p + j];
      f[3 * p + i] = s;
    }
  // Every channel blurred at both σ; luma keeps the first, chroma the second.
  const std::vector<double> luma = blur_rgb(f, W, H, loss_stencil(sigma));
  const std::vector<double> chroma = blur_rgb(f, W, H, loss_stencil(chroma_sigma));
  std::vector<double> out(in.size());
  for (size_t p = 0; p < px; ++p) {
    const double v[3] = {luma[3 * p], chroma[3 * p + 1], chroma[3 * p + 2]};
    for (int i = 0; i < 3; ++i) out[3 * p + i] = out_of(i, 0) * v[0] + out_of(i, 1) * v[1] + out_of(i, 2) * v[2];
  }
  return out;
}

std::vector<double> chroma_metric(const std::vector<double>& e, double w) {
  const double* y = kYcc[0];
  const double yy = y[0] * y[0] + y[1] * y[1] + y[2] * y[2];
  std::vector<double> out(e.size());
  for (size_t i = 0; i + 2 < e.size(); i += 3) {
    const double l = (1 - w) * (y[0] * e[i] + y[1] * e[i + 1] + y[2] * e[i + 2]) / yy;
    for (int c = 0; c < 3; ++c) out[i + c] = w * e[i + c] + l * y[c];
  }
  return out;
}

}  // namespace svgm
