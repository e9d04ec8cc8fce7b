// The double-precision CPU reference of the rasteriser (see raster_ref.h).
#include "raster/raster_ref.h"
#include "raster/stroke_geometry_ref.h"

#include <algorithm>
#include <cmath>

namespace svgm::ref {

namespace {

using namespace stroke_geom;

// The stroke of one subpath, mirroring stroke.cl line by line in meaning (see its essay).
class SubpathStroker {
 public:
  SubpathStroker(const StrokeSubpath& s, const P2* p, const uint8_t* kinds)
      : s_(s), p_(p), kinds_(kinds), N_(s.vertex_count), S_(s.closed ? N_ : std::max(N_ - 1, 1)) {}

  void emit(P2* w) {
    const double h = s_.half_width;
    const int J = s_.join_points;
    P2 X0, X1;
    bool x0 = inner_point(0, 1.0, &X0), x1 = false;
    P2 d = dir(0);
    for (int i = 0; i < S_; ++i) {
      const P2 n = perp(d), pi = p_[i], qi = p_[(i + 1) % N_];
      x1 = inner_point(i + 1, 1.0, &X1);
      *w++ = x0 ? X0 : pi + h * n;
      *w++ = x1 ? X1 : qi + h * n;
      if (i + 1 < S_ || s_.closed) {
        const P2 dn = dir((i + 1) % S_);
        join(w, 1.0, qi, d, dn, kinds_[(i + 1) % N_], false, x1, X1);
        w += J;
        d = dn;
      }
      x0 = x1;
      X0 = X1;
    }
    if (!s_.closed) {
      cap(w, p_[S_ % N_], dir(S_ - 1));
      w += s_.cap_points;
    }
    d = dir(S_ - 1);
    x1 = inner_point(S_, -1.0, &X1);
    for (int i = S_ - 1; i >= 0; --i) {
      const P2 n = perp(d), pi = p_[i], qi = p_[(i + 1) % N_];
      x0 = inner_point(i, -1.0, &X0);
      if (s_.closed) {
        join(w, -1.0, qi, d, dir((i + 1) % S_), kinds_[(i + 1) % N_], true, x1, X1);
        w += J;
      }
      *w++ = x1 ? X1 : qi - h * n;
      *w++ = x0 ? X0 : pi - h * n;
      if (i > 0) {
        const P2 dp = dir(i - 1);
        if (!s_.closed) {
          join(w, -1.0, pi, dp, d, kinds_[i], true, x0, X0);
          w += J;
        }
        d = dp;
      }
      x1 = x0;
      X1 = X0;
    }
    if (!s_.closed) cap(w, p_[0], -1.0 * dir(0));
  }

 private:
  P2 dir(int i) const { return seg_dir(p_, N_, S_, s_.closed, i); }

  // The inner join point X of vertex v on `side` (stroke.cl's inner_point).
  bool inner_point(int v, double side, P2* X) const {
    if (!s_.closed && (v == 0 || v >= S_)) return false;
    const int a = (v + S_ - 1) % S_, b = v % S_;
    const P2 da = dir(a), db = dir(b);
    const double turn = cross(da, db), c = dot(da, db);
    if (side * turn <= 0 || 1 + c < 1e-6) return false;
    const double t = s_.half_width * std::fabs(turn) / (1 + c);
    const P2 ea = p_[(a + 1) % N_] - p_[a], eb = p_[(b + 1) % N_] - p_[b];
    if (t > 0.5 * std::min(std::sqrt(dot(ea, ea)), std::sqrt(dot(eb, eb)))) return false;
    *X = p_[b] + side * s_.half_width * (perp(da) + perp(db)) / (1 + c);
    return true;
  }

