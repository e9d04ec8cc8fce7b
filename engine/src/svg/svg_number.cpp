// SVG number scanning (see svg_number.h).
#include "svg/svg_number.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <string>

namespace svgm::svg {

namespace {
bool is_ws(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }
}  // namespace

void Cursor::skip_ws() {
  while (pos < s.size() && is_ws(s[pos])) ++pos;
}

void Cursor::skip_comma_ws() {
  skip_ws();
  if (peek() == ',') {
    ++pos;
    skip_ws();
  }
}

std::optional<double> Cursor::number() {
  // sign? (digits ('.' digits?)? | '.' digits) (('e'|'E') sign? digits)?
  size_t p = pos;
  if (p < s.size() && (s[p] == '+' || s[p] == '-')) ++p;
  const size_t int_start = p;
  while (p < s.size() && std::isdigit(static_cast<unsigned char>(s[p]))) ++p;
  bool digits = p > int_start;
  if (p < s.size() && s[p] == '.') {
    const size_t frac = ++p;
    while (p < s.size() && std::isdigit(static_cast<unsigned char>(s[p]))) ++p;
    digits = digits || p > frac;
  }
  if (!digits) {
    if (spells_non_finite(s.substr(pos, 8))) out_of_range = true;
    return std::nullopt;
  }
  if (p < s.size() && (s[p] == 'e' || s[p] == 'E')) {
    size_t q = p + 1;
    if (q < s.size() && (s[q] == '+' || s[q] == '-')) ++q;
    const size_t exp_start = q;
    while (q < s.size() && std::isdigit(static_cast<unsigned char>(s[q]))) ++q;
    if (q > exp_start) p = q;  // "1em" keeps its 'e' for the unit
  }
  const size_t start = s[pos] == '+' ? pos + 1 : pos;  // from_chars rejects a leading '+'
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data() + start, s.data() + p, v);
  if (ec == std::errc::result_out_of_range || (ec == std::errc() && !std::isfinite(v))) {
    // Underflow to zero is harmless; overflow is not.
    std::string text(s.substr(start, p - start));
    const double big = std::strtod(text.c_str(), nullptr);
    if (!std::isfinite(big) || std::fabs(big) > 1e300) {
      out_of_range = true;
      return std::nullopt;
    }
    v = big;
  } else if (ec != std::errc() || end != s.data() + p) {
    return std::nullopt;
  }
  pos = p;
  return v;
}

std::optional<bool> Cursor::flag() {
  if (peek() == '0' || peek() == '1') return s[pos++] == '1';
  return std::nullopt;
}

std::optional<double> parse_number(std::string_view s, bool* out_of_range) {
  Cursor c{s};
  c.skip_ws();
  const auto v = c.number();
  c.skip_ws();
  if (out_of_range) *out_of_range = c.out_of_range || spells_non_finite(s);
  if (!v || !c.done()) return std::nullopt;
  return v;
}

bool spells_non_finite(std::string_view s) {
  std::string low;
  for (char c : s) low += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return low.find("nan") != std::string::npos || low.find("inf") != std::string::npos;
}

std::optional<double> parse_clock_value(std::string_view s) {
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\n' || s.back() == '\r')) s.remove_suffix(1);
  double scale = 1;
  auto strip = [&](std::string_view unit, double factor) {
    if (s.size() > unit.size() && s.substr(s.size() - unit.size()) == unit) {
      s.remove_suffix(unit.size());
      scale = factor;
      return true;
    }
    return false;
  };
  strip("ms", 1e-3) || strip("min", 60) || strip("h", 3600) || strip("s", 1);
  const auto v = parse_number(s);
  if (!v) return std::nullopt;
  return *v * scale;
}

void append_rounded(std::string& s, double v, double scale) {
  if (std::fabs(v) < 1e9) v = std::round(v * scale) / scale;
  if (v == 0) v = 0;  // no "-0"
  char buf[32];
  auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v);
  s.append(buf, ec == std::errc() ? p : buf);
}

}  // namespace svgm::svg
