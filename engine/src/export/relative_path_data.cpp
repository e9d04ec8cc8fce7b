// Relative, tight path data (see relative_path_data.h).
#include "export/relative_path_data.h"

#include <charconv>
#include <cmath>
#include <cstdint>

namespace svgm {

namespace {

// Writes numbers (whole units of the last decimal place) as the shortest text, "0.5" as ".5",
// "-0.5" as "-.5", with a separator only where the grammar needs one: not after a command
// letter, nor before a minus sign, nor before a '.' after a number that has one.
struct NumberWriter {
  std::string& s;
  double scale;
  bool after_letter = true, last_has_point = false;

  void letter(char c) {
    s += c;
    after_letter = true;
  }
  void number(int64_t units) {
    char buf[40];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, static_cast<double>(units) / scale);
    std::string text(buf, ec == std::errc() ? end : buf);
    if (text.rfind("0.", 0) == 0) text.erase(0, 1);
    else if (text.rfind("-0.", 0) == 0) text.erase(1, 1);
    const bool has_point = text.find('.') != std::string::npos && text.find('e') == std::string::npos;
    const bool glued = after_letter || text[0] == '-' || (text[0] == '.' && last_has_point);
    if (!glued) s += ' ';
    s += text;
    after_letter = false;
    last_has_point = has_point;
  }
};

}  // namespace

std::string relative_path_data(const Path& path, const double* cp, const Affine& to_local, int decimals) {
  const double scale = std::pow(10.0, decimals);
  auto units = [scale](double v) { return static_cast<int64_t>(std::llround(v * scale)); };
  std::string d;
  NumberWriter w{d, scale};
  for (const Subpath& sp : path.subpaths) {
    if (sp.points.empty()) continue;
    int64_t x0 = 0, y0 = 0;  // the current point: the segment's start
    for (size_t i = 0; i < sp.points.size(); ++i) {
      const Vec2 q = to_local.apply({cp[2 * i], cp[2 * i + 1]});
      const int64_t x = units(q.x), y = units(q.y);
      if (i == 0) {
        w.letter('M');
        w.number(x);
        w.number(y);
        x0 = x, y0 = y;
        continue;
      }
      // A closed subpath's last cubic is absolute: readers close it with a line unless its end
      // is exactly the start, which summed relative numbers miss by a rounding of a double
      // (our reader then counts other points in that value and cannot blend it with the next).
      const bool last_absolute = sp.closed && i + 3 >= sp.points.size() && sp.points.size() >= 4;
      if (i == 1) w.letter('c');
      if (last_absolute && i + 3 == sp.points.size()) w.letter('C');
      w.number(last_absolute ? x : x - x0);
      w.number(last_absolute ? y : y - y0);
      if (i % 3 == 0) x0 = x, y0 = y;
    }
    if (sp.closed) w.letter('Z');
    cp += 2 * sp.points.size();
  }
  return d;
}

}  // namespace svgm
