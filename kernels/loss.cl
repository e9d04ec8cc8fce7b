/* loss.cl: the image loss, a Gaussian-blurred mean squared error, and its gradient.
 *
 * With C the rendered frames composited over the background and T the target frames (RGB),
 *
 *     L = w / N · Σ_{k, pixel, channel} E²,     E = G ∗ C − G_t ∗ T,     N = K · H · W · 3,
 *
 * G_t the 5x5 Gaussian with σ = 1 (paper, appendix), applied separably as g ⊗ g with
 * g = exp(-j²/2σ²) / Σ over j = -2..2, and zero padding outside the frame. G, the render's, is
 * the same unless blur matching widened it, to radius LOSS_R (prelude.cl's taps: a video
 * softer than the render is matched by blurring the render as much; raster/loss_taps.h, and
 * the LOSS_MATCHED build, whose taps are the kernels' LossBlur argument).
 * Then only what is drawn takes G: the paper (bg, the same at every pose) is blurred by G_t
 * as the target is, so that E = G ∗ (C − bg) − G_t ∗ (T − bg); with zero padding a wider G on
 * the paper left a band along the frame's border that no pose could fit (see Q below).
 * Only the host touches G_t (in Q below). The gradient is
 *
 *     ∂L/∂C = G ∗ (2 w / N · E)
 *
 * because a separable convolution with a symmetric kernel and zero padding is its own adjoint
 * (the plain form: ∂L/∂C[p] = Σ_q G[q - p] · 2w/N · E[q], the same stencil).
 *
 * With LOSS_REFLECTS (a render σ above 1, prelude.cl) both blurs pad by reflection instead of
 * zeros: a tap beyond the frame reads the pixel mirrored inside it, in the render's passes
 * here and in the host's G_t of the target (raster/loss_taps.h, loss_reflects). The operator
 * is then not its own adjoint within LOSS_R of the border: there ∂L/∂C[p] = Σ_q A[q][p] ·
 * 2w/N · E[q] with A[q][p] the sum of the taps of q that read p (loss_adjoint_taps); every
 * other pixel keeps the stencil. A mirrored pixel lies within LOSS_R of the tap's pixel, so
 * the extents below hold as they are.
 *
 * Only the drawn part changes between iterations. Write C = bg + X with X = P − a·bg, zero
 * wherever nothing is drawn (P the premultiplied render, a its alpha). Then, by linearity,
 *
 *     E = E' + Q,   E' = G ∗ X,   Q = bg·(G_t ∗ 1) − G_t ∗ T,
 *     Σ E² = Σ Q² + Σ (2 Q·E' + E'·E'),
 *     ∂L/∂C = 2w/N · (R + G ∗ E'),   R = G ∗ Q.
 *
 * Chroma blur matching generalises G to a per-group blur in YCbCr (prelude.cl):
 * B = A⁻¹ · diag(G, G_c, G_c) · A, luma sharp at the render σ, chroma soft at its own σ
 * (codecs subsample and quantise chroma harder). Then E' = B X, Q = bg·(G_t 1) − G_t ∗ T,
 * R = Bᵀ Q and ∂L/∂C = 2w/N · (R + Bᵀ E'), Bᵀ = Aᵀ · diag(G, G_c, G_c) · A⁻ᵀ: the raster pass
 * blurs A·X along x, blur_y_loss_rows finishes the blur and keeps A⁻ᵀ E', blurred_gradient
 * blurs that and applies Aᵀ. With G_c = G (LOSS_YCC 0) the passes stay in RGB, the plain form
 * above.
 *
 * Q, R and Σ Q² depend on the targets only and are computed once (ClRaster::set_targets); each
 * iteration touches only the pixels within LOSS_R (or 2 LOSS_R, for the gradient) of something drawn: the
 * work follows the drawing, not the frame. The raster pass writes X' = x-blur of X with each
 * row's extent; blur_y_loss_rows makes E' and the rows' Σ (2 Q·E' + E'·E'); loss_total adds
 * Σ Q²; the backward raster pass evaluates ∂L/∂C at the pixels edges cross
 * (blurred_gradient). Sums run in a fixed order: the loss is bit-reproducible.
 *
 * X' and E' are packed RGB, three floats a pixel (vload3/vstore3): their fourth channel is
 * 0, and these passes wait for memory more than they compute (the same floats, the same bits).
 *
 * Q and R are stored as halves (read with vload_half4, core OpenCL without cl_khr_fp16): they
 * are only read, and a half is within 2^-11 of them, a twentieth of an 8-bit level, while it
 * halves the two largest buffers of the fit. The host computes Σ Q² and R from the rounded Q,
 * so the loss is exactly that of a target whose Q is the stored one; everything the kernels
 * add up stays in float.
 *
 * And they are stored by tiles of LOSS_TILE x LOSS_TILE pixels (raster/loss_tiles.h): a
 * clipart frame is mostly white paper far from any ink, where Q and R are one value (the
 * blurred background less the blurred white target), as inside a flat fill, so each frame
 * stores only its tiles that are not all one value (near the figure's edges, and at the
 * frame's border, where zero padding bends the blurs) and holds each other tile as its value.
 * Layout (ClRaster::prepare_loss_constants): Q's pool and R's, pixels of four halves, hold the
 * stored tiles, each LOSS_TILE² pixels in rows, then the uniform tiles' values, a pixel each;
 * `tiles` holds per frame and tile (row-major) the tile's number in the pools, or −1 − c for
 * the value at pool pixel c. The kernels read the same halves as from a dense frame, so the
 * same bits; the bundled example's Q and R at 512 px were 88 MB dense.
 */

