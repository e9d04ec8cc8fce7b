/* lines.cl: gathers the line segments of every draw from the point buffer.
 *
 * Fills use the flattened polyline of each subpath, closed; strokes use the outline contours
 * written by stroke.cl. The topology (which two points make line j) is a fixed table built at
 * plan time, so this is a pure gather: lines[k][j] = (pts[k][a_j], pts[k][b_j]).
 *
 * With snap_y (RasterPlan::browser_edges; renders that people watch, never the fitter) every
 * end point's y is rounded to the nearest quarter pixel first, as browsers do: Skia's analytic
 * rasteriser, which draws SVG in Chromium, stores an edge's end points in fixed point and snaps
 * their y to 1/4 pixel (SkAnalyticEdge::setLine, SnapY with kDefaultAccuracy = 2) before
 * integrating coverage exactly. On a thin stroke that moves each side's edge by up to 1/8 px,
 * which is most of its edge pixels' coverage: measured against Chromium, a straight 3-px
 * stroke drawn with exact edges is 39 dB away, with snapped edges 55 dB (Chromium's stroke is
 * exactly its fill of our outline; tests/tools/stroke_agreement.py). Curved strokes need more:
 * Skia outlines a curve's offset with quadratics and cuts those into few chords, so the browser
 * mode also rebuilds every stroke that way before planning (raster/browser_stroke.h), which
 * takes 2-6 px curves and circles from 34-37 dB to 50-54 dB; strokes at most a pixel wide are
 * hairlines there, drawn on the CPU (raster/browser_hairline.cpp, 54-57 dB). The snap has no
 * derivative, so the fit's forward pass keeps exact edges.
 */
__kernel void gather_lines(__global const float2* pts,   /* [K][n_pts] */
                           __global const int2* line_ab,  /* [n_lines] point indices */
                           __global float4* lines,        /* [K][n_lines] (x0, y0, x1, y1) */
                           int n_pts, int n_lines, int snap_y) {
  const int j = get_global_id(0), k = get_global_id(1);
  if (j >= n_lines) return;
  const int2 ab = line_ab[j];
  __global const float2* p = pts + (size_t)k * n_pts;
  float2 a = p[ab.x], b = p[ab.y];
  if (snap_y) {
    a.y = floor(4.0f * a.y + 0.5f) * 0.25f;
    b.y = floor(4.0f * b.y + 0.5f) * 0.25f;
  }
  lines[(size_t)k * n_lines + j] = (float4)(a, b);
}
