// A stroke's outline as Skia's stroker (SkStroke, SkStrokerPriv) builds it; see browser_stroke.h.
//
// Each side of a curved segment is approximated by quadratics: for a piece [t0, t1] of the
// cubic, the quadratic runs between the offset points at t0 and t1 with its control point where
// the two offset tangents meet; it is accepted when the offset point at the middle t lies within
// a quarter pixel of it (Skia's tolerance: 1 / (4 * resScale), resScale 1 in pixel space) and
// otherwise the piece is halved. Cubics are first cut at their inflections. Lines offset
// exactly. Joins: miter (a miter point, or a bevel past the miter limit), bevel, round (a
// conic arc per quarter turn); on the inner side a join goes through the pivot, as Skia's does,
// except between two straight sides, where it dips only to where they cross (cut_pivot_dips
// says why). Caps: butt, square, round (two quarter-circle conics). An open subpath becomes one contour (outer
// side, end cap, inner side backwards, start cap), a closed one two (outer, inner reversed).
// Re-derived from reading Skia's sources (third_party_notes.md); the structure is ours.
#include "raster/browser_stroke.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace svgm {

namespace {

constexpr double kTol = 0.25;            // px: Skia's stroke tolerance, 1 / (4 * resScale)
constexpr double kNearlyZero = 1.0 / 4096;  // Skia's SK_ScalarNearlyZero
constexpr int kMaxDepth = 26 * 3;        // Skia's recursion limit for a cubic's pieces

double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
double len(Vec2 a) { return std::hypot(a.x, a.y); }
Vec2 lerp(Vec2 a, Vec2 b, double t) { return a + t * (b - a); }
// Skia's normal of a direction: the direction turned a quarter counter-clockwise on screen.
Vec2 normal_of(Vec2 d) { return {d.y, -d.x}; }
Vec2 cubic_at(const Vec2* c, double t) {
  const double u = 1 - t;
  return u * u * u * c[0] + 3 * u * u * t * c[1] + 3 * u * t * t * c[2] + t * t * t * c[3];
}
Vec2 cubic_tangent(const Vec2* c, double t) {
  const double u = 1 - t;
  return 3 * (u * u) * (c[1] - c[0]) + 6 * u * t * (c[2] - c[1]) + 3 * (t * t) * (c[3] - c[2]);
}
// A conic (rational quadratic of weight w) at t, and a vector along its tangent.
Vec2 conic_at(const Vec2* c, double w, double t) {
  const double u = 1 - t, d = u * u + 2 * w * u * t + t * t;
  return (1 / d) * (u * u * c[0] + 2 * w * u * t * c[1] + t * t * c[2]);
}
Vec2 conic_tangent(const Vec2* c, double w, double t) {
  const Vec2 p20 = c[2] - c[0], p10 = c[1] - c[0];
  const Vec2 C = w * p10, A = (w - 1) * p20, B = p20 - 2 * C;
  return t * (t * A + B) + C;
}
Vec2 quad_at(const Vec2* q, double t) {
  const double u = 1 - t;
  return u * u * q[0] + 2 * u * t * q[1] + t * t * q[2];
}
bool degenerate(Vec2 v) { return std::fabs(v.x) <= kNearlyZero && std::fabs(v.y) <= kNearlyZero; }
// Squared distance from p to the infinite line through a and b.
double dist2_to_line(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  if (degenerate(d)) return dot(p - a, p - a);
  const Vec2 h = lerp(a, b, dot(p - a, d) / dot(d, d));
  return dot(p - h, p - h);
}

// A contour side under construction: a start and verbs (the outer side, the inner side).
struct Side {
  Vec2 start;
  std::vector<OutlineVerb> verbs;
  std::vector<size_t> pivots;  // indices of the verbs that dip to a join's pivot (inner side)
  bool empty = true;
  void move_to(Vec2 p) { start = p, verbs.clear(), pivots.clear(), empty = false; }
  Vec2 last() const { return verbs.empty() ? start : verbs.back().p; }
  void line_to(Vec2 p) { verbs.push_back({OutlineVerb::Line, {}, p, 1}); }
  void quad_to(Vec2 c, Vec2 p) { verbs.push_back({OutlineVerb::Quad, c, p, 1}); }
  void conic_to(Vec2 c, Vec2 p, double w) { verbs.push_back({OutlineVerb::Conic, c, p, w}); }
  void set_last(Vec2 p) { (verbs.empty() ? start : verbs.back().p) = p; }
  // Appends `other` walked backwards from its second-to-last point (its last point is where
  // this side already is, or is replaced by it: Skia's reversePathTo).
  void reverse_append(const Side& other) {
    for (size_t i = other.verbs.size(); i-- > 0;) {
      OutlineVerb v = other.verbs[i];
      v.p = i == 0 ? other.start : other.verbs[i - 1].p;
      verbs.push_back(v);
    }
  }
};

// Where a join's inner side dips through the pivot P between two straight sides (D -> E, then
// B -> F), the dip is moved to X, where those two inner offset lines cross, when X lies in the
// half of each side next to the join: D -> E -> X -> B -> F. E and B stay (Chromium's edges end
// there, and their y snaps move the inner edges' ends), the returns E -> X and X -> B run back
// along the same lines, and only the doubly wound loop E, P, B, X is gone. Chromium's
// rasteriser resolves the winding span by span, so that loop adds nothing there, but ours
// integrates the winding number over a pixel before clamping it to 1 (kernels/stroke.cl), which
// made the pixels around a sharp join's inner corner too dark (join rows of stroke_agreement.py
// 44 -> 50 dB at 3 px). Curved sides keep their dip.
void cut_pivot_dips(Side& s, bool closed) {
  for (auto it = s.pivots.rbegin(); it != s.pivots.rend(); ++it) {
    const size_t k = *it;  // verbs[k] goes to the pivot, verbs[k + 1] back out to the next side
    const size_t n = s.verbs.size();
    if (k == 0 || k + 1 >= n) continue;
    const bool wraps = k + 2 == n;  // a closed side's last join: the next side is its first
    if (wraps && !closed) continue;
    const OutlineVerb& in = s.verbs[k - 1];
    const OutlineVerb& out = s.verbs[wraps ? 0 : k + 2];
    if (in.kind != OutlineVerb::Line || out.kind != OutlineVerb::Line) continue;
    const Vec2 d = k >= 2 ? s.verbs[k - 2].p : s.start, e = in.p;
    const Vec2 b = wraps ? s.start : s.verbs[k + 1].p, f = out.p;
    const Vec2 r = e - d, q = f - b;
    const double den = cross(r, q);
    if (std::fabs(den) <= 1e-12 * (dot(r, r) + dot(q, q))) continue;
    const double t = cross(b - d, q) / den, u = cross(b - d, r) / den;
    if (!(t >= 0.5 && t <= 1 && u >= 0 && u <= 0.5)) continue;
    s.verbs[k].p = d + t * r;
  }
  s.pivots.clear();
}

// One piece [t0, t1] of a cubic's side being fitted with a quadratic (Skia's SkQuadConstruct).
struct Piece {
  Vec2 q[3];             // the quadratic
  Vec2 tan0, tan1;       // a point along the offset tangent at q[0] and at q[2]
  double t0 = 0, tm = 0, t1 = 0;
  bool has0 = false, has1 = false;
  bool init(double a, double b) {
    t0 = a, tm = 0.5 * (a + b), t1 = b, has0 = has1 = false;
    return t0 < tm && tm < t1;
  }
};

enum class Fit { Split, Degenerate, Quad, Error };

class Stroker {
 public:
  Stroker(double radius, LineJoin join, LineCap cap, double miter_limit)
      : r_(radius), join_(join), cap_(cap) {
    if (join_ == LineJoin::Miter || join_ == LineJoin::MiterClip) {
      if (miter_limit <= 1) join_ = LineJoin::Bevel;
      else inv_miter_ = 1 / miter_limit;
    }
  }

