// Bytes a fit holds for later but does not read meanwhile, kept deflated (zlib, its fastest
// level): a target's 8-bit frames before cleanup are the preview's and the result gate's only
// (compact_raw.h), read once per keyframe at the end of a fit, and their white paper and flat
// colours deflate to a small share of their size. Lossless: inflating gives the same bytes.
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

}  // namespace svgm
