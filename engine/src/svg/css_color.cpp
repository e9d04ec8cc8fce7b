// CSS colour parsing (see css_color.h).
#include "svg/css_color.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <utility>

#include "svg/svg_number.h"

namespace svgm::svg {

namespace {

// The CSS named colours (CSS Color Module Level 4, §6.1), sorted for binary search.
constexpr std::pair<std::string_view, uint32_t> kNamed[] = {
    {"aliceblue", 0xf0f8ff}, {"antiquewhite", 0xfaebd7}, {"aqua", 0x00ffff},
    {"aquamarine", 0x7fffd4}, {"azure", 0xf0ffff}, {"beige", 0xf5f5dc}, {"bisque", 0xffe4c4},
    {"black", 0x000000}, {"blanchedalmond", 0xffebcd}, {"blue", 0x0000ff},
    {"blueviolet", 0x8a2be2}, {"brown", 0xa52a2a}, {"burlywood", 0xdeb887},
    {"cadetblue", 0x5f9ea0}, {"chartreuse", 0x7fff00}, {"chocolate", 0xd2691e},
    {"coral", 0xff7f50}, {"cornflowerblue", 0x6495ed}, {"cornsilk", 0xfff8dc},
    {"crimson", 0xdc143c}, {"cyan", 0x00ffff}, {"darkblue", 0x00008b}, {"darkcyan", 0x008b8b},
    {"darkgoldenrod", 0xb8860b}, {"darkgray", 0xa9a9a9}, {"darkgreen", 0x006400},
    {"darkgrey", 0xa9a9a9}, {"darkkhaki", 0xbdb76b}, {"darkmagenta", 0x8b008b},
    {"darkolivegreen", 0x556b2f}, {"darkorange", 0xff8c00}, {"darkorchid", 0x9932cc},
    {"darkred", 0x8b0000}, {"darksalmon", 0xe9967a}, {"darkseagreen", 0x8fbc8f},
    {"darkslateblue", 0x483d8b}, {"darkslategray", 0x2f4f4f}, {"darkslategrey", 0x2f4f4f},
    {"darkturquoise", 0x00ced1}, {"darkviolet", 0x9400d3}, {"deeppink", 0xff1493},
    {"deepskyblue", 0x00bfff}, {"dimgray", 0x696969}, {"dimgrey", 0x696969},
    {"dodgerblue", 0x1e90ff}, {"firebrick", 0xb22222}, {"floralwhite", 0xfffaf0},
    {"forestgreen", 0x228b22}, {"fuchsia", 0xff00ff}, {"gainsboro", 0xdcdcdc},
    {"ghostwhite", 0xf8f8ff}, {"gold", 0xffd700}, {"goldenrod", 0xdaa520}, {"gray", 0x808080},
    {"green", 0x008000}, {"greenyellow", 0xadff2f}, {"grey", 0x808080}, {"honeydew", 0xf0fff0},
    {"hotpink", 0xff69b4}, {"indianred", 0xcd5c5c}, {"indigo", 0x4b0082}, {"ivory", 0xfffff0},
    {"khaki", 0xf0e68c}, {"lavender", 0xe6e6fa}, {"lavenderblush", 0xfff0f5},
    {"lawngreen", 0x7cfc00}, {"lemonchiffon", 0xfffacd}, {"lightblue", 0xadd8e6},
    {"lightcoral", 0xf08080}, {"lightcyan", 0xe0ffff}, {"lightgoldenrodyellow", 0xfafad2},
    {"lightgray", 0xd3d3d3}, {"lightgreen", 0x90ee90}, {"lightgrey", 0xd3d3d3},
    {"lightpink", 0xffb6c1}, {"lightsalmon", 0xffa07a}, {"lightseagreen", 0x20b2aa},
    {"lightskyblue", 0x87cefa}, {"lightslategray", 0x778899}, {"lightslategrey", 0x778899},
    {"lightsteelblue", 0xb0c4de}, {"lightyellow", 0xffffe0}, {"lime", 0x00ff00},
    {"limegreen", 0x32cd32}, {"linen", 0xfaf0e6}, {"magenta", 0xff00ff}, {"maroon", 0x800000},
    {"mediumaquamarine", 0x66cdaa}, {"mediumblue", 0x0000cd}, {"mediumorchid", 0xba55d3},
    {"mediumpurple", 0x9370db}, {"mediumseagreen", 0x3cb371}, {"mediumslateblue", 0x7b68ee},
    {"mediumspringgreen", 0x00fa9a}, {"mediumturquoise", 0x48d1cc},
    {"mediumvioletred", 0xc71585}, {"midnightblue", 0x191970}, {"mintcream", 0xf5fffa},
    {"mistyrose", 0xffe4e1}, {"moccasin", 0xffe4b5}, {"navajowhite", 0xffdead},
    {"navy", 0x000080}, {"oldlace", 0xfdf5e6}, {"olive", 0x808000}, {"olivedrab", 0x6b8e23},
    {"orange", 0xffa500}, {"orangered", 0xff4500}, {"orchid", 0xda70d6},
    {"palegoldenrod", 0xeee8aa}, {"palegreen", 0x98fb98}, {"paleturquoise", 0xafeeee},
    {"palevioletred", 0xdb7093}, {"papayawhip", 0xffefd5}, {"peachpuff", 0xffdab9},
    {"peru", 0xcd853f}, {"pink", 0xffc0cb}, {"plum", 0xdda0dd}, {"powderblue", 0xb0e0e6},
    {"purple", 0x800080}, {"rebeccapurple", 0x663399}, {"red", 0xff0000},
    {"rosybrown", 0xbc8f8f}, {"royalblue", 0x4169e1}, {"saddlebrown", 0x8b4513},
    {"salmon", 0xfa8072}, {"sandybrown", 0xf4a460}, {"seagreen", 0x2e8b57},
    {"seashell", 0xfff5ee}, {"sienna", 0xa0522d}, {"silver", 0xc0c0c0}, {"skyblue", 0x87ceeb},
    {"slateblue", 0x6a5acd}, {"slategray", 0x708090}, {"slategrey", 0x708090},
    {"snow", 0xfffafa}, {"springgreen", 0x00ff7f}, {"steelblue", 0x4682b4}, {"tan", 0xd2b48c},
    {"teal", 0x008080}, {"thistle", 0xd8bfd8}, {"tomato", 0xff6347}, {"turquoise", 0x40e0d0},
    {"violet", 0xee82ee}, {"wheat", 0xf5deb3}, {"white", 0xffffff}, {"whitesmoke", 0xf5f5f5},
    {"yellow", 0xffff00}, {"yellowgreen", 0x9acd32},
};

int hex(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

std::string lower_trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  std::string out;
  for (char c : s) out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// The comma- (or space-) separated arguments of "name(a, b, c[, d])", each a number with an
// optional '%'. Returns how many were read (0 on a syntax error).
int functional_args(std::string_view body, double v[4], bool pct[4]) {
  Cursor c{body};
  int n = 0;
  c.skip_ws();
  while (!c.done()) {
    if (n == 4) return 0;
    const auto x = c.number();
    if (!x) return 0;
    v[n] = *x;
    pct[n] = c.peek() == '%';
    if (pct[n]) ++c.pos;
    ++n;
    c.skip_ws();
    if (c.peek() == ',' || c.peek() == '/') ++c.pos;
    c.skip_ws();
  }
  return n;
}

float clamp01(double x) { return static_cast<float>(std::clamp(x, 0.0, 1.0)); }

double hue_to_rgb(double m1, double m2, double h) {
  h -= std::floor(h);
  if (h * 6 < 1) return m1 + (m2 - m1) * h * 6;
  if (h * 2 < 1) return m2;
  if (h * 3 < 2) return m1 + (m2 - m1) * (2.0 / 3.0 - h) * 6;
  return m1;
}

}  // namespace

std::optional<Rgba> parse_color(std::string_view in) {
  const std::string s = lower_trim(in);
  if (s.empty()) return std::nullopt;
  if (s[0] == '#') {
    const size_t n = s.size() - 1;
    int d[8];
    for (size_t i = 0; i < n && i < 8; ++i)
      if ((d[i] = hex(s[1 + i])) < 0) return std::nullopt;
    if (n == 3 || n == 4)
      return Rgba{d[0] * 17 / 255.f, d[1] * 17 / 255.f, d[2] * 17 / 255.f, n == 4 ? d[3] * 17 / 255.f : 1.f};
    if (n == 6 || n == 8)
      return Rgba{(d[0] * 16 + d[1]) / 255.f, (d[2] * 16 + d[3]) / 255.f, (d[4] * 16 + d[5]) / 255.f,
                  n == 8 ? (d[6] * 16 + d[7]) / 255.f : 1.f};
    return std::nullopt;
  }
  if (s == "transparent") return Rgba{0, 0, 0, 0};
  const size_t open = s.find('(');
  if (open != std::string::npos && s.back() == ')') {
    const std::string name = lower_trim(s.substr(0, open));
    double v[4];
    bool pct[4];
    const int n = functional_args(std::string_view(s).substr(open + 1, s.size() - open - 2), v, pct);
    if (n != 3 && n != 4) return std::nullopt;
    // CSS Color 4 allows a percentage alpha, but resvg (whose renderings are our reference)
    // rejects rgba(0, 127, 0, 50%) as a whole, drawing the default paint instead: we agree.
    if (n == 4 && pct[3]) return std::nullopt;
    const float alpha = n == 4 ? clamp01(pct[3] ? v[3] / 100 : v[3]) : 1.f;
    if (name == "rgb" || name == "rgba") {
      float c[3];
      for (int i = 0; i < 3; ++i) c[i] = clamp01(pct[i] ? v[i] / 100 : v[i] / 255);
      return Rgba{c[0], c[1], c[2], alpha};
    }
    if (name == "hsl" || name == "hsla") {
      const double h = v[0] / 360, sat = std::clamp(v[1] / 100, 0.0, 1.0), l = std::clamp(v[2] / 100, 0.0, 1.0);
      const double m2 = l <= 0.5 ? l * (sat + 1) : l + sat - l * sat, m1 = l * 2 - m2;
      return Rgba{clamp01(hue_to_rgb(m1, m2, h + 1.0 / 3)), clamp01(hue_to_rgb(m1, m2, h)),
                  clamp01(hue_to_rgb(m1, m2, h - 1.0 / 3)), alpha};
    }
    return std::nullopt;
  }
  const auto it = std::lower_bound(std::begin(kNamed), std::end(kNamed), s,
                                   [](const auto& e, const std::string& k) { return e.first < k; });
  if (it != std::end(kNamed) && it->first == s) {
    const uint32_t c = it->second;
    return Rgba{((c >> 16) & 255) / 255.f, ((c >> 8) & 255) / 255.f, (c & 255) / 255.f, 1.f};
  }
  return std::nullopt;
}

}  // namespace svgm::svg
