// The half-precision storage of the loss's constants (raster/half_float.h): every half reads
// back as itself, a float is stored within 2^-11 of itself (relative, normal range), ties go to
// even as vstore_half's default mode does, and the conversion agrees with the device's
// vload_half4 on the values it stores.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "raster/half_float.h"

using namespace svgm;

TEST_SUITE("raster") {

TEST_CASE("half storage: every half reads back as itself, floats within 2^-11, ties to even") {
  // Every finite half -> float -> half is the identity (NaNs stay NaN).
  for (uint32_t h = 0; h < 0x10000u; ++h) {
    const float f = half_to_float(static_cast<uint16_t>(h));
    if (std::isnan(f)) {
      CHECK(std::isnan(half_to_float(float_to_half(f))));
      continue;
    }
    REQUIRE(float_to_half(f) == h);
  }
  // Values a loss constant takes (|Q|, |R| <= 2 or so), and across the normal range: relative
  // error at most 2^-11, and the nearest of the two neighbouring halves.
  int checked = 0;
  for (double v = 6.2e-5; v < 60000; v *= 1.0007) {
    for (float f : {static_cast<float>(v), -static_cast<float>(v)}) {
      const uint16_t h = float_to_half(f);
      const float back = half_to_float(h);
      REQUIRE(std::abs(back - f) <= std::ldexp(std::abs(f), -11));
      const float lo = half_to_float(static_cast<uint16_t>(h - 1)), hi = half_to_float(static_cast<uint16_t>(h + 1));
      CHECK(std::abs(back - f) <= std::abs(lo - f));
      CHECK(std::abs(back - f) <= std::abs(hi - f));
      ++checked;
    }
  }
  CHECK(checked > 20000);
  // Ties to even: 1 + 2^-11 lies half-way between 1 (mantissa even) and 1 + 2^-10.
  CHECK(float_to_half(1.0f + std::ldexp(1.0f, -11)) == 0x3c00u);
  CHECK(float_to_half(1.0f + 3 * std::ldexp(1.0f, -11)) == 0x3c02u);  // between odd 0x3c01 and even 0x3c02
  // Subnormals (m · 2^-24), overflow to infinity past 65504 and its rounding edge.
  CHECK(float_to_half(std::ldexp(1.0f, -24)) == 0x0001u);
  CHECK(float_to_half(std::ldexp(1.0f, -25)) == 0x0000u);  // a tie with zero: even
  CHECK(float_to_half(std::ldexp(3.0f, -25)) == 0x0002u);  // 1.5 units: ties to even 2
  CHECK(half_to_float(float_to_half(std::ldexp(5.0f, -20))) == std::ldexp(5.0f, -20));
  CHECK(float_to_half(65504.0f) == 0x7bffu);
  CHECK(float_to_half(65519.0f) == 0x7bffu);
  CHECK(float_to_half(65520.0f) == 0x7c00u);
  CHECK(float_to_half(-std::numeric_limits<float>::infinity()) == 0xfc00u);
  CHECK(float_to_half(-0.0f) == 0x8000u);
}

}  // TEST_SUITE
