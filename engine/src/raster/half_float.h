// IEEE 754 binary16 ("half") on the host, for images the device only reads: the loss's
// constants Q and R (kernels/loss.cl) are stored as halves and read with vload_half4, which
// every OpenCL 1.x device has without the cl_khr_fp16 extension. Half the bytes of a float:
// at 512 px, 21 keyframes, Q and R together drop from 176 MB to 88 MB, held in host memory
// by PoCL. Arithmetic stays in float on the device; only the storage is narrow.
#pragma once

#include <cstdint>

namespace svgm {

// Rounds to the nearest half, ties to even (vstore_half's default mode), with subnormals,
// infinities and NaN. The relative error of a normal result is at most 2^-11.
uint16_t float_to_half(float f);
// Exact: every half is a float.
float half_to_float(uint16_t h);

}  // namespace svgm
