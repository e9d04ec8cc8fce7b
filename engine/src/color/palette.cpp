// distinct_palette: the offline table for N <= 256, the live optimiser beyond (see palette.h).
#include "color/palette.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "color/palette_optimiser.h"

namespace svgm {
namespace {

#include "color/palette_table.inc"

int hex_digit(char c) { return c <= '9' ? c - '0' : c - 'a' + 10; }

uint8_t hex_byte(const char* s) { return static_cast<uint8_t>(hex_digit(s[0]) * 16 + hex_digit(s[1])); }

}  // namespace

std::vector<Rgb8> distinct_palette(int n) {
  if (n < 0 || n > kMaxPaletteSize)
    throw std::invalid_argument("distinct_palette: n must be in 0.." + std::to_string(kMaxPaletteSize) +
                                ", got " + std::to_string(n));
  std::vector<Rgb8> out;
  if (n == 0) return out;
  if (n <= kPaletteTableMax) {
    const char* s = kPaletteTable[n];
    out.resize(n);
    for (int i = 0; i < n; ++i)
      out[i] = {hex_byte(s + 6 * i), hex_byte(s + 6 * i + 2), hex_byte(s + 6 * i + 4)};
    return out;
  }
  // Live: one fixed seed and a work budget that grows like n log n (1-2 s at n = 1000).
  color::PackOptions opt;
  opt.seed = 0x5EED0000ull + static_cast<uint64_t>(n);
  opt.work = 4e4 * n * std::log2(static_cast<double>(n));
  return color::quantise_packing(color::pack_points(n, opt).points);
}

double min_distance(const std::vector<Rgb8>& palette, bool include_white) {
  std::vector<Rgb8> all = palette;
  if (include_white) all.push_back({255, 255, 255});
  long best = std::numeric_limits<long>::max();
  for (size_t i = 0; i < all.size(); ++i)
    for (size_t j = i + 1; j < all.size(); ++j) {
      const long r = all[i].r - all[j].r, g = all[i].g - all[j].g, b = all[i].b - all[j].b;
      best = std::min(best, r * r + g * g + b * b);
    }
  if (best == std::numeric_limits<long>::max()) return std::numeric_limits<double>::infinity();
  return std::sqrt(static_cast<double>(best)) / 255.0;
}

}  // namespace svgm
