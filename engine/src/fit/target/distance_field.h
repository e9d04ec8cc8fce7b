// A target keyframe's distance field (TargetFrames::sdf) from its mask: the cleanup makes the
// one from the other, so a fit that holds a target long before its fitter is built (the
// refinement's, read before the coarse stage) keeps the mask (1 byte per pixel) and makes the
// field (4) again when the fitter needs it, bit for bit: 22 MB for 21 keyframes at 512 px not
// held through the coarse stage.
#pragma once

#include <cstdint>

#include "svgmotion/target_video.h"

namespace svgm {

// `sdf` (width x height floats): 0 on the mask, elsewhere the exact Euclidean distance between
// pixel centres to the nearest mask pixel; width + height everywhere when the mask is empty.
void distance_field_from_mask(const uint8_t* mask, int width, int height, float* sdf);

// t.sdf made from t.mask for every keyframe (t.sdf's memory is made here).
void fill_distance_fields(TargetFrames& t);

}  // namespace svgm
