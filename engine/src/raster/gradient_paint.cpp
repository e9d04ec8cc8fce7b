// Gradient colours (see gradient_paint.h).
#include "raster/gradient_paint.h"

#include <cmath>

namespace svgm {

namespace {

double spread(double t, Spread s) {
  switch (s) {
    case Spread::Pad: return std::fmin(std::fmax(t, 0.0), 1.0);
    case Spread::Repeat: return t - std::floor(t);
    case Spread::Reflect: {
      const double m = t - 2.0 * std::floor(0.5 * t);  // in [0, 2)
      return m > 1 ? 2 - m : m;
    }
  }
  return t;
}

}  // namespace

Rgba gradient_color_at(const Gradient& g, double t) {
  const auto& s = g.stops;
  if (t <= s.front().offset) return s.front().color;
  if (t >= s.back().offset) return s.back().color;
  size_t i = 1;
  while (i < s.size() && s[i].offset <= t) ++i;
  // s[i - 1].offset <= t < s[i].offset, so the span is not empty.
  const GradientStop &a = s[i - 1], &b = s[i];
  const float u = static_cast<float>((t - a.offset) / (b.offset - a.offset));
  return Rgba{a.color.r + u * (b.color.r - a.color.r), a.color.g + u * (b.color.g - a.color.g),
              a.color.b + u * (b.color.b - a.color.b), a.color.a + u * (b.color.a - a.color.a)};
}

std::optional<Rgba> gradient_color(const Gradient& g, const Affine& canvas_to_gradient, Vec2 p) {
  const Vec2 q = canvas_to_gradient.apply(p);
  if (g.stops.size() == 1) return g.stops[0].color;
  double t = 0;
  if (!g.radial) {
    const Vec2 d = g.p2 - g.p1, v = q - g.p1;
    t = (v.x * d.x + v.y * d.y) / (d.x * d.x + d.y * d.y);
  } else {
    // |q - (f + t (c - f))| = fr + t (r - fr), for the largest t with a radius >= 0.
    const Vec2 cd = g.center - g.focal, pd = q - g.focal;
    const double dr = g.r - g.fr;
    const double a = cd.x * cd.x + cd.y * cd.y - dr * dr;
    const double b = pd.x * cd.x + pd.y * cd.y + g.fr * dr;
    const double c = pd.x * pd.x + pd.y * pd.y - g.fr * g.fr;
    auto valid = [&](double x) { return g.fr + x * dr >= 0; };
    if (std::fabs(a) < 1e-12 * (cd.x * cd.x + cd.y * cd.y + dr * dr)) {
      if (b == 0) return std::nullopt;
      t = c / (2 * b);
      if (!valid(t)) return std::nullopt;
    } else {
      const double disc = b * b - a * c;
      if (disc < 0) return std::nullopt;
      const double s = std::sqrt(disc);
      const double t1 = (b + s) / a, t2 = (b - s) / a;
      const double hi = std::fmax(t1, t2), lo = std::fmin(t1, t2);
      if (valid(hi)) t = hi;
      else if (valid(lo)) t = lo;
      else return std::nullopt;
    }
  }
  return gradient_color_at(g, spread(t, g.spread));
}

}  // namespace svgm
