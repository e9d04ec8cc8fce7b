/* flatten.cl: Bézier flattening as a fixed sparse linear map, F = B · P.
 *
 * Each cubic was given, at plan time, a fixed number of line segments (Wang's bound on the rest
 * pose at the render scale, see engine/src/raster/raster_plan.cpp). Every flattened vertex v is
 * then B(t_v) of one cubic, i.e. a fixed linear combination of four consecutive control points:
 *
 *     flat[v] = w0 * cp[i] + w1 * cp[i+1] + w2 * cp[i+2] + w3 * cp[i+3],
 *     (w0..w3) = Bernstein weights ((1-t)^3, 3t(1-t)^2, 3t^2(1-t), t^3),  i = vert_cp[v].
 *
 * The weights do not depend on the frame, so the same table flattens all K frames and its
 * transpose carries gradients back to the control points. One work-item per (vertex, frame).
 */
__kernel void flatten(__global const float2* cp,       /* [K][n_cp] control points */
                      __global const int* vert_cp,     /* [n_flat] first control point */
                      __global const float4* vert_w,   /* [n_flat] Bernstein weights */
                      __global float2* pts,            /* [K][n_pts], writes [0, n_flat) */
                      int n_cp, int n_flat, int n_pts) {
  const int v = get_global_id(0), k = get_global_id(1);
  if (v >= n_flat) return;
  __global const float2* c = cp + (size_t)k * n_cp + vert_cp[v];
  const float4 w = vert_w[v];
  pts[(size_t)k * n_pts + v] = w.x * c[0] + w.y * c[1] + w.z * c[2] + w.w * c[3];
}

/* The transpose: ∂L/∂cp[c] = Σ_v B[v][c] · ∂L/∂flat[v], over the fixed list of vertices whose
 * window contains c (CSR built at plan time; entry = 4 * v + j, j the position of c in v's
 * 4-point window), summed in order. One work-item per (control point, frame). */
__kernel void flatten_backward(__global const float2* grad_pts, /* [K][n_pts] */
                               __global const float4* vert_w, __global const int* cp_first,
                               __global const int* cp_entries, __global float2* grad_cp,
                               int n_cp, int n_pts) {
  const int c = get_global_id(0), k = get_global_id(1);
  if (c >= n_cp) return;
  float2 g = (float2)(0.0f);
  for (int e = cp_first[c]; e < cp_first[c + 1]; ++e) {
    const int v = cp_entries[e] >> 2, j = cp_entries[e] & 3;
    const float4 w = vert_w[v];
    const float wj = j == 0 ? w.x : j == 1 ? w.y : j == 2 ? w.z : w.w;
    g += wj * grad_pts[(size_t)k * n_pts + v];
  }
  grad_cp[(size_t)k * n_cp + c] = g;
}
