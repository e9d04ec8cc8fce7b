/* raster.cl: exact area coverage and painter's-order compositing, one band of rows per
 * work-item.
 *
 * Coverage. The box-filtered coverage of pixel (x, y) by a polygon is the integral of its
 * winding number over the pixel square, a(x, y) = ∫∫_pixel w(u, v) du dv. Summed over the
 * polygon's edges this splits into a per-edge "signed area to the right" (Green's theorem with
 * the x axis as reference): an edge piece inside row y, going from height ya to yb (row-local
 * units, dy = yb - ya, sign = direction) and lying in cell i between x_enter and x_exit,
 * contributes
 *     dy * (i + 1 - x_mid)   to pixel i     (the trapezoid right of the piece),
 *     dy                     to every pixel right of i (full cover).
 * Writing both as deltas, acc[i] += dy * (i + 1 - x_mid), acc[i + 1] += dy * (x_mid - i), a
 * prefix sum along the row recovers a(x, y) for every pixel: work in proportion to boundary
 * length plus covered span, no supersampling, no random samples (the font-rs / stb_truetype
 * accumulation idea; see third_party_notes.md). Then nonzero gives min(1, |a|) and evenodd the
 * fold of a (prelude's fill_rule_coverage). Edges left of the canvas are projected onto x = 0
 * (they add cover only); pieces right of it are dropped, and a winding integral left nonzero
 * after the last touched cell covers the rest of the row.
 *
 * Compositing. Draws (a path's fill, then its stroke) arrive in the band list in paint order.
 * When the draw changes, the previous draw's span is swept once: prefix sum, coverage, and
 * "over" into the row's premultiplied RGBA, alpha = coverage * opacity. The accumulation cells
 * are zeroed during the sweep, so each row needs W + 2 cells of scratch and no paths x pixels
 * buffer exists at any time.
 *
 * Work split. One work-group renders one band of BAND_H rows of one frame. It walks the draws
 * in paint order and their lines chunk by chunk, skipping chunks whose bounding box
 * (chunk_bounds) misses the band, and adds each remaining line to just the rows it crosses.
 * (A work-item per row tested every line of its band BAND_H times, 70% of the time on PoCL;
 * per-band line lists cost a pass over all lines per band; per-draw boxes still left large
 * draws' lines tested by every band they span.)
 * The band's accumulation cells and colours live in local memory and the result is written
 * once, as float RGBA or directly as 8-bit RGBA: clearing and re-reading full-frame float
 * buffers in global memory was a third of the time (memory traffic, not arithmetic).
 *
 * Plain form of the fused loop, for reference:
 *     for draw d in order: acc = 0; for line in d: accumulate(line); s = 0;
 *       for x: s += acc[x]; c = coverage(s); out[x] = c * col_d + (1 - c * a_d) * out[x]
 */

/* Below this, a coverage left over after a draw's last edge is rounding noise of a closed
 * contour (float sums of dy), not geometry: 1e-5 is far under one 8-bit step. */
#define RESIDUAL_COVERAGE 1e-5f

/* Adds one line's contribution inside row `row` to the accumulation cells. Tracks the span of
 * cells touched in [*xlo, *xhi]. The part of a line right of the canvas is dropped. */
