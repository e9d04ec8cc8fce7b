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
 * (the plain form: ∂L/∂C[p] = Σ_q G[q - p] · 2w/N · E[q], the same stencil). So the backward is
 * the forward blur applied to the scaled residual. Every pass is one work-item per pixel of all
 * K frames, reading a 5-tap neighbourhood: no atomics, and the loss itself is reduced in a fixed
 * order (rows, then one work-item over the rows), so it is bit-reproducible.
 */

/* g for j = 0, ±1, ±2: exp(-j²/2) normalised (0.40262, 0.24420, 0.05449). */
#define G0 0.4026199469f
#define G1 0.2442019099f
#define G2 0.0544886845f

/* D = (C over background) - T for every pixel; premultiplied RGBA in, RGB difference out. */
__kernel void loss_residual(__global const float4* image,  /* [K][H][W] premultiplied RGBA */
                            __global const float4* target, /* [K][H][W] RGB (w unused) */
                            __global float4* diff, float4 background, int n_pixels) {
  const int i = get_global_id(0);
  if (i >= n_pixels) return;
  const float4 c = image[i];
  const float3 rgb = c.xyz + background.xyz * (1.0f - c.w);
  diff[i] = (float4)(rgb - target[i].xyz, 0.0f);
}

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

/* Per (row, frame): the sum of E² over the row's pixels and channels. */
__kernel void loss_rows(__global const float4* E, __global float* row_sums, int width,
                        int height, int frames) {
  const int y = get_global_id(0), k = get_global_id(1);
  if (y >= height || k >= frames) return;
  __global const float4* e = E + ((size_t)k * height + y) * width;
  float s = 0.0f;
  for (int x = 0; x < width; ++x) s += dot(e[x].xyz, e[x].xyz);
  row_sums[(size_t)k * height + y] = s;
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
