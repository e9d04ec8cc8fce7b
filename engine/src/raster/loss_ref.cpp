// The blurred-MSE reference (see loss_ref.h), written plainly: a direct 2-D stencil, per
// channel group in YCbCr when the chroma blur has its own σ.
#include "raster/loss_ref.h"

#include <algorithm>
#include <cmath>

#include "raster/loss_taps.h"

namespace svgm::ref {

namespace {

// The per-group form, as plainly: C to YCbCr by A, each channel's own direct 2-D stencil (luma
// at render σ, chroma at chroma σ), back to RGB by A⁻¹, minus the target's blur in RGB.
// eᵀ M e for one pixel's RGB residual e: M = w·I + (1 − w)·y yᵀ/|y|² (loss_taps.h's
// chroma_metric, written out).
double metric_sq(const double e[3], double w) {
  const double* y = kYcc[0];
  const double l = y[0] * e[0] + y[1] * e[1] + y[2] * e[2];
  return w * (e[0] * e[0] + e[1] * e[1] + e[2] * e[2]) + (1 - w) * l * l / (y[0] * y[0] + y[1] * y[1] + y[2] * y[2]);
}

double chroma_sq_sum(const std::vector<double>& image, const std::vector<float>& target, int width,
                     int height, const std::array<double, 4>& background, double render_sigma,
                     double chroma_sigma, double chroma_weight) {
  const std::vector<double> gl = loss_stencil(render_sigma), gc = loss_stencil(chroma_sigma),
                            gt = loss_stencil(kLossSigma);
  auto tap = [](const std::vector<double>& g, int j) {
    const int r = static_cast<int>(g.size() / 2);
    return std::abs(j) <= r ? g[static_cast<size_t>(j + r)] : 0.0;
  };
  const int R = static_cast<int>(std::max({gl.size(), gc.size(), gt.size()}) / 2);
  const bool reflect = loss_reflects(render_sigma);  // both blurs, as the kernels' LOSS_REFLECTS
  std::vector<double> ycc(static_cast<size_t>(width) * height * 3), t(ycc.size());
  for (size_t p = 0; p < ycc.size() / 3; ++p) {
    double c[3];
    for (int ch = 0; ch < 3; ++ch) {
      c[ch] = image[4 * p + ch] - background[ch] * image[4 * p + 3];  // what is drawn, X
      t[3 * p + ch] = target[4 * p + ch] - background[ch];
    }
    for (int i = 0; i < 3; ++i) ycc[3 * p + i] = kYcc[i][0] * c[0] + kYcc[i][1] * c[1] + kYcc[i][2] * c[2];
  }
  double sum = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      double v[3] = {0, 0, 0}, gtt[3] = {0, 0, 0};
      for (int dy = -R; dy <= R; ++dy)
        for (int dx = -R; dx <= R; ++dx) {
          int xx = x + dx, yy = y + dy;
          if (reflect) xx = reflect101(xx, width), yy = reflect101(yy, height);
          if (xx < 0 || yy < 0 || xx >= width || yy >= height) continue;  // zero padding
          const size_t at = 3 * (static_cast<size_t>(yy) * width + xx);
          for (int ch = 0; ch < 3; ++ch) {
            const std::vector<double>& g = ch == 0 ? gl : gc;
            v[ch] += tap(g, dx) * tap(g, dy) * ycc[at + ch];
            gtt[ch] += tap(gt, dx) * tap(gt, dy) * t[at + ch];
          }
        }
      double e[3];
      for (int ch = 0; ch < 3; ++ch) e[ch] = kYccInv[ch][0] * v[0] + kYccInv[ch][1] * v[1] + kYccInv[ch][2] * v[2] - gtt[ch];
      sum += metric_sq(e, chroma_weight);
    }
  return sum;
}

}  // namespace

double blurred_sq_sum(const std::vector<double>& image, const std::vector<float>& target,
                      int width, int height, const std::array<double, 4>& background,
                      double render_sigma, double chroma_sigma, double chroma_weight) {
  if (chroma_sigma > 0 && chroma_sigma != render_sigma)
    return chroma_sq_sum(image, target, width, height, background, render_sigma, chroma_sigma, chroma_weight);
  const std::vector<double> gr = loss_stencil(render_sigma), gt = loss_stencil(kLossSigma);
  const int Rr = static_cast<int>(gr.size() / 2), Rt = static_cast<int>(gt.size() / 2), R = std::max(Rr, Rt);
  const bool reflect = loss_reflects(render_sigma);  // both blurs, as the kernels' LOSS_REFLECTS
  // A tap outside a stencil's radius weighs 0.
  auto tap = [](const std::vector<double>& g, int r, int j) { return std::abs(j) <= r ? g[static_cast<size_t>(j + r)] : 0.0; };
  std::vector<double> c(static_cast<size_t>(width) * height * 3), t(c.size());
  for (size_t p = 0; p < c.size() / 3; ++p)
    for (int ch = 0; ch < 3; ++ch) {
      // What is drawn (X = C - bg) against the target less the paper: the paper blurs as the
      // target does, whatever the render's σ (raster_cl_backward.cpp, Q).
      c[3 * p + ch] = image[4 * p + ch] - background[ch] * image[4 * p + 3];
      t[3 * p + ch] = target[4 * p + ch] - background[ch];
    }
  double sum = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      double e[3] = {0, 0, 0};
      for (int ch = 0; ch < 3; ++ch)
        for (int dy = -R; dy <= R; ++dy)
          for (int dx = -R; dx <= R; ++dx) {
            int xx = x + dx, yy = y + dy;
            if (reflect) xx = reflect101(xx, width), yy = reflect101(yy, height);
            if (xx < 0 || yy < 0 || xx >= width || yy >= height) continue;  // zero padding
            const size_t at = 3 * (static_cast<size_t>(yy) * width + xx) + ch;
            e[ch] += tap(gr, Rr, dx) * tap(gr, Rr, dy) * c[at] - tap(gt, Rt, dx) * tap(gt, Rt, dy) * t[at];
          }
      sum += metric_sq(e, chroma_weight);
    }
  return sum;
}

}  // namespace svgm::ref