inline void accumulate_line(float4 l, int row, int width, __local float* acc, int* xlo,
                            int* xhi) {
  float x0 = l.x, y0 = l.y - (float)row, x1 = l.z, y1 = l.w - (float)row;
  if (y0 == y1) return;
  /* Clip to the row's vertical extent [0, 1], keeping the direction (sign of dy). */
  const float dxdy = (x1 - x0) / (y1 - y0);
  if (y0 < 0.0f) { x0 += (0.0f - y0) * dxdy; y0 = 0.0f; }
  else if (y0 > 1.0f) { x0 += (1.0f - y0) * dxdy; y0 = 1.0f; }
  if (y1 < 0.0f) { x1 += (0.0f - y1) * dxdy; y1 = 0.0f; }
  else if (y1 > 1.0f) { x1 += (1.0f - y1) * dxdy; y1 = 1.0f; }
  const float dy = y1 - y0;
  if (dy == 0.0f) return;

  /* Work left to right; the sign of dy carries the direction. */
  float xa = fmin(x0, x1);
  const float xb = fmax(x0, x1), w = (float)width;
  if (xa >= w) return;
  if (xb == xa) { /* vertical: one cell */
    const int i = (int)fmax(xa, 0.0f);
    const float xm = fmax(xa, 0.0f) - (float)i;
    acc[i] += dy * (1.0f - xm);
    acc[i + 1] += dy * xm;
    *xlo = min(*xlo, i);
    *xhi = max(*xhi, i + 1);
    return;
  }
  const float dy_per_x = dy / (xb - xa);
  if (xa < 0.0f) { /* the part left of x = 0 is pure cover for the whole row */
    acc[0] += dy_per_x * (fmin(xb, 0.0f) - xa);
    *xlo = 0;
    *xhi = max(*xhi, 0);
    if (xb <= 0.0f) return;
    xa = 0.0f;
  }
  const float xend = fmin(xb, w);
  int i = (int)xa;
  *xlo = min(*xlo, i);
  for (float xc = xa; xc < xend; ++i) {
    const float xn = fmin((float)(i + 1), xend);
    const float share = dy_per_x * (xn - xc);
    const float xm = 0.5f * (xc + xn) - (float)i;
    acc[i] += share * (1.0f - xm);
    acc[i + 1] += share * xm;
    xc = xn;
  }
  *xhi = max(*xhi, i);
}

/* Lazily cleared row buffers. A band's rows are not cleared up front: each row keeps the hull
 * [lo, hi] of cells known to be valid (zero, or written since), and grows it, zeroing only the
 * new cells, before a line or span touches cells outside it. Pixels no draw reaches are never
 * touched at all and come out as background. (Clearing and converting every pixel of every
 * band was 90% of a three-path frame.) */
inline void grow_hull_fill(__local float* buf, int* lo, int* hi, int a, int b, float value) {
  if (*hi < *lo) {
    for (int x = a; x <= b; ++x) buf[x] = value;
    *lo = a; *hi = b;
    return;
  }
  for (int x = a; x < *lo; ++x) buf[x] = value;
  for (int x = *hi + 1; x <= b; ++x) buf[x] = value;
  *lo = min(*lo, a); *hi = max(*hi, b);
}

inline void grow_hull(__local float* buf, int* lo, int* hi, int a, int b) {
  grow_hull_fill(buf, lo, hi, a, b, 0.0f);
}

inline void grow_hull4(__local float4* buf, int* lo, int* hi, int a, int b) {
  if (*hi < *lo) {
    for (int x = a; x <= b; ++x) buf[x] = (float4)(0.0f);
    *lo = a; *hi = b;
    return;
  }
  for (int x = a; x < *lo; ++x) buf[x] = (float4)(0.0f);
  for (int x = *hi + 1; x <= b; ++x) buf[x] = (float4)(0.0f);
  *lo = min(*lo, a); *hi = max(*hi, b);
}

/* Adds the lines of one draw that reach this band (chunks culled by their boxes) to the rows'
 * accumulation cells, growing each row's clean hull [alo, ahi] first. Returns whether any chunk
 * reached the band. Shared by the forward and backward raster kernels, which must visit the
 * same lines in the same order to get the same bits. */
