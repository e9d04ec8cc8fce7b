// The blurred-MSE reference (see loss_ref.h), written plainly: a direct 5x5 stencil.
#include "raster/loss_ref.h"

#include <cmath>

namespace svgm::ref {

double blurred_sq_sum(const std::vector<double>& image, const std::vector<float>& target,
                      int width, int height, const std::array<double, 4>& background) {
  double g[5], gs = 0;
  for (int j = -2; j <= 2; ++j) gs += g[j + 2] = std::exp(-0.5 * j * j);
  for (double& v : g) v /= gs;
  std::vector<double> d(static_cast<size_t>(width) * height * 3);
  for (size_t p = 0; p < d.size() / 3; ++p)
    for (int c = 0; c < 3; ++c)
      d[3 * p + c] = image[4 * p + c] + background[c] * (1.0 - image[4 * p + 3]) - target[4 * p + c];
  double sum = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) {
        double e = 0;
        for (int dy = -2; dy <= 2; ++dy)
          for (int dx = -2; dx <= 2; ++dx) {
            const int xx = x + dx, yy = y + dy;
            if (xx < 0 || yy < 0 || xx >= width || yy >= height) continue;  // zero padding
            e += g[dx + 2] * g[dy + 2] * d[3 * (static_cast<size_t>(yy) * width + xx) + c];
          }
        sum += e * e;
      }
  return sum;
}

}  // namespace svgm::ref
