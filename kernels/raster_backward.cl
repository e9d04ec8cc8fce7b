/* raster_backward.cl: exact gradients of the rendered frames with respect to every line endpoint.
 *
 * Built in one program after raster.cl and loss.cl (it reuses accumulate_line, the band
 * structure and blurred_gradient).
 *
 * Compositing. A draw i composites α_i = coverage_i · alpha_i over what is below it. With T_i
 * the transmittance of the draws in front of it, Π_{j>i} (1 − α_j), and B_i the colour below it
 * on the background, the final colour C satisfies (DESIGN.md §4)
 *
 *     ∂C/∂α_i = T_i (c_i − B_i).
 *
 * T_i is known walking the draws from the top down; B_i is known walking them from the bottom
 * up. B_i is only needed where the coverage has a non-zero derivative, i.e. where the winding
 * integral a is fractional, which happens only in pixels an edge of the draw crosses. So the
 * kernel first replays the forward pass bottom-up and keeps B_i on a tape for exactly those
 * pixels (in local memory, in the order (draw, row, x)), then walks the draws top-down,
 * recomputes each draw's winding integrals (same lines, same order, so the same bits), reads
 * B_i back from the tape and forms
 *
 *     g(p) = ∂L/∂a_i(p) = Σ_c ∂L/∂C_c(p) · T_i(p) (c_i − B_i(p))_c · alpha_i · f'(a),
 *
 * f' the slope of the fill rule (nonzero: sign(a) where |a| < 1; evenodd: the sign of the fold).
 * No paths x pixels buffer: the tape holds one float4 per edge pixel of the band.
 *
 * Coverage. For a region moving with velocity v, d/dθ ∫_pixel w = ∫_{∂Ω ∩ pixel} (v · n) ds
 * (Reynolds transport; n the unit normal from the higher-winding side to the lower, which for
 * our orientation convention is perp(e1 − e0)/L with perp(d) = (−d.y, d.x)). A point at
 * parameter s of the line e0 → e1 moves with (1 − s) ė0 + s ė1, so a piece of the line inside
 * pixel p, between parameters s_a < s_b, adds
 *
 *     ∂L/∂e0 += g(p) · perp(e1 − e0) · [(s_b − s_a) − (s_b² − s_a²)/2]
 *     ∂L/∂e1 += g(p) · perp(e1 − e0) · (s_b² − s_a²)/2
 *
 * (the L of ds = L ds' cancels the 1/L of the normal). This is exact for line segments: what
 * DiffVG estimates with random boundary samples, here in closed form. Horizontal lines matter
 * here although they add nothing to the forward accumulation: moving them vertically changes
 * the covered area. Pieces outside the canvas add nothing (no pixel sees them).
 *
 * Output. A line may cross several bands; each band writes its partial gradient of the line
 * into its own slot, partial[k][line][band], and gather_line_grads sums the slots of the bands
 * the line crosses in band order. Deterministic, no atomics.
 */

#define FRACTION_EPS 1e-6f /* |a| this close to an integer is treated as interior or exterior */

inline float fold(float a, int rule) {
  return rule == RULE_EVENODD ? a - 2.0f * rint(0.5f * a) : a;
}

inline int is_fractional(float a, int rule) {
  const float m = fabs(fold(a, rule));
  return m > FRACTION_EPS && m < 1.0f - FRACTION_EPS;
}

/* The forward sweep of one draw's span (composite_span), also pushing B onto the tape at every
 * fractional pixel. */
inline void replay_span(__local float* acc, __local float4* out, int* hlo, int* hhi, int xlo,
                        int xhi, int width, float4 color, int rule, float4 background,
                        __local float4* tape, int* tp, int cap) {
  float s = 0.0f;
  const int xe = min(xhi, width - 1);
  const float4 premul = (float4)(color.xyz, 1.0f);
  grow_hull4(out, hlo, hhi, xlo, xe);
  for (int x = xlo; x <= xe; ++x) {
    s += acc[x];
    acc[x] = 0.0f;
    if (is_fractional(s, rule)) {
      if (*tp < cap) tape[*tp] = out[x] + background * (1.0f - out[x].w);
      ++*tp;
    }
    const float a = fill_rule_coverage(s, rule) * color.w;
    if (a > 0.0f) out[x] = premul * a + out[x] * (1.0f - a);
  }
  acc[xe + 1] = 0.0f;
  const float a = fill_rule_coverage(s, rule) * color.w;
  if (a > RESIDUAL_COVERAGE && xe + 1 < width) {
    grow_hull4(out, hlo, hhi, xe + 1, width - 1);
    for (int x = xe + 1; x < width; ++x) out[x] = premul * a + out[x] * (1.0f - a);
  }
}