  void move_to(Vec2 p) {
    if (segments_ > 0) finish(false, false);
    segments_ = 0;
    first_ = prev_ = p;
  }

  void line_to(Vec2 p) {
    if (degenerate(p - prev_)) return;
    Vec2 n, u;
    if (!pre_join(p, &n, &u, true)) return;
    outer_.line_to(p + n);
    inner_.line_to(p - n);
    post_join(p, n, u);
  }

  void cubic_to(Vec2 c1, Vec2 c2, Vec2 p3) {
    const Vec2 c[4] = {prev_, c1, c2, p3};
    const bool dab = degenerate(c1 - prev_), dbc = degenerate(c2 - c1), dcd = degenerate(p3 - c2);
    if (dab && dbc && dcd) return;
    // Straight (our lines are cubics with handles on the chord): a line, as Skia reduces it.
    if (dab + dbc + dcd == 2 || in_line(c)) return line_to(p3);
    Vec2 n, u;
    if (!pre_join(dab ? c2 : c1, &n, &u, false)) return line_to(p3);
    std::vector<double> ts = inflections(c);
    ts.push_back(1);
    double t0 = 0;
    for (double t1 : ts) {
      for (int side : {1, -1}) {
        side_ = side;
        found_tangents_ = false;
        depth_ = 0;
        Piece piece;
        piece.init(t0, t1);
        cubic_piece(c, piece);
      }
      t0 = t1;
    }
    // The end normal from the last handle (or the one before it when it is degenerate).
    Vec2 ab = c[1] - c[0], cd = c[3] - c[2];
    if (degenerate(ab)) ab = c[2] - c[0];
    if (degenerate(cd)) cd = c[3] - c[1];
    if (!degenerate(ab) && !degenerate(cd)) {
      u = normal_of((1 / len(cd)) * cd);
      n = r_ * u;
    }
    post_join(p3, n, u);
  }