/* The pool pixel holding (x, y) of the frame whose tile index is `tiles`. */
inline size_t loss_tile_pixel(__global const int* tiles, int x, int y, int width) {
  const int t = tiles[(y / LOSS_TILE) * ((width + LOSS_TILE - 1) / LOSS_TILE) + x / LOSS_TILE];
  return t < 0 ? (size_t)(-1 - t)
               : (size_t)t * (LOSS_TILE * LOSS_TILE) + (y % LOSS_TILE) * LOSS_TILE + x % LOSS_TILE;
}

/* The tile index of frame k. */
inline __global const int* loss_frame_tiles(__global const int* tiles, int k, int width, int height) {
  return tiles + (size_t)k * ((width + LOSS_TILE - 1) / LOSS_TILE) * ((height + LOSS_TILE - 1) / LOSS_TILE);
}

/* LOSS_R, gv_tap (and g_tap in the paper's build): the render's 1-D Gaussian taps, defined in
 * prelude.cl from the build or from `lb`. */

/* One separable pass of the blur, along x (dir = 0) or y (dir = 1), times `scale`. No host
 * routine launches it today (the fit's passes are raster.cl's residual output and the kernels
 * below); it is kept as the plain form of one pass. With the per-group blur its pixels are in
 * YCbCr and each group takes its own taps, as in the fused passes. */
__kernel void blur_pass(__global const float4* src, __global float4* dst, float scale, int dir,
                        int width, int height, int frames, __constant LossBlur* loss_blur) {
  LOSS_BLUR_PRIVATE;
  const int x = get_global_id(0), y = get_global_id(1), k = get_global_id(2);
  if (x >= width || y >= height || k >= frames) return;
  __global const float4* f = src + (size_t)k * width * height;
  const int step = dir == 0 ? 1 : width, pos = y * width + x;
  const int at = dir == 0 ? x : y, n = dir == 0 ? width : height;
  float4 s = (float4)(0.0f);
  for (int j = -LOSS_R; j <= LOSS_R; ++j) {
    const int t = LOSS_REFLECTS ? loss_reflect(at + j, n) : at + j;
    if (t >= 0 && t < n) s += gv_tap(j) * f[pos + (t - at) * step];
  }
  dst[(size_t)k * width * height + pos] = scale * s;
}

#ifdef LOSS_MATCHED
/* The chroma weight w (LossBlur's chroma_w, fit/target/blur_match.h): the squared residual is
 * measured as Eᵀ M E with M = w·I + (1 − w)·y yᵀ/|y|², y = (.299, .587, .114) the luma row of
 * A. A residual of luma alone (along y) counts fully; one of chroma alone (yᵀE = 0: a codec's
 * chroma error, A⁻¹ (0, Cb, Cr)) counts w times. M is symmetric and constant, so it commutes
 * with the blur: with it, Σ E² becomes Σ (Qᵀ M Q + 2 Qᵀ M E' + E'ᵀ M E'), the host's Σ Q² and
 * R take M (ClRaster::prepare_loss_constants) and the backward pass blurs M E' where it
 * blurred E'. At w = 1 it returns e exactly (1·e + 0·y). */
