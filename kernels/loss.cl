/* loss.cl: the image loss, a Gaussian-blurred mean squared error, and its gradient.
 *
 * With C the rendered frames composited over the background and T the target frames (RGB),
 *
 *     L = w / N · Σ_{k, pixel, channel} E²,     E = G ∗ (C − T),     N = K · H · W · 3,
 *
 * G the 5x5 Gaussian with σ = 1 (paper, appendix), applied separably as g ⊗ g with
 * g = exp(-j²/2) / Σ over j = -2..2, and zero padding outside the frame. The gradient is
 *
 *     ∂L/∂C = G ∗ (2 w / N · E)
 *
 * because a separable convolution with a symmetric kernel and zero padding is its own adjoint
 * (the plain form: ∂L/∂C[p] = Σ_q G[q - p] · 2w/N · E[q], the same stencil). The backward
 * raster pass needs ∂L/∂C only at pixels an edge crosses, a few percent of all pixels, so it
 * evaluates this 5x5 stencil there (blurred_gradient below) instead of blurring every pixel.
 *
 * The forward raster writes D = C − T already blurred along x (raster.cl, OUT_RESIDUAL; the
 * stand-alone x pass is blur_pass); blur_y_loss_rows blurs along y, keeps E and sums E² per
 * row; loss_total adds the rows in a fixed order. No atomics anywhere: the loss is
 * bit-reproducible.
 */

/* G0, G1, G2: the 1-D Gaussian taps, defined in prelude.cl. */

/* One separable pass of the blur, along x (dir = 0) or y (dir = 1), times `scale`. */
__kernel void blur_pass(__global const float4* src, __global float4* dst, float scale, int dir,
                        int width, int height, int frames) {
  const int x = get_global_id(0), y = get_global_id(1), k = get_global_id(2);
  if (x >= width || y >= height || k >= frames) return;
  __global const float4* f = src + (size_t)k * width * height;
  const int step = dir == 0 ? 1 : width, pos = y * width + x;
  const int at = dir == 0 ? x : y, n = dir == 0 ? width : height;
  float4 s = G0 * f[pos];
  if (at >= 1) s += G1 * f[pos - step];
  if (at + 1 < n) s += G1 * f[pos + step];
  if (at >= 2) s += G2 * f[pos - 2 * step];
  if (at + 2 < n) s += G2 * f[pos + 2 * step];
  dst[(size_t)k * width * height + pos] = scale * s;
}

/* Per (row, frame): E = the y-blur of the x-blurred residual for the row, kept for the
 * backward pass, and the row's Σ E² over pixels and channels (in x order). */
__kernel void blur_y_loss_rows(__global const float4* src, __global float4* E,
                               __global float* row_sums, int width, int height, int frames) {
  const int y = get_global_id(0), k = get_global_id(1);
  if (y >= height || k >= frames) return;
  __global const float4* f = src + (size_t)k * width * height;
  __global float4* e = E + ((size_t)k * height + y) * width;
  float s = 0.0f;
  for (int x = 0; x < width; ++x) {
    const int pos = y * width + x;
    float4 v = G0 * f[pos];
    if (y >= 1) v += G1 * f[pos - width];
    if (y + 1 < height) v += G1 * f[pos + width];
    if (y >= 2) v += G2 * f[pos - 2 * width];
    if (y + 2 < height) v += G2 * f[pos + 2 * width];
    e[x] = v;
    s += dot(v.xyz, v.xyz);
  }
  row_sums[(size_t)k * height + y] = s;
}

/* ∂L/∂C at pixel (x, y) of a frame: the 5x5 stencil of G over E, times 2w/N. */
inline float3 blurred_gradient(__global const float4* E, int x, int y, int width, int height,
                               float scale) {
  const float g[5] = {G2, G1, G0, G1, G2};
  float3 s = (float3)(0.0f);
  for (int dy = -2; dy <= 2; ++dy) {
    const int yy = y + dy;
    if (yy < 0 || yy >= height) continue;
    float3 row = (float3)(0.0f);
    for (int dx = -2; dx <= 2; ++dx) {
      const int xx = x + dx;
      if (xx >= 0 && xx < width) row += g[dx + 2] * E[yy * width + xx].xyz;
    }
    s += g[dy + 2] * row;
  }
  return scale * s;
}

/* One work-item: L = scale · Σ row sums (in order), and per-frame losses. */
__kernel void loss_total(__global const float* row_sums, __global float* loss, float scale,
                         int height, int frames) {
  if (get_global_id(0) != 0) return;
  float total = 0.0f;
  for (int k = 0; k < frames; ++k) {
    float f = 0.0f;
    for (int y = 0; y < height; ++y) f += row_sums[(size_t)k * height + y];
    loss[1 + k] = scale * f;
    total += f;
  }
  loss[0] = scale * total;
}
