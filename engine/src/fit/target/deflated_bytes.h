// Bytes a fit holds for later but does not read meanwhile, kept deflated (zlib, its fastest
// level): a target's 8-bit frames before cleanup are the preview's and the result gate's only
// (compact_raw.h), read once per keyframe at the end of a fit, and their white paper and flat
// colours deflate to a small share of their size. Lossless: inflating gives the same bytes.
// Floats the same way, their bytes split into four planes first (each float's lowest bytes,
// then the next, ...): a denoised frame's white paper is exactly 1.0f, and inside a flat fill
// the sign, exponent and high mantissa repeat while the low bytes vary, which interleaved
// bytes hide from the deflater.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace svgm {

// `n` bytes from `data`, deflated.
std::vector<uint8_t> deflate_bytes(const uint8_t* data, size_t n);
// The `n` bytes `packed` was made from, into `out`; throws svgm::Error ("internal: ...") when
// `packed` does not inflate to exactly `n` bytes.
void inflate_bytes(const std::vector<uint8_t>& packed, uint8_t* out, size_t n);
// `n` floats from `data`, by byte planes, deflated; and back, the same bits (throws as
// inflate_bytes does when `packed` was not made from `n` floats).
std::vector<uint8_t> deflate_floats(const float* data, size_t n);
void inflate_floats(const std::vector<uint8_t>& packed, float* out, size_t n);

}  // namespace svgm
