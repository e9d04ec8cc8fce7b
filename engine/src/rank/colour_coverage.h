// Soft colour areas for the pixel ranker's continuity signal: each foreground pixel of a frame
// shares its unit of area among the palette colours it is made of, by where its colour lies
// between them (a pixel half covered by a black line over white is half a pixel of black).
//
// Why soft: at the ranker's analysis size a line drawing's strokes are one or two pixels wide,
// so most of a stroke's pixels are anti-aliased mixtures of its colour and what lies beside it.
// Counted whole or not at all, a stroke's area follows where it crosses the pixel grid, not how
// long and wide it is: a thin colour of an openmoji water buffalo measured 43-56 px as it walked
// steadily (a 23 % swing on no change of shape), and a 2 px door of a bus turning edge on fell
// to 0 px when all its pixels became mixtures. Shared by coverage, the same strokes keep their
// area within a few per cent. A seam where two other shapes meet is still no area of the
// colour that happens to lie between them (the mixture of the two neighbours explains it): a
// ladybird's spot (36 px at the analysis size) once counted 90-107 px in some frames as it
// crawled, the seams of its shell and head counting for it as they crossed pixel rows.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace svgm {

using CoverageRgb = std::array<double, 3>;

// Adds frame `f`'s (straight RGB in [0,1], W*H*4) soft area per palette colour to `area`
// (area[c] += the colour's coverage summed over the pixels). `fg`: foreground mask; `label`:
// each pixel's nearest palette colour within the far distance (-1 none); `dnear`: its distance
// to that colour; `bg`: the frame's background; `far`: the distance beyond which a pixel is
// made of none of the candidates (no area at all).
void add_soft_colour_areas(const float* f, int W, int H, const CoverageRgb& bg, const std::vector<uint8_t>& fg,
                           const std::vector<int32_t>& label, const std::vector<float>& dnear,
                           const std::vector<CoverageRgb>& pal, double far, std::vector<double>& area);

}  // namespace svgm
