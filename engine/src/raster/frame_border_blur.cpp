// Taking the outside's blur out of a target's border band (see frame_border_blur.h).
#include "raster/frame_border_blur.h"

#include <algorithm>

#include "raster/loss_taps.h"

namespace svgm {

namespace {

// One separable pass of `g` (g_{-R}..g_R) along x (dx = 1) or y, each pixel's sum split into
// the taps inside the frame (`in`) and those beyond it, read mirrored (reflect-101: -1 reads
// 1): `out` gets the latter alone, the outside's share.
void outside_pass(const std::vector<double>& src, std::vector<double>& inside, std::vector<double>& outside, int W,
                  int H, const std::vector<double>& g, bool along_x) {
  const int R = static_cast<int>(g.size() / 2), n = along_x ? W : H;
  auto at = [W](int x, int y, int c) { return 3 * (static_cast<size_t>(y) * W + x) + c; };
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      for (int c = 0; c < 3; ++c) {
        const int i = along_x ? x : y;
        double in = 0, out = 0;
        for (int j = -R; j <= R; ++j) {
          int k = i + j;
          const bool beyond = k < 0 || k >= n;
          if (beyond) k = k < 0 ? -k : 2 * (n - 1) - k;
          k = std::clamp(k, 0, n - 1);  // a frame narrower than the stencil: the edge pixel
          const double v = g[static_cast<size_t>(j + R)] * src[along_x ? at(k, y, c) : at(x, k, c)];
          (beyond ? out : in) += v;
        }
        inside[at(x, y, c)] = in;
        outside[at(x, y, c)] = out;
      }
}

}  // namespace

std::vector<double> outside_blur(const std::vector<double>& d, int W, int H, double render_sigma) {
  std::vector<double> share(d.size(), 0.0);
  if (!(render_sigma > kLossSigma)) return share;
  const std::vector<double> g = gaussian_stencil(video_sigma(render_sigma), video_radius(render_sigma));
  // Reflect ∗ D − zero ∗ D of the separable blur gy ∘ gx: with gx's result split into its
  // inside part a and outside part b, gy_reflect(a + b) − gy_zero(a) = gy_outside(a + b) +
  // gy_inside(b).
  std::vector<double> a(d.size()), b(d.size()), ab(d.size()), in1(d.size()), out1(d.size()), in2(d.size()),
      out2(d.size());
  outside_pass(d, a, b, W, H, g, true);
  for (size_t i = 0; i < d.size(); ++i) ab[i] = a[i] + b[i];
  outside_pass(ab, in1, out1, W, H, g, false);
  outside_pass(b, in2, out2, W, H, g, false);
  for (size_t i = 0; i < d.size(); ++i) share[i] = out1[i] + in2[i];
  return share;
}

void remove_outside_blur(std::vector<double>& d, int W, int H, double render_sigma) {
  const std::vector<double> share = outside_blur(d, W, H, render_sigma);
  for (size_t i = 0; i < d.size(); ++i) d[i] -= share[i];
}

}  // namespace svgm