inline float3 loss_metric(const LossBlur* lb, float3 e) {
  const float3 y = (float3)(0.299f, 0.587f, 0.114f);
  return lb->chroma_w * e + ((1.0f - lb->chroma_w) * dot(y, e) / dot(y, y)) * y;
}

/* The row term of pixel x and what the backward pass keeps of it. The y-blur `v` is B·X, in
 * YCbCr with the per-group blur (LOSS_YCC, prelude.cl): then E' = A⁻¹ v in RGB makes the row's
 * term with the RGB q, and what is kept is A⁻ᵀ M E', so that its blur (the same per-group taps,
 * the operator's adjoint Aᵀ·diag(G)·A⁻ᵀ) works in the same coordinates; in RGB, M E'. */
inline float matched_residual(const LossBlur* lb, float3 q, float3 v, __global float* e, int x) {
  const float3 E = LOSS_YCC ? rgb_from_ycc(v) : v;
  const float3 M = loss_metric(lb, E);
  vstore3(LOSS_YCC ? ycc_adjoint_from_rgb(M) : M, x, e);
  return dot(2.0f * q + E, M);
}
#endif

/* Where a row's Q is read from x on, to the end of x's tile (blur_y_loss_rows): pool pixel
 * *at, advancing by *step (1 in a stored tile, 0 on a uniform tile's value) per pixel. A lookup per
 * tile, not per pixel: one per pixel made the row loop several times slower. */
inline void q_tile_start(__global const int* row, int in, int x, size_t* at, int* step) {
  const int t = row[x / LOSS_TILE];
  *step = t < 0 ? 0 : 1;
  *at = t < 0 ? (size_t)(-1 - t) : (size_t)t * (LOSS_TILE * LOSS_TILE) + in + x % LOSS_TILE;
}

/* Prefetches what the next row of blur_y_loss_rows touches first in memory (CPU devices,
 * PREFETCH_ROWS): the X' row its newest tap reads (row y + LOSS_R + 1; the older tap rows
 * were read by the rows before) over that row's extent, one prefetch per 64-byte line, Q's
 * stored tiles along row y + 1 (16 pixels of four halves, two lines a tile), and the lines of
 * E' it writes (for writing). PoCL runs a group's work-items one after the other, rows in
 * order, so the next row's lines stream in while this row computes; as demand misses they
 * were most of this kernel's time (the load of Q, of the newest tap row and the E' store,
 * perf on sushi). Changes no value. */
inline void prefetch_next_row(const LossBlur* lb, __global const float* f, __global const int2* ex,
                              __global const half* Q, __global const int* qrow,
                              __global float* e, int y, int width, int height) {
#ifdef PREFETCH_ROWS
  const int yx = y + LOSS_R + 1;
  if (yx < height && ex[yx].x <= ex[yx].y)
    for (int i = 3 * ex[yx].x; i <= 3 * ex[yx].y + 2; i += 16) PREFETCH(f + (size_t)yx * width * 3 + i);
  const int yq = y + 1, tiles_x = (width + LOSS_TILE - 1) / LOSS_TILE;
  if (yq >= height) return;
  int lo = width, hi = -1; /* row yq's E' extent, as blur_y_loss_rows takes it */
  for (int yy = max(yq - LOSS_R, 0); yy <= min(yq + LOSS_R, height - 1); ++yy)
    if (ex[yy].x <= ex[yy].y) {
      lo = min(lo, ex[yy].x);
      hi = max(hi, ex[yy].y);
    }
  if (lo > hi) return;
  for (int i = 3 * lo; i <= 3 * hi + 2; i += 16) PREFETCH_W(e + (size_t)width * 3 + i);
  __global const int* row = qrow + (yq % LOSS_TILE == 0 ? tiles_x : 0);
  const int in = (yq % LOSS_TILE) * LOSS_TILE;
  for (int t = lo / LOSS_TILE; t <= hi / LOSS_TILE; ++t) {
    const int n = row[t];
    if (n < 0) continue; /* a uniform tile's value: one pixel, read by every row */
    __global const half* p = Q + ((size_t)n * (LOSS_TILE * LOSS_TILE) + in) * 4;
    for (int i = 0; i < LOSS_TILE * 4; i += 32) PREFETCH(p + i);
  }
#endif
}

