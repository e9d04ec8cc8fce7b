// binary16 conversions (see half_float.h).
#include "raster/half_float.h"

#include <cstring>

namespace svgm {

uint16_t float_to_half(float f) {
  uint32_t x;
  std::memcpy(&x, &f, sizeof x);
  const uint32_t sign = (x >> 16) & 0x8000u;
  const uint32_t abs = x & 0x7fffffffu;
  if (abs >= 0x7f800000u)  // infinity, or NaN (kept quiet, non-zero mantissa)
    return static_cast<uint16_t>(sign | 0x7c00u | (abs > 0x7f800000u ? 0x200u : 0u));
  if (abs >= 0x477ff000u) return static_cast<uint16_t>(sign | 0x7c00u);  // rounds past 65504
  if (abs < 0x38800000u) {
    // Below the smallest normal half (2^-14): a subnormal, m · 2^-24. Shift the full mantissa
    // (implicit bit included) so that one unit is 2^-24, rounding to nearest even.
    if (abs < 0x33000000u) return static_cast<uint16_t>(sign);  // under half of 2^-24: zero
    const uint32_t e = abs >> 23;
    const uint32_t m = (abs & 0x7fffffu) | 0x800000u;
    const uint32_t shift = 126u - e;  // the value is m · 2^(e-150) = (m >> shift) · 2^-24
    const uint32_t half_m = m >> shift;
    const uint32_t rest = m & ((1u << shift) - 1u), mid = 1u << (shift - 1u);
    const uint32_t up = rest > mid || (rest == mid && (half_m & 1u));
    return static_cast<uint16_t>(sign | (half_m + up));
  }
  // Normal: rebias the exponent (127 -> 15) and round the 13 dropped mantissa bits to even; a
  // carry out of the mantissa moves into the exponent, which is the right result.
  const uint32_t r = abs - 0x38000000u;  // exponent - 112
  const uint32_t h = r >> 13, rest = r & 0x1fffu;
  const uint32_t up = rest > 0x1000u || (rest == 0x1000u && (h & 1u));
  return static_cast<uint16_t>(sign | (h + up));
}

float half_to_float(uint16_t h) {
  const uint32_t sign = static_cast<uint32_t>(h & 0x8000u) << 16;
  const uint32_t e = (h >> 10) & 0x1fu, m = h & 0x3ffu;
  uint32_t x;
  if (e == 0x1fu) {
    x = sign | 0x7f800000u | (m << 13);
  } else if (e != 0) {
    x = sign | ((e + 112u) << 23) | (m << 13);
  } else {
    float v = static_cast<float>(m) * (1.0f / 16777216.0f);  // m · 2^-24, exact
    return sign ? -v : v;
  }
  float f;
  std::memcpy(&f, &x, sizeof f);
  return f;
}

}  // namespace svgm
