// Edge blur read off a frame (see edge_width.h).
#include "fit/target/edge_width.h"

#include <algorithm>
#include <cmath>

namespace svgm {

namespace {

constexpr double kMinContrast = 0.2;   // luma rise of a ramp worth measuring (noise is ~0.01)
constexpr double kMonotone = 1.25;     // total variation along the run / its rise, at most
constexpr int kMaxRun = 24;            // longer runs are texture or shading, not one edge
constexpr double kMaxOblique = 0.87;   // cos 30 degrees: the gradient's share along the scan

}  // namespace

EdgeWidth measure_edge_width(const float* rgba, int w, int h, const std::vector<char>& flat) {
  EdgeWidth out;
  if (w < 3 || h < 3 || flat.size() < static_cast<size_t>(w) * h) return out;
  std::vector<float> y(static_cast<size_t>(w) * h);
  for (size_t i = 0; i < y.size(); ++i) y[i] = 0.299f * rgba[4 * i] + 0.587f * rgba[4 * i + 1] + 0.114f * rgba[4 * i + 2];
  auto at = [&](int x, int yy) { return static_cast<double>(y[static_cast<size_t>(yy) * w + x]); };
  std::vector<double> sigmas;
  // One scan line: `n` pixels, pixel i at (x0 + i*dx, y0 + i*dy).
  auto scan = [&](int x0, int y0, int dx, int dy, int n) {
    auto idx = [&](int i) { return static_cast<size_t>(y0 + i * dy) * w + (x0 + i * dx); };
    int i = 1;
    while (i < n - 1) {
      if (flat[idx(i)] || !flat[idx(i - 1)]) { ++i; continue; }
      int b = i;  // the run i..b of non-flat pixels, flat at i-1 and b+1
      while (b + 1 < n && !flat[idx(b + 1)]) ++b;
      const int a = i;
      i = b + 1;
      if (b + 1 >= n || b - a + 1 > kMaxRun) continue;
      const double rise = y[idx(b + 1)] - y[idx(a - 1)];
      if (std::fabs(rise) < kMinContrast) continue;
      double tv = 0, steepest = 0;
      int at_steep = a;
      for (int k = a - 1; k <= b; ++k) {
        const double d = y[idx(k + 1)] - y[idx(k)];
        tv += std::fabs(d);
        if (std::fabs(d) > steepest) steepest = std::fabs(d), at_steep = k;
      }
      if (tv > kMonotone * std::fabs(rise) || steepest <= 0) continue;
      // The 2-D gradient where the ramp is steepest (central differences): skip oblique crossings.
      const int px = x0 + at_steep * dx, py = y0 + at_steep * dy;
      if (px < 1 || py < 1 || px + 1 >= w || py + 1 >= h) continue;
      const double gx = at(px + 1, py) - at(px - 1, py), gy = at(px, py + 1) - at(px, py - 1);
      const double along = std::fabs(dx ? gx : gy), norm = std::hypot(gx, gy);
      if (norm <= 0 || along < kMaxOblique * norm) continue;
      sigmas.push_back(std::fabs(rise) / (std::sqrt(2 * M_PI) * steepest));
    }
  };
  for (int r = 0; r < h; ++r) scan(0, r, 1, 0, w);
  for (int c = 0; c < w; ++c) scan(c, 0, 0, 1, h);
  out.runs = static_cast<int>(sigmas.size());
  if (sigmas.empty()) return out;
  auto mid = sigmas.begin() + static_cast<std::ptrdiff_t>(sigmas.size() / 2);
  std::nth_element(sigmas.begin(), mid, sigmas.end());
  out.sigma = *mid;
  return out;
}

}  // namespace svgm