inline int accumulate_draw(__global const float4* L, __global const float4* B,
                           __global const int2* chunk_lines, int2 chunks, int y0, int rows,
                           int width, int stride, __local float* acc, int* xlo, int* xhi,
                           int* alo, int* ahi) {
  const float fy0 = (float)y0, fy1 = (float)(y0 + rows), fw = (float)width;
  int any = 0;
  for (int c = chunks.x; c < chunks.x + chunks.y; ++c) {
    const float4 b = B[c];
    if (b.w <= fy0 || b.y >= fy1 || b.x >= fw) continue; /* misses the band or right of canvas */
    any = 1;
    const int2 range = chunk_lines[c];
    for (int j = range.x; j < range.x + range.y; ++j) {
      /* Each line visits only the rows of this band it crosses. */
      const float4 l = L[j];
      const float ymin = fmin(l.y, l.w) - fy0, ymax = fmax(l.y, l.w) - fy0;
      const int r0 = max((int)floor(ymin), 0), r1 = min((int)ceil(ymax), rows) - 1;
      if (r0 > r1) continue;
      /* The cells the line can write in any row (accumulate_line's i and i + 1). */
      const int ca = (int)clamp(floor(fmin(l.x, l.z)), 0.0f, fw);
      const int cb = (int)clamp(floor(fmax(l.x, l.z)) + 1.0f, 0.0f, fw + 1.0f);
      for (int r = r0; r <= r1; ++r) {
        grow_hull(acc + r * stride, &alo[r], &ahi[r], ca, max(ca, cb));
        accumulate_line(l, y0 + r, width, acc + r * stride, &xlo[r], &xhi[r]);
      }
    }
  }
  return any;
}

/* Sweeps cells [xlo, xhi] (clamped to the row), compositing one draw over `out` (whose valid
 * hull is [*hlo, *hhi]). Past xhi the cells are zero, so a winding integral still nonzero there
 * (the draw's closing edges lie right of the canvas) is a constant coverage for the rest of the
 * row. */
/* The draw's straight colour and alpha at pixel x of a row: its flat colour, or its paint
 * image's row (a gradient, RasterPlan::paint) when `painted`. */
inline float4 paint_at(float4 color, __global const float4* prow, int painted, int x) {
  return painted ? prow[x] : color;
}

/* The first row of draw image `p`'s paint (any valid address when p < 0: paint_at ignores it). */
inline __global const float4* paint_image(__global const float4* paint, int p, int width,
                                          int height) {
  return paint + (size_t)max(p, 0) * height * width;
}

/* Prefetches the rows of a painted draw's image that the band's sweeps will read (each row's
 * span [xlo, xhi], 4 pixels to a 64-byte line). A row of a 256 px paint image is a 4 kB page of
 * its own, on which the hardware's streamer starts cold: the sweeps' reads of it waited for
 * memory (half of the backward sweep's time on a scene of gradients). */
inline void prefetch_paint(__global const float4* pimg, int painted, int y0, int rows,
                           const int* xlo, const int* xhi, int width) {
#ifdef PREFETCH_ROWS
  if (!painted) return;
  for (int r = 0; r < rows; ++r) {
    __global const float4* prow = pimg + (size_t)(y0 + r) * width;
    for (int x = xlo[r]; x <= min(xhi[r], width - 1); x += 4) PREFETCH(prow + x);
  }
#endif
}

inline void composite_span(__local float* acc, __local float4* out, int* hlo, int* hhi, int xlo,
                           int xhi, int width, float4 color, __global const float4* prow,
                           int painted, int rule) {
  float s = 0.0f;
  const int xe = min(xhi, width - 1);
  grow_hull4(out, hlo, hhi, xlo, xe);
  for (int x = xlo; x <= xe; ++x) {
    s += acc[x];
    acc[x] = 0.0f;
    const float4 c = paint_at(color, prow, painted, x);
    const float a = fill_rule_coverage(s, rule) * c.w;
    if (a > 0.0f) out[x] = (float4)(c.xyz, 1.0f) * a + out[x] * (1.0f - a);
  }
  acc[xe + 1] = 0.0f; /* the spill cell of the last pixel */
  const float cov = fill_rule_coverage(s, rule);
  if (cov * (painted ? 1.0f : color.w) > RESIDUAL_COVERAGE && xe + 1 < width) {
    grow_hull4(out, hlo, hhi, xe + 1, width - 1);
    for (int x = xe + 1; x < width; ++x) {
      const float4 c = paint_at(color, prow, painted, x);
      const float a = cov * c.w;
      out[x] = (float4)(c.xyz, 1.0f) * a + out[x] * (1.0f - a);
    }
  }
}

/* Lines on pixel boundaries. Clipart puts axis-aligned edges on integer coordinates, where the
 * coverage has a kink and the backward pass (raster_backward.cl, "Edges on pixel boundaries")
 * takes them apart: the pixels beside such a line get tape entries and its boundary integral
 * is split between them. */