  // A conic arc from the current point (browsers draw circles, ellipses and rounded corners
  // with conics): its sides are fitted with quadratics like a cubic's, without the first
  // stage that waits for the offset tangents to meet (Skia's conicStroke).
  void conic_to(Vec2 ctrl, Vec2 p2, double w) {
    const Vec2 c[4] = {prev_, ctrl, p2, p2};
    if (degenerate(ctrl - prev_) || degenerate(p2 - ctrl)) return line_to(p2);
    Vec2 n, u;
    if (!pre_join(ctrl, &n, &u, false)) return line_to(p2);
    conic_w_ = w;
    for (int side : {1, -1}) {
      side_ = side;
      found_tangents_ = true;
      depth_ = 0;
      Piece piece;
      piece.init(0, 1);
      cubic_piece(c, piece);
    }
    conic_w_ = 0;
    const Vec2 d = p2 - ctrl;
    u = normal_of((1 / len(d)) * d);
    post_join(p2, r_ * u, u);
  }

  void close_contour() { finish(true, prev_is_line_); }
  std::vector<OutlineContour> done() {
    finish(false, prev_is_line_);
    return std::move(out_);
  }

 private:
  // Skia's test for a cubic whose four points lie on one line.
  static bool in_line(const Vec2* c) {
    double best = -1;
    int o1 = 0, o2 = 1;
    for (int i = 0; i < 3; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const Vec2 d = c[j] - c[i];
        const double m = std::max(std::fabs(d.x), std::fabs(d.y));
        if (best < m) best = m, o1 = i, o2 = j;
      }
    const int m1 = (1 + (2 >> o2)) >> o1, m2 = o1 ^ o2 ^ m1;
    const double slop = best * best * 1e-5;
    return dist2_to_line(c[m1], c[o1], c[o2]) <= slop && dist2_to_line(c[m2], c[o1], c[o2]) <= slop;
  }

  // Parameters in (0, 1) where the cubic's curvature changes sign, ascending.
  static std::vector<double> inflections(const Vec2* c) {
    const Vec2 A = c[1] - c[0], B = c[2] - 2 * c[1] + c[0];
    const Vec2 C = c[3] + 3 * (c[1] - c[2]) - c[0];
    const double a = cross(B, C), b = cross(A, C), k = cross(A, B);
    std::vector<double> ts;
    auto keep = [&](double t) {
      if (t > 0 && t < 1 && (ts.empty() || ts.back() != t)) ts.push_back(t);
    };
    if (a == 0) {
      if (b != 0) keep(-k / b);
    } else {
      const double disc = b * b - 4 * a * k;
      if (disc >= 0) {
        const double s = std::sqrt(disc), q = -0.5 * (b + (b < 0 ? -s : s));
        double r0 = q / a, r1 = q != 0 ? k / q : r0;
        if (r0 > r1) std::swap(r0, r1);
        keep(r0);
        keep(r1);
      }
    }
    return ts;
  }

