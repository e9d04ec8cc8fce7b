/* field.cl: each group's displacement field, the smooth part of the per-point offsets.
 *
 * Free per-point offsets let the points of a part that is 1-2 px wide at the fitting size
 * wander: the image loss barely sees them, so at 4x the fitting size outline ribbons break
 * into beads, dots turn into triangles and fingers merge. A field cannot tear: the offset of
 * control point i is
 *
 *     Δ_ik = δ_ik + Σ_b w_ib c_bk
 *
 * with c_bk the coefficients (pixels) of the nodes b of a uniform quadratic B-spline over the
 * rest bounding box of i's group (knot spacing h, engine/src/fit/plan/fit_plan.cpp), w_ib the
 * tensor-product weights of i's rest position (3 x 3 nodes, they sum to 1), and δ_ik the free
 * per-point residual. Points closer than h see nearly the same coefficients, so the two sides
 * of a thin ribbon, a small dot or a finger move as one smooth (C1) deformation, while the
 * field still bends a long part freely at the scale of h. The weights reproduce constant and
 * linear functions, so translations and affine maps of a part are exact.
 *
 * Backward is the transpose, ∂L/∂c_bk = Σ_i w_ib ∂L/∂Δ_ik, computed per node over its list of
 * points (a gather in a fixed order: deterministic, no atomics); ∂L/∂δ_ik = ∂L/∂Δ_ik.
 */

/* Δ = δ + W c for every (control point, keyframe). */
__kernel void field_forward(__global const float2* free_offsets, /* [K][n_cp] δ */
                            __global const float2* coef,         /* [K][n_nodes] c */
                            __global const int* cp_node_first,   /* CSR over points */
                            __global const int* cp_node, __global const float* cp_node_w,
                            __global float2* offsets, /* [K][n_cp] Δ (written) */
                            int n_cp, int n_nodes) {
  const int i = get_global_id(0), k = get_global_id(1);
  if (i >= n_cp) return;
  const size_t at = (size_t)k * n_cp + i;
  float2 d = free_offsets[at];
  for (int e = cp_node_first[i]; e < cp_node_first[i + 1]; ++e)
    d += cp_node_w[e] * coef[(size_t)k * n_nodes + cp_node[e]];
  offsets[at] = d;
}

/* ∂L/∂c = Wᵀ ∂L/∂Δ for every (node, keyframe). */
__kernel void field_backward(__global const float2* grad_offsets, /* [K][n_cp] ∂L/∂Δ */
                             __global const int* node_cp_first,  /* CSR over nodes */
                             __global const int* node_cp, __global const float* node_cp_w,
                             __global float2* grad_coef, /* [K][n_nodes] (written) */
                             int n_cp, int n_nodes) {
  const int b = get_global_id(0), k = get_global_id(1);
  if (b >= n_nodes) return;
  float2 g = (float2)(0.0f);
  for (int e = node_cp_first[b]; e < node_cp_first[b + 1]; ++e)
    g += node_cp_w[e] * grad_offsets[(size_t)k * n_cp + node_cp[e]];
  grad_coef[(size_t)k * n_nodes + b] = g;
}
