/* regularise.cl: the fitter's regularisers (paper, appendix), their values and gradients.
 *
 *   smoothness   Σ_pairs w_ij ‖Δ_i − Δ_j‖²,  w_ij = exp(−‖r_i − r_j‖ / σ), pairs = consecutive
 *                control points of a subpath (r at rest, σ = 1% of the canvas width): nearby
 *                offsets should agree, distant ones are free. Its weight is below the
 *                paper's (engine/src/fit/optimise/fitter.h: the displacement field is smooth already).
 *   G1           Σ_joints (1 − cos θ), θ the angle between the incoming and outgoing tangents
 *                (anchor − in-handle, out-handle − anchor) at joints that were smooth at rest.
 *   containment  Σ_points max(0, sdf_k(x̂) − m_i)², sdf_k the distance to keyframe k's
 *                foreground mask, bilinearly interpolated: points should stay on the subject
 *                as far as they were at rest. m_i is the margin plus point i's own distance to
 *                the rest pose's foreground: a Bézier handle of a convex bulge lies outside
 *                the shape it draws, and a fixed margin pulled such handles inwards in every
 *                keyframe, flattening the curves against the image loss (octopus, non-rigid
 *                target fitted to clean frames: worst keyframe at 1024 px 34.7 dB with a
 *                1 px margin for all, 36.9 with containment off). Beyond the canvas the
 *                distance goes on growing: sdf at the nearest sampled point plus the distance
 *                to it. No pixel sees a point out there, so nothing else holds it, and a
 *                straight edge of a sun's ray, drawn to the canvas's edge, went 64 px out
 *                (emoji_u1f304, refused by the result gate).
 *   cohesion     Σ_pairs (‖x̂_i − x̂_j‖ − ℓ_ij)², pairs = control points closer than a few pixels
 *                at rest (ℓ_ij their rest distance), in any path or group: what touches at rest
 *                keeps touching and what is thin stays as thick. Parts drawn in one colour
 *                over each other (an arm over the body, fingers over the hand) can slide
 *                without the image loss noticing, and 1-2 px ribbons and dots can collapse or
 *                twist at no visible cost at the fitting size; both tear at 4x. Distances, not
 *                edge vectors, so a rotation or articulation of the whole neighbourhood is free
 *                (an as-rigid-as-possible energy without the per-point rotations: Sorkine and
 *                Alexa 2007; the distance form is the usual mass-spring one).
 *
 * Each term is scaled by its weight over its count of terms (`scale`). The kernels add their
 * gradients into buffers the image loss has already written and write one partial loss per
 * work-item; sum_partials adds partials in a fixed order. Each control point belongs to at most
 * one joint and owns its own neighbour list, so no two work-items write the same element.
 */

/* Smoothness on the offsets, per (point, keyframe): adds to grad_offsets. */
__kernel void smoothness(__global const float2* offsets, __global const int* nbr_first,
                         __global const int* nbr, __global const float* nbr_w,
                         __global float2* grad_offsets, __global float* partial, float scale,
                         int n_cp) {
  const int i = get_global_id(0), k = get_global_id(1);
  if (i >= n_cp) return;
  const size_t at = (size_t)k * n_cp + i;
  const float2 di = offsets[at];
  float2 g = (float2)(0.0f);
  float l = 0.0f;
  for (int e = nbr_first[i]; e < nbr_first[i + 1]; ++e) {
    const int j = nbr[e];
    const float2 diff = di - offsets[(size_t)k * n_cp + j];
    g += 2.0f * nbr_w[e] * diff;
    if (j > i) l += nbr_w[e] * dot(diff, diff); /* each pair counted once */
  }
  grad_offsets[at] += scale * g;
  partial[at] = scale * l;
}

/* G1 continuity, per (joint, keyframe): joint = (in-handle, anchor, out-handle); adds to grad_cp. */
__kernel void g1_continuity(__global const float2* cp, __global const int4* joints,
                            __global float2* grad_cp, __global float* partial, float scale,
                            int n_cp, int n_joints) {
  const int j = get_global_id(0), k = get_global_id(1);
  if (j >= n_joints) return;
  const int4 J = joints[j];
  __global const float2* p = cp + (size_t)k * n_cp;
  const float2 a = p[J.y] - p[J.x], b = p[J.z] - p[J.y];
  const float la = length(a), lb = length(b);
  float l = 0.0f;
  if (la > 1e-6f && lb > 1e-6f) {
    const float c = dot(a, b) / (la * lb);
    l = scale * (1.0f - c);
    /* ∂cos/∂a = b/(|a||b|) − cos a/|a|², likewise for b; L = scale (1 − cos). */
    const float2 ga = -scale * (b / (la * lb) - c * a / (la * la));
    const float2 gb = -scale * (a / (la * lb) - c * b / (lb * lb));
    __global float2* g = grad_cp + (size_t)k * n_cp;
    g[J.x] -= ga;
    g[J.y] += ga - gb;
    g[J.z] += gb;
  }
  partial[(size_t)k * n_joints + j] = l;
}