  void join(P2* out, double side, P2 pivot, P2 da, P2 db, int kind, bool rev, bool has_x,
            P2 X) const {
    const int J = s_.join_points;
    const double h = s_.half_width;
    const P2 na = side * perp(da), nb = side * perp(db);
    const double turn = cross(da, db);
    const P2 A = pivot + h * na, B = pivot + h * nb;
    for (int j = 0; j < J; ++j) {
      P2 q;
      if (side * turn > 0) {
        q = has_x ? X : pivot;
      } else {
        const double c = dot(na, nb);
        const double half_cos = std::sqrt(std::max(0.5 * (1 + c), 0.0));
        const double limit = kind == kJoinInterior ? 4.0 : s_.miter_limit;
        const bool fits = half_cos * limit >= 1.0 && 1 + c > 1e-6;
        const P2 M = pivot + h * (na + nb) / std::max(1 + c, 1e-6);
        if (kind == kJoinRound) {
          q = pivot + h * rotate(na, std::atan2(cross(na, nb), c) * (j + 1) / (J + 1));
        } else if (kind == kJoinBevel) {
          q = A;
        } else if (fits) {
          q = M;
        } else if (kind == kJoinMiterClip && 1 + c > 1e-6) {
          const double a_proj = h * half_cos, m_proj = h / half_cos;
          const double t = (limit * h - a_proj) / (m_proj - a_proj);
          q = j == 0 ? A + t * (M - A) : B + t * (M - B);
        } else {
          q = A;
        }
      }
      out[rev ? J - 1 - j : j] = q;
    }
  }

  void cap(P2* out, P2 e, P2 d) const {
    const P2 n = perp(d);
    const double h = s_.half_width;
    for (int j = 0; j < s_.cap_points; ++j) {
      if (s_.cap == kCapSquare) {
        out[j] = e + h * d + (j == 0 ? h * n : -h * n);
      } else {
        const double phi = M_PI * (j + 1) / (s_.cap_points + 1);
        out[j] = e + h * (std::cos(phi) * n + std::sin(phi) * d);
      }
    }
  }

