// What the forward and backward CPU references of the stroker share (raster_ref.cpp,
// stroke_backward_ref.cpp): a double-precision 2D vector, and the direction inheritance of
// kernels/stroke.cl (seg_valid, seg_src; see its essay): a degenerate segment takes the
// direction of the nearest valid one before it, else (closed) wrapping round, else after it.
#pragma once

#include <cmath>

namespace svgm::ref::stroke_geom {

struct P2 {
  double x = 0, y = 0;
};
inline P2 operator+(P2 a, P2 b) { return {a.x + b.x, a.y + b.y}; }
inline P2 operator-(P2 a, P2 b) { return {a.x - b.x, a.y - b.y}; }
inline P2 operator*(double s, P2 a) { return {s * a.x, s * a.y}; }
inline P2 operator/(P2 a, double s) { return {a.x / s, a.y / s}; }
inline P2& operator+=(P2& a, P2 b) { return a = a + b; }
inline P2& operator-=(P2& a, P2 b) { return a = a - b; }
inline double dot(P2 a, P2 b) { return a.x * b.x + a.y * b.y; }
inline double cross(P2 a, P2 b) { return a.x * b.y - a.y * b.x; }
inline P2 perp(P2 d) { return {-d.y, d.x}; }
inline P2 rotate(P2 v, double a) {
  return {std::cos(a) * v.x - std::sin(a) * v.y, std::sin(a) * v.x + std::cos(a) * v.y};
}

constexpr double kDegenerateLen2 = 1e-12;  // as DEGENERATE_LEN2 in stroke.cl

// Segment i of a subpath of N vertices (p[i] -> p[(i + 1) % N]): its unit direction in *d, or
// false when it is degenerate.
inline bool seg_valid(const P2* p, int N, int i, P2* d) {
  const P2 v = p[(i + 1) % N] - p[i];
  const double l2 = dot(v, v);
  if (l2 <= kDegenerateLen2) return false;
  *d = v / std::sqrt(l2);
  return true;
}

// The segment (of S) whose direction segment i takes; -1 when every segment is degenerate.
inline int seg_src(const P2* p, int N, int S, bool closed, int i) {
  P2 d;
  for (int j = i; j >= 0; --j)
    if (seg_valid(p, N, j, &d)) return j;
  if (closed) {
    for (int j = S - 1; j > i; --j)
      if (seg_valid(p, N, j, &d)) return j;
  } else {
    for (int j = i + 1; j < S; ++j)
      if (seg_valid(p, N, j, &d)) return j;
  }
  return -1;
}

// Segment i's direction after inheritance; +x when there is none.
inline P2 seg_dir(const P2* p, int N, int S, bool closed, int i) {
  P2 d{1, 0};
  const int j = seg_src(p, N, S, closed, i);
  if (j >= 0) seg_valid(p, N, j, &d);
  return d;
}

}  // namespace svgm::ref::stroke_geom
