// The double-precision reference of the stroke backward pass (see stroke_backward_ref.h and the
// essay of kernels/stroke_backward.cl). It mirrors the kernel function by function; the branch
// tests are copied from raster_ref.cpp's SubpathStroker (the forward reference).
#include "raster/stroke_backward_ref.h"
#include "raster/stroke_geometry_ref.h"

#include <algorithm>
#include <cmath>

namespace svgm::ref {

namespace {

using namespace stroke_geom;
P2 perp_t(P2 g) { return {g.y, -g.x}; }  // perp(d) . g == d . perp_t(g)

// A direction after inheritance and the valid segment it is the direction of (-1: constant +x).
struct Dir {
  P2 d{1, 0};
  int src = -1;
};

// Y = sh (perp(da) + perp(db)) / (1 + c), c = da . db: adds dY/d(da, db)^T g.
void miter_vec_backward(P2 da, P2 db, double sh, P2 g, P2* gda, P2* gdb) {
  const double inv = 1.0 / (1.0 + dot(da, db));
  const P2 u = perp(da) + perp(db);
  const P2 gu = perp_t(sh * inv * g);
  const double gc = -sh * inv * inv * dot(g, u);
  *gda += gu + gc * db;
  *gdb += gu + gc * da;
}

class SubpathBackward {
 public:
  SubpathBackward(const StrokeSubpath& s, const P2* p, const uint8_t* kinds, const P2* go, P2* gp)
      : s_(s), p_(p), kinds_(kinds), go_(go), gp_(gp), N_(s.vertex_count),
        S_(s.closed ? N_ : std::max(N_ - 1, 1)) {}

  void run() {
    const int J = s_.join_points, N = N_, S = S_;
    const bool closed = s_.closed != 0;
    const P2* go = go_;
    bool x0 = has_x(0, 1.0), x1 = false;
    for (int i = 0; i < S; ++i) {
      const Dir d = dir(i);
      x1 = has_x(i + 1, 1.0);
      point_backward(go[0], x0, i, 1.0, i, d);
      point_backward(go[1], x1, i + 1, 1.0, (i + 1) % N, d);
      go += 2;
      if (i + 1 < S || closed) {
        join_backward(go, 1.0, (i + 1) % N, d, dir((i + 1) % S), kinds_[(i + 1) % N], false, x1);
        go += J;
      }
      x0 = x1;
    }
    if (!closed) {
      cap_backward(go, S % N, dir(S - 1), 1.0);
      go += s_.cap_points;
    }
    x1 = has_x(S, -1.0);
    for (int i = S - 1; i >= 0; --i) {
      const Dir d = dir(i);
      x0 = has_x(i, -1.0);
      if (closed) {
        join_backward(go, -1.0, (i + 1) % N, d, dir((i + 1) % S), kinds_[(i + 1) % N], true, x1);
        go += J;
      }
      point_backward(go[0], x1, i + 1, -1.0, (i + 1) % N, d);
      point_backward(go[1], x0, i, -1.0, i, d);
      go += 2;
      if (i > 0 && !closed) {
        join_backward(go, -1.0, i, dir(i - 1), d, kinds_[i], true, x0);
        go += J;
      }
      x1 = x0;
    }
    if (!closed) cap_backward(go, 0, dir(0), -1.0);
  }

