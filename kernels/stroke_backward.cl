/* stroke_backward.cl: the vector-Jacobian product of stroke expansion (stroke.cl).
 *
 * Given g_k = dL/d(outline point k) for every point the forward `stroke` wrote, this adds
 * dL/d(p_j) = sum_k J_kj^T g_k to every polyline vertex p_j. Half widths, miter limits, join
 * kinds and caps are constants. The forward is piecewise smooth; on the branch the current
 * geometry selects (inner X or pivot, miter within the limit or not, which segment a
 * degenerate one inherits its direction from, ...) its Jacobian is that branch's derivative,
 * and the branch is decided by the very same code as the forward (seg_valid, inner_point), so
 * forward and backward never disagree about it.
 *
 * Every outline point is a function of a pivot vertex p and one or two unit directions
 * d = dir(i), and every direction is the normalised vector of ONE valid segment, its source
 * src(i): segment i itself, or for a degenerate segment the one seg_dir finds (no source at
 * all for a dot's constant +x). So the backward of a point splits into "g to the pivot" plus
 * "gd to a direction", and a direction's gradient goes to its source segment's endpoints:
 *
 *   Normalisation. d = v / |v|, v = q - p:  dd/dv = (I - d d^T) / |v|  (symmetric), so
 *     g_v = (gd - d (d . gd)) / |v|,   g_q += g_v,   g_p -= g_v.
 *   Only valid segments (|v|^2 > DEGENERATE_LEN2) are ever sources, so this never divides by
 *   zero; a degenerate segment itself gets nothing (its direction does not depend on it).
 *
 *   Perpendicular. perp(d) = (-d.y, d.x) = R d with R the +90 degree rotation, so the adjoint
 *     is R^T g = (g.y, -g.x) = perp_t(g) = -perp(g).
 *
 *   Offset point. P = p + s h perp(d):  g_p += g,  gd += s h perp_t(g).
 *
 *   Miter vector (inner point X and the miter point M share it). With c = da . db,
 *     Y = p + s h (perp(da) + perp(db)) / (1 + c)   (for M: na + nb = s (perp(da) + perp(db)),
 *     and na . nb = da . db):
 *       g_p += g,  with u = perp(da) + perp(db), w = s h / (1 + c):
 *       gda += perp_t(w g) - (w / (1 + c)) (g . u) db,   gdb += perp_t(w g) - (...) da.
 *     Both are used only when 1 + c > 1e-6 (the forward's own guard), so the division is safe.
 *
 *   Bevel point / fallback. A = p + s h perp(da): g_p += g, gda += s h perp_t(g).
 *
 *   Round join. q = p + h rot(na, phi), phi = f sweep, f = (j + 1) / (J + 1),
 *     sweep = atan2(y, x), y = cross(da, db) (= cross(na, nb)), x = da . db. Then
 *       d rot(v, phi) / dv = Rot(phi)        -> gna = h Rot(-phi) g,  gda += s perp_t(gna);
 *       d rot(v, phi) / dphi = perp(rot(v, phi))  -> g_sweep = f h g . perp(rot(na, phi));
 *       d atan2(y, x) = (x dy - y dx) / (x^2 + y^2),  dy/dda = perp_t(db), dy/ddb = perp(da),
 *       dx/dda = db, dx/ddb = da. x^2 + y^2 = |da|^2 |db|^2 ~ 1, never zero.
 *     atan2 jumps at y = 0, x < 0 (a full reversal): a branch switch like the others.
 *
 *   Clipped miter (miter-clip beyond its limit L). hc = sqrt((1 + c) / 2) (cos of half the turn),
 *     a = h hc, m = h / hc, t = (L h - a) / (m - a), and q = (1 - t) E + t M with E = A for the
 *     first point, B = p + s h perp(db) for the others. So
 *       g_p += g;  E's part gets (1 - t) g, M's part t g (both as above);
 *       g_t = g . (M - E),  dt/dhc = (-h (m - a) + (L h - a) h (1 + 1 / hc^2)) / (m - a)^2,
 *       dhc/dc = 1 / (4 hc),  gda += g_c db,  gdb += g_c da.
 *     m - a > 0 whenever hc < 1, which holds here for any limit L >= 1 (hc = 1 fits); for an
 *     invalid L < 1 the forward itself is not finite there and the t term is skipped.
 *
 *   Inner join points. All J points are the pivot (g_p += g) or X (the miter vector above).
 *
 *   Caps, at end point e with direction d (d = -dir(0) at the start, so gdir = -gd):
 *     square  e + h d +/- h perp(d):            gd += h g +/- h perp_t(g)
 *     round   e + h (cos phi perp(d) + sin phi d):  gd += h (cos phi perp_t(g) + sin phi g)
 *     and g_e += g.
 *
 * Order and determinism: one work-item per (subpath, frame) walks the outline in the forward's
 * order, recomputing what it needs, and adds into its own vertices' gradients with plain
 * read-modify-writes (each vertex belongs to exactly one stroked subpath, so there are no
 * races and no atomics): the sums happen in a fixed order and the result is bit-identical run
 * to run. The gradients of outline points are only read.
 */