/* A coordinate within SNAP_REL · max(|v|, W) of an integer lies on a pixel boundary. 2^-18:
 * 32 float ulps of the canvas width, above the rounding of the fitter's control points (the
 * motion model works in units of half the canvas, ~6 roundings of 2^-24 of it, and the
 * flattening adds a Bernstein combination), far below any offset a drawing means (4e-3 px at
 * 1024 px): within it, which side of the boundary the float geometry lands on is rounding. */
#define SNAP_REL 3.8146973e-6f

/* Whether v lies on an integer (within rounding on a canvas `extent` wide, SNAP_REL); *n gets
 * the integer. */
inline int on_integer(float v, float extent, float* n) {
  *n = rint(v);
  return fabs(v - *n) <= SNAP_REL * fmax(extent, fabs(v));
}

/* Whether line l lies on the pixel column boundary x = *X (both ends on the same integer). */
inline int on_column(float4 l, float extent, float* X) {
  float b;
  return on_integer(l.x, extent, X) && on_integer(l.z, extent, &b) && b == *X;
}

/* Whether line l lies on the pixel row boundary y = *Y. */
inline int on_row(float4 l, float extent, float* Y) {
  float b;
  return on_integer(l.y, extent, Y) && on_integer(l.w, extent, &b) && b == *Y;
}

/* Where a line lies (line_boundary): inside the pixels it crosses, or on a pixel column or
 * row boundary. */
#define ON_NONE 0
#define ON_COLUMN 1
#define ON_ROW 2

/* ON_COLUMN with *at = X, ON_ROW with *at = Y, or ON_NONE, on a canvas `width` pixels wide. */
inline int line_boundary(float4 l, int width, float* at) {
  /* Both ends on one integer puts them within the sum of their two tolerances of each other:
   * a line neither that nearly vertical nor horizontal (twice the bound, against the rounding
   * of this test) is on no boundary, without the rint of on_integer. A filter only: what it
   * lets through is decided by the tests below. */
  const float fw = (float)width;
  const float tx = 4.0f * SNAP_REL * fmax(fw, fmax(fabs(l.x), fabs(l.z)));
  const float ty = 4.0f * SNAP_REL * fmax(fw, fmax(fabs(l.y), fabs(l.w)));
  if (fabs(l.x - l.z) > tx && fabs(l.y - l.w) > ty) return ON_NONE;
  if (on_column(l, (float)width, at)) return ON_COLUMN;
  if (on_row(l, (float)width, at)) return ON_ROW;
  return ON_NONE;
}

/* The bounding box (xmin, ymin, xmax, ymax) of every chunk of lines (up to 16 consecutive lines
 * of one draw, so spatially coherent) in every frame: a band tests a chunk's box before its
 * lines. And whether any line of the chunk lies on a pixel boundary (line_boundary), in
 * `snapped`: the fit's bands skip the boundary tests of a chunk without one. Classified once
 * per line and frame here, they were made again by every band the chunk reaches, in the taped
 * forward and in the backward: 4% of `bench raster`'s iteration on the train. One work-item per
 * (chunk, frame). */
__kernel void chunk_bounds(__global const float4* lines,    /* [K][n_lines] */
                           __global const int2* chunk_lines, /* [n_chunks] (first line, count) */
                           __global float4* bounds,          /* [K][n_chunks] */
                           int n_lines, int n_chunks,
                           __global int* snapped,            /* [K][n_chunks] */
                           int width) {
  const int c = get_global_id(0), k = get_global_id(1);
  if (c >= n_chunks) return;
  const int2 range = chunk_lines[c];
  __global const float4* L = lines + (size_t)k * n_lines + range.x;
  float4 b = (float4)(INFINITY, INFINITY, -INFINITY, -INFINITY);
  int snap = 0;
  for (int j = 0; j < range.y; ++j) {
    const float4 l = L[j];
    b = (float4)(fmin(b.x, fmin(l.x, l.z)), fmin(b.y, fmin(l.y, l.w)),
                 fmax(b.z, fmax(l.x, l.z)), fmax(b.w, fmax(l.y, l.w)));
    float at;
    snap |= line_boundary(l, width, &at) != ON_NONE;
  }
  bounds[(size_t)k * n_chunks + c] = b;
  snapped[(size_t)k * n_chunks + c] = snap;
}

