// Procedural scenes for benchmarks: N smooth random blobs of cubic Béziers on a square canvas.
#pragma once

#include <cstdint>

#include "svgmotion/scene.h"

namespace svgm {

// `paths` closed blobs (6 cubics each, radius 3-12% of the canvas) with random colours, some
// translucent, on a size x size canvas. Deterministic for a seed.
Scene synthetic_blobs(int paths, double size, uint32_t seed = 1);

}  // namespace svgm