  const StrokeSubpath& s_;
  const P2* p_;
  const uint8_t* kinds_;
  int N_, S_;
};

// Signed area of a closed polygon clipped to the square [x0, x0+1] x [y0, y0+1]
// (Sutherland-Hodgman against four half-planes, then the shoelace formula). For a
// self-intersecting polygon this is the integral of its winding number over the square.
double clipped_area(const std::vector<P2>& poly, double x0, double y0) {
  std::vector<P2> a = poly, b;
  auto clip = [&](auto inside, auto intersect) {
    b.clear();
    for (size_t i = 0; i < a.size(); ++i) {
      const P2 cur = a[i], prev = a[(i + a.size() - 1) % a.size()];
      const bool ci = inside(cur), pi = inside(prev);
      if (ci) {
        if (!pi) b.push_back(intersect(prev, cur));
        b.push_back(cur);
      } else if (pi) {
        b.push_back(intersect(prev, cur));
      }
    }
    std::swap(a, b);
  };
  auto at_x = [](double X) {
    return [X](P2 p, P2 q) { return P2{X, p.y + (q.y - p.y) * (X - p.x) / (q.x - p.x)}; };
  };
  auto at_y = [](double Y) {
    return [Y](P2 p, P2 q) { return P2{p.x + (q.x - p.x) * (Y - p.y) / (q.y - p.y), Y}; };
  };
  clip([&](P2 p) { return p.x >= x0; }, at_x(x0));
  if (a.empty()) return 0;
  clip([&](P2 p) { return p.x <= x0 + 1; }, at_x(x0 + 1));
  if (a.empty()) return 0;
  clip([&](P2 p) { return p.y >= y0; }, at_y(y0));
  if (a.empty()) return 0;
  clip([&](P2 p) { return p.y <= y0 + 1; }, at_y(y0 + 1));
  double s = 0;
  for (size_t i = 0; i < a.size(); ++i) s += cross(a[i], a[(i + 1) % a.size()]);
  return 0.5 * s;
}

}  // namespace

std::vector<double> flatten(const RasterPlan& plan, const std::vector<double>& cp) {
  std::vector<double> pts(static_cast<size_t>(plan.n_pts) * 2, 0.0);
  for (int v = 0; v < plan.n_flat; ++v) {
    const int c = plan.vert_cp[v];
    for (int j = 0; j < 4; ++j) {
      const double w = plan.vert_w[4 * v + j];
      pts[2 * v] += w * cp[2 * (c + j)];
      pts[2 * v + 1] += w * cp[2 * (c + j) + 1];
    }
  }
  return pts;
}

void stroke(const RasterPlan& plan, std::vector<double>& pts) {
  P2* P = reinterpret_cast<P2*>(pts.data());
  for (const StrokeSubpath& s : plan.strokes)
    SubpathStroker(s, P + s.first_vertex, plan.vert_join.data() + s.first_vertex)
        .emit(P + s.first_out);
}

std::vector<double> winding_integrals(const RasterPlan& plan, const std::vector<double>& pts,
                                      int draw) {
  const Draw& d = plan.draws[draw];
  const P2* P = reinterpret_cast<const P2*>(pts.data());
  std::vector<double> a(static_cast<size_t>(plan.width) * plan.height, 0.0);
  // Lines of a draw come as consecutive closed contours (raster_plan.cpp's add_contour).
  int j = d.first_line;
  const int end = d.first_line + d.line_count;
  while (j < end) {
    std::vector<P2> poly;
    const int start_point = plan.line_ab[2 * j];
    do {
      poly.push_back(P[plan.line_ab[2 * j]]);
      ++j;
    } while (plan.line_ab[2 * (j - 1) + 1] != start_point);
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const P2& q : poly) {
      x0 = std::min(x0, q.x); x1 = std::max(x1, q.x);
      y0 = std::min(y0, q.y); y1 = std::max(y1, q.y);
    }
    // Outside its bounding box a closed contour has winding number 0: only the box is visited.
    const int px0 = std::max(0, static_cast<int>(std::floor(x0)));
    const int px1 = std::min(plan.width - 1, static_cast<int>(std::floor(x1)));
    const int py0 = std::max(0, static_cast<int>(std::floor(y0)));
    const int py1 = std::min(plan.height - 1, static_cast<int>(std::floor(y1)));
    for (int y = py0; y <= py1; ++y)
      for (int x = px0; x <= px1; ++x)
        a[static_cast<size_t>(y) * plan.width + x] += clipped_area(poly, x, y);
  }
  return a;
}

double fill_rule_coverage(double a, int rule) {
  if (rule == kRuleEvenOdd) return std::min(std::fabs(a - 2.0 * std::nearbyint(0.5 * a)), 1.0);
  return std::min(std::fabs(a), 1.0);
}

std::vector<double> raster(const RasterPlan& plan, const std::vector<double>& pts) {
  std::vector<double> img(static_cast<size_t>(plan.width) * plan.height * 4, 0.0);
  for (size_t di = 0; di < plan.draws.size(); ++di) {
    const Draw& d = plan.draws[di];
    const auto a = winding_integrals(plan, pts, static_cast<int>(di));
    const size_t image = static_cast<size_t>(plan.width) * plan.height * 4;
    for (size_t p = 0; p < a.size(); ++p) {
      const float* col = d.paint >= 0 ? &plan.paint[d.paint * image + 4 * p] : d.rgba;
      const double alpha = fill_rule_coverage(a[p], d.rule) * col[3];
      for (int c = 0; c < 4; ++c) {
        const double src = (c < 3 ? col[c] : 1.0) * alpha;
        img[4 * p + c] = src + img[4 * p + c] * (1.0 - alpha);
      }
    }
  }
  return img;
}

std::vector<double> render(const RasterPlan& plan, const std::vector<double>& cp) {
  auto pts = flatten(plan, cp);
  stroke(plan, pts);
  return raster(plan, pts);
}

}  // namespace svgm::ref
