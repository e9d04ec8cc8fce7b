// Deflated bytes (deflated_bytes.h), through zlib.
#include "fit/target/deflated_bytes.h"

#include <zlib.h>

#include <cstring>

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

std::vector<uint8_t> deflate_floats(const float* data, size_t n) {
  std::vector<uint8_t> planes(n * sizeof(float));
  const auto* b = reinterpret_cast<const uint8_t*>(data);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < sizeof(float); ++j) planes[j * n + i] = b[i * sizeof(float) + j];
  return deflate_bytes(planes.data(), planes.size());
}

void inflate_floats(const std::vector<uint8_t>& packed, float* out, size_t n) {
  std::vector<uint8_t> planes(n * sizeof(float));
  inflate_bytes(packed, planes.data(), planes.size());
  auto* b = reinterpret_cast<uint8_t*>(out);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < sizeof(float); ++j) b[i * sizeof(float) + j] = planes[j * n + i];
}

}  // namespace svgm