/* Output of one band: premultiplied float RGBA for tests and previews (OUT_FLOAT), 8-bit
 * straight RGBA over a background for rendering (OUT_RGBA8), or for fitting the drawn part of
 * the image, X = C − background, blurred along x where it is not zero, with each row's extent
 * (OUT_RESIDUAL; the loss's first step, see loss.cl; packed RGB, three floats a pixel). */
#define OUT_FLOAT 0
#define OUT_RGBA8 1
#define OUT_RESIDUAL 2

/* The largest BAND_H a host may choose (the hull table is sized by it). */
#define MAX_BAND_H 64

inline uchar4 to_rgba8_pixel(float4 c, float4 background) {
  c = c + background * (1.0f - c.w);
  const float a = c.w;
  float3 rgb = a > 0.0f ? c.xyz / a : (float3)(0.0f);
  rgb = clamp(rgb, 0.0f, 1.0f);
  return convert_uchar4_sat((float4)(rgb, clamp(a, 0.0f, 1.0f)) * 255.0f + 0.5f); /* round half up */
}

/* X' at pixel x of a row from its X (`f`, valid in [lo, hi]) with each tap tested against
 * the hull: the taps outside it are zero. Taps beyond the frame read it mirrored with
 * LOSS_REFLECTS (prelude.cl); a mirrored pixel lies within LOSS_R of x, so X' still ends
 * LOSS_R beyond the hull. */
inline void x_blur_tested(const LossBlur* lb, __local const float4* f, __global float* o, int x, int lo, int hi,
                          int width) {
  float4 v = (float4)(0.0f);
  for (int j = -LOSS_R; j <= LOSS_R; ++j) {
    const int xx = LOSS_REFLECTS ? loss_reflect(x + j, width) : x + j;
    if (xx >= lo && xx <= hi) v += gv_tap(j) * f[xx];
  }
  vstore3(v.xyz, x, o);
}

/* The output stage of a band (raster and raster_taped): `band_rgba` holds the band's
 * premultiplied colours, valid within each row's hull (hull[2r], hull[2r + 1]); the work-items
 * of the group share the rows. */
