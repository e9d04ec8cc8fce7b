// 2-D points and affine transforms, the geometry vocabulary of the scene model.
//
// An Affine is the SVG matrix(a b c d e f): x' = a x + c y + e, y' = b x + d y + f. Composition
// follows SVG's convention: A * B applies B first, then A (a transform list "T1 T2" is T1 * T2).
#pragma once

#include <cmath>

namespace svgm {

struct Vec2 {
  double x = 0, y = 0;
  friend Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
  friend Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
  friend Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
  friend bool operator==(const Vec2&, const Vec2&) = default;
};

struct Affine {
  double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;

  static Affine translate(double tx, double ty) { return {1, 0, 0, 1, tx, ty}; }
  static Affine scale(double sx, double sy) { return {sx, 0, 0, sy, 0, 0}; }
  static Affine rotate_deg(double deg) {
    const double r = deg * (M_PI / 180.0), cs = std::cos(r), sn = std::sin(r);
    return {cs, sn, -sn, cs, 0, 0};
  }
  static Affine skew_x_deg(double deg) { return {1, 0, std::tan(deg * (M_PI / 180.0)), 1, 0, 0}; }
  static Affine skew_y_deg(double deg) { return {1, std::tan(deg * (M_PI / 180.0)), 0, 1, 0, 0}; }

  Vec2 apply(Vec2 p) const { return {a * p.x + c * p.y + e, b * p.x + d * p.y + f}; }
  double det() const { return a * d - b * c; }
  // The factor by which the transform scales lengths on average (sqrt of |det|): used to scale
  // stroke widths, which is exact for similarities and an approximation under skew.
  double mean_scale() const { return std::sqrt(std::fabs(det())); }

  Affine inverse() const {
    const double k = 1.0 / det();
    return {d * k, -b * k, -c * k, a * k, (c * f - d * e) * k, (b * e - a * f) * k};
  }

  friend Affine operator*(const Affine& m, const Affine& n) {
    return {m.a * n.a + m.c * n.b,       m.b * n.a + m.d * n.b,
            m.a * n.c + m.c * n.d,       m.b * n.c + m.d * n.d,
            m.a * n.e + m.c * n.f + m.e, m.b * n.e + m.d * n.f + m.f};
  }
  friend bool operator==(const Affine&, const Affine&) = default;
};

}  // namespace svgm
