/* prelude.cl: definitions shared by every svgmotion kernel; prepended to each program.
 *
 * Tunables arrive as -D options chosen per device by the host (engine/src/opencl/tuning.cpp);
 * the defaults below are what PoCL on a CPU gets. Kernels know nothing of the host: every size
 * and offset is an argument.
 */
/* No fused multiply-adds behind our back: a contracted a*b - c*d is not antisymmetric, so
 * cross2(d, d) came out as ±3e-9 instead of 0 and a straight join looked like a turn. Exact
 * and device-independent results matter more here than the last few percent of speed. */
#pragma OPENCL FP_CONTRACT OFF

#ifndef BAND_H
#define BAND_H 16 /* rows per bin band, also the work-group height of raster kernels */
#endif

/* Draw kinds' fill rules (must match engine/src/raster/raster_plan.h). */
#define RULE_NONZERO 0
#define RULE_EVENODD 1

/* Join kinds per stroke vertex (must match raster_plan.h). INTERIOR marks vertices inside one
 * flattened cubic, where the true offset curve is smooth: a miter there (bevel past a ratio of
 * 4) is within a hair of the exact offset and costs one point. */
#define JOIN_MITER 0
#define JOIN_MITER_CLIP 1
#define JOIN_ROUND 2
#define JOIN_BEVEL 3
#define JOIN_INTERIOR 4

#define CAP_BUTT 0
#define CAP_ROUND 1
#define CAP_SQUARE 2

/* The render's blur in the loss (loss.cl, raster.cl's fused residual pass; raster/loss_taps.h
 * on the host). Two builds of the raster program serve every blur:
 *
 * - the paper's (no LOSS_MATCHED): the 1-D Gaussian g_j = exp(-j²/2σ²) normalised over
 *   j = -2..2, σ = 1 (5 taps; paper, appendix), as compile-time constants G0..G2, zero padding
 *   at the frame's border, the same blur for every channel;
 * - LOSS_MATCHED (blur matching, raster/loss_blur.h): any render σ, chroma σ and chroma
 *   weight, read at run time from a LossBlur the host fills: the taps, the radius (up to
 *   LOSS_R_MAX, 17 taps), the padding and the chroma weight. Blur matching picks σ in steps of
 *   0.05 from the video (1.1 to 1.35 on an H.264 target), and taps compiled into the program
 *   made every σ a program of its own, 30-50 s of PoCL compiling and 210 MB at the first run
 *   that chose it, which `devices --warm` could not foresee; with them as data one program
 *   per width covers every σ.
 *
 * Every kernel that blurs takes `__constant LossBlur* loss_blur` as its last argument in both
 * builds (the paper's never reads it), copies it to private memory (LOSS_BLUR_PRIVATE: a
 * private copy cannot alias the global buffers the loops write, so its loads leave the loops),
 * and hands `lb` to the helpers, whose macros below read it. */
#define LOSS_TAPS_MAX 9 /* g_0..g_8 */
typedef struct {
  float4 g[LOSS_TAPS_MAX]; /* tap j: (luma, chroma, chroma, 0) */
  int r;                   /* the radius: taps j = -r..r */
  int reflect;             /* reflect-101 padding (else zeros) */
  int ycc;                 /* the per-group blur in YCbCr (its chroma taps are not its luma's) */
  float chroma_w;          /* the chroma weight w of loss_metric (loss.cl) */
} LossBlur;
#define LOSS_BLUR_PRIVATE                 \
  const LossBlur loss_blur_copy = *loss_blur; \
  const LossBlur* lb = &loss_blur_copy

#ifdef LOSS_MATCHED
#define LOSS_R_MAX (LOSS_TAPS_MAX - 1)
#define LOSS_R (lb->r)
#define LOSS_REFLECTS (lb->reflect)
#define LOSS_YCC (lb->ycc)
/* The taps of both groups as a vector (luma, chroma, chroma, 0), for float4 pixels in YCbCr
 * (LOSS_YCC) or RGB (then the host gives chroma the luma taps). */