/* The top-down sweep of one draw's span: g(p) into gcell, then T *= (1 - α). */
inline void backward_span(__local float* acc, __local float* T, int* tlo, int* thi,
                          __local float* gcell, int* glo, int* ghi, __global const float4* E,
                          __global const int2* ext_e, __global const float4* R,
                          int row, int height, float scale, int xlo, int xhi, int width,
                          float4 color, int rule, __local const float4* tape, int* tp, int cap) {
  float s = 0.0f;
  const int xe = min(xhi, width - 1);
  grow_hull_fill(T, tlo, thi, xlo, xe, 1.0f);  /* transmittance starts at 1 */
  grow_hull(gcell, glo, ghi, xlo, xe);
  for (int x = xlo; x <= xe; ++x) {
    s += acc[x];
    acc[x] = 0.0f;
    float g = 0.0f;
    if (is_fractional(s, rule)) {
      if (*tp < cap) {
        const float3 dC = blurred_gradient(E, ext_e, R, x, row, width, height, scale);
        const float ga = dot(dC, T[x] * (color.xyz - tape[*tp].xyz));
        g = ga * color.w * sign(fold(s, rule));
      }
      ++*tp;
    }
    gcell[x] = g;
    T[x] *= 1.0f - fill_rule_coverage(s, rule) * color.w;
  }
  acc[xe + 1] = 0.0f;
  const float a = fill_rule_coverage(s, rule) * color.w;
  if (a > RESIDUAL_COVERAGE && xe + 1 < width) {
    grow_hull_fill(T, tlo, thi, xe + 1, width - 1, 1.0f);
    for (int x = xe + 1; x < width; ++x) T[x] *= 1.0f - a;
  }
}

/* The gradient (∂e0, ∂e1) of one line from the pixels of row `row` it crosses. */
inline float4 walk_line_grad(float4 l, int row, int width, __local const float* g) {
  const float2 e0 = l.xy, d = l.zw - l.xy;
  float ta, tb;
  if (d.y == 0.0f) {
    if (e0.y < (float)row || e0.y >= (float)(row + 1)) return (float4)(0.0f);
    ta = 0.0f;
    tb = 1.0f;
  } else {
    const float t0 = ((float)row - e0.y) / d.y, t1 = ((float)(row + 1) - e0.y) / d.y;
    ta = fmax(0.0f, fmin(t0, t1));
    tb = fmin(1.0f, fmax(t0, t1));
    if (!(ta < tb)) return (float4)(0.0f);
  }
  float c0 = 0.0f, c1 = 0.0f; /* Σ g·∫(1 - s), Σ g·∫ s over the pieces */
  const float w = (float)width;
  if (d.x == 0.0f) {
    const float x = e0.x;
    if (x >= 0.0f && x < w) {
      const float gp = g[(int)x];
      c0 = gp * ((tb - ta) - 0.5f * (tb * tb - ta * ta));
      c1 = gp * 0.5f * (tb * tb - ta * ta);
    }
  } else {
    /* Walk the cells in increasing t, stepping the cell index (recomputing it from x would
     * stall where rounding puts x a hair short of a boundary). Moving left from an integer x
     * starts in the cell to the left. */
    const int step = d.x > 0.0f ? 1 : -1;
    const float xs = e0.x + ta * d.x;
    int cell = (int)floor(xs);
    if (step < 0 && xs == floor(xs)) cell -= 1;
    float t = ta;
    for (;;) {
      const float xb = (float)(step > 0 ? cell + 1 : cell);
      const float tn = fmax(t, fmin(tb, (xb - e0.x) / d.x));
      if (cell >= 0 && cell < width) {
        const float gp = g[cell];
        c0 += gp * ((tn - t) - 0.5f * (tn * tn - t * t));
        c1 += gp * 0.5f * (tn * tn - t * t);
      }
      if (tn >= tb) break;
      t = tn;
      cell += step;
    }
  }
  const float2 n = (float2)(-d.y, d.x);
  return (float4)(c0 * n, c1 * n);
}

