/* bin.cl: sorts line segments into horizontal bands of BAND_H pixel rows.
 *
 * The raster kernel gives each pixel row to one work-item; without bins every row would test
 * every line. Here one work-item per (band, frame) walks all lines of its frame in order and
 * keeps those whose vertical extent overlaps the band, so each band's list stays in draw
 * order (the raster kernel's compositing depends on it) and the result is deterministic.
 *
 * Kept: lines that cross the band vertically and are not entirely right of the canvas. Lines
 * left of the canvas stay: they still contribute winding ("cover") to every pixel to their
 * right. Horizontal lines contribute nothing and are dropped.
 */
__kernel void bin_lines(__global const float4* lines, /* [K][n_lines] */
                        __global int* bins,           /* [K][n_bands][n_lines] line indices */
                        __global int* bin_count,      /* [K][n_bands] */
                        int n_lines, int n_bands, int width) {
  const int band = get_global_id(0), k = get_global_id(1);
  if (band >= n_bands) return;
  const float y0 = (float)(band * BAND_H), y1 = y0 + (float)BAND_H;
  __global const float4* L = lines + (size_t)k * n_lines;
  __global int* out = bins + ((size_t)k * n_bands + band) * n_lines;
  int n = 0;
  for (int j = 0; j < n_lines; ++j) {
    const float4 l = L[j];
    const float ymin = fmin(l.y, l.w), ymax = fmax(l.y, l.w);
    if (ymax > y0 && ymin < y1 && ymin < ymax && fmin(l.x, l.z) < (float)width) out[n++] = j;
  }
  bin_count[(size_t)k * n_bands + band] = n;
}
