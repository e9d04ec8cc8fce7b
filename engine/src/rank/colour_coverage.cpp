// Soft colour areas (see colour_coverage.h).
#include "rank/colour_coverage.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace svgm {

namespace {

double dist3(const CoverageRgb& a, const CoverageRgb& b) {
  const double x = a[0] - b[0], y = a[1] - b[1], z = a[2] - b[2];
  return std::sqrt(x * x + y * y + z * z);
}

// Distance from p to the mixture segment a -> b, and in `t` the share of b in the nearest mixture.
double to_mixture(const CoverageRgb& p, const CoverageRgb& a, const CoverageRgb& b, double& t) {
  const CoverageRgb d{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  t = dd < 1e-12 ? 0.0 : std::clamp(((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1] + (p[2] - a[2]) * d[2]) / dd, 0.0, 1.0);
  return dist3(p, {a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]});
}

constexpr int kBackground = -2;  // a neighbour that is background (no palette colour)

}  // namespace

void add_soft_colour_areas(const float* f, int W, int H, const CoverageRgb& bg, const std::vector<uint8_t>& fg,
                           const std::vector<int32_t>& label, const std::vector<float>& dnear,
                           const std::vector<CoverageRgb>& pal, double far, std::vector<double>& area) {
  auto colour = [&](int q) -> const CoverageRgb& { return q == kBackground ? bg : pal[static_cast<size_t>(q)]; };
  auto give = [&](int q, double share) {
    if (q >= 0) area[static_cast<size_t>(q)] += share;
  };
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const size_t i = static_cast<size_t>(y) * W + x;
      if (!fg[i]) continue;
      const int c = label[i];
      const CoverageRgb p{f[4 * i], f[4 * i + 1], f[4 * i + 2]};
      // The other colours around: neighbours of another palette colour, and the background.
      std::array<int, 9> around{};
      size_t n = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int u = x + dx, v = y + dy;
          if ((dx == 0 && dy == 0) || u < 0 || v < 0 || u >= W || v >= H) continue;
          const size_t j = static_cast<size_t>(v) * W + u;
          const int q = !fg[j] ? kBackground : label[j] >= 0 && label[j] != c ? label[j] : -1;
          if (q != -1 && std::find(around.begin(), around.begin() + n, q) == around.begin() + n) around[n++] = q;
        }
      const double own = c >= 0 ? dnear[i] : std::numeric_limits<double>::infinity();
      // A mixture of two other colours around it (a seam where two shapes meet) nearer than its
      // own colour: shared between those two, none for the colour between them.
      double best = std::min(own, far), t = 0, bt = 0;
      int ba = -1, bb = -1;
      for (size_t a = 0; a < n; ++a)
        for (size_t b = a + 1; b < n; ++b)
          if (const double d = to_mixture(p, colour(around[a]), colour(around[b]), t); d < best) best = d, ba = around[a], bb = around[b], bt = t;
      if (ba != -1) {
        give(ba, 1 - bt), give(bb, bt);
        continue;
      }
      if (c >= 0) {
        // Its own colour, partly covered: mixed with the background or a colour around it.
        double cover = 1;
        int with = -1;
        best = own;
        for (size_t a = 0; a < n; ++a)
          if (const double d = to_mixture(p, pal[static_cast<size_t>(c)], colour(around[a]), t); d < best) best = d, cover = 1 - t, with = around[a];
        give(c, cover), give(with, 1 - cover);
        continue;
      }
      // No palette colour near and no two around: a stroke thinner than a pixel, its colour
      // blended with the background (the nearest such blend).
      best = far;
      int q = -1;
      double cover = 0;
      for (size_t a = 0; a < pal.size(); ++a)
        if (const double d = to_mixture(p, bg, pal[a], t); d < best) best = d, q = static_cast<int>(a), cover = t;
      give(q, cover);
    }
}

}  // namespace svgm
