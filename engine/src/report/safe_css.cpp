// CSS reduced to an allow-list for report.html (see safe_css.h). The filter never repairs:
// a declaration, value or rule it does not fully understand is dropped and counted.
#include "report/safe_css.h"

#include <algorithm>
#include <array>
#include <cctype>

namespace svgm {

namespace {

// What svgmotion's renderer reads (svg/svg_style.cpp) and what an SVG drawing needs to look the
// same in a browser; none of them takes anything but a colour, length, keyword or url(#id).
constexpr std::array<std::string_view, 39> kProperties = {
    "fill",           "fill-opacity",     "fill-rule",       "stroke",       "stroke-width",
    "stroke-opacity", "stroke-linejoin",  "stroke-linecap",  "stroke-miterlimit",
    "stroke-dasharray", "stroke-dashoffset", "color",        "opacity",      "visibility",
    "display",        "clip-path",        "clip-rule",       "mask",         "mask-type",
    "stop-color",     "stop-opacity",     "vector-effect",   "paint-order",  "shape-rendering",
    "overflow",       "font-family",      "font-size",       "font-weight",  "font-style",
    "text-anchor",    "dominant-baseline", "letter-spacing", "transform",    "transform-origin",
    "transform-box",  "mix-blend-mode",   "isolation",       "line-height",  "font-variant"};

// Functions a kept value may call: colours and transforms, none of which loads anything.
constexpr std::array<std::string_view, 15> kFunctions = {
    "rgb",    "rgba",   "hsl",        "hsla",       "matrix", "translate", "translatex", "translatey",
    "scale",  "scalex", "scaley",     "rotate",     "skew",   "skewx",     "skewy"};

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_'; }

// A property's name for the warning: itself when it is a plain CSS name, else a placeholder
// (the warning line is printed on the terminal and shown on the page).
std::string shown_name(std::string_view name) {
  if (name.empty() || name.size() > 40 || !std::all_of(name.begin(), name.end(), ident_char)) return "CSS";
  return std::string(name);
}

// "fill: red !important" -> the declaration kept ("fill:red!important"), or "" (counted).
std::string safe_declaration(std::string_view decl, DropTally& dropped) {
  const size_t colon = decl.find(':');
  if (trim(decl).empty()) return {};
  if (colon == std::string_view::npos) {
    dropped.add("malformed CSS declaration", "malformed CSS declarations");
    return {};
  }
  const std::string name = lower(trim(decl.substr(0, colon)));
  std::string_view value = trim(decl.substr(colon + 1));
  std::string important;
  if (const size_t bang = value.rfind('!'); bang != std::string_view::npos && lower(trim(value.substr(bang + 1))) == "important") {
    important = "!important";
    value = trim(value.substr(0, bang));
  }
  if (!safe_css_property(name)) {
    dropped.add(shown_name(name) + " declaration", shown_name(name) + " declarations");
    return {};
  }
  if (!safe_css_value(value)) {
    dropped.add(name + " declaration with an unsafe value", name + " declarations with unsafe values");
    return {};
  }
  return name + ":" + std::string(value) + important;
}

// Selectors of tags, .classes and #ids, descendant and child combinators, lists: what the
// renderer's style sheets support (svg/css_sheet.h), with no escapes or pseudo-classes.
bool safe_selector(std::string_view sel) {
  if (trim(sel).empty()) return false;
  for (const char c : sel)
    if (!(ident_char(c) || c == '.' || c == '#' || c == '*' || c == ',' || c == '>' ||
          std::isspace(static_cast<unsigned char>(c))))
      return false;
  for (size_t at = 0; at <= sel.size();) {  // no empty member of a list ("a,,b")
    const size_t comma = std::min(sel.find(',', at), sel.size());
    if (trim(sel.substr(at, comma - at)).empty()) return false;
    at = comma + 1;
  }
  return true;
}

std::string scoped(std::string_view sel, std::string_view scope) {
  std::string out;
  for (size_t at = 0; at <= sel.size();) {
    const size_t comma = std::min(sel.find(',', at), sel.size());
    out += (out.empty() ? "" : ",") + std::string(scope) + std::string(trim(sel.substr(at, comma - at)));
    at = comma + 1;
  }
  return out;
}

// The end of the block opening at css[open] ('{'): the index after its matching '}'.
size_t block_end(std::string_view css, size_t open) {
  int depth = 0;
  for (size_t i = open; i < css.size(); ++i) {
    if (css[i] == '{') ++depth;
    else if (css[i] == '}' && --depth == 0) return i + 1;
  }
  return css.size();
}

}  // namespace

bool safe_css_property(std::string_view name) {
  return std::find(kProperties.begin(), kProperties.end(), name) != kProperties.end();
}

bool local_reference(std::string_view ref) {
  if (ref.size() < 2 || ref[0] != '#') return false;
  // Plain ids only: no "#xpointer(...)", "#svgView(...)" or anything a URL parser reads on.
  return std::all_of(ref.begin() + 1, ref.end(), [](char c) {
    return ident_char(c) || c == '.' || c == ':' || static_cast<unsigned char>(c) >= 0x80;
  });
}

bool safe_css_value(std::string_view v) {
  for (size_t i = 0; i < v.size(); ++i) {
    const char c = v[i];
    if (c == '\\' || c == '@' || c == '{' || c == '}' || c == '<' || c == '>' || c == ';' || c == '&' || c == '`' ||
        c == '!' || (static_cast<unsigned char>(c) < 0x20 && !std::isspace(static_cast<unsigned char>(c))))
      return false;
    if (c == '/' && i + 1 < v.size() && v[i + 1] == '*') return false;
    if (c != '(') continue;
    size_t start = i;
    while (start > 0 && ident_char(v[start - 1])) --start;
    const std::string fn = lower(v.substr(start, i - start));
    if (fn == "url") {
      const size_t close = v.find(')', i);
      if (close == std::string_view::npos) return false;
      std::string_view ref = trim(v.substr(i + 1, close - i - 1));
      if (ref.size() >= 2 && (ref.front() == '"' || ref.front() == '\'') && ref.back() == ref.front())
        ref = ref.substr(1, ref.size() - 2);
      if (!local_reference(ref)) return false;
      i = close;
    } else if (std::find(kFunctions.begin(), kFunctions.end(), fn) == kFunctions.end()) {
      return false;
    }
  }
  return true;
}

std::string safe_style_declarations(std::string_view style, DropTally& dropped) {
  std::string out;
  for (size_t at = 0; at <= style.size();) {
    const size_t semi = std::min(style.find(';', at), style.size());
    const std::string d = safe_declaration(style.substr(at, semi - at), dropped);
    if (!d.empty()) out += (out.empty() ? "" : ";") + d;
    at = semi + 1;
  }
  return out;
}

std::string safe_style_sheet(std::string_view css_in, std::string_view scope, DropTally& dropped) {
  // Comments first (an unterminated one runs to the end, as in CSS).
  std::string css;
  for (size_t at = 0; at < css_in.size();) {
    const size_t open = css_in.find("/*", at);
    css += css_in.substr(at, open == std::string_view::npos ? std::string_view::npos : open - at);
    if (open == std::string_view::npos) break;
    const size_t close = css_in.find("*/", open + 2);
    at = close == std::string_view::npos ? css_in.size() : close + 2;
  }
  std::string out;
  for (size_t at = 0; at < css.size();) {
    while (at < css.size() && std::isspace(static_cast<unsigned char>(css[at]))) ++at;
    if (at >= css.size()) break;
    if (css[at] == '@') {
      // @import, @font-face, @media, @namespace ...: up to its ';' or through its block.
      size_t n = at + 1;
      while (n < css.size() && ident_char(css[n])) ++n;
      const std::string name = shown_name(lower(std::string_view(css).substr(at + 1, n - at - 1)));
      dropped.add("@" + name + " rule", "@" + name + " rules");
      const size_t semi = css.find(';', n), brace = css.find('{', n);
      at = brace < semi ? block_end(css, brace) : (semi == std::string::npos ? css.size() : semi + 1);
      continue;
    }
    if (css[at] == '}' || css[at] == ';') {  // stray: skipped as a CSS parser does
      ++at;
      continue;
    }
    const size_t open = css.find('{', at);
    if (open == std::string::npos) {
      dropped.add("malformed CSS rule", "malformed CSS rules");
      break;
    }
    const size_t end = block_end(css, open);
    const std::string_view selector(std::string_view(css).substr(at, open - at));
    const bool closed = css[end - 1] == '}' && end > open + 1;  // else the sheet ended inside it
    const std::string_view body = std::string_view(css).substr(open + 1, (closed ? end - 1 : css.size()) - open - 1);
    if (!safe_selector(selector) || body.find('{') != std::string_view::npos) {
      dropped.add("CSS rule with an unsupported selector", "CSS rules with unsupported selectors");
    } else {
      const std::string decls = safe_style_declarations(body, dropped);
      if (!decls.empty()) out += scoped(selector, scope) + "{" + decls + "}";
    }
    at = end;
  }
  return out;
}

}  // namespace svgm