/* Per (row, frame): E' = the y-blur of X' over the rows' extents, kept (with its extent) for
 * the backward pass, and the row's Σ (2 Q·E' + E'·E') over pixels and channels, in x order.
 * The host may launch a few frames at a time (ClRaster's loss chunks, to keep X' and E' to a
 * few frames' memory): the launch's global offset is the first frame, and X' and E' hold the
 * launched frames only, indexed from it; everything else is indexed by the frame itself. */
__kernel void blur_y_loss_rows(__global const float* Xb, __global const int2* ext_x,
                               __global const half* Q, __global float* E,
                               __global int2* ext_e, __global float* row_sums, int width,
                               int height, int frames, __global const int* tiles,
                               __constant LossBlur* loss_blur) {
  LOSS_BLUR_PRIVATE;
  const int y = get_global_id(0), k = get_global_id(1);
  if (y >= height || k >= frames) return;
  __global const int2* ex = ext_x + (size_t)k * height;
  int lo = width, hi = -1;
  for (int j = -LOSS_R; j <= LOSS_R; ++j) {
    /* Mirrored, a row within LOSS_R of y: the same extent. */
    const int yy = LOSS_REFLECTS ? loss_reflect(y + j, height) : y + j;
    if (yy < 0 || yy >= height || ex[yy].x > ex[yy].y) continue;
    lo = min(lo, ex[yy].x);
    hi = max(hi, ex[yy].y);
  }
  ext_e[(size_t)k * height + y] = (int2)(lo, hi);
  float s = 0.0f;
  const size_t kc = (size_t)k - get_global_offset(1); /* the frame within the chunk */
  __global const float* f = Xb + kc * width * height * 3; /* packed RGB (vload3) */
  __global float* e = E + (kc * height + y) * width * 3;
  /* Row y's tiles in frame k's index (a tile's number in Q's pool, or the constant's −1 − k),
   * and where row y starts within a tile. */
  __global const int* qrow = loss_frame_tiles(tiles, k, width, height) + (y / LOSS_TILE) * ((width + LOSS_TILE - 1) / LOSS_TILE);
  const int qin = (y % LOSS_TILE) * LOSS_TILE;
  /* Each tap's row contributes on its extent only (zero padding outside the frame and the
   * drawing). Those ranges are taken once per row: [fa, fb] is where every tap is inside (a
   * background makes it the whole row), and there no tap needs its test. Rows of a drawing that
   * is not a rectangle have extents that differ, and testing every tap of every pixel against
   * them was most of this kernel's time. Either way the same taps are added in the same order
   * (tap rows top to bottom), so the same bits. */
  int ta[2 * LOSS_R_MAX + 1], tb[2 * LOSS_R_MAX + 1];
  int fa = lo, fb = hi;
#ifdef LOSS_MATCHED
  /* Tap row j reads row ro[j] / width (mirrored into the frame with LOSS_REFLECTS). */
  int ro[2 * LOSS_R_MAX + 1];
#endif
  for (int j = 0; j <= 2 * LOSS_R; ++j) {
#ifdef LOSS_MATCHED
    const int yy = LOSS_REFLECTS ? loss_reflect(y + j - LOSS_R, height) : y + j - LOSS_R;
    ro[j] = yy * width;
#else
    const int yy = y + j - LOSS_R;
#endif
    const int ok = yy >= 0 && yy < height;
    ta[j] = ok ? ex[yy].x : width;
    tb[j] = ok ? ex[yy].y : -1;
    fa = max(fa, ta[j]);
    fb = min(fb, tb[j]);
  }
  prefetch_next_row(lb, f, ex, Q, qrow, e, y, width, height);
#ifndef LOSS_MATCHED
  const int r = (y - LOSS_R) * width; /* tap row j starts at f + r + j * width */
  /* The plain blur is the same for each of a pixel's three floats: over the span where every
   * tap is inside, E' is blurred as a flat run of floats, eight at a time (PoCL kept the
   * pixel loop scalar), then the row's sum is taken pixel by pixel from the stored E' in x
   * order. Each float gets the same taps in the same order, and the sum the same terms in
   * the same order: the same bits as the loop below. */
  if (fa <= fb) {
    const int a = 3 * fa, n = 3 * (fb - fa + 1), r3 = 3 * r, w3 = 3 * width;
    int i = 0;
    for (; i + 8 <= n; i += 8) {
      float8 v = (float8)(0.0f);
      v += G2 * vload8(0, f + r3 + a + i);
      v += G1 * vload8(0, f + r3 + w3 + a + i);
      v += G0 * vload8(0, f + r3 + 2 * w3 + a + i);
      v += G1 * vload8(0, f + r3 + 3 * w3 + a + i);
      v += G2 * vload8(0, f + r3 + 4 * w3 + a + i);
      vstore8(v, 0, e + a + i);
    }
    for (; i < n; ++i) {
      float v = 0.0f;
      v += G2 * f[r3 + a + i];
      v += G1 * f[r3 + w3 + a + i];
      v += G0 * f[r3 + 2 * w3 + a + i];
      v += G1 * f[r3 + 3 * w3 + a + i];
      v += G2 * f[r3 + 4 * w3 + a + i];
      e[a + i] = v;
    }
  }
  size_t qa = 0;
  int qs = 0;
  for (int x = lo; x <= hi; ++x, qa += qs) {
    if (x == lo || x % LOSS_TILE == 0) q_tile_start(qrow, qin, x, &qa, &qs);
    float3 v = (float3)(0.0f);
    if (x >= fa && x <= fb) {
      v = vload3(x, e);
    } else {
      for (int j = 0; j <= 2 * LOSS_R; ++j)
        if (x >= ta[j] && x <= tb[j]) v += g_tap(j - LOSS_R) * vload3(r + j * width + x, f);
      vstore3(v, x, e);
    }
    s += dot(2.0f * vload_half4(qa, Q).xyz + v, v);
  }
#else
  /* Any radius and taps (LossBlur): the same taps in the same order with or without the
   * extents' tests. */
  size_t qa = 0;
  int qs = 0;
  for (int x = lo; x <= hi; ++x, qa += qs) {
    if (x == lo || x % LOSS_TILE == 0) q_tile_start(qrow, qin, x, &qa, &qs);
    float3 v = (float3)(0.0f);
    if (x >= fa && x <= fb) {
      for (int j = 0; j <= 2 * LOSS_R; ++j) v += gv_tap(j - LOSS_R).xyz * vload3(ro[j] + x, f);
    } else {
      for (int j = 0; j <= 2 * LOSS_R; ++j)
        if (x >= ta[j] && x <= tb[j]) v += gv_tap(j - LOSS_R).xyz * vload3(ro[j] + x, f);
    }
    s += matched_residual(lb, vload_half4(qa, Q).xyz, v, e, x);
  }
#endif
  row_sums[(size_t)k * height + y] = s;
}