  // The point on the cubic at t and the side's offset point and a point along its tangent.
  bool offset_at(const Vec2* c, double t, Vec2* on_curve, Vec2* off, Vec2* tangent) const {
    Vec2 d = conic_w_ > 0 ? conic_tangent(c, conic_w_, t) : cubic_tangent(c, t);
    *on_curve = conic_w_ > 0 ? conic_at(c, conic_w_, t) : cubic_at(c, t);
    if (conic_w_ > 0 && d.x == 0 && d.y == 0) d = c[2] - c[0];
    if (d.x == 0 && d.y == 0) {
      if (std::fabs(t) <= kNearlyZero) d = c[2] - c[0];
      else if (std::fabs(1 - t) <= kNearlyZero) d = c[3] - c[1];
      else return false;
      if (d.x == 0 && d.y == 0) d = c[3] - c[0];
    }
    d = (r_ / len(d)) * d;
    *off = {on_curve->x + side_ * d.y, on_curve->y - side_ * d.x};
    if (tangent) *tangent = *off + d;
    return true;
  }

  bool piece_ends(const Vec2* c, Piece& p) const {
    Vec2 on;
    if (!p.has0 && !offset_at(c, p.t0, &on, &p.q[0], &p.tan0)) return false;
    p.has0 = true;
    if (!p.has1 && !offset_at(c, p.t1, &on, &p.q[2], &p.tan1)) return false;
    p.has1 = true;
    return true;
  }

  // Where the two offset tangents meet: the quadratic's control point (when set_control).
  Fit intersect(Piece& p, bool set_control) const {
    const Vec2 a = p.tan0 - p.q[0], b = p.tan1 - p.q[2];
    const double denom = cross(a, b);
    if (denom == 0 || !std::isfinite(denom)) return Fit::Degenerate;
    const Vec2 ab0 = p.q[0] - p.q[2];
    double na = cross(b, ab0);
    const double nb = cross(a, ab0);
    if ((na >= 0) == (nb >= 0)) {  // the tangents meet outside the piece's ends
      const double d1 = dist2_to_line(p.q[0], p.q[2], p.tan1);
      const double d2 = dist2_to_line(p.q[2], p.q[0], p.tan0);
      return std::max(d1, d2) <= kTol * kTol ? Fit::Degenerate : Fit::Split;
    }
    if (std::fabs(na) * kNearlyZero >= std::fabs(denom)) return Fit::Degenerate;
    if (set_control) {
      na /= denom;
      p.q[1] = lerp(p.q[0], p.tan0, na);
    }
    return Fit::Quad;
  }

  static bool sharp_angle(const Vec2* q) {
    Vec2 small = q[1] - q[0], large = q[1] - q[2];
    double ls = dot(small, small), ll = dot(large, large);
    if (ls > ll) std::swap(small, large), ll = ls;
    const double l = len(small);
    if (l == 0) return false;
    small = (std::sqrt(ll) / l) * small;
    return dot(small, large) > 0;
  }

  // Whether the quadratic q is within tolerance of the offset point `ray0` (ray1: on the curve).
  Fit close_enough(const Vec2* q, Vec2 ray0, Vec2 ray1) const {
    const Vec2 mid = quad_at(q, 0.5);
    if (dot(ray0 - mid, ray0 - mid) <= kTol * kTol) return sharp_angle(q) ? Fit::Split : Fit::Quad;
    const double xmin = std::min({q[0].x, q[1].x, q[2].x}), xmax = std::max({q[0].x, q[1].x, q[2].x});
    const double ymin = std::min({q[0].y, q[1].y, q[2].y}), ymax = std::max({q[0].y, q[1].y, q[2].y});
    if (ray0.x + kTol < xmin || ray0.x - kTol > xmax || ray0.y + kTol < ymin || ray0.y - kTol > ymax)
      return Fit::Split;
    // Where the ray from the curve through ray0 crosses the quadratic: exactly once, or split.
    const Vec2 v = ray1 - ray0;
    double rr[3];
    for (int i = 0; i < 3; ++i) rr[i] = (q[i].y - ray0.y) * v.x - (q[i].x - ray0.x) * v.y;
    const double A = rr[2] + rr[0] - 2 * rr[1], B = 2 * (rr[1] - rr[0]), C = rr[0];
    std::vector<double> roots;
    if (A == 0) {
      if (B != 0) roots.push_back(-C / B);
    } else {
      const double disc = B * B - 4 * A * C;
      if (disc >= 0) {
        const double s = std::sqrt(disc), qq = -0.5 * (B + (B < 0 ? -s : s));
        roots.push_back(qq / A);
        if (qq != 0) roots.push_back(C / qq);
      }
    }
    std::vector<double> in;
    for (double t : roots)
      if (t >= 0 && t <= 1 && (in.empty() || in.back() != t)) in.push_back(t);
    if (in.size() != 1) return Fit::Split;
    const Vec2 hit = quad_at(q, in[0]);
    const double err = kTol * (1 - std::fabs(in[0] - 0.5) * 2);
    if (dot(ray0 - hit, ray0 - hit) <= err * err) return sharp_angle(q) ? Fit::Split : Fit::Quad;
    return Fit::Split;
  }

