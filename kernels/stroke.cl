/* stroke.cl: stroke expansion into fill outlines with a topology fixed at plan time.
 *
 * The rasteriser has one primitive, a filled polygon, so each stroked subpath (a flattened
 * polyline p_0 .. p_{N-1}, half width h) becomes outline contours that are filled with the
 * nonzero rule:
 *
 *   open:   left side forward, end cap, right side backward, start cap        (one contour)
 *   closed: left side forward (closed), right side backward (closed)          (two contours)
 *
 * Segment i (p_i -> q_i) with unit direction d_i and left normal n_i = perp(d_i) contributes
 * S_i = p_i + s h n_i and E_i = q_i + s h n_i on side s (+1 left, -1 right); between segments
 * a join of exactly J points is emitted, so the number of points never depends on the frame
 * (the differentiable fitter needs fixed topology). On the outer side of a turn the J points
 * are the join geometry (miter point, clipped miter, arc points, or repeats of E_i for a
 * bevel). On the inner side, E_i, the J points and S_{i+1} all move to X, the intersection of
 * the two inner offset lines, when X lies well inside both segments (its distance from the
 * pivot, h tan(turn/2), at most half of either segment); otherwise the J points sit on the
 * pivot p (Skia's trick: the contour dips through the centre line). Both are filled
 * correctly, but only X avoids a doubly-wound sliver along the inner edge: exact area coverage
 * integrates the winding number over a pixel before clamping it to 1, so overlaps that touch
 * boundary pixels would over-cover them (a 1.3% excess on a thin circle's stroke otherwise).
 * Unused points repeat, giving zero-length lines that contribute nothing.
 *
 * Why this fills correctly: written as chains, the contour equals the sum of every segment's
 * quad (S_i^L, E_i^L, E_i^R, S_i^R), every outer join's pie wedge (E_i, join points, S_{i+1},
 * pivot) and the caps, all oriented the same way; the shared edges cancel. So the winding
 * number is >= 1 inside the stroke and 0 outside, and nonzero coverage is exact (the same
 * min(1, |winding integral|) as for any fill).
 *
 * Degenerate (zero-length) segments inherit the direction of the nearest valid segment before
 * them (wrapping for closed subpaths, else the first valid one); a subpath with no valid
 * segment at all is a dot drawn along +x, which gives the round/square caps SVG asks for on
 * zero-length subpaths. Counts (must match raster_plan.cpp):
 *   open   (S = max(N-1, 1) segments): 2 * (2S + J (S - 1)) + 2C points
 *   closed (S = N segments):           2 * S (2 + J) points
 */

#define DEGENERATE_LEN2 1e-12f

inline float2 perp(float2 d) { return (float2)(-d.y, d.x); }

inline int seg_valid(__global const float2* p, int i, int N, float2* dir) {
  const float2 a = p[i], b = p[(i + 1) % N];
  const float2 d = b - a;
  const float l2 = dot(d, d);
  if (l2 <= DEGENERATE_LEN2) return 0;
  *dir = d * rsqrt(l2);
  return 1;
}

/* Which segment gives segment i its direction after inheritance (see the essay): i itself if
 * it is not degenerate, else the search below; -1 when every segment is degenerate. The
 * backward pass (stroke_backward.cl) needs the source, not only the direction. */
inline int seg_src(__global const float2* p, int i, int S, int N, int closed) {
  float2 d;
  for (int j = i; j >= 0; --j)
    if (seg_valid(p, j, N, &d)) return j;
  if (closed) {
    for (int j = S - 1; j > i; --j)
      if (seg_valid(p, j, N, &d)) return j;
  } else {
    for (int j = i + 1; j < S; ++j)
      if (seg_valid(p, j, N, &d)) return j;
  }
  return -1;
}

/* Direction of segment i after inheritance; +x when there is none. */
inline float2 seg_dir(__global const float2* p, int i, int S, int N, int closed) {
  float2 d = (float2)(1.0f, 0.0f);
  const int j = seg_src(p, i, S, N, closed);
  if (j >= 0) seg_valid(p, j, N, &d);
  return d;
}

/* The inner join point X of vertex v on side s (see the essay), if it applies. */
inline int inner_point(__global const float2* p, int v, float s, int S, int N, int closed, float h,
                       float2* X) {
  if (!closed && (v == 0 || v >= S)) return 0; /* open ends have no join */
  const int a = (v + S - 1) % S, b = v % S;
  const float2 da = seg_dir(p, a, S, N, closed), db = seg_dir(p, b, S, N, closed);
  const float turn = cross2(da, db), c = dot(da, db);
  if (s * turn <= 0.0f || 1.0f + c < 1e-6f) return 0;
  const float t = h * fabs(turn) / (1.0f + c);
  const float la = length(p[(a + 1) % N] - p[a]), lb = length(p[(b + 1) % N] - p[b]);
  if (t > 0.5f * fmin(la, lb)) return 0;
  *X = p[b] + s * h * (perp(da) + perp(db)) / (1.0f + c);
  return 1;
}

inline float2 rotate2(float2 v, float ang) {
  const float c = cos(ang), s = sin(ang);
  return (float2)(c * v.x - s * v.y, s * v.x + c * v.y);
}

/* Writes the J join points at pivot between directions da -> db on side s, in forward order,
 * or reversed when rev (the right side is emitted backwards). */