#ifdef LOSS_MATCHED
/* The adjoint's taps at pixel p of a row (or column) of n pixels with reflect padding:
 * w[i] = A[q][p] for q = p − LOSS_R + i, the taps of output q that read p (q + j itself, or
 * mirrored into p). Beyond LOSS_R of the border that is the stencil. Per channel group (x luma,
 * y and z chroma). */
inline void loss_adjoint_taps(const LossBlur* lb, int p, int n, float4* w) {
  const int plain = p > LOSS_R && p + LOSS_R + 1 < n;
  for (int i = 0; i <= 2 * LOSS_R; ++i) {
    const int q = p - LOSS_R + i;
    float4 s = (float4)(0.0f);
    if (plain) {
      s = gv_tap(i - LOSS_R);
    } else if (q >= 0 && q < n) {
      for (int j = -LOSS_R; j <= LOSS_R; ++j)
        if (loss_reflect(q + j, n) == p) s += gv_tap(j);
    }
    w[i] = s;
  }
}
#endif

/* ∂L/∂C at pixel (x, y) of a frame: 2w/N · (R + G ∗ E'), E' read within its row extents. */
inline float3 blurred_gradient(const LossBlur* lb, __global const float* E, __global const int2* ext_e,
                               __global const half* R, __global const int* tiles, int x, int y,
                               int width, int height, float scale) {
  float3 s = vload_half4(loss_tile_pixel(tiles, x, y, width), R).xyz;
  /* Inside the frame with every tap within its row's extent (a layered scene's usual case):
   * the same sum without the tests. With reflect padding the pixels LOSS_R from the border
   * also take back what mirrored taps read of them: one pixel more is not inside. */
  const int m = LOSS_REFLECTS ? LOSS_R + 1 : LOSS_R;
  int inside = x >= m && x + m < width && y >= m && y + m < height;
  for (int dy = -LOSS_R; dy <= LOSS_R && inside; ++dy)
    inside = ext_e[y + dy].x <= x - LOSS_R && ext_e[y + dy].y >= x + LOSS_R;
#ifdef LOSS_MATCHED
  /* The blur's adjoint per channel group: blur the stored M E' (A⁻ᵀ M E' in YCbCr), then Aᵀ
   * with LOSS_YCC (matched_residual). The same taps in the same order with or without the
   * tests. In RGB the sum starts from R, as the paper's build's does (the taps compiled into
   * the program added the same terms in this order). */
  float3 acc = LOSS_YCC ? (float3)(0.0f) : s;
  if (inside) {
    for (int dy = -LOSS_R; dy <= LOSS_R; ++dy) {
      const int at = (y + dy) * width + x;
      float3 row = (float3)(0.0f);
      for (int dx = -LOSS_R; dx <= LOSS_R; ++dx) row += gv_tap(dx).xyz * vload3(at + dx, E);
      acc += gv_tap(dy).xyz * row;
    }
  } else {
    /* Only within LOSS_R (+1) of the border do reflect padding's adjoint taps differ from the
     * stencil (the same values elsewhere: loss_adjoint_taps' plain case), and only there are
     * they made. */
    const int near = LOSS_REFLECTS && (x <= LOSS_R || x + LOSS_R + 1 >= width || y <= LOSS_R || y + LOSS_R + 1 >= height);
    float4 wx[2 * LOSS_R_MAX + 1], wy[2 * LOSS_R_MAX + 1];
    if (near) {
      loss_adjoint_taps(lb, x, width, wx);
      loss_adjoint_taps(lb, y, height, wy);
    }
    for (int dy = -LOSS_R; dy <= LOSS_R; ++dy) {
      const int yy = y + dy;
      if (yy < 0 || yy >= height) continue;
      const int2 ex = ext_e[yy];
      float3 row = (float3)(0.0f);
      for (int dx = -LOSS_R; dx <= LOSS_R; ++dx) {
        const int xx = x + dx;
        if (xx >= ex.x && xx <= ex.y) row += (near ? wx[dx + LOSS_R] : gv_tap(dx)).xyz * vload3(yy * width + xx, E);
      }
      acc += (near ? wy[dy + LOSS_R] : gv_tap(dy)).xyz * row;
    }
  }
  return scale * (LOSS_YCC ? s + rgb_adjoint_from_ycc(acc) : acc);
#else
  if (inside) {
    for (int dy = -LOSS_R; dy <= LOSS_R; ++dy) {
      const int at = (y + dy) * width + x;
      float3 row = (float3)(0.0f);
      row += G2 * vload3(at - 2, E);
      row += G1 * vload3(at - 1, E);
      row += G0 * vload3(at, E);
      row += G1 * vload3(at + 1, E);
      row += G2 * vload3(at + 2, E);
      s += g_tap(dy) * row;
    }
    return scale * s;
  }
  for (int dy = -LOSS_R; dy <= LOSS_R; ++dy) {
    const int yy = y + dy;
    if (yy < 0 || yy >= height) continue;
    const int2 ex = ext_e[yy];
    float3 row = (float3)(0.0f);
    for (int dx = -LOSS_R; dx <= LOSS_R; ++dx) {
      const int xx = x + dx;
      if (xx >= ex.x && xx <= ex.y) row += g_tap(dx) * vload3(yy * width + xx, E);
    }
    s += g_tap(dy) * row;
  }
  return scale * s;
#endif
}

/* One work-item: L = scale · Σ_k (Σ Q²_k + Σ row sums), in order, and per-frame losses. */
__kernel void loss_total(__global const float* row_sums, __global const float* qsum,
                         __global float* loss, float scale, int height, int frames) {
  if (get_global_id(0) != 0) return;
  float total = 0.0f;
  for (int k = 0; k < frames; ++k) {
    float f = qsum[k];
    for (int y = 0; y < height; ++y) f += row_sums[(size_t)k * height + y];
    loss[1 + k] = scale * f;
    total += f;
  }
  loss[0] = scale * total;
}
