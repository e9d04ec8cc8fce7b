// A string_view cursor over SVG attribute micro-syntax: numbers (including compact forms such
// as "1.5.5" = 1.5 .5 and "-1e-2"), comma-whitespace, arc flags.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace svgm::svg {

struct Cursor {
  std::string_view s;
  size_t pos = 0;
  // Set when a number overflowed (1e999) or spelled nan/inf: the document is malformed.
  bool out_of_range = false;

  bool done() const { return pos >= s.size(); }
  char peek() const { return pos < s.size() ? s[pos] : '\0'; }
  void skip_ws();
  void skip_comma_ws();  // whitespace, at most one comma, whitespace
  // An SVG number at the cursor (no leading whitespace skipped).
  std::optional<double> number();
  // A single '0' or '1' (arc flags need no separators: "a1 1 0 00 1 1").
  std::optional<bool> flag();
};

// The whole string as one number (surrounding whitespace allowed); nothing if it is not one.
std::optional<double> parse_number(std::string_view s, bool* out_of_range = nullptr);

// True when the text spells nan or inf(inity) in any case: such numbers make a document
// malformed rather than merely invalid.
bool spells_non_finite(std::string_view s);

// A SMIL clock value in seconds: "2.04s", "500ms", "1.5min", "0.5h" or a bare number of
// seconds; nothing if it is not one.
std::optional<double> parse_clock_value(std::string_view s);

// Appends the shortest text that reads back as v rounded to 1/scale (no "-0"); values of
// 1e9 and beyond are written unrounded. For writing SVG coordinates compactly.
void append_rounded(std::string& s, double v, double scale);

}  // namespace svgm::svg
