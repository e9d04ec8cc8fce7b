// Fuzz target: the SVG transform attribute (matrix, translate, scale, rotate with a centre,
// skewX, skewY, in lists). Properties checked on every input: no crash or sanitizer report;
// a list that parses and flagged no out-of-range number, written back as one matrix(...) of
// shortest round-tripping decimals, parses to exactly the same six numbers.
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

#include "fuzz_check.h"
#include "svg/transform_list.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view s(reinterpret_cast<const char*>(data), size);
  bool out_of_range = false;
  const auto m = svgm::svg::parse_transform(s, &out_of_range);
  if (!m) return 0;
  FUZZ_REQUIRE(!out_of_range, "a list with a nan/inf/overflowing number is refused");
  const double v[6] = {m->a, m->b, m->c, m->d, m->e, m->f};
  std::string back = "matrix(";
  for (int i = 0; i < 6; ++i) {
    if (!std::isfinite(v[i])) return 0;  // products may overflow; the reader checks the result
    char buf[32];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v[i]);
    back.append(buf, end);
    back += i < 5 ? "," : ")";
  }
  bool again_oor = false;
  const auto again = svgm::svg::parse_transform(back, &again_oor);
  FUZZ_REQUIRE(again.has_value() && !again_oor, "matrix() written back parses");
  FUZZ_REQUIRE(again->a == m->a && again->b == m->b && again->c == m->c && again->d == m->d &&
                   again->e == m->e && again->f == m->f,
               "matrix() written back is the same transform");
  return 0;
}
