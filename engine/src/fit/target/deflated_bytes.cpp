// Deflated bytes (deflated_bytes.h), through zlib.
#include "fit/target/deflated_bytes.h"

#include <zlib.h>

#include "svgmotion/error.h"

namespace svgm {

std::vector<uint8_t> deflate_bytes(const uint8_t* data, size_t n) {
  uLongf size = compressBound(static_cast<uLong>(n));
  std::vector<uint8_t> out(size);
  if (compress2(out.data(), &size, data, static_cast<uLong>(n), Z_BEST_SPEED) != Z_OK)
    throw Error("internal: zlib could not deflate a frame");
  out.resize(size);
  out.shrink_to_fit();
  return out;
}

void inflate_bytes(const std::vector<uint8_t>& packed, uint8_t* out, size_t n) {
  uLongf size = static_cast<uLongf>(n);
  if (uncompress(out, &size, packed.data(), static_cast<uLong>(packed.size())) != Z_OK || size != n)
    throw Error("internal: a deflated frame does not inflate to its size");
}

}  // namespace svgm
