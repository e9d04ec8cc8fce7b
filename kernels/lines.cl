/* lines.cl: gathers the line segments of every draw from the point buffer.
 *
 * Fills use the flattened polyline of each subpath, closed; strokes use the outline contours
 * written by stroke.cl. The topology (which two points make line j) is a fixed table built at
 * plan time, so this is a pure gather: lines[k][j] = (pts[k][a_j], pts[k][b_j]).
 */
__kernel void gather_lines(__global const float2* pts,   /* [K][n_pts] */
                           __global const int2* line_ab,  /* [n_lines] point indices */
                           __global float4* lines,        /* [K][n_lines] (x0, y0, x1, y1) */
                           int n_pts, int n_lines) {
  const int j = get_global_id(0), k = get_global_id(1);
  if (j >= n_lines) return;
  const int2 ab = line_ab[j];
  __global const float2* p = pts + (size_t)k * n_pts;
  lines[(size_t)k * n_lines + j] = (float4)(p[ab.x], p[ab.y]);
}
