// The loss's separable blurs on the host (see loss_taps.h): the plain one and the per-group
// YCbCr one of chroma blur matching.
#include "raster/loss_taps.h"

namespace svgm {

namespace {

// One separable pass along x (`along_x`) or y. Zero padding drops the taps beyond the frame;
// reflect-101 reads them mirrored. The adjoint scatters each output's taps back to the pixels
// they read (with zero padding that is the same sum, as the stencil is symmetric; it is taken
// the plain way then, so the zero-padded bits stay those of the gather).
void blur_pass(const std::vector<double>& in, std::vector<double>& out, int W, int H, const std::vector<double>& g,
               bool along_x, bool reflect, bool adjoint) {
  const int R = static_cast<int>(g.size() / 2);
  auto at = [W](int x, int y, int c) { return 3 * (static_cast<size_t>(y) * W + x) + c; };
  const int n = along_x ? W : H;
  if (!reflect) {
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x)
        for (int c = 0; c < 3; ++c) {
          const int i = along_x ? x : y;
          double s = 0;
          for (int j = -R; j <= R; ++j)
            if (i + j >= 0 && i + j < n) s += g[static_cast<size_t>(j + R)] * in[along_x ? at(x + j, y, c) : at(x, y + j, c)];
          out[at(x, y, c)] = s;
        }
    return;
  }
  std::fill(out.begin(), out.end(), 0.0);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      for (int c = 0; c < 3; ++c) {
        const int i = along_x ? x : y;
        for (int j = -R; j <= R; ++j) {
          const int k = reflect101(i + j, n);
          const size_t from = at(x, y, c), to = along_x ? at(k, y, c) : at(x, k, c);
          if (adjoint)
            out[to] += g[static_cast<size_t>(j + R)] * in[from];
          else
            out[from] += g[static_cast<size_t>(j + R)] * in[to];
        }
      }
}

}  // namespace

std::vector<double> blur_rgb(const std::vector<double>& in, int W, int H, const std::vector<double>& g, bool reflect,
                             bool adjoint) {
  // The 2-D operator is the product of the two passes, which commute: the adjoint is the
  // product of their adjoints.
  std::vector<double> tmp(in.size()), out(in.size());
  blur_pass(in, tmp, W, H, g, true, reflect, adjoint);
  blur_pass(tmp, out, W, H, g, false, reflect, adjoint);
  return out;
}

std::vector<double> render_blur(const std::vector<double>& in, int W, int H, double sigma, double chroma_sigma,
                                bool adjoint, bool reflect) {
  if (chroma_sigma == sigma) return blur_rgb(in, W, H, loss_stencil(sigma), reflect, adjoint);
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
  const std::vector<double> luma = blur_rgb(f, W, H, loss_stencil(sigma), reflect, adjoint);
  const std::vector<double> chroma = blur_rgb(f, W, H, loss_stencil(chroma_sigma), reflect, adjoint);
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
