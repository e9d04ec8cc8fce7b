// Escaping text for report.html (see html_text.h).
#include "report/html_text.h"

#include <cmath>
#include <cstdio>

#include "svgmotion/utf8_text.h"

namespace svgm {

std::string html_escape(std::string_view raw) {
  // The page is UTF-8: a name that is not (a Latin-1 file name) shows U+FFFD for its stray bytes.
  const std::string text = shown_utf8(raw);
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string html_number(double x, int digits) {
  if (!std::isfinite(x)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

}  // namespace svgm