/* perp's transpose: perp(d) . g == d . perp_t(g). */
inline float2 perp_t(float2 g) { return (float2)(g.y, -g.x); }

/* A segment direction after inheritance, and the valid segment it is the direction of (-1: the
 * constant +x of a subpath without any valid segment). */
typedef struct {
  float2 d;
  int src;
} StrokeDir;

/* seg_dir with its source segment (seg_src, stroke.cl); the direction is seg_dir's bit for bit. */
inline StrokeDir stroke_dir(__global const float2* p, int i, int S, int N, int closed) {
  StrokeDir r;
  float2 d = (float2)(1.0f, 0.0f);
  r.src = seg_src(p, i, S, N, closed);
  if (r.src >= 0) seg_valid(p, r.src, N, &d);
  r.d = d;
  return r;
}

/* Normalisation backward: gd on a direction goes to its source segment's end points. */
inline void dir_backward(__global const float2* p, __global float2* gp, StrokeDir sd, int N,
                         float2 gd) {
  if (sd.src < 0) return;
  const int j = sd.src, j1 = (sd.src + 1) % N;
  const float2 v = p[j1] - p[j];
  const float r = rsqrt(dot(v, v));
  const float2 d = v * r;
  const float2 gv = (gd - d * dot(d, gd)) * r;
  gp[j1] += gv;
  gp[j] -= gv;
}

/* Y = pivot + sh (perp(da) + perp(db)) / (1 + c), c = da . db: adds dY/d(da, db)^T g. */
inline void miter_vec_backward(float2 da, float2 db, float sh, float2 g, float2* gda,
                               float2* gdb) {
  const float inv = 1.0f / (1.0f + dot(da, db));
  const float2 u = perp(da) + perp(db);
  const float2 gu = perp_t(sh * inv * g);
  const float gc = -sh * inv * inv * dot(g, u);
  *gda += gu + gc * db;
  *gdb += gu + gc * da;
}

/* The backward of an offset end point: X of vertex v on side s when has_x, else
 * p[idx] + s h perp(d.d). */
inline void point_backward(__global const float2* p, __global float2* gp, float2 g, int has_x,
                           int v, float s, int idx, StrokeDir d, int S, int N, int closed,
                           float h) {
  if (has_x) {
    const int a = (v + S - 1) % S, b = v % S;
    const StrokeDir da = stroke_dir(p, a, S, N, closed), db = stroke_dir(p, b, S, N, closed);
    float2 gda = (float2)(0.0f), gdb = (float2)(0.0f);
    miter_vec_backward(da.d, db.d, s * h, g, &gda, &gdb);
    gp[b] += g;
    dir_backward(p, gp, da, N, gda);
    dir_backward(p, gp, db, N, gdb);
  } else {
    gp[idx] += g;
    dir_backward(p, gp, d, N, s * h * perp_t(g));
  }
}

