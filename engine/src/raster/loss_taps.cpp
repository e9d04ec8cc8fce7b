// The loss's separable blur on the host (see loss_taps.h).
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

}  // namespace svgm