  Side& side_path() { return side_ > 0 ? outer_ : inner_; }

  // Fits one piece of a cubic's side with quadratics, halving it until each is close enough.
  bool cubic_piece(const Vec2* c, Piece& p) {
    if (!found_tangents_) {
      if (!piece_ends(c, p)) return false;
      const Fit f = intersect(p, false);
      if (f != Fit::Quad) {
        Vec2 on, mid;
        const bool near = dot(p.q[0] - p.q[2], p.q[0] - p.q[2]) <= kTol * kTol;
        if ((f == Fit::Degenerate || near) && offset_at(c, p.tm, &on, &mid, nullptr) &&
            dist2_to_line(mid, p.q[0], p.q[2]) < kTol * kTol) {
          side_path().line_to(p.q[2]);
          return true;
        }
      } else {
        found_tangents_ = true;
      }
    }
    if (found_tangents_) {
      if (!piece_ends(c, p)) return false;
      Fit f = intersect(p, true);
      if (f == Fit::Quad) {
        Vec2 ray0, ray1;
        if (!offset_at(c, p.tm, &ray1, &ray0, nullptr)) return false;
        f = close_enough(p.q, ray0, ray1);
      }
      if (f == Fit::Quad) {
              side_path().quad_to(p.q[1], p.q[2]);
        return true;
      }
      if (f == Fit::Degenerate) {
        side_path().line_to(p.q[2]);
        return true;
      }
    }
    if (!std::isfinite(p.q[2].x) || !std::isfinite(p.q[2].y) || ++depth_ > kMaxDepth) return false;
    Piece half;
    if (!half.init(p.t0, p.tm)) {
      side_path().line_to(p.q[2]);
      return true;
    }
    half.q[0] = p.q[0], half.tan0 = p.tan0, half.has0 = true;
    if (!cubic_piece(c, half)) return false;
    if (!half.init(p.tm, p.t1)) {
      side_path().line_to(p.q[2]);
      return true;
    }
    half.q[2] = p.q[2], half.tan1 = p.tan1, half.has1 = true;
    if (!cubic_piece(c, half)) return false;
    --depth_;
    return true;
  }

  bool pre_join(Vec2 p, Vec2* n, Vec2* u, bool is_line) {
    const Vec2 d = p - prev_;
    const double l = len(d);
    if (l == 0 || !std::isfinite(l)) return false;
    *u = normal_of((1 / l) * d);
    *n = r_ * *u;
    if (segments_ == 0) {
      first_normal_ = *n, first_unit_ = *u, first_outer_ = prev_ + *n;
      outer_.move_to(first_outer_);
      inner_.move_to(prev_ - *n);
    } else {
      join(prev_unit_, prev_, *u, prev_is_line_, is_line);
    }
    prev_is_line_ = is_line;
    return true;
  }

  void post_join(Vec2 p, Vec2 n, Vec2 u) {
    prev_ = p, prev_unit_ = u, prev_normal_ = n;
    ++segments_;
  }

  static void inner_join(Side& inner, Vec2 pivot, Vec2 after) {
    inner.pivots.push_back(inner.verbs.size());
    inner.line_to(pivot);  // through the pivot, as Skia does
    inner.line_to(pivot - after);
  }