/* The backward of emit_join: go holds the gradients of its J points (in output order). */
inline void join_backward(__global const float2* p, __global float2* gp, __global const float2* go,
                          int J, float s, int piv, StrokeDir sa, StrokeDir sb, int kind, float h,
                          float miter_limit, int rev, int has_x, int N) {
  const float2 da = sa.d, db = sb.d;
  const float2 na = s * perp(da), nb = s * perp(db);
  const float turn = cross2(da, db);
  float2 gpiv = (float2)(0.0f), gda = (float2)(0.0f), gdb = (float2)(0.0f);
  if (s * turn > 0.0f) {
    for (int j = 0; j < J; ++j) gpiv += go[j];
    if (has_x) miter_vec_backward(da, db, s * h, gpiv, &gda, &gdb);
  } else {
    const float c = dot(na, nb);
    const float half_cos = sqrt(fmax(0.5f * (1.0f + c), 0.0f));
    const float limit = kind == JOIN_INTERIOR ? 4.0f : miter_limit;
    const int fits = half_cos * limit >= 1.0f && 1.0f + c > 1e-6f;
    for (int j = 0; j < J; ++j) {
      const float2 g = go[rev ? J - 1 - j : j];
      gpiv += g;
      if (kind == JOIN_ROUND) {
        const float y = cross2(na, nb);
        const float sweep = atan2(y, c);
        const float f = (float)(j + 1) / (float)(J + 1);
        const float phi = sweep * (float)(j + 1) / (float)(J + 1);
        const float2 r = rotate2(na, phi);
        gda += s * perp_t(h * rotate2(g, -phi));
        const float gsw = f * h * dot(g, perp(r));
        const float r2 = c * c + y * y;
        const float gy = gsw * c / r2, gx = -gsw * y / r2;
        gda += gy * perp_t(db) + gx * db;
        gdb += gy * perp(da) + gx * da;
      } else if (kind == JOIN_BEVEL) {
        gda += s * h * perp_t(g);
      } else if (fits) {
        miter_vec_backward(da, db, s * h, g, &gda, &gdb);
      } else if (kind == JOIN_MITER_CLIP && 1.0f + c > 1e-6f) {
        const float a_proj = h * half_cos, m_proj = h / half_cos;
        const float den = m_proj - a_proj;
        const float t = (limit * h - a_proj) / den;
        const float2 ne = j == 0 ? na : nb; /* E = pivot + h ne */
        const float2 gE = (1.0f - t) * g;
        if (j == 0)
          gda += s * h * perp_t(gE);
        else
          gdb += s * h * perp_t(gE);
        miter_vec_backward(da, db, s * h, t * g, &gda, &gdb);
        if (den > 0.0f) {
          const float2 m_minus_e = h * (na + nb) / (1.0f + c) - h * ne;
          const float gt = dot(g, m_minus_e);
          const float dt_dhc =
              (-h * den + (limit * h - a_proj) * h * (1.0f + 1.0f / (half_cos * half_cos))) /
              (den * den);
          const float gc = gt * dt_dhc * 0.25f / half_cos;
          gda += gc * db;
          gdb += gc * da;
        }
      } else {
        gda += s * h * perp_t(g);
      }
    }
  }
  gp[piv] += gpiv;
  dir_backward(p, gp, sa, N, gda);
  dir_backward(p, gp, sb, N, gdb);
}

/* The backward of emit_cap at vertex e with direction sign * sd.d. */
inline void cap_backward(__global const float2* p, __global float2* gp, __global const float2* go,
                         int C, int cap, int e, StrokeDir sd, float sign, float h, int N) {
  float2 ge = (float2)(0.0f), gd = (float2)(0.0f);
  for (int j = 0; j < C; ++j) {
    const float2 g = go[j];
    ge += g;
    if (cap == CAP_SQUARE) {
      gd += h * g + (j == 0 ? h : -h) * perp_t(g);
    } else {
      const float phi = M_PI_F * (float)(j + 1) / (float)(C + 1);
      gd += h * (cos(phi) * perp_t(g) + sin(phi) * g);
    }
  }
  gp[e] += ge;
  dir_backward(p, gp, sd, N, sign * gd);
}