  void branches(StrokeBranches& b) const {
    const int N = N_, S = S_;
    const double h = s_.half_width;
    auto margin = [&](double m) { b.margin = std::min(b.margin, std::fabs(m)); };
    for (int j = 0; j < S; ++j) {
      const P2 v = p_[(j + 1) % N] - p_[j];
      const double l2 = dot(v, v);
      if (l2 > 0) margin(std::sqrt(l2) - std::sqrt(kDegenerateLen2));
      if (src(j) != j) ++b.inherited;
    }
    if (src(0) < 0) ++b.dots;
    if (!s_.closed) {
      const int C = s_.cap_points;
      if (s_.cap == kCapSquare && C > 0) b.square_caps += 2;
      if (s_.cap == kCapRound && C > 0) b.round_caps += 2;
    }
    // Join vertices: every vertex of a closed subpath, the interior ones of an open one.
    for (int v = s_.closed ? 0 : 1; v < S; ++v) {
      const int a = (v + S - 1) % S, bb = v % S;
      const Dir da = dir(a), db = dir(bb);
      const int kind = kinds_[v % N];
      if (da.src == db.src) {
        b.straight += 2;
        continue;
      }
      const double turn = cross(da.d, db.d), c = dot(da.d, db.d);
      margin(turn);
      margin(1 + c - 1e-6);
      for (const double side : {1.0, -1.0}) {
        if (side * turn > 0) {
          const double t = h * std::fabs(turn) / (1 + c);
          const double la = std::sqrt(dot(p_[(a + 1) % N] - p_[a], p_[(a + 1) % N] - p_[a]));
          const double lb = std::sqrt(dot(p_[(bb + 1) % N] - p_[bb], p_[(bb + 1) % N] - p_[bb]));
          margin(t - 0.5 * std::min(la, lb));
          ++(t > 0.5 * std::min(la, lb) ? b.inner_pivot : b.inner_x);
        } else if (kind == kJoinRound) {
          ++b.round;
        } else if (kind == kJoinBevel) {
          ++b.bevel;
        } else {
          const double half_cos = std::sqrt(std::max(0.5 * (1 + c), 0.0));
          const double limit = kind == kJoinInterior ? 4.0 : s_.miter_limit;
          margin(half_cos * limit - 1.0);
          if (half_cos * limit >= 1.0)
            ++b.miter;
          else if (kind == kJoinMiterClip)
            ++b.miter_clip;
          else
            ++b.miter_over;
        }
      }
    }
  }

 private:
  int src(int i) const { return seg_src(p_, N_, S_, s_.closed, i); }

  Dir dir(int i) const {
    Dir r;
    r.src = src(i);
    if (r.src >= 0) seg_valid(p_, N_, r.src, &r.d);
    return r;
  }

  // Normalisation backward: gd on a direction goes to its source segment's end points.
  void dir_backward(const Dir& sd, P2 gd) {
    if (sd.src < 0) return;
    const int j = sd.src, j1 = (sd.src + 1) % N_;
    const P2 v = p_[j1] - p_[j];
    const double r = 1.0 / std::sqrt(dot(v, v));
    const P2 d = r * v;
    const P2 gv = r * (gd - dot(d, gd) * d);
    gp_[j1] += gv;
    gp_[j] -= gv;
  }

  // Whether the forward's inner_point(v, side) applies (its tests, verbatim).
  bool has_x(int v, double side) const {
    if (!s_.closed && (v == 0 || v >= S_)) return false;
    const int a = (v + S_ - 1) % S_, b = v % S_;
    const P2 da = dir(a).d, db = dir(b).d;
    const double turn = cross(da, db), c = dot(da, db);
    if (side * turn <= 0 || 1 + c < 1e-6) return false;
    const double t = s_.half_width * std::fabs(turn) / (1 + c);
    const P2 ea = p_[(a + 1) % N_] - p_[a], eb = p_[(b + 1) % N_] - p_[b];
    return !(t > 0.5 * std::min(std::sqrt(dot(ea, ea)), std::sqrt(dot(eb, eb))));
  }

  // An offset end point: X of vertex v on `side` if it applies, else p[idx] + side h perp(d).
  void point_backward(P2 g, bool x, int v, double side, int idx, const Dir& d) {
    const double h = s_.half_width;
    if (x) {
      const int a = (v + S_ - 1) % S_, b = v % S_;
      const Dir da = dir(a), db = dir(b);
      P2 gda, gdb;
      miter_vec_backward(da.d, db.d, side * h, g, &gda, &gdb);
      gp_[b] += g;
      dir_backward(da, gda);
      dir_backward(db, gdb);
    } else {
      gp_[idx] += g;
      dir_backward(d, side * h * perp_t(g));
    }
  }