#define gv_tap(j) (lb->g[abs(j)])
#else
#define LOSS_R_MAX 2
#define LOSS_R 2
#define LOSS_REFLECTS 0
#define LOSS_YCC 0
#define G0 0.4026199469f
#define G1 0.2442019099f
#define G2 0.0544886845f
inline float g_tap(int j) {
  j = abs(j);
  return j == 0 ? G0 : j == 1 ? G1 : G2;
}
#define gv_tap(j) ((float4)(g_tap(j)))
#endif

/* The loss's padding at the frame's border (raster/loss_taps.h, loss_reflects): zeros, or with
 * LOSS_REFLECTS (blur matching, a render σ above 1) reflect-101, index −1 reading 1 and n
 * reading n − 2, so that a soft video's ink running off the frame, which its blur kept dark to
 * the border, is matched by a render that does not fade there. loss_reflect(k, n) is the pixel
 * tap index k reads (clamped when the frame is narrower than the stencil), as reflect101 on the
 * host. */
inline int loss_reflect(int k, int n) {
  if (k < 0) k = -k;
  if (k >= n) k = 2 * (n - 1) - k;
  return clamp(k, 0, n - 1);
}

/* Chroma blur matching (raster/loss_taps.h, render_blur): with LOSS_YCC the render is blurred
 * per channel group in YCbCr (BT.601 without offsets), luma Y by the taps' x and chroma Cb, Cr
 * by their y and z, B = A⁻¹ · diag(G, GC, GC) · A: codecs keep luma sharp and chroma soft, and
 * a loss that blurs both alike makes the fitter move edges between colours of similar luma.
 * The radius is the larger of the two (a tap beyond a group's own radius weighs 0). */
/* A: RGB -> YCbCr, Y = .299R + .587G + .114B, Cb = (B − Y)/1.772, Cr = (R − Y)/1.402. */
inline float3 ycc_from_rgb(float3 c) {
  return (float3)(0.299f * c.x + 0.587f * c.y + 0.114f * c.z,
                  -0.168735892f * c.x - 0.331264108f * c.y + 0.5f * c.z,
                  0.5f * c.x - 0.418687589f * c.y - 0.0813124108f * c.z);
}
/* A⁻¹: YCbCr -> RGB. */
inline float3 rgb_from_ycc(float3 v) {
  return (float3)(v.x + 1.402f * v.z, v.x - 0.344136286f * v.y - 0.714136286f * v.z,
                  v.x + 1.772f * v.y);
}
/* A⁻ᵀ: an RGB gradient into the coordinates the blur's adjoint works in. */
inline float3 ycc_adjoint_from_rgb(float3 e) {
  return (float3)(e.x + e.y + e.z, -0.344136286f * e.y + 1.772f * e.z,
                  1.402f * e.x - 0.714136286f * e.y);
}
/* Aᵀ: back to RGB after the adjoint's blur. */
inline float3 rgb_adjoint_from_ycc(float3 v) {
  return (float3)(0.299f * v.x - 0.168735892f * v.y + 0.5f * v.z,
                  0.587f * v.x - 0.331264108f * v.y - 0.418687589f * v.z,
                  0.114f * v.x + 0.5f * v.y - 0.0813124108f * v.z);
}

/* A hint that the line holding *p will be read soon (PREFETCH_ROWS, set by the host for CPU
 * devices, engine/src/opencl/tuning.cpp): clang's builtin, which PoCL lowers to the CPU's
 * prefetch instruction. Nothing elsewhere, and it never changes a value. */
#if defined(PREFETCH_ROWS) && defined(__clang__)
#define PREFETCH(p) __builtin_prefetch(p)
#define PREFETCH_W(p) __builtin_prefetch(p, 1) /* the line will be written */
#else
#undef PREFETCH_ROWS
#define PREFETCH(p) ((void)0)
#define PREFETCH_W(p) ((void)0)
#endif

inline float cross2(float2 a, float2 b) { return a.x * b.y - a.y * b.x; }

/* Coverage from the winding integral a of one pixel (the box-filtered winding number). */
inline float fill_rule_coverage(float a, int rule) {
  if (rule == RULE_EVENODD) {
    float m = fabs(a - 2.0f * rint(0.5f * a)); /* fold: 0 at even, 1 at odd windings */
    return fmin(m, 1.0f);
  }
  return fmin(fabs(a), 1.0f);
}