__kernel void stroke_backward(__global const float2* pts,    /* [K][n_pts]: polylines */
                              __global float2* grad_pts,     /* [K][n_pts]: reads outline
                                                                gradients, adds vertex ones */
                              __global const int4* sp_a,     /* (first vertex, N, first out, closed) */
                              __global const int4* sp_b,     /* (cap, J, C, path join kind) */
                              __global const float2* sp_f,   /* (half width, miter limit) */
                              __global const uchar* vkind,   /* [n_flat] join kind per vertex */
                              int n_sp, int n_pts) {
  const int sid = get_global_id(0), k = get_global_id(1);
  if (sid >= n_sp) return;
  const int4 a = sp_a[sid], b = sp_b[sid];
  const float h = sp_f[sid].x, ml = sp_f[sid].y;
  __global const float2* p = pts + (size_t)k * n_pts + a.x;
  __global float2* gp = grad_pts + (size_t)k * n_pts + a.x;
  __global const float2* go = grad_pts + (size_t)k * n_pts + a.z;
  __global const uchar* kinds = vkind + a.x;
  const int N = a.y, closed = a.w, cap = b.x, J = b.y, C = b.z;
  const int S = closed ? N : max(N - 1, 1);
  float2 Xunused;

  /* Left side, forward: S_i, E_i, join after segment i. */
  int x0 = inner_point(p, 0, 1.0f, S, N, closed, h, &Xunused), x1;
  for (int i = 0; i < S; ++i) {
    const StrokeDir d = stroke_dir(p, i, S, N, closed);
    x1 = inner_point(p, i + 1, 1.0f, S, N, closed, h, &Xunused);
    point_backward(p, gp, go[0], x0, i, 1.0f, i, d, S, N, closed, h);
    point_backward(p, gp, go[1], x1, i + 1, 1.0f, (i + 1) % N, d, S, N, closed, h);
    go += 2;
    if (i + 1 < S || closed) {
      const StrokeDir dn = stroke_dir(p, (i + 1) % S, S, N, closed);
      join_backward(p, gp, go, J, 1.0f, (i + 1) % N, d, dn, kinds[(i + 1) % N], h, ml, 0, x1,
                    N);
      go += J;
    }
    x0 = x1;
  }
  if (!closed) {
    cap_backward(p, gp, go, C, cap, S % N, stroke_dir(p, S - 1, S, N, closed), 1.0f, h, N);
    go += C;
  }
  /* Right side, backward: [join after i, reversed,] E_i, S_i, [join before i, reversed]. */
  x1 = inner_point(p, S, -1.0f, S, N, closed, h, &Xunused);
  for (int i = S - 1; i >= 0; --i) {
    const StrokeDir d = stroke_dir(p, i, S, N, closed);
    x0 = inner_point(p, i, -1.0f, S, N, closed, h, &Xunused);
    if (closed) {
      const StrokeDir dn = stroke_dir(p, (i + 1) % S, S, N, closed);
      join_backward(p, gp, go, J, -1.0f, (i + 1) % N, d, dn, kinds[(i + 1) % N], h, ml, 1, x1,
                    N);
      go += J;
    }
    point_backward(p, gp, go[0], x1, i + 1, -1.0f, (i + 1) % N, d, S, N, closed, h);
    point_backward(p, gp, go[1], x0, i, -1.0f, i, d, S, N, closed, h);
    go += 2;
    if (i > 0 && !closed) {
      const StrokeDir dp = stroke_dir(p, i - 1, S, N, closed);
      join_backward(p, gp, go, J, -1.0f, i, dp, d, kinds[i], h, ml, 1, x0, N);
      go += J;
    }
    x1 = x0;
  }
  if (!closed)
    cap_backward(p, gp, go, C, cap, 0, stroke_dir(p, 0, S, N, closed), -1.0f, h, N);
}