  // Unit arc from `from` to `to` turning clockwise on screen (cw) or not, as conics of at most
  // a quarter turn each, scaled by r_ around pivot (Skia's SkConic::BuildUnitArc).
  void arc(Side& s, Vec2 pivot, Vec2 from, Vec2 to, bool cw) const {
    double x = dot(from, to), y = cross(from, to);
    if (std::fabs(y) <= kNearlyZero && x > 0 && ((y >= 0 && cw) || (y <= 0 && !cw))) return;
    if (!cw) y = -y;
    int quadrant = 0;
    if (y == 0) quadrant = 2;
    else if (x == 0) quadrant = y > 0 ? 1 : 3;
    else {
      if (y < 0) quadrant += 2;
      if ((x < 0) != (y < 0)) quadrant += 1;
    }
    static const Vec2 qp[] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
    const double w45 = std::sqrt(0.5);
    // Unit frame: from = (1, 0); y flipped for counter-clockwise turns.
    auto place = [&](Vec2 v) {
      const double vy = cw ? v.y : -v.y;
      return pivot + r_ * Vec2{from.x * v.x - from.y * vy, from.y * v.x + from.x * vy};
    };
    for (int i = 0; i < quadrant; ++i) s.conic_to(place(qp[2 * i + 1]), place(qp[2 * i + 2]), w45);
    const Vec2 fin{x, y}, lastq = qp[2 * quadrant % 8];
    const double d = dot(lastq, fin);
    if (d < 1) {
      Vec2 off = lastq + fin;
      const double cos_half = std::sqrt((1 + d) / 2);
      off = (1 / (cos_half * len(off))) * off;
      if (!(std::fabs(off.x - lastq.x) <= kNearlyZero && std::fabs(off.y - lastq.y) <= kNearlyZero))
        s.conic_to(place(off), place(fin), cos_half);
    }
  }

  // The join at pivot from unit normal `before` to unit normal `after` (Skia's joiners).
  void join(Vec2 before, Vec2 pivot, Vec2 after, bool prev_line, bool curr_line) {
    const double dp = dot(before, after);
    const bool nearly_line = dp >= 0 && std::fabs(1 - dp) <= kNearlyZero;
    const bool nearly_180 = dp < 0 && std::fabs(1 + dp) <= kNearlyZero;
    Side* outer = &outer_;
    Side* inner = &inner_;
    const bool cw = before.x * after.y > before.y * after.x;
    if (join_ == LineJoin::Bevel) {
      Vec2 a = r_ * after;
      if (!cw) std::swap(outer, inner), a = -1 * a;
      outer->line_to(pivot + a);
      return inner_join(*inner, pivot, a);
    }
    if (nearly_line) return;
    if (join_ == LineJoin::Round) {
      Vec2 b = before, a = after;
      if (!cw) std::swap(outer, inner), b = -1 * b, a = -1 * a;
      const size_t before_count = outer->verbs.size();
      arc(*outer, pivot, b, a, cw);
      if (outer->verbs.size() > before_count) inner_join(*inner, pivot, r_ * a);
      return;
    }
    // Miter (and miter-clip, which Skia's SVG path draws as miter).
    Vec2 b = before, a = after, mid;
    if (nearly_180) {
      a = r_ * a;
      outer->line_to(pivot + a);
      return inner_join(*inner, pivot, a);
    }
    if (!cw) std::swap(outer, inner), b = -1 * b, a = -1 * a;
    bool miter = false;
    if (dp == 0 && inv_miter_ <= std::sqrt(0.5)) {
      mid = r_ * (b + a);
      miter = true;
    } else {
      const double sin_half = std::sqrt(0.5 * (1 + dp));
      if (sin_half >= inv_miter_) {
        mid = dp < 0 ? Vec2{a.y - b.y, b.x - a.x} : b + a;
        if (dp < 0 && !cw) mid = -1 * mid;
        mid = (r_ / sin_half / len(mid)) * mid;
        miter = true;
      } else {
        curr_line = false;
      }
    }
    if (miter) {
      if (prev_line) outer->set_last(pivot + mid);
      else outer->line_to(pivot + mid);
    }
    a = r_ * a;
    if (!curr_line) outer->line_to(pivot + a);
    inner_join(*inner, pivot, a);
  }