inline void emit_join(__global float2* out, int J, float s, float2 pivot, float2 da, float2 db,
                      int kind, float h, float miter_limit, int rev, int has_x, float2 X) {
  const float2 na = s * perp(da), nb = s * perp(db);
  const float turn = cross2(da, db);
  const float2 A = pivot + h * na, B = pivot + h * nb;
  for (int j = 0; j < J; ++j) {
    float2 q;
    if (s * turn > 0.0f) {
      q = has_x ? X : pivot; /* inner side */
    } else {
      const float c = dot(na, nb); /* cos of the turn angle */
      const float half_cos = sqrt(fmax(0.5f * (1.0f + c), 0.0f)); /* cos(turn/2) */
      const float limit = kind == JOIN_INTERIOR ? 4.0f : miter_limit;
      /* The miter point: pivot + h (na + nb) / (1 + c); its distance ratio is 1/cos(turn/2). */
      const int fits = half_cos * limit >= 1.0f && 1.0f + c > 1e-6f;
      const float2 M = pivot + h * (na + nb) / fmax(1.0f + c, 1e-6f);
      if (kind == JOIN_ROUND) {
        const float sweep = atan2(cross2(na, nb), c);
        q = pivot + h * rotate2(na, sweep * (float)(j + 1) / (float)(J + 1));
      } else if (kind == JOIN_BEVEL) {
        q = A;
      } else if (fits) {
        q = M;
      } else if (kind == JOIN_MITER_CLIP && 1.0f + c > 1e-6f) {
        /* Clip the miter at distance limit * h from the pivot along the bisector. */
        const float a_proj = h * half_cos, m_proj = h / half_cos;
        const float t = (limit * h - a_proj) / (m_proj - a_proj);
        q = j == 0 ? A + t * (M - A) : B + t * (M - B);
      } else {
        q = A;
      }
    }
    out[rev ? J - 1 - j : j] = q;
  }
}

/* C cap points around end point e, from e + h n to e - h n through e + h d. */
inline void emit_cap(__global float2* out, int C, int cap, float2 e, float2 d, float h) {
  const float2 n = perp(d);
  for (int j = 0; j < C; ++j) {
    if (cap == CAP_SQUARE) {
      out[j] = e + h * d + (j == 0 ? h * n : -h * n);
    } else {
      const float phi = M_PI_F * (float)(j + 1) / (float)(C + 1);
      out[j] = e + h * (n * cos(phi) + d * sin(phi));
    }
  }
}

__kernel void stroke(__global float2* pts,            /* [K][n_pts]: reads polylines, writes outlines */
                     __global const int4* sp_a,       /* (first vertex, N, first out point, closed) */
                     __global const int4* sp_b,       /* (cap, J, C, path join kind) */
                     __global const float2* sp_f,     /* (half width, miter limit) */
                     __global const uchar* vkind,     /* [n_flat] join kind per vertex */
                     int n_sp, int n_pts) {
  const int sid = get_global_id(0), k = get_global_id(1);
  if (sid >= n_sp) return;
  const int4 a = sp_a[sid], b = sp_b[sid];
  const float h = sp_f[sid].x, ml = sp_f[sid].y;
  __global float2* P = pts + (size_t)k * n_pts;
  __global const float2* p = P + a.x;
  __global const uchar* kinds = vkind + a.x;
  const int N = a.y, closed = a.w, cap = b.x, J = b.y, C = b.z;
  const int S = closed ? N : max(N - 1, 1);
  __global float2* w = P + a.z;

  /* Left side, forward. */
  float2 X0, X1;
  int x0 = inner_point(p, 0, 1.0f, S, N, closed, h, &X0), x1;
  float2 d = seg_dir(p, 0, S, N, closed);
  for (int i = 0; i < S; ++i) {
    const float2 n = perp(d), pi = p[i], qi = p[(i + 1) % N];
    x1 = inner_point(p, i + 1, 1.0f, S, N, closed, h, &X1);
    *w++ = x0 ? X0 : pi + h * n;
    *w++ = x1 ? X1 : qi + h * n;
    if (i + 1 < S || closed) {
      const float2 dn = seg_dir(p, (i + 1) % S, S, N, closed);
      emit_join(w, J, 1.0f, qi, d, dn, kinds[(i + 1) % N], h, ml, 0, x1, X1);
      w += J;
      d = dn;
    }
    x0 = x1;
    X0 = X1;
  }
  if (!closed) {
    /* End cap, right side backward, start cap. */
    const float2 dl = seg_dir(p, S - 1, S, N, closed);
    emit_cap(w, C, cap, p[S % N], dl, h); /* q_{S-1}; p_0 for a one-point dot */
    w += C;
  }
  /* Right side, backward. For closed subpaths this starts a second contour; the join after
   * segment i (towards i+1) is emitted reversed, before E_i. */
  d = seg_dir(p, S - 1, S, N, closed);
  x1 = inner_point(p, S, -1.0f, S, N, closed, h, &X1);
  for (int i = S - 1; i >= 0; --i) {
    const float2 n = perp(d), pi = p[i], qi = p[(i + 1) % N];
    x0 = inner_point(p, i, -1.0f, S, N, closed, h, &X0);
    if (closed) {
      const float2 dn = seg_dir(p, (i + 1) % S, S, N, closed);
      emit_join(w, J, -1.0f, qi, d, dn, kinds[(i + 1) % N], h, ml, 1, x1, X1);
      w += J;
    }
    *w++ = x1 ? X1 : qi - h * n;
    *w++ = x0 ? X0 : pi - h * n;
    if (i > 0) {
      const float2 dp = seg_dir(p, i - 1, S, N, closed);
      if (!closed) {
        emit_join(w, J, -1.0f, pi, dp, d, kinds[i], h, ml, 1, x0, X0);
        w += J;
      }
      d = dp;
    }
    x1 = x0;
    X1 = X0;
  }
  if (!closed) emit_cap(w, C, cap, p[0], -seg_dir(p, 0, S, N, closed), h);
}