inline void write_band(const LossBlur* lb, __local float4* band_rgba, __local const int* hull,
                       __global float4* image, __global uchar4* rgba8, __global int2* extents,
                       float4 background, int out_mode, int k, int y0, int rows, int width,
                       int height, int lid, int lsize) {
  const size_t base = ((size_t)k * height + y0) * width;
  if (out_mode == OUT_RGBA8) {
    /* Outside a row's hull no draw wrote: background. Over an opaque background the result is
     * opaque, so no un-premultiplying there either. */
    const uchar4 bg8 = to_rgba8_pixel((float4)(0.0f), background);
    const int opaque = background.w == 1.0f;
    for (int r = lid; r < rows; r += lsize) {
      const int lo = hull[2 * r], hi = hull[2 * r + 1];
      __local const float4* row = band_rgba + r * width;
      __global uchar4* o = rgba8 + base + (size_t)r * width;
      for (int x = 0; x < width; ++x) {
        if (x < lo || x > hi) {
          o[x] = bg8;
        } else if (opaque) {
          const float4 c = row[x] + background * (1.0f - row[x].w);
          o[x] = convert_uchar4_sat((float4)(c.xyz, 1.0f) * 255.0f + 0.5f);
        } else {
          o[x] = to_rgba8_pixel(row[x], background);
        }
      }
    }
  } else if (out_mode == OUT_RESIDUAL) {
    /* X = C − background = P − a·bg, zero where nothing was drawn, then its x-blur X' for the
     * pixels it can reach (the hull ± 2), with the row's extent for loss.cl. */
#ifdef PREFETCH_ROWS
    /* The lines of X' the rows below will write, for writing, all rows first: as store misses
     * they were a quarter of this stage's time (sushi). Changes no value. */
    for (int r = lid; r < rows; r += lsize) {
      const int lo = hull[2 * r], hi = hull[2 * r + 1];
      __global float* o = (__global float*)image + (base + (size_t)r * width) * 3;
      if (hi >= lo)
        for (int i = 3 * max(lo - LOSS_R, 0); i <= 3 * min(hi + LOSS_R, width - 1) + 2; i += 16) PREFETCH_W(o + i);
    }
#endif
    for (int r = lid; r < rows; r += lsize) {
      const int lo = hull[2 * r], hi = hull[2 * r + 1];
      __global int2* ext = extents + (size_t)k * height + y0 + r;
      if (hi < lo) {
        *ext = (int2)(1, 0); /* empty */
        continue;
      }
      __local float4* f = band_rgba + r * width;
      if (LOSS_YCC) /* the per-group blur works in YCbCr (prelude.cl): X' = x-blur of A·X */
        for (int x = lo; x <= hi; ++x) f[x] = (float4)(ycc_from_rgb(f[x].xyz - background.xyz * f[x].w), 0.0f);
      else
        for (int x = lo; x <= hi; ++x) f[x] = (float4)(f[x].xyz - background.xyz * f[x].w, 0.0f);
      const int lo2 = max(lo - LOSS_R, 0), hi2 = min(hi + LOSS_R, width - 1);
      /* X' packed, three floats a pixel (its fourth channel is 0): a quarter less memory
       * traffic in the loss's passes, which wait for memory. */
      __global float* o = (__global float*)image + (base + (size_t)r * width) * 3;
      /* Taps outside the hull are zero and skipped; in [lo + LOSS_R, hi − LOSS_R] none is, and
       * the taps go without their tests (the same sum in the same order: the same bits). */
      int x = lo2;
#ifndef LOSS_MATCHED
      /* The span without tests, four pixels (sixteen floats) a step, packed to twelve: PoCL
       * kept the pixel loop one float4 a tap. Each float gets the same taps in the same
       * order as below. */
      __local const float* ff = (__local const float*)f;
      for (; x < lo + LOSS_R && x <= hi2; ++x) x_blur_tested(lb, f, o, x, lo, hi, width);
      for (; x + 3 <= hi - LOSS_R; x += 4) {
        float16 v = (float16)(0.0f);
        v += G2 * vload16(0, ff + 4 * (x - 2));
        v += G1 * vload16(0, ff + 4 * (x - 1));
        v += G0 * vload16(0, ff + 4 * x);
        v += G1 * vload16(0, ff + 4 * (x + 1));
        v += G2 * vload16(0, ff + 4 * (x + 2));
        vstore8((float8)(v.s012, v.s456, v.s89), 0, o + 3 * x);
        vstore4((float4)(v.sa, v.scde), 0, o + 3 * x + 8);
      }
#endif
      for (; x <= hi2; ++x) {
        float4 v = (float4)(0.0f);
        if (x >= lo + LOSS_R && x <= hi - LOSS_R) {
#ifdef LOSS_MATCHED
          for (int j = -LOSS_R; j <= LOSS_R; ++j) v += gv_tap(j) * f[x + j];
#else
          /* The loop written out: PoCL kept it a loop with a table lookup per tap (a quarter
           * of raster_taped's own time). Same taps, same order. */
          v += G2 * f[x - 2];
          v += G1 * f[x - 1];
          v += G0 * f[x];
          v += G1 * f[x + 1];
          v += G2 * f[x + 2];
#endif
          vstore3(v.xyz, x, o);
        } else {
          x_blur_tested(lb, f, o, x, lo, hi, width);
        }
      }
      *ext = (int2)(lo2, hi2);
    }
  } else {
    for (int i = lid; i < rows * width; i += lsize) image[base + i] = band_rgba[i];
  }
}