  // The cap at `pivot` whose side normal is n, from the outer side to `stop`.
  void add_cap(Side& s, Vec2 pivot, Vec2 n, Vec2 stop, bool other_is_line) const {
    const Vec2 par{-n.y, n.x};  // n turned a quarter clockwise on screen
    if (cap_ == LineCap::Butt) return s.line_to(stop);
    if (cap_ == LineCap::Square) {
      if (other_is_line) {
        s.set_last(pivot + n + par);
        s.line_to(pivot - n + par);
      } else {
        s.line_to(pivot + n + par);
        s.line_to(pivot - n + par);
        s.line_to(stop);
      }
      return;
    }
    const Vec2 centre = pivot + par;  // two quarter circles of weight cos(45 degrees)
    s.conic_to(centre + n, centre, std::sqrt(0.5));
    s.conic_to(centre - n, stop, std::sqrt(0.5));
  }

  void emit(const Side& s) { out_.push_back({s.start, s.verbs}); }

  void finish(bool close, bool curr_line) {
    if (segments_ > 0) {
      if (close) join(prev_unit_, prev_, first_unit_, prev_is_line_, curr_line);
      cut_pivot_dips(outer_, close);  // a left turn's inner side is the outer_ one
      cut_pivot_dips(inner_, close);
      if (close) {
        emit(outer_);
        Side rev;
        rev.move_to(inner_.last());
        rev.reverse_append(inner_);
        emit(rev);
      } else {
        Side s = outer_;
        add_cap(s, prev_, prev_normal_, inner_.last(), curr_line);
        s.reverse_append(inner_);
        add_cap(s, first_, -1 * first_normal_, first_outer_, prev_is_line_);
        emit(s);
      }
    }
    inner_ = Side{};
    outer_ = Side{};
    segments_ = -1;
  }

  double r_;
  LineJoin join_;
  LineCap cap_;
  double inv_miter_ = 0;
  Vec2 first_normal_, prev_normal_, first_unit_, prev_unit_, first_, prev_, first_outer_;
  int segments_ = -1;
  bool prev_is_line_ = false;
  int side_ = 1, depth_ = 0;
  bool found_tangents_ = false;
  double conic_w_ = 0;  // the weight while stroking a conic, 0 for a cubic
  Side outer_, inner_;
  std::vector<OutlineContour> out_;
};

}  // namespace

// Every affine image of a quarter ellipse keeps its end tangents' meeting point as its conic
// control point.
bool quarter_arc_conic(const Vec2* q, Vec2* ctrl) {
  const Vec2 a = q[1] - q[0], b = q[2] - q[3];
  const double den = cross(a, b);
  if (std::fabs(den) <= 1e-9 * (dot(a, a) + dot(b, b))) return false;
  const double s = cross(q[3] - q[0], b) / den;
  if (!(s > 0)) return false;
  *ctrl = q[0] + s * a;
  return true;
}

std::vector<OutlineContour> browser_stroke_outline(const Path& path, const Affine& view) {
  if (!path.has_stroke) return {};
  const double radius = 0.5 * path.stroke.width * view.mean_scale();
  if (!(radius > 0)) return {};
  Stroker st(radius, path.stroke.join, path.stroke.cap, path.stroke.miter_limit);
  // Browsers draw these shapes' curves as quarter-ellipse conics (Chromium's drawOval and
  // drawRRect); our reader made each quarter one cubic. A path's own curves stay cubics.
  const bool arcs = path.tag == "circle" || path.tag == "ellipse" || path.tag == "rect";
  for (const Subpath& sp : path.subpaths) {
    if (sp.points.empty()) continue;
    std::vector<Vec2> px(sp.points.size());
    for (size_t i = 0; i < px.size(); ++i) px[i] = view.apply(sp.points[i]);
    st.move_to(px[0]);
    for (size_t c = 0; c < sp.segment_count(); ++c) {
      const Vec2* q = &px[3 * c];
      Vec2 ctrl;
      if (arcs && quarter_arc_conic(q, &ctrl)) st.conic_to(ctrl, q[3], std::sqrt(0.5));
      else st.cubic_to(q[1], q[2], q[3]);
    }
    if (sp.closed) {
      st.line_to(px[0]);  // the closing line SVG implies (nothing when already there)
      st.close_contour();
    }
  }
  return st.done();
}

}  // namespace svgm