  void join_backward(const P2* go, double side, int piv, const Dir& sa, const Dir& sb, int kind,
                     bool rev, bool x) {
    const int J = s_.join_points;
    const double h = s_.half_width;
    const P2 da = sa.d, db = sb.d;
    const P2 na = side * perp(da), nb = side * perp(db);
    const double turn = cross(da, db);
    P2 gpiv, gda, gdb;
    if (side * turn > 0) {
      for (int j = 0; j < J; ++j) gpiv += go[j];
      if (x) miter_vec_backward(da, db, side * h, gpiv, &gda, &gdb);
    } else {
      const double c = dot(na, nb);
      const double half_cos = std::sqrt(std::max(0.5 * (1 + c), 0.0));
      const double limit = kind == kJoinInterior ? 4.0 : s_.miter_limit;
      const bool fits = half_cos * limit >= 1.0 && 1 + c > 1e-6;
      for (int j = 0; j < J; ++j) {
        const P2 g = go[rev ? J - 1 - j : j];
        gpiv += g;
        if (kind == kJoinRound) {
          const double y = cross(na, nb);
          const double f = static_cast<double>(j + 1) / (J + 1);
          const double phi = std::atan2(y, c) * f;
          const P2 r = rotate(na, phi);
          gda += side * perp_t(h * rotate(g, -phi));
          const double gsw = f * h * dot(g, perp(r));
          const double r2 = c * c + y * y;
          const double gy = gsw * c / r2, gx = -gsw * y / r2;
          gda += gy * perp_t(db) + gx * db;
          gdb += gy * perp(da) + gx * da;
        } else if (kind == kJoinBevel) {
          gda += side * h * perp_t(g);
        } else if (fits) {
          miter_vec_backward(da, db, side * h, g, &gda, &gdb);
        } else if (kind == kJoinMiterClip && 1 + c > 1e-6) {
          const double a_proj = h * half_cos, m_proj = h / half_cos;
          const double den = m_proj - a_proj;
          const double t = (limit * h - a_proj) / den;
          const P2 ne = j == 0 ? na : nb;  // the clipped edge starts at pivot + h ne
          const P2 gE = (1 - t) * g;
          (j == 0 ? gda : gdb) += side * h * perp_t(gE);
          miter_vec_backward(da, db, side * h, t * g, &gda, &gdb);
          if (den > 0) {
            const P2 m_minus_e = h * (na + nb) / (1 + c) - h * ne;
            const double gt = dot(g, m_minus_e);
            const double dt_dhc =
                (-h * den + (limit * h - a_proj) * h * (1 + 1 / (half_cos * half_cos))) /
                (den * den);
            const double gc = gt * dt_dhc * 0.25 / half_cos;
            gda += gc * db;
            gdb += gc * da;
          }
        } else {
          gda += side * h * perp_t(g);
        }
      }
    }
    gp_[piv] += gpiv;
    dir_backward(sa, gda);
    dir_backward(sb, gdb);
  }

  // emit_cap at vertex e with direction sign * sd.d.
  void cap_backward(const P2* go, int e, const Dir& sd, double sign) {
    const int C = s_.cap_points;
    const double h = s_.half_width;
    P2 ge, gd;
    for (int j = 0; j < C; ++j) {
      const P2 g = go[j];
      ge += g;
      if (s_.cap == kCapSquare) {
        gd += h * g + (j == 0 ? h : -h) * perp_t(g);
      } else {
        const double phi = M_PI * (j + 1) / (C + 1);
        gd += h * (std::cos(phi) * perp_t(g) + std::sin(phi) * g);
      }
    }
    gp_[e] += ge;
    dir_backward(sd, sign * gd);
  }

  const StrokeSubpath& s_;
  const P2* p_;
  const uint8_t* kinds_;
  const P2* go_;
  P2* gp_;
  int N_, S_;
};

}  // namespace

void stroke_backward(const RasterPlan& plan, const std::vector<double>& pts,
                     std::vector<double>& grad_pts) {
  const P2* P = reinterpret_cast<const P2*>(pts.data());
  P2* G = reinterpret_cast<P2*>(grad_pts.data());
  for (const StrokeSubpath& s : plan.strokes)
    SubpathBackward(s, P + s.first_vertex, plan.vert_join.data() + s.first_vertex,
                    G + s.first_out, G + s.first_vertex)
        .run();
}

StrokeBranches stroke_branches(const RasterPlan& plan, const std::vector<double>& pts) {
  StrokeBranches b;
  const P2* P = reinterpret_cast<const P2*>(pts.data());
  for (const StrokeSubpath& s : plan.strokes)
    SubpathBackward(s, P + s.first_vertex, plan.vert_join.data() + s.first_vertex, nullptr,
                    nullptr)
        .branches(b);
  return b;
}

}  // namespace svgm::ref
