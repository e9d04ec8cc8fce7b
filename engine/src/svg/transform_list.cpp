// Transform list parsing (see transform_list.h).
#include "svg/transform_list.h"

#include <cctype>
#include <string>

#include "svg/svg_number.h"

namespace svgm::svg {

std::optional<Affine> parse_transform(std::string_view s, bool* out_of_range) {
  Cursor c{s};
  Affine m;
  c.skip_ws();
  auto bad = [&]() -> std::optional<Affine> {
    if (out_of_range) *out_of_range = c.out_of_range;
    return std::nullopt;
  };
  while (!c.done()) {
    size_t p = c.pos;
    while (p < s.size() && std::isalpha(static_cast<unsigned char>(s[p]))) ++p;
    const std::string name(s.substr(c.pos, p - c.pos));
    c.pos = p;
    c.skip_ws();
    if (c.peek() != '(') return bad();
    ++c.pos;
    double v[6];
    int n = 0;
    c.skip_ws();
    while (c.peek() != ')') {
      if (n == 6) return bad();
      const auto x = c.number();
      if (!x) return bad();
      v[n++] = *x;
      c.skip_comma_ws();
    }
    ++c.pos;
    Affine t;
    if (name == "matrix" && n == 6) t = {v[0], v[1], v[2], v[3], v[4], v[5]};
    else if (name == "translate" && (n == 1 || n == 2)) t = Affine::translate(v[0], n == 2 ? v[1] : 0);
    else if (name == "scale" && (n == 1 || n == 2)) t = Affine::scale(v[0], n == 2 ? v[1] : v[0]);
    else if (name == "rotate" && n == 1) t = Affine::rotate_deg(v[0]);
    else if (name == "rotate" && n == 3)
      t = Affine::translate(v[1], v[2]) * Affine::rotate_deg(v[0]) * Affine::translate(-v[1], -v[2]);
    else if (name == "skewX" && n == 1) t = Affine::skew_x_deg(v[0]);
    else if (name == "skewY" && n == 1) t = Affine::skew_y_deg(v[0]);
    else return bad();
    m = m * t;
    c.skip_comma_ws();
  }
  if (out_of_range) *out_of_range = c.out_of_range;
  return m;
}

}  // namespace svgm::svg
