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
 * up. Both are only needed where the coverage has a non-zero derivative, i.e. where the winding
 * integral a is fractional, which happens only in pixels an edge of the draw crosses. So the
 * fit's forward pass (raster_taped, below) keeps an entry on a tape for exactly those pixels (in
 * the order (draw, row, x)) while it composites bottom-up, and hands it over in a pool in
 * global memory; a band whose tape did not fit replays the forward pass here (replay_band,
 * the same code, so the same bits). An entry holds B_i(p), a (the same bits as the sweep's),
 * the pixel, and V: the product of (1 − α_j(p)) over the draws j above i up to (not including)
 * the next draw with an entry at p, or to the top. The forward gets V from a running product
 * per pixel, restarted at each entry and stored into the pixel's previous entry. Then
 * T_i(p) = V · W(p), W(p) the transmittance below the entries at p visited so far
 * (T · (1 − α) of the last one, 1 before any), and the kernel walks the draws top-down over
 * their entries alone, forming
 *
 *     g(p) = ∂L/∂a_i(p) = Σ_c ∂L/∂C_c(p) · T_i(p) (c_i − B_i(p))_c · alpha_i · f'(a),
 *
 * f' the slope of the fill rule (nonzero: sign(a) where |a| < 1; evenodd: the sign of the fold).
 * An entry whose draw is hidden at its pixel (V = 0, or below such an entry there) has T = 0 and
 * g = 0: raster_taped keeps it out of the pool (drop_hidden_entries). Taping only where
 * ∂L/∂C is not zero would save nothing: none of the kept entries had an exactly zero ∂L/∂C,
 * in `bench raster` (train, 111k entries an iteration) or over a fit's last iterations
 * (the example's procedural wave, 1.1M entries); a fit's residual is nowhere exactly zero.
 * No paths x pixels buffer and no second accumulation of the lines: the tape holds 24 bytes
 * per edge pixel of the band. (The backward pass used to accumulate every draw's lines again
 * and sweep its spans top-down for T: half of its time. T's factors are now multiplied in
 * another association, so T differs from that walk's in the last bits.)
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
 * Edges on pixel boundaries. Clipart puts axis-aligned edges on integer coordinates, and
 * there the loss is not differentiable: the winding integrals of the pixels on both sides are
 * integers (0 and 1, say), the coverage f(a) has a kink at an integer a (|a| at 0, the clamp
 * or the fold at ±1), and moving the edge one way changes only the pixel on that side.
 * Its one-sided derivatives are the boundary integral taken in that pixel with that
 * pixel's one-sided slope of f in the direction the edge moves a there: an edge moving
 * into the pixel on its low side (the side n points to) raises that pixel's a (the right slope
 * f'(a+)), one moving into the high side lowers it (the left slope f'(a−)). The kernel
 * uses their mean, the symmetric derivative: what central finite differences converge to,
 * and never a dead gradient (an optimiser at an integer-aligned rectangle would otherwise see
 * zero and never move it). So each pixel keeps both one-sided slopes, g± = ∂L/∂f · f'(a±)
 * (equal where a is fractional), an edge piece inside a pixel uses (g+ + g−)/2, and a line
 * lying on a column boundary x = X (both ends within rounding of it, SNAP_REL) gives half of
 * its boundary integral to pixel X − 1 and half to pixel X, each with its side's slope; one on
 * a row boundary y = Y likewise to rows Y − 1 and Y. The pixels beside such a line get a tape
 * entry although their a is an integer (mark_boundary_lines), and a band visits a line that
 * only touches its top or bottom (BAND_REACH). Off the canvas a side contributes nothing:
 * an edge on the canvas border gets half of its inside one-sided derivative, which is again
 * the symmetric one.
 *
 * Output. A line may cross several bands; each band writes its partial gradient of the line
 * into its own slot, partial[k][band][line], and gather_line_grads sums the slots of the bands
 * the line crosses in band order. Deterministic, no atomics. (Slots grouped by band: a band
 * writes its chunks' lines side by side; grouped by line, every write was a cache line of its
 * own, n_bands · 16 bytes apart.)
 */

#define FRACTION_EPS 1e-6f /* |a| this close to an integer is treated as interior or exterior */

/* How far (px) outside a band a chunk's box may end and still be visited by the band's
 * gradient walk: a line on the band's top or bottom boundary gives half its integral to the
 * row inside. Must match between raster_backward and gather_line_grads. */
#define BAND_REACH 0.5f

inline float fold(float a, int rule) {
  return rule == RULE_EVENODD ? a - 2.0f * rint(0.5f * a) : a;
}

inline int is_fractional(float a, int rule) {
  const float m = fabs(fold(a, rule));
  return m > FRACTION_EPS && m < 1.0f - FRACTION_EPS;
}

/* One-sided slopes (f'(a+), f'(a−)) of the coverage f = fill_rule_coverage at a. Off the
 * integers both are sign(fold(a)) inside (0, 1) and 0 beyond; at an integer they are the
 * sides of the kink: |a| at 0, the clamp of nonzero at ±1, the fold of evenodd at odd a. */
inline float2 fill_rule_slopes(float a, int rule) {
  const float m = fold(a, rule), n = rint(m);
  if (fabs(m - n) > FRACTION_EPS) {
    const float s = fabs(m) < 1.0f ? sign(m) : 0.0f;
    return (float2)(s, s);
  }
  if (n == 0.0f) return (float2)(1.0f, -1.0f);
  if (rule == RULE_EVENODD) return (float2)(-1.0f, 1.0f); /* fold peaks at odd a */
  if (n == 1.0f) return (float2)(0.0f, 1.0f);
  if (n == -1.0f) return (float2)(-1.0f, 0.0f);
  return (float2)(0.0f);
}

/* Whether the band [fy0, fy1) walks the lines of a chunk with box b for gradients. */
inline int band_reaches(float4 b, float fy0, float fy1, float fw) {
  return !(b.w < fy0 - BAND_REACH || b.y > fy1 + BAND_REACH || b.x > fw + BAND_REACH);
}

inline void grow_hull2(__local float2* buf, int* lo, int* hi, int a, int b) {
  if (*hi < *lo) {
    for (int x = a; x <= b; ++x) buf[x] = (float2)(0.0f);
    *lo = a; *hi = b;
    return;
  }
  for (int x = a; x < *lo; ++x) buf[x] = (float2)(0.0f);
  for (int x = *hi + 1; x <= b; ++x) buf[x] = (float2)(0.0f);
  *lo = min(*lo, a); *hi = max(*hi, b);
}

/* Marks the pixels beside the lines of one draw that lie on a pixel boundary (they need B on
 * the tape and their one-sided slopes although their a may be an integer) and widens the rows'
 * spans and clean accumulation hulls to them. The sweeps read and clear the marks. Returns
 * whether any chunk of the draw reaches the band (band_reaches). */
inline int mark_boundary_lines(__global const float4* L, __global const float4* B,
                               __global const int* S, __global const int2* chunk_lines,
                               int2 chunks, int y0, int rows, int width, int stride,
                               __local float* acc, __local uchar* mark, int* xlo, int* xhi,
                               int* alo, int* ahi) {
  const float fy0 = (float)y0, fy1 = (float)(y0 + rows), fw = (float)width;
  int any = 0;
  for (int c = chunks.x; c < chunks.x + chunks.y; ++c) {
    const float4 b = B[c];
    if (!band_reaches(b, fy0, fy1, fw)) continue;
    any = 1;
    if (!S[c]) continue; /* no line of the chunk on a pixel boundary (chunk_bounds) */
    const int2 range = chunk_lines[c];
    for (int j = range.x; j < range.x + range.y; ++j) {
      const float4 l = L[j];
      float at;
      const int on = line_boundary(l, width, &at);
      if (on == ON_NONE) continue;
      const float X = at, Y = at;
      int r0, r1, c0, c1;
      if (on == ON_COLUMN) { /* pixels X − 1 and X of the rows it crosses */
        r0 = max((int)floor(fmin(l.y, l.w) - fy0), 0);
        r1 = min((int)ceil(fmax(l.y, l.w) - fy0), rows) - 1;
        c0 = (int)clamp(X - 1.0f, 0.0f, fw);
        c1 = (int)clamp(X, -1.0f, fw - 1.0f);
      } else { /* ON_ROW: rows Y − 1 and Y under its x extent */
        r0 = (int)clamp(Y - fy0 - 1.0f, 0.0f, (float)rows);
        r1 = (int)clamp(Y - fy0, -1.0f, (float)(rows - 1));
        c0 = (int)clamp(floor(fmin(l.x, l.z)), 0.0f, fw);
        c1 = (int)clamp(ceil(fmax(l.x, l.z)) - 1.0f, -1.0f, fw - 1.0f);
      }
      if (c0 > c1) continue;
      for (int r = r0; r <= r1; ++r) {
        grow_hull(acc + r * stride, &alo[r], &ahi[r], c0, c1 + 1);
        for (int x = c0; x <= c1; ++x) mark[r * width + x] = 1;
        xlo[r] = min(xlo[r], c0);
        xhi[r] = max(xhi[r], c1);
      }
    }
  }
  return any;
}

/* The forward sweep of one draw's span (composite_span), also pushing an entry onto the tape
 * at every fractional or marked pixel: (B, a) with B the colour below and a the winding
 * integral, and aux = (pixel index in the band, V). V, the product of 1 − α over the draws
 * above the entry's draw up to (not including) the next entry at the same pixel, or to the
 * top, is filled in later: `prod` holds each pixel's running product since its last entry
 * and `last` that entry's index (see replay_band). */
inline void replay_span(__local float* acc, __local uchar* mark, __local float4* out, int* hlo,
                        int* hhi, int xlo, int xhi, int width, float4 color,
                        __global const float4* prow, int painted, int rule,
                        float4 background, __local float4* tape, __local float2* aux, int* tp,
                        int cap, __local float* prod, __local int* last, int row_base) {
  float s = 0.0f;
  const int xe = min(xhi, width - 1);
  grow_hull4(out, hlo, hhi, xlo, xe);
  for (int x = xlo; x <= xe; ++x) {
    s += acc[x];
    acc[x] = 0.0f;
    const int marked = mark[x];
    mark[x] = 0;
    const float4 c = paint_at(color, prow, painted, x);
    const float a = fill_rule_coverage(s, rule) * c.w;
    if (marked || is_fractional(s, rule)) {
      const int l = last[x];
      if (l >= 0 && l < cap) aux[l].y = prod[x];
      if (*tp < cap) {
        tape[*tp] = (float4)((out[x] + background * (1.0f - out[x].w)).xyz, s);
        aux[*tp] = (float2)((float)(row_base + x), 1.0f);
      }
      last[x] = *tp;
      prod[x] = 1.0f;
      ++*tp;
    } else {
      prod[x] *= 1.0f - a;
    }
    if (a > 0.0f) out[x] = (float4)(c.xyz, 1.0f) * a + out[x] * (1.0f - a);
  }
  acc[xe + 1] = 0.0f;
  const float cov = fill_rule_coverage(s, rule);
  if (cov * (painted ? 1.0f : color.w) > RESIDUAL_COVERAGE && xe + 1 < width) {
    grow_hull4(out, hlo, hhi, xe + 1, width - 1);
    for (int x = xe + 1; x < width; ++x) {
      const float4 c = paint_at(color, prow, painted, x);
      const float a = cov * c.w;
      prod[x] *= 1.0f - a;
      out[x] = (float4)(c.xyz, 1.0f) * a + out[x] * (1.0f - a);
    }
  }
}

/* ∂L/∂a of cell `cell` of a row for an edge piece: the mean of its one-sided values inside
 * the pixel (side 0), half of the right one (side 1) or of the left one (side −1) for a line on
 * the pixel's boundary. Cells off the canvas see nothing. */
inline float cell_grad(__local const float2* g, int cell, int width, int side) {
  if (cell < 0 || cell >= width) return 0.0f;
  const float2 v = g[cell];
  return side == 0 ? 0.5f * (v.x + v.y) : 0.5f * (side > 0 ? v.x : v.y);
}

/* The gradient (∂e0, ∂e1) of one line from the pixels of row `row` it crosses (or, for a line
 * on a row boundary, borders); `on` and `at` from line_boundary. */
inline float4 walk_line_grad(float4 l, int on, float at, int row, int width,
                             __local const float2* g) {
  const float2 e0 = l.xy, d = l.zw - l.xy;
  const float X = at, Y = at;
  float ta, tb;
  int side = 0; /* which one-sided value the cells of this row give (cell_grad) */
  if (on == ON_ROW) {
    /* On y = Y: row Y is below it, the low side when d.x > 0 (n = (0, d.x)). */
    if ((float)row != Y && (float)row != Y - 1.0f) return (float4)(0.0f);
    side = ((float)row == Y) == (d.x > 0.0f) ? 1 : -1;
    ta = 0.0f;
    tb = 1.0f;
  } else if (d.y == 0.0f) {
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
  if (on == ON_COLUMN) {
    /* On x = X: pixel X − 1 is left of it, the low side when d.y > 0 (n = (−d.y, d.x)). */
    const int right = (int)clamp(X, -1.0f, w + 1.0f);
    const float gp = d.y > 0.0f ? cell_grad(g, right - 1, width, 1) + cell_grad(g, right, width, -1)
                                : cell_grad(g, right - 1, width, -1) + cell_grad(g, right, width, 1);
    c0 = gp * ((tb - ta) - 0.5f * (tb * tb - ta * ta));
    c1 = gp * 0.5f * (tb * tb - ta * ta);
  } else if (d.x == 0.0f) {
    const float x = e0.x;
    if (x >= 0.0f && x < w) {
      const float gp = cell_grad(g, (int)x, width, side);
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
        const float gp = cell_grad(g, cell, width, side);
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

/* The forward pass of one band replayed bottom-up with its tape: every draw's span composited
 * into band_rgba (the rows' hulls in hlo, hhi) and an entry pushed onto `tape` and `aux` at
 * each pixel whose winding integral is fractional or that borders a line on a pixel boundary,
 * in the order (draw, row, x) (replay_span); draw_tape[d] gets the index of draw d's first
 * entry. Returns the tape's length, which may exceed `cap` (the entries past it are not
 * stored). `mark` must be clear; it is clear again after. `prod` and `last` are scratch of
 * rows × width (filled here). Shared by raster_taped and raster_backward's fallback, so both
 * tape the same bits. */
inline int replay_band(__global const float4* L, __global const float4* B,
                       __global const int* S, __global const int2* draw_chunks, __global const int2* chunk_lines,
                       __global const float4* draw_color, __global const int* draw_rule,
                       __global const int* draw_paint, __global const float4* paint, int height,
                       int n_draws, int y0, int rows, int width, int stride, __local float* acc,
                       __local float4* band_rgba, __local uchar* mark, float4 background,
                       __local float4* tape, __local float2* aux, int cap,
                       __global int* draw_tape, int* hlo, int* hhi, __local float* prod,
                       __local int* last) {
  int xlo[BAND_H], xhi[BAND_H], alo[BAND_H], ahi[BAND_H];
  for (int r = 0; r < BAND_H; ++r) {
    xlo[r] = width; xhi[r] = -1;
    alo[r] = width + 2; ahi[r] = -1;
    hlo[r] = width; hhi[r] = -1;
  }
  for (int i = 0; i < rows * width; ++i) {
    prod[i] = 1.0f;
    last[i] = -1;
  }
  int tp = 0;
  for (int d = 0; d < n_draws; ++d) {
    draw_tape[d] = tp;
    accumulate_draw(L, B, chunk_lines, draw_chunks[d], y0, rows, width, stride, acc, xlo, xhi,
                    alo, ahi);
    mark_boundary_lines(L, B, S, chunk_lines, draw_chunks[d], y0, rows, width, stride, acc, mark,
                        xlo, xhi, alo, ahi);
    const float4 color = draw_color[d];
    const int rule = draw_rule[d];
    const int painted = draw_paint[d] >= 0;
    __global const float4* pimg = paint_image(paint, draw_paint[d], width, height);
    prefetch_paint(pimg, painted, y0, rows, xlo, xhi, width);
    for (int r = 0; r < rows; ++r) {
      if (xhi[r] >= xlo[r])
        replay_span(acc + r * stride, mark + r * width, band_rgba + r * width, &hlo[r], &hhi[r],
                    xlo[r], xhi[r], width, color, pimg + (size_t)(y0 + r) * width, painted, rule,
                    background, tape, aux, &tp, cap, prod + r * width, last + r * width,
                    r * width);
      xlo[r] = width;
      xhi[r] = -1;
    }
  }
  /* Each pixel's last entry gets the product of the draws above it (its V up to the top).
   * A walk over the entries, not the band's pixels: a fraction of them are on the tape. */
  for (int e = 0; e < min(tp, cap); ++e) {
    const int px = (int)aux[e].x;
    if (last[px] == e) aux[e].y = prod[px];
  }
  return tp;
}

/* Drops from a band's tape (raster_taped, before the pool gets it) the entries whose draw is
 * hidden at their pixel: raster_backward would find T = 0 there and give them g = 0 exactly
 * (its T != 0 test). An entry is hidden when its V is 0 (a draw above it, up to the pixel's next
 * entry, covers the pixel opaquely: 1 − α = 0) or when the pixel's next entry above is hidden
 * (T is a product down the pixel's entries, so a zero stays). What the backward does without
 * them gives the same bits: the entries at a pixel are visited top-down and the hidden ones are
 * the last of them, so no kept entry reads a T they wrote; their ∂L/∂a cells read +0 whether
 * written as g = 0 or left cleared (the walk's ±0 terms add nothing to a sum begun at +0).
 * In a layered drawing a fifth to a third of the entries (the train and sushi of `bench
 * raster`): the pool's copies of them both ways and the backward's visit go. Marks a dropped
 * entry with V = −1 (a kept V is >= 0) and returns how many are kept. `last` is replay_band's
 * (each pixel's last entry), overwritten: a pixel's first visit here finds its own index there
 * (>= 0), later ones whether the entry above was hidden (−2) or not (−3). */
inline int drop_hidden_entries(__local float2* aux, int tp, __local int* last) {
  int kept = 0;
  for (int e = tp - 1; e >= 0; --e) { /* (draw, row, x) backwards: each pixel's entries top-down */
    const int px = (int)aux[e].x;
    const int hidden = last[px] == -2 || aux[e].y == 0.0f;
    last[px] = hidden ? -2 : -3;
    if (hidden)
      aux[e].y = -1.0f;
    else
      ++kept;
  }
  return kept;
}

/* The fit's forward pass: raster's OUT_RESIDUAL output (loss.cl's first step), made by
 * replay_band so that the band's tape comes out of the same sweep. The tape is copied to a
 * pool in global memory, at an offset taken with an atomic add (the order in which bands
 * finish decides where a tape lies, never what it holds), and raster_backward reads it back
 * instead of replaying the band: one pass over the draws instead of two. A band whose tape
 * does not fit its local capacity or the pool gets the offset -1 and raster_backward replays
 * it. The pool holds one chunk of frames' tapes (the launch's): raster_backward reads them
 * before the next chunk's raster_taped writes over them, and each chunk counts its entries in
 * its own slot, pool_used[k0], which ends as the total its bands asked for, so the host can
 * grow the pool. */
__kernel void raster_taped(__global const float4* lines,      /* [K][n_lines] */
                           __global const int2* draw_chunks,   /* [n_draws] */
                           __global const int2* chunk_lines,   /* [n_chunks] */
                           __global const float4* draw_color,  /* [n_draws] */
                           __global const int* draw_rule,      /* [n_draws] */
                           __global const float4* bounds,      /* [K][n_chunks] */
                           __local float* acc,                 /* [BAND_H][W + 2] */
                           __local float4* band_rgba,          /* [BAND_H][W] */
                           __local uchar* mark,                /* [BAND_H][W] */
                           __local float4* tape, int tape_cap,
                           __global float4* image,             /* [chunk][H][W][3] X', packed (loss.cl) */
                           __global int2* extents,             /* [K][H] its row extents */
                           float4 background,
                           __global float4* pool, int pool_cap,
                           __global int* pool_draw,            /* [K][n_bands][n_draws] */
                           __global int2* pool_at,             /* [K][n_bands] (offset, length) */
                           __global int* pool_used,            /* [K]: [k0] this chunk's */
                           int n_lines, int n_chunks, int n_draws, int n_bands, int width,
                           int height,
                           __global const int* draw_paint,     /* [n_draws] */
                           __global const float4* paint,       /* [n_images][H][W] */
                           __local float* prod,                /* [BAND_H][W] (replay_band) */
                           __local int* last,                  /* [BAND_H][W] */
                           __local float2* aux,                /* [tape_cap] the tape's (pixel, V) */
                           __global float2* pool_aux,          /* [pool_cap] */
                           __constant LossBlur* loss_blur,     /* the residual's blur (prelude.cl) */
                           __global const int* snapped) {      /* [K][n_chunks] (chunk_bounds) */
  /* The frame: the launch's global offset is the first of its chunk (one work-item deep in
   * that dimension, so the global id is the frame); X' holds the chunk's frames only. */
  const int band = get_group_id(0), k = get_global_id(1), k0 = get_global_offset(1);
  const int lid = get_local_id(0), lsize = get_local_size(0);
  const int y0 = band * BAND_H, rows = min(BAND_H, height - y0);
  __local int hull[4 * MAX_BAND_H];
  if (lid == 0) {
    int hlo[BAND_H], hhi[BAND_H];
    for (int i = 0; i < rows * width; ++i) mark[i] = 0;
    const int slot = k * n_bands + band;
    const int tp = replay_band(lines + (size_t)k * n_lines, bounds + (size_t)k * n_chunks,
                               snapped + (size_t)k * n_chunks, draw_chunks, chunk_lines, draw_color, draw_rule, draw_paint, paint,
                               height, n_draws, y0, rows, width, width + 2, acc, band_rgba, mark,
                               background, tape, aux, tape_cap,
                               pool_draw + (size_t)slot * n_draws, hlo, hhi, prod, last);
    int2 at = (int2)(-1, tp);
    if (tp <= tape_cap) {
      __global int* draw_tape = pool_draw + (size_t)slot * n_draws;
      const int kept = drop_hidden_entries(aux, tp, last);
      const int off = atomic_add(pool_used + k0, kept);
      if (off <= pool_cap - kept) {
        /* The kept entries, each draw's still in a run: draw_tape[d] becomes its run's start. */
        for (int d = 0, i = 0, e = 0; d < n_draws; ++d) {
          const int e1 = d + 1 < n_draws ? draw_tape[d + 1] : tp; /* read before it is rewritten */
          draw_tape[d] = i;
          for (; e < e1; ++e)
            if (aux[e].y >= 0.0f) {
              pool[off + i] = tape[e];
              pool_aux[off + i] = aux[e];
              ++i;
            }
        }
        at = (int2)(off, kept);
      }
    }
    pool_at[slot] = at;
    for (int r = 0; r < rows; ++r) {
      hull[2 * r] = hlo[r];
      hull[2 * r + 1] = hhi[r];
    }
  }
  barrier(CLK_LOCAL_MEM_FENCE);
  LOSS_BLUR_PRIVATE; /* after the barrier: nothing private of it lives across one */
  write_band(lb, band_rgba, hull, image, (__global uchar4*)image, extents + (size_t)k0 * height, background,
             OUT_RESIDUAL, k - k0, y0, rows, width, height, lid, lsize);
}

__kernel void raster_backward(__global const float4* lines,      /* [K][n_lines] */
                              __global const int2* draw_chunks,   /* [n_draws] */
                              __global const int2* chunk_lines,   /* [n_chunks] */
                              __global const float4* draw_color,  /* [n_draws] */
                              __global const int* draw_rule,      /* [n_draws] */
                              __global const float4* bounds,      /* [K][n_chunks] */
                              __global const float* E,            /* [chunk][H][W][3] E' (loss.cl) */
                              __global const int2* ext_e,         /* [K][H] its row extents */
                              __global const half* R,             /* G ∗ Q, half, by tiles (loss.cl) */
                              float grad_scale,                   /* 2w/N */
                              float4 background,
                              __local float* acc,                 /* [BAND_H][W + 2] */
                              __local float4* band_rgba,          /* [BAND_H][W] (replay, then ∂L/∂C) */
                              __local float* band_T,              /* [BAND_H][W] */
                              __local float2* gcell,              /* [BAND_H][W] (g+, g−) */
                              __local uchar* mark,                /* [BAND_H][W] */
                              __local float4* tape, int tape_cap,
                              __global const float4* pool,        /* raster_taped's tapes */
                              __global int* pool_draw,            /* [K][n_bands][n_draws] */
                              __global const int2* pool_at,       /* [K][n_bands] */
                              __global float4* partial,           /* [chunk][n_bands][n_lines] */
                              __global int* overflow,             /* [1]: tape overflows */
                              int n_lines, int n_chunks, int n_draws, int n_bands, int width,
                              int height,
                              __global const int* draw_paint,     /* [n_draws] */
                              __global const float4* paint,       /* [n_images][H][W] */
                              __local int* last,                  /* [BAND_H][W] (replay) */
                              __local float2* aux,                /* [tape_cap] */
                              __global const float2* pool_aux,    /* raster_taped's (pixel, V) */
                              __global const int* tiles,          /* R's tile index (loss.cl) */
                              __constant LossBlur* loss_blur,     /* the loss's blur (prelude.cl) */
                              __global const int* snapped) {      /* [K][n_chunks] (chunk_bounds) */
  /* The frame, and E' of the chunk's frames only, as in raster_taped. */
  const int band = get_group_id(0), k = get_global_id(1), k0 = get_global_offset(1);
  const int lid = get_local_id(0), lsize = get_local_size(0);
  const int y0 = band * BAND_H, rows = min(BAND_H, height - y0);
  const float fy0 = (float)y0, fy1 = (float)(y0 + rows), fw = (float)width;
  const int stride = width + 2;

  if (lid == 0) {
    LOSS_BLUR_PRIVATE; /* within work-item 0's part: nothing private of it lives across a barrier */
    __global const float4* L = lines + (size_t)k * n_lines;
    __global const float4* B = bounds + (size_t)k * n_chunks;
    __global const int* S = snapped + (size_t)k * n_chunks;
    __global const float* Ek = E + (size_t)(k - k0) * height * width * 3;
    __global const int2* Xk = ext_e + (size_t)k * height;
    __global const int* Rt = loss_frame_tiles(tiles, k, width, height);
#ifdef PREFETCH_ROWS
    /* The rows of E' and R this band's edge pixels read (blurred_gradient), within their
     * drawing extents, one prefetch per 64-byte line: the reads come scattered over the draws'
     * edges, and as demand misses each waited for memory. Changes no value. */
    for (int y = max(y0 - LOSS_R, 0); y < min(y0 + rows + LOSS_R, height); ++y) {
      const int2 ex = Xk[y];
      /* E' is packed, 12 bytes a pixel: one prefetch per 16 floats. */
      for (int i = 3 * ex.x; i <= 3 * ex.y + 2; i += 16) PREFETCH(Ek + (size_t)y * width * 3 + i);
      if (y >= y0 && y < y0 + rows)
        for (int x = ex.x; x <= ex.y; x += 8) PREFETCH(R + loss_tile_pixel(Rt, x, y, width) * 4);
    }
#endif
    /* Per row: the valid hull of the lazily cleared ∂L/∂a cells (see grow_hull in raster.cl),
     * and the colour hull of the fallback's replay. */
    int hlo[BAND_H], hhi[BAND_H], glo[BAND_H], ghi[BAND_H];
    for (int r = 0; r < BAND_H; ++r) {
      glo[r] = width;
      ghi[r] = -1;
    }
    const int slot = k * n_bands + band;
    __global int* draw_tape = pool_draw + (size_t)slot * n_draws;

    /* 1. The band's tape: raster_taped's copy, or (when it did not fit the pool) a bottom-up
     *    replay of the forward pass (band_T its running products). */
    const int2 at = pool_at[slot];
    int tp = at.y;
    if (at.x >= 0) {
      for (int i = 0; i < tp; ++i) {
        tape[i] = pool[at.x + i];
        aux[i] = pool_aux[at.x + i];
      }
    } else {
      for (int i = 0; i < rows * width; ++i) mark[i] = 0;
      tp = replay_band(L, B, S, draw_chunks, chunk_lines, draw_color, draw_rule, draw_paint, paint,
                       height, n_draws, y0, rows, width, stride, acc, band_rgba, mark, background,
                       tape, aux, tape_cap, draw_tape, hlo, hhi, band_T, last);
    }
    if (tp > tape_cap) atomic_max(overflow, tp);
    /* band_T: each pixel's transmittance below the entries visited so far (W in the essay). */
    for (int i = 0; i < rows * width; ++i) band_T[i] = 1.0f;
    /* band_rgba (the fallback replay's colours, not read again) keeps ∂L/∂C of each pixel with
     * an entry once computed (w = 1): it depends on the pixel alone, and where draws overlap
     * (a fill and its stroke, shapes that touch) several entries share a pixel. */
    for (int e = 0; e < min(tp, tape_cap); ++e) band_rgba[(int)aux[e].x].w = 0.0f;

    /* 2. Top-down: ∂L/∂a at each of the draw's entries, then the boundary integrals of its
     *    lines. Only the tape is visited: no accumulation, no sweep. */
    for (int d = n_draws - 1; d >= 0; --d) {
      const int2 chunks = draw_chunks[d];
      const float4 color = draw_color[d];
      const int rule = draw_rule[d];
      const int painted = draw_paint[d] >= 0;
      __global const float4* pimg = paint_image(paint, draw_paint[d], width, height);
      const int e0 = draw_tape[d], e1 = min(d + 1 < n_draws ? draw_tape[d + 1] : tp, tape_cap);
#ifdef PREFETCH_ROWS
      /* A painted draw's colour at its entries, prefetched before the walk over them: read on
       * demand, between one entry's 25-tap ∂L/∂C and the next, each waited for memory (over
       * half of this kernel's own time on a scene of gradients, sunrise). Changes no value. */
      if (painted)
        for (int e = e0; e < e1; ++e) PREFETCH(pimg + (size_t)y0 * width + (int)aux[e].x);
#endif
      for (int e = e0; e < e1; ++e) {
        const float4 b = tape[e];
        const float2 u = aux[e];
        const int px = (int)u.x, r = px / width, x = px - r * width;
        const float4 c = paint_at(color, pimg + (size_t)(y0 + r) * width, painted, x);
        const float T = u.y * band_T[px];
        float2 g = (float2)(0.0f);
        /* Where the draws in front are opaque (T = 0) the pixel's colour does not depend on
         * this draw: g is 0 exactly, without the 25-tap ∂L/∂C (whose reads of E' and R miss
         * the cache; in a layered scene most of the lower draws' edges are hidden). */
        if (T != 0.0f) {
          if (band_rgba[px].w == 0.0f)
            band_rgba[px] = (float4)(blurred_gradient(lb, Ek, Xk, R, Rt, x, y0 + r, width, height, grad_scale), 1.0f);
          const float3 dC = band_rgba[px].xyz;
          const float ga = dot(dC, T * (c.xyz - b.xyz));
          g = ga * c.w * fill_rule_slopes(b.w, rule);
        }
        grow_hull2(gcell + r * width, &glo[r], &ghi[r], x, x);
        gcell[px] = g;
        band_T[px] = T * (1.0f - fill_rule_coverage(b.w, rule) * c.w);
      }
      for (int c = chunks.x; c < chunks.x + chunks.y; ++c) {
        const float4 b = B[c];
        if (!band_reaches(b, fy0, fy1, fw)) continue;
        const int2 range = chunk_lines[c];
        const int snap = S[c];
        if (e0 == e1) {
          /* No entry of the draw in the band (none, or every one hidden: raster_taped's
           * drop_hidden_entries): every cell its lines cross reads +0, and their walks give
           * +0 (a sum of ±0 terms begun at +0). */
          for (int j = range.x; j < range.x + range.y; ++j)
            partial[((size_t)(k - k0) * n_bands + band) * n_lines + j] = (float4)(0.0f);
          continue;
        }
        for (int j = range.x; j < range.x + range.y; ++j) {
          const float4 l = L[j];
          const float ymin = fmin(l.y, l.w) - fy0, ymax = fmax(l.y, l.w) - fy0;
          int r0 = max((int)floor(ymin), 0), r1 = min((int)ceil(ymax), rows) - 1;
          /* A chunk without a line on a pixel boundary needs no test of its lines. */
          float at = 0.0f;
          const int on = snap ? line_boundary(l, width, &at) : ON_NONE;
          if (on == ON_ROW) { /* rows Y − 1 and Y border it */
            r0 = (int)clamp(at - fy0 - 1.0f, 0.0f, (float)rows);
            r1 = (int)clamp(at - fy0, -1.0f, (float)(rows - 1));
          }
          /* The walk reads ∂L/∂a at the cells the line crosses or borders: make them valid. */
          const int ca = (int)clamp(floor(fmin(l.x, l.z)) - 1.0f, 0.0f, fw - 1.0f);
          const int cb = (int)clamp(floor(fmax(l.x, l.z)), 0.0f, fw - 1.0f);
          float4 g = (float4)(0.0f);
          for (int r = r0; r <= r1; ++r) {
            grow_hull2(gcell + r * width, &glo[r], &ghi[r], ca, cb);
            g += walk_line_grad(l, on, at, y0 + r, width, gcell + r * width);
          }
          partial[((size_t)(k - k0) * n_bands + band) * n_lines + j] = g;
        }
      }
      for (int e = e0; e < e1; ++e) gcell[(int)aux[e].x] = (float2)(0.0f);
    }
  }
}

/* ∂L/∂line: the sum of a line's band partials, over the bands that visited it, in order. Run
 * for each chunk of frames after its raster_backward (the launch's offset is its first frame):
 * the partials are the chunk's only. */
__kernel void gather_line_grads(__global const float4* lines, __global const int* line_chunk,
                                __global const float4* bounds, __global const float4* partial,
                                __global float4* line_grad, int n_lines, int n_chunks,
                                int n_bands, int width, int height) {
  const int j = get_global_id(0), k = get_global_id(1), k0 = get_global_offset(1);
  if (j >= n_lines) return;
  const float4 l = lines[(size_t)k * n_lines + j];
  const float4 b = bounds[(size_t)k * n_chunks + line_chunk[j]];
  const float ymin = fmin(l.y, l.w) - BAND_REACH, ymax = fmax(l.y, l.w) + BAND_REACH;
  const int b0 = clamp((int)floor(ymin / (float)BAND_H), 0, n_bands - 1);
  const int b1 = clamp((int)floor(ymax / (float)BAND_H), 0, n_bands - 1);
  float4 g = (float4)(0.0f);
  for (int band = b0; band <= b1; ++band) {
    const int y0 = band * BAND_H, rows = min(BAND_H, height - y0);
    const float fy0 = (float)y0, fy1 = (float)(y0 + rows);
    if (!band_reaches(b, fy0, fy1, (float)width)) continue; /* the band skipped it */
    g += partial[((size_t)(k - k0) * n_bands + band) * n_lines + j];
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
