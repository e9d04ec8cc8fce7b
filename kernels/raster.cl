/* raster.cl: exact area coverage and painter's-order compositing, one pixel row per work-item.
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
 * Plain form of the fused loop, for reference:
 *     for draw d in order: acc = 0; for line in d: accumulate(line); s = 0;
 *       for x: s += acc[x]; c = coverage(s); out[x] = c * col_d + (1 - c * a_d) * out[x]
 */

/* Below this, a coverage left over after a draw's last edge is rounding noise of a closed
 * contour (float sums of dy), not geometry: 1e-5 is far under one 8-bit step. */
#define RESIDUAL_COVERAGE 1e-5f

/* Adds one line's contribution inside row `row` to the accumulation cells. Tracks the span of
 * cells touched in [*xlo, *xhi]. The part of a line right of the canvas is dropped. */
inline void accumulate_line(float4 l, int row, int width, __global float* acc, int* xlo,
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

/* Sweeps cells [xlo, xhi] (clamped to the row), compositing one draw over `out`. Past xhi the
 * cells are zero, so a winding integral still nonzero there (the draw's closing edges lie right
 * of the canvas) is a constant coverage for the rest of the row. */
inline void composite_span(__global float* acc, __global float4* out, int xlo, int xhi,
                           int width, float4 color, int rule) {
  float s = 0.0f;
  const int xe = min(xhi, width - 1);
  const float4 premul = (float4)(color.xyz, 1.0f);
  for (int x = xlo; x <= xe; ++x) {
    s += acc[x];
    acc[x] = 0.0f;
    const float a = fill_rule_coverage(s, rule) * color.w;
    if (a > 0.0f) out[x] = premul * a + out[x] * (1.0f - a);
  }
  acc[xe + 1] = 0.0f; /* the spill cell of the last pixel */
  const float a = fill_rule_coverage(s, rule) * color.w;
  if (a > RESIDUAL_COVERAGE)
    for (int x = xe + 1; x < width; ++x) out[x] = premul * a + out[x] * (1.0f - a);
}

__kernel void raster(__global const float4* lines,     /* [K][n_lines] */
                     __global const int* line_draw,    /* [n_lines] draw index */
                     __global const float4* draw_color,/* [n_draws] rgb, alpha * opacity */
                     __global const int* draw_rule,    /* [n_draws] */
                     __global const int* bins, __global const int* bin_count,
                     __global float* acc_buf,          /* [K][H][W + 2] scratch */
                     __global float4* image,           /* [K][H][W] premultiplied RGBA */
                     int n_lines, int n_bands, int width, int height) {
  const int row = get_global_id(0), k = get_global_id(1);
  if (row >= height) return;
  const int band = row / BAND_H;
  __global float* acc = acc_buf + ((size_t)k * height + row) * (width + 2);
  __global float4* out = image + ((size_t)k * height + row) * width;
  for (int x = 0; x < width + 2; ++x) acc[x] = 0.0f;
  for (int x = 0; x < width; ++x) out[x] = (float4)(0.0f);

  __global const float4* L = lines + (size_t)k * n_lines;
  __global const int* list = bins + ((size_t)k * n_bands + band) * n_lines;
  const int count = bin_count[(size_t)k * n_bands + band];
  int cur = -1, xlo = width, xhi = -1;
  for (int e = 0; e < count; ++e) {
    const int j = list[e];
    const int d = line_draw[j];
    if (d != cur) {
      if (xhi >= xlo) composite_span(acc, out, xlo, xhi, width, draw_color[cur], draw_rule[cur]);
      cur = d; xlo = width; xhi = -1;
    }
    accumulate_line(L[j], row, width, acc, &xlo, &xhi);
  }
  if (cur >= 0 && xhi >= xlo) composite_span(acc, out, xlo, xhi, width, draw_color[cur], draw_rule[cur]);
}

/* Converts premultiplied float RGBA to 8-bit straight RGBA, over `background` (premultiplied;
 * (1,1,1,1) for white, 0 for transparent). One work-item per pixel of all K frames. */
__kernel void to_rgba8(__global const float4* image, __global uchar4* rgba, float4 background,
                       int n_pixels) {
  const int i = get_global_id(0);
  if (i >= n_pixels) return;
  float4 c = image[i];
  c = c + background * (1.0f - c.w);
  const float a = c.w;
  float3 rgb = a > 0.0f ? c.xyz / a : (float3)(0.0f);
  rgb = clamp(rgb, 0.0f, 1.0f);
  rgba[i] = convert_uchar4_sat_rte((float4)(rgb, clamp(a, 0.0f, 1.0f)) * 255.0f);
}
