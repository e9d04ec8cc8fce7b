// keySplines timing (see smil_spline.h).
#include "svg/smil_spline.h"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <vector>

#include "svg/svg_number.h"

namespace svgm::svg {

namespace {

double bezier(double p1, double p2, double t) {
  const double s = 1 - t;
  return 3 * s * s * t * p1 + 3 * s * t * t * p2 + t * t * t;
}

}  // namespace

double spline_fraction(pugi::xml_node anim, size_t interval, double u) {
  if (std::string_view(anim.attribute("calcMode").value()) != "spline") return u;
  std::string_view all = anim.attribute("keySplines").value();
  for (size_t i = 0; i < interval; ++i) {
    const size_t semi = all.find(';');
    if (semi == std::string_view::npos) return u;
    all.remove_prefix(semi + 1);
  }
  const std::string_view entry = all.substr(0, all.find(';'));
  std::vector<double> c;
  size_t at = 0;
  while (at < entry.size() && c.size() < 4) {
    const size_t start = entry.find_first_not_of(" \t\r\n,", at);
    if (start == std::string_view::npos) break;
    size_t end = entry.find_first_of(" \t\r\n,", start);
    if (end == std::string_view::npos) end = entry.size();
    const auto n = parse_number(entry.substr(start, end - start));
    if (!n) return u;
    c.push_back(*n);
    at = end;
  }
  if (c.size() != 4) return u;
  // x(t) is increasing for x1, x2 in [0, 1]: bisection finds the t where x(t) = u.
  double lo = 0, hi = 1;
  for (int k = 0; k < 40; ++k) {
    const double mid = 0.5 * (lo + hi);
    (bezier(c[0], c[2], mid) < u ? lo : hi) = mid;
  }
  return bezier(c[1], c[3], 0.5 * (lo + hi));
}

}  // namespace svgm::svg
