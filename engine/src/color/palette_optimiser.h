// The maximin point-packing optimiser behind distinct_palette (see palette.h and the essay at
// the top of palette_optimiser.cpp). Used live for large palettes and offline by
// tools/gen_palette_table.cpp to write palette_table.inc.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "color/palette.h"

namespace svgm::color {

using Point3 = std::array<double, 3>;

struct PackOptions {
  uint64_t seed = 1;
  // Work budget in pair evaluations (one force or distance computation of one pair). The search
  // stops once it is spent, so the result depends only on the seed and the budget, never on the
  // clock. About 1e8 pair evaluations take a second on one core.
  double work = 1e8;
  // Pin a point at white (1,1,1) that every free point must stay away from (palettes); false
  // packs n free points (used to check the optimiser against published cube packings).
  bool pin_white = true;
  // A packing to start from (its points are polished first, then used as the incumbent of the
  // basin hopping); must have n points if given.
  const std::vector<Point3>* start = nullptr;
};

struct Packing {
  std::vector<Point3> points;  // the n free points, in [0,1]^3
  double min_distance = 0;     // over all pairs, and to white if pinned
};

// Maximin packing of n free points in the unit cube (plus white when pinned).
Packing pack_points(int n, const PackOptions& options);

// The smallest pairwise distance of the points (and to (1,1,1) when pin_white).
double packing_min_distance(const std::vector<Point3>& points, bool pin_white);

// 8-bit colours for a packing: rounded to the 1/255 grid, then a local search on the grid that
// only ever raises the distance from each colour to its nearest neighbour (white included), so
// the quantised palette loses as little as possible of the packing's minimum distance.
std::vector<Rgb8> quantise_packing(const std::vector<Point3>& points);

}  // namespace svgm::color