__kernel void raster_backward(__global const float4* lines,      /* [K][n_lines] */
                              __global const int2* draw_chunks,   /* [n_draws] */
                              __global const int2* chunk_lines,   /* [n_chunks] */
                              __global const float4* draw_color,  /* [n_draws] */
                              __global const int* draw_rule,      /* [n_draws] */
                              __global const float4* bounds,      /* [K][n_chunks] */
                              __global const float4* E,           /* [K][H][W] E' (loss.cl) */
                              __global const int2* ext_e,         /* [K][H] its row extents */
                              __global const float4* R,           /* [K][H][W] G ∗ Q (loss.cl) */
                              float grad_scale,                   /* 2w/N */
                              float4 background,
                              __local float* acc,                 /* [BAND_H][W + 2] */
                              __local float4* band_rgba,          /* [BAND_H][W] */
                              __local float* band_T,              /* [BAND_H][W] */
                              __local float* gcell,               /* [BAND_H][W] */
                              __local float4* tape, int tape_cap,
                              __local int* draw_tape,             /* [n_draws] */
                              __global float4* partial,           /* [K][n_lines][n_bands] */
                              __global int* overflow,             /* [1]: tape overflows */
                              int n_lines, int n_chunks, int n_draws, int n_bands, int width,
                              int height) {
  const int band = get_group_id(0), k = get_group_id(1);
  const int lid = get_local_id(0), lsize = get_local_size(0);
  const int y0 = band * BAND_H, rows = min(BAND_H, height - y0);
  const float fy0 = (float)y0, fy1 = (float)(y0 + rows), fw = (float)width;
  const int stride = width + 2;

  if (lid == 0) {
    __global const float4* L = lines + (size_t)k * n_lines;
    __global const float4* B = bounds + (size_t)k * n_chunks;
    __global const float4* Ek = E + (size_t)k * height * width;
    __global const int2* Xk = ext_e + (size_t)k * height;
    __global const float4* Rk = R + (size_t)k * height * width;
    /* Per row: the draw's span, and the valid hulls of the lazily cleared row buffers
     * (accumulation, colour, transmittance, ∂L/∂a; see grow_hull in raster.cl). */
    int xlo[BAND_H], xhi[BAND_H], alo[BAND_H], ahi[BAND_H], hlo[BAND_H], hhi[BAND_H];
    int tlo[BAND_H], thi[BAND_H], glo[BAND_H], ghi[BAND_H];
    for (int r = 0; r < BAND_H; ++r) {
      xlo[r] = width; xhi[r] = -1;
      alo[r] = width + 2; ahi[r] = -1;
      hlo[r] = tlo[r] = glo[r] = width;
      hhi[r] = thi[r] = ghi[r] = -1;
    }
    int tp = 0;

    /* 1. Bottom-up replay of the forward pass, taping B at fractional pixels. */
    for (int d = 0; d < n_draws; ++d) {
      draw_tape[d] = tp;
      accumulate_draw(L, B, chunk_lines, draw_chunks[d], y0, rows, width, stride, acc, xlo, xhi,
                      alo, ahi);
      const float4 color = draw_color[d];
      const int rule = draw_rule[d];
      for (int r = 0; r < rows; ++r) {
        if (xhi[r] >= xlo[r])
          replay_span(acc + r * stride, band_rgba + r * width, &hlo[r], &hhi[r], xlo[r], xhi[r],
                      width, color, rule, background, tape, &tp, tape_cap);
        xlo[r] = width;
        xhi[r] = -1;
      }
    }
    if (tp > tape_cap) atomic_max(overflow, tp);

    /* 2. Top-down: ∂L/∂a per edge pixel, then the boundary integrals of every line. */
    for (int d = n_draws - 1; d >= 0; --d) {
      const int2 chunks = draw_chunks[d];
      if (!accumulate_draw(L, B, chunk_lines, chunks, y0, rows, width, stride, acc, xlo, xhi, alo,
                           ahi))
        continue;
      const float4 color = draw_color[d];
      const int rule = draw_rule[d];
      int tq = draw_tape[d];
      int slo[BAND_H], shi[BAND_H]; /* the spans written into gcell, cleared after the walk */
      for (int r = 0; r < rows; ++r) {
        slo[r] = xlo[r];
        shi[r] = min(xhi[r], width - 1);
        if (xhi[r] >= xlo[r])
          backward_span(acc + r * stride, band_T + r * width, &tlo[r], &thi[r], gcell + r * width,
                        &glo[r], &ghi[r], Ek, Xk, Rk, y0 + r, height, grad_scale, xlo[r], xhi[r], width,
                        color, rule, tape, &tq, tape_cap);
        xlo[r] = width;
        xhi[r] = -1;
      }
      for (int c = chunks.x; c < chunks.x + chunks.y; ++c) {
        const float4 b = B[c];
        if (b.w <= fy0 || b.y >= fy1 || b.x >= fw) continue;
        const int2 range = chunk_lines[c];
        for (int j = range.x; j < range.x + range.y; ++j) {
          const float4 l = L[j];
          const float ymin = fmin(l.y, l.w) - fy0, ymax = fmax(l.y, l.w) - fy0;
          const int r0 = max((int)floor(ymin), 0), r1 = min((int)ceil(ymax), rows) - 1;
          /* The walk reads ∂L/∂a at the cells the line crosses: make them valid first. */
          const int ca = (int)clamp(floor(fmin(l.x, l.z)), 0.0f, fw - 1.0f);
          const int cb = (int)clamp(floor(fmax(l.x, l.z)), 0.0f, fw - 1.0f);
          float4 g = (float4)(0.0f);
          for (int r = r0; r <= r1; ++r) {
            grow_hull(gcell + r * width, &glo[r], &ghi[r], ca, cb);
            g += walk_line_grad(l, y0 + r, width, gcell + r * width);
          }
          partial[((size_t)k * n_lines + j) * n_bands + band] = g;
        }
      }
      for (int r = 0; r < rows; ++r)
        for (int x = slo[r]; x <= shi[r]; ++x) gcell[r * width + x] = 0.0f;
    }
  }
}

