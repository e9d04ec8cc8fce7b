// Text taken from files (ids, prompts, ranker reasons, paths) placed into report.html: escaped
// so that it is always shown as text, never read as markup, in element content and in quoted
// attribute values alike.
#pragma once

#include <string>
#include <string_view>

namespace svgm {

// & < > " ' as character references; everything else (UTF-8 included) as it is, except bytes
// that are not UTF-8, which become U+FFFD (svgmotion/utf8_text.h).
std::string html_escape(std::string_view text);

// A number for display: `digits` significant digits (printf %g), "-" when not finite.
std::string html_number(double x, int digits = 4);

}  // namespace svgm
