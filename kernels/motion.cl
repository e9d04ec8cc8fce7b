/* motion.cl: the motion model, control points of every keyframe from group homographies and
 * per-point offsets, and its backward pass.
 *
 * For control point i of group g at keyframe k (LiveSVG's model, DESIGN.md §4):
 *
 *     x̂ = o + s · π(H_gk · [n, 1]ᵀ),   n = (r_i + Δ_ik − o) / s,
 *     H = P · T · T_c · R · Sh · S · T_−c
 *
 * with r_i the rest position and Δ_ik the offset (pixels), o the canvas centre and s half the
 * canvas width (so the homography works in normalised units where the Adam learning rate 1e-3
 * of the paper is meaningful), and the 11 parameters of θ_gk, in this order:
 *     tx, ty (T), rot (R), sx, sy (S), shx, shy (Sh: [[1, shx], [shy, 1]]), px, py (P: the
 *     bottom row (px, py, 1)), cx, cy (the learned centre c).
 * Applied step by step: a = n − c; b = (sx a.x, sy a.y); d = (b.x + shx b.y, shy b.x + b.y);
 * e = R(rot) d; f = e + c + t; w = px f.x + py f.y + 1; π = f / w.
 *
 * Backward, by the chain rule through the same steps (g_y = ∂L/∂y):
 *     g_π = s g_x̂;  g_f = g_π / w − (g_π·f) p / w²;  g_p = −(g_π·f) f / w²;
 *     g_t = g_f;  g_c = g_f − g_a;  g_d = Rᵀ g_f;  g_rot = g_d · (−d.y, d.x);
 *     g_b = (g_d.x + shy g_d.y, shx g_d.x + g_d.y);  g_shx = g_d.x b.y;  g_shy = g_d.y b.x;
 *     g_a = (sx g_b.x, sy g_b.y);  g_sx = g_b.x a.x;  g_sy = g_b.y a.y;  g_Δ = g_a / s.
 * One work-item per (group, keyframe) walks its points in order: it owns their offsets and
 * sums the parameter gradient in a fixed order, so the result is deterministic. A closed
 * subpath's closing copy of its first point reads (and adds its gradient to) the first point's
 * offset, so the outline cannot open.
 */

#define MOTION_PARAMS 12 /* 11 used, padded */

typedef struct {
  float2 a, b, d, f;
  float w;
} MotionTrace;

inline float2 motion_apply(__global const float* th, float2 n, MotionTrace* tr) {
  const float2 c = (float2)(th[9], th[10]);
  const float2 a = n - c;
  const float2 b = (float2)(th[3] * a.x, th[4] * a.y);
  const float2 d = (float2)(b.x + th[5] * b.y, th[6] * b.x + b.y);
  const float cs = cos(th[2]), sn = sin(th[2]);
  const float2 e = (float2)(cs * d.x - sn * d.y, sn * d.x + cs * d.y);
  const float2 f = e + c + (float2)(th[0], th[1]);
  const float w = th[7] * f.x + th[8] * f.y + 1.0f;
  tr->a = a; tr->b = b; tr->d = d; tr->f = f; tr->w = w;
  return f / w;
}

/* cp[k][i] for every control point of every keyframe; padding points (group < 0) stay 0. */
__kernel void motion_forward(__global const float* params,   /* [K][G][MOTION_PARAMS] */
                             __global const float2* offsets, /* [K][n_cp] */
                             __global const float2* rest,    /* [n_cp] */
                             __global const int* cp_group,   /* [n_cp] */
                             __global const int* cp_offset,  /* [n_cp] offset slot it reads */
                             __global float2* cp,            /* [K][n_cp] */
                             float2 origin, float scale, int n_cp, int n_groups) {
  const int i = get_global_id(0), k = get_global_id(1);
  if (i >= n_cp) return;
  const int g = cp_group[i];
  if (g < 0) { cp[(size_t)k * n_cp + i] = (float2)(0.0f); return; }
  __global const float* th = params + ((size_t)k * n_groups + g) * MOTION_PARAMS;
  const float2 n = (rest[i] + offsets[(size_t)k * n_cp + cp_offset[i]] - origin) / scale;
  MotionTrace tr;
  cp[(size_t)k * n_cp + i] = origin + scale * motion_apply(th, n, &tr);
}

__kernel void motion_backward(__global const float* params, __global const float2* offsets,
                              __global const float2* rest, __global const int* cp_offset,
                              __global const int* group_first,
                              __global const int* group_cps,  /* CSR: the points of each group */
                              __global const float2* grad_cp, /* [K][n_cp] ∂L/∂x̂ */
                              __global float* grad_params,    /* [K][G][MOTION_PARAMS] */
                              __global float2* grad_offsets,  /* [K][n_cp] (written) */
                              float2 origin, float scale, int n_cp, int n_groups) {
  const int g = get_global_id(0), k = get_global_id(1);
  if (g >= n_groups) return;
  __global const float* th = params + ((size_t)k * n_groups + g) * MOTION_PARAMS;
  const float cs = cos(th[2]), sn = sin(th[2]);
  float gp[11] = {0.0f};
  /* The group's offsets are zeroed first: a closed subpath's closing copy adds its gradient to
   * the slot it shares with the subpath's first point. */
  for (int e = group_first[g]; e < group_first[g + 1]; ++e)
    grad_offsets[(size_t)k * n_cp + group_cps[e]] = (float2)(0.0f);
  for (int e = group_first[g]; e < group_first[g + 1]; ++e) {
    const int i = group_cps[e];
    const size_t at = (size_t)k * n_cp + i;
    const size_t slot = (size_t)k * n_cp + cp_offset[i];
    const float2 n = (rest[i] + offsets[slot] - origin) / scale;
    MotionTrace tr;
    motion_apply(th, n, &tr);
    const float2 g_pi = scale * grad_cp[at];
    const float2 p = (float2)(th[7], th[8]);
    const float gf_dot = dot(g_pi, tr.f);
    const float2 g_f = g_pi / tr.w - gf_dot * p / (tr.w * tr.w);
    const float2 g_p = -gf_dot * tr.f / (tr.w * tr.w);
    const float2 g_d = (float2)(cs * g_f.x + sn * g_f.y, -sn * g_f.x + cs * g_f.y); /* Rᵀ g_f */
    const float g_rot = dot(g_d, (float2)(-tr.d.y, tr.d.x));
    const float2 g_b = (float2)(g_d.x + th[6] * g_d.y, th[5] * g_d.x + g_d.y);
    const float2 g_a = (float2)(th[3] * g_b.x, th[4] * g_b.y);
    gp[0] += g_f.x;
    gp[1] += g_f.y;
    gp[2] += g_rot;
    gp[3] += g_b.x * tr.a.x;
    gp[4] += g_b.y * tr.a.y;
    gp[5] += g_d.x * tr.b.y;
    gp[6] += g_d.y * tr.b.x;
    gp[7] += g_p.x;
    gp[8] += g_p.y;
    gp[9] += g_f.x - g_a.x;
    gp[10] += g_f.y - g_a.y;
    grad_offsets[slot] += g_a / scale;
  }
  __global float* out = grad_params + ((size_t)k * n_groups + g) * MOTION_PARAMS;
  for (int j = 0; j < 11; ++j) out[j] = gp[j];
  out[11] = 0.0f;
}
