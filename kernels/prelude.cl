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

/* The 1-D Gaussian the loss blurs the render with: g_j = exp(-j²/2σ²) normalised over
 * j = -LOSS_R..LOSS_R, for j = 0, ±1, ..., σ = 1 and LOSS_R = 2 (5 taps; paper, appendix) unless
 * the build sets them (blur matching, up to 17 taps: raster/loss_taps.h). Used by loss.cl and by
 * raster.cl's fused residual pass. */
#ifndef LOSS_R
#define LOSS_R 2
#define G0 0.4026199469f
#define G1 0.2442019099f
#define G2 0.0544886845f
#endif
#ifndef G3
#define G3 0.0f
#endif
#ifndef G4
#define G4 0.0f
#endif
#ifndef G5
#define G5 0.0f
#endif
#ifndef G6
#define G6 0.0f
#endif
#ifndef G7
#define G7 0.0f
#endif
#ifndef G8
#define G8 0.0f
#endif

inline float g_tap(int j) {
  j = abs(j);
  return j == 0 ? G0 : j == 1 ? G1 : j == 2 ? G2 : j == 3 ? G3 : j == 4 ? G4 : j == 5 ? G5 : j == 6 ? G6
       : j == 7 ? G7 : G8;
}

/* The loss's padding at the frame's border (raster/loss_taps.h, loss_reflects): zeros, or with
 * LOSS_REFLECT (blur matching, a render σ above 1) reflect-101, index −1 reading 1 and n
 * reading n − 2, so that a soft video's ink running off the frame, which its blur kept dark to
 * the border, is matched by a render that does not fade there. loss_reflect(k, n) is the pixel
 * tap index k reads (clamped when the frame is narrower than the stencil), as reflect101 on the
 * host. */
inline int loss_reflect(int k, int n) {
  if (k < 0) k = -k;
  if (k >= n) k = 2 * (n - 1) - k;
  return clamp(k, 0, n - 1);
}

/* Chroma blur matching (raster/loss_taps.h, render_blur): when the build defines CHROMA_R and
 * GC0..GC8, the render is blurred per channel group in YCbCr (BT.601 without offsets), luma Y
 * by G0..G8 and chroma Cb, Cr by GC0..GC8, B = A⁻¹ · diag(G, GC, GC) · A: codecs keep luma
 * sharp and chroma soft, and a loss that blurs both alike makes the fitter move edges between
 * colours of similar luma. LOSS_R is then the larger of the two radii (a tap beyond a
 * channel's own radius weighs 0). Without CHROMA_R none of this is compiled. */
#ifdef CHROMA_R
#ifndef GC3
#define GC3 0.0f
#endif
#ifndef GC4
#define GC4 0.0f
#endif
#ifndef GC5
#define GC5 0.0f
#endif
#ifndef GC6
#define GC6 0.0f
#endif
#ifndef GC7
#define GC7 0.0f
#endif
#ifndef GC8
#define GC8 0.0f
#endif
/* The taps of both groups in one vector: (luma, chroma, chroma, 0), for float4 pixels in YCbCr. */
inline float4 gv_tap(int j) {
  j = abs(j);
  return j == 0 ? (float4)(G0, GC0, GC0, 0.0f) : j == 1 ? (float4)(G1, GC1, GC1, 0.0f)
       : j == 2 ? (float4)(G2, GC2, GC2, 0.0f) : j == 3 ? (float4)(G3, GC3, GC3, 0.0f)
       : j == 4 ? (float4)(G4, GC4, GC4, 0.0f) : j == 5 ? (float4)(G5, GC5, GC5, 0.0f)
       : j == 6 ? (float4)(G6, GC6, GC6, 0.0f) : j == 7 ? (float4)(G7, GC7, GC7, 0.0f)
       : (float4)(G8, GC8, GC8, 0.0f);
}
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
#endif

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