/* Containment, per (point, keyframe): adds to grad_cp. sdf is [K][H][W], pixel centres at +0.5;
 * margin is per point ([n_cp]). */
__kernel void containment(__global const float2* cp, __global const int* cp_group,
                          __global const float* sdf, __global float2* grad_cp,
                          __global float* partial, float scale, __global const float* margin,
                          int n_cp, int width, int height) {
  const int i = get_global_id(0), k = get_global_id(1);
  if (i >= n_cp) return;
  const size_t at = (size_t)k * n_cp + i;
  float l = 0.0f;
  if (cp_group[i] >= 0) {
    const float2 q = cp[at] - 0.5f;
    const float x = clamp(q.x, 0.0f, (float)(width - 1)), y = clamp(q.y, 0.0f, (float)(height - 1));
    const int x0 = min((int)x, max(width - 2, 0)), y0 = min((int)y, max(height - 2, 0));
    const int x1 = min(x0 + 1, width - 1), y1 = min(y0 + 1, height - 1);
    const float fx = x - (float)x0, fy = y - (float)y0;
    __global const float* S = sdf + (size_t)k * width * height;
    const float s00 = S[y0 * width + x0], s10 = S[y0 * width + x1];
    const float s01 = S[y1 * width + x0], s11 = S[y1 * width + x1];
    const float2 out = q - (float2)(x, y); /* beyond the sampled pixel centres */
    const float o = length(out);
    const float s = (1 - fy) * ((1 - fx) * s00 + fx * s10) + fy * ((1 - fx) * s01 + fx * s11) + o;
    const float d = s - margin[i];
    if (d > 0.0f) {
      l = scale * d * d;
      /* The gradient of the bilinear interpolant, zero along an axis where q was clamped, plus
       * that of the distance beyond the canvas. */
      float2 grad = (float2)((1 - fy) * (s10 - s00) + fy * (s11 - s01),
                             (1 - fx) * (s01 - s00) + fx * (s11 - s10));
      if (q.x != x) grad.x = 0.0f;
      if (q.y != y) grad.y = 0.0f;
      if (o > 0.0f) grad += out / o;
      grad_cp[at] += 2.0f * scale * d * grad;
    }
  }
  partial[at] = l;
}

/* Cohesion, per (point, keyframe): adds to grad_cp. The pair lists are symmetric, so each
 * work-item adds only its own point's gradient, 2 scale (‖e‖ − ℓ) e/‖e‖ with e = x̂_i − x̂_j,
 * and counts the loss of the pairs with j > i. */
__kernel void cohesion(__global const float2* cp, __global const int* coh_first,
                       __global const int* coh_nbr, __global const float* coh_len,
                       __global float2* grad_cp, __global float* partial, float scale, int n_cp) {
  const int i = get_global_id(0), k = get_global_id(1);
  if (i >= n_cp) return;
  __global const float2* p = cp + (size_t)k * n_cp;
  const float2 xi = p[i];
  float2 g = (float2)(0.0f);
  float l = 0.0f;
  for (int e = coh_first[i]; e < coh_first[i + 1]; ++e) {
    const int j = coh_nbr[e];
    const float2 d = xi - p[j];
    const float len = length(d);
    if (len < 1e-6f) continue; /* no direction: the pair pushes neither way */
    const float r = len - coh_len[e];
    g += (2.0f * r / len) * d;
    if (j > i) l += r * r;
  }
  grad_cp[(size_t)k * n_cp + i] += scale * g;
  partial[(size_t)k * n_cp + i] = scale * l;
}

/* One work-item: out[at] = Σ partial[0 .. n), in order. */
__kernel void sum_partials(__global const float* partial, __global float* out, int at, int n) {
  if (get_global_id(0) != 0) return;
  float s = 0.0f;
  for (int i = 0; i < n; ++i) s += partial[i];
  out[at] = s;
}
