// Maximally distinct palettes: N colours in the RGB cube that are as far apart as possible,
// and also far from white (the video background), so that every path of a recoloured SVG can
// be told apart in a video.
//
// The problem is a maximin ("sphere packing") problem: place N points in [0,1]^3 maximising the
// minimum pairwise Euclidean distance, with one extra point pinned at white (1,1,1). Palettes
// for N <= 256 come from a table computed offline (palette_table.inc, written by
// tools/gen_palette_table.cpp with the optimiser in palette_optimiser.h); larger N run the same
// optimiser live with a fixed seed and a bounded amount of work
// (1-2 s for N = 1000), which gives a good palette but not a record one.
//
// Colours are 8-bit, since the recoloured image is 8-bit; distances are measured in the unit
// cube, i.e. the 8-bit differences divided by 255.
#pragma once

#include <cstdint>
#include <vector>

namespace svgm {

struct Rgb8 {
  uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb8&) const = default;
};

// Largest N distinct_palette accepts (the live optimiser's work grows with N).
inline constexpr int kMaxPaletteSize = 4096;

// The N most distinct colours, none of them white. Deterministic: the same N always gives the
// same colours in the same order. The order carries no meaning (the table lists each palette
// sorted by #rrggbb); it is a set, and the caller decides which path gets which colour.
// n == 0 gives an empty palette; n < 0 or n > kMaxPaletteSize throws std::invalid_argument.
std::vector<Rgb8> distinct_palette(int n);

// The smallest Euclidean distance between two colours of the palette, in unit-cube units
// (8-bit difference / 255); with include_white, white (255,255,255) counts as one more colour.
// +infinity when there are fewer than two colours to compare.
double min_distance(const std::vector<Rgb8>& palette, bool include_white);

}  // namespace svgm