/* ∂L/∂line: the sum of a line's band partials, over the bands that visited it, in order. */
__kernel void gather_line_grads(__global const float4* lines, __global const int* line_chunk,
                                __global const float4* bounds, __global const float4* partial,
                                __global float4* line_grad, int n_lines, int n_chunks,
                                int n_bands, int width, int height) {
  const int j = get_global_id(0), k = get_global_id(1);
  if (j >= n_lines) return;
  const float4 l = lines[(size_t)k * n_lines + j];
  const float4 b = bounds[(size_t)k * n_chunks + line_chunk[j]];
  const float ymin = fmin(l.y, l.w), ymax = fmax(l.y, l.w);
  const int b0 = clamp((int)floor(ymin / (float)BAND_H), 0, n_bands - 1);
  const int b1 = clamp((int)floor(ymax / (float)BAND_H), 0, n_bands - 1);
  float4 g = (float4)(0.0f);
  for (int band = b0; band <= b1; ++band) {
    const int y0 = band * BAND_H, rows = min(BAND_H, height - y0);
    const float fy0 = (float)y0, fy1 = (float)(y0 + rows);
    if (b.w <= fy0 || b.y >= fy1 || b.x >= (float)width) continue; /* the band skipped it */
    g += partial[((size_t)k * n_lines + j) * n_bands + band];
  }
  line_grad[(size_t)k * n_lines + j] = g;
}

/* ∂L/∂point from the lines that use it: a fixed list per point (CSR), summed in order.
 * Entry e of point p's list is 2 * line + end (end 0: the line's first point). */
__kernel void gather_point_grads(__global const float4* line_grad, __global const int* pt_first,
                                 __global const int* pt_entries, __global float2* grad_pts,
                                 int n_lines, int n_pts) {
  const int p = get_global_id(0), k = get_global_id(1);
  if (p >= n_pts) return;
  float2 g = (float2)(0.0f);
  for (int e = pt_first[p]; e < pt_first[p + 1]; ++e) {
    const int code = pt_entries[e];
    const float4 lg = line_grad[(size_t)k * n_lines + (code >> 1)];
    g += (code & 1) ? lg.zw : lg.xy;
  }
  grad_pts[(size_t)k * n_pts + p] = g;
}
