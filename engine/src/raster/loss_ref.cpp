// The blurred-MSE reference (see loss_ref.h), written plainly: a direct 2-D stencil.
#include "raster/loss_ref.h"

#include <algorithm>
#include <cmath>

#include "raster/loss_taps.h"

namespace svgm::ref {

double blurred_sq_sum(const std::vector<double>& image, const std::vector<float>& target,
                      int width, int height, const std::array<double, 4>& background,
                      double render_sigma) {
  const std::vector<double> gr = loss_stencil(render_sigma), gt = loss_stencil(kLossSigma);
  const int Rr = static_cast<int>(gr.size() / 2), Rt = static_cast<int>(gt.size() / 2), R = std::max(Rr, Rt);
  // A tap outside a stencil's radius weighs 0.
  auto tap = [](const std::vector<double>& g, int r, int j) { return std::abs(j) <= r ? g[static_cast<size_t>(j + r)] : 0.0; };
  std::vector<double> c(static_cast<size_t>(width) * height * 3), t(c.size());
  for (size_t p = 0; p < c.size() / 3; ++p)
    for (int ch = 0; ch < 3; ++ch) {
      c[3 * p + ch] = image[4 * p + ch] + background[ch] * (1.0 - image[4 * p + 3]);
      t[3 * p + ch] = target[4 * p + ch];
    }
  double sum = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int ch = 0; ch < 3; ++ch) {
        double e = 0;
        for (int dy = -R; dy <= R; ++dy)
          for (int dx = -R; dx <= R; ++dx) {
            const int xx = x + dx, yy = y + dy;
            if (xx < 0 || yy < 0 || xx >= width || yy >= height) continue;  // zero padding
            const size_t at = 3 * (static_cast<size_t>(yy) * width + xx) + ch;
            e += tap(gr, Rr, dx) * tap(gr, Rr, dy) * c[at] - tap(gt, Rt, dx) * tap(gt, Rt, dy) * t[at];
          }
        sum += e * e;
      }
  return sum;
}

}  // namespace svgm::ref