__kernel void raster(__global const float4* lines,      /* [K][n_lines] */
                     __global const int2* draw_chunks,  /* [n_draws] (first chunk, count) */
                     __global const int2* chunk_lines,  /* [n_chunks] (first line, count) */
                     __global const float4* draw_color, /* [n_draws] rgb, alpha * opacity */
                     __global const int* draw_rule,     /* [n_draws] */
                     __global const float4* bounds,     /* [K][n_chunks] from chunk_bounds */
                     __local float* acc,                /* [BAND_H][W + 2] scratch */
                     __local float4* band_rgba,         /* [BAND_H][W] */
                     __global float4* image,            /* [K][H][W] premultiplied (OUT_FLOAT) */
                     __global uchar4* rgba8,            /* [K][H][W] (OUT_RGBA8) */
                     __global int2* extents,            /* [K][H] row extents (OUT_RESIDUAL) */
                     float4 background, int out_mode,
                     int n_lines, int n_chunks, int n_draws, int width, int height,
                     __global const int* draw_paint,    /* [n_draws] paint image or -1 */
                     __global const float4* paint,      /* [n_images][H][W] (RasterPlan::paint) */
                     __constant LossBlur* loss_blur) {  /* the residual's blur (prelude.cl) */
  /* One work-group per (band, frame). Clearing and the final write are spread over the group's
   * work-items (PoCL vectorises such loops across work-items); the draw loop, which must run
   * in paint order, is done by work-item 0. */
  /* k: the frame whose geometry is drawn; slot: where its image goes. A launch offset to a
   * chunk of frames (ClRaster::render_frames) writes them at slots 0.., so the output holds that
   * chunk alone; without an offset the two are the same. */
  const int band = get_group_id(0), k = get_global_id(1), slot = get_group_id(1);
  const int lid = get_local_id(0), lsize = get_local_size(0);
  const int y0 = band * BAND_H, rows = min(BAND_H, height - y0);
  const float fy0 = (float)y0, fy1 = (float)(y0 + rows), fw = (float)width;
  const int stride = width + 2;
  /* Valid hulls of each row's accumulation cells and colours (see grow_hull); shared with the
   * output stage, hence local. */
  __local int hull[4 * MAX_BAND_H];

  if (lid == 0) {
  int xlo[BAND_H], xhi[BAND_H], alo[BAND_H], ahi[BAND_H], hlo[BAND_H], hhi[BAND_H];
  for (int r = 0; r < BAND_H; ++r) {
    xlo[r] = width; xhi[r] = -1;
    alo[r] = width + 2; ahi[r] = -1;
    hlo[r] = width; hhi[r] = -1;
  }
  __global const float4* L = lines + (size_t)k * n_lines;
  __global const float4* B = bounds + (size_t)k * n_chunks;
  for (int d = 0; d < n_draws; ++d) {
    accumulate_draw(L, B, chunk_lines, draw_chunks[d], y0, rows, width, stride, acc, xlo, xhi, alo,
                    ahi);
    const float4 color = draw_color[d];
    const int rule = draw_rule[d];
    const int painted = draw_paint[d] >= 0;
    __global const float4* pimg = paint_image(paint, draw_paint[d], width, height);
    prefetch_paint(pimg, painted, y0, rows, xlo, xhi, width);
    for (int r = 0; r < rows; ++r) {
      if (xhi[r] >= xlo[r])
        composite_span(acc + r * stride, band_rgba + r * width, &hlo[r], &hhi[r], xlo[r], xhi[r],
                       width, color, pimg + (size_t)(y0 + r) * width, painted, rule);
      xlo[r] = width;
      xhi[r] = -1;
    }
  }
  for (int r = 0; r < rows; ++r) {
    if (out_mode == OUT_FLOAT) grow_hull4(band_rgba + r * width, &hlo[r], &hhi[r], 0, width - 1);
    hull[2 * r] = hlo[r];
    hull[2 * r + 1] = hhi[r];
  }
  }
  barrier(CLK_LOCAL_MEM_FENCE);
  LOSS_BLUR_PRIVATE; /* after the barrier: nothing private of it lives across one */
  write_band(lb, band_rgba, hull, image, rgba8, extents, background, out_mode, slot, y0, rows, width,
             height, lid, lsize);
}

