// The raster plan: the fixed topology of a scene's rendering, built once on the host.
//
// The plan fixes everything that does not change from frame to frame: how many line segments
// each cubic flattens into (and the Bernstein weights of every flattened vertex), how each
// stroke expands into outline points, which two points make each line, and the draws (a path's
// fill, then its stroke) in paint order with colour and fill rule. Frames then differ only in
// their control points, which is what lets the fitter batch K frames in one launch and carry
// gradients back through the same tables. The CPU reference and the OpenCL routine both
// execute a plan, so they agree by construction on topology and are compared on numbers.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "svgmotion/affine.h"
#include "svgmotion/scene.h"

namespace svgm {

// Must match kernels/prelude.cl.
enum : uint8_t { kJoinMiter = 0, kJoinMiterClip = 1, kJoinRound = 2, kJoinBevel = 3,
                 kJoinInterior = 4 };
enum : int { kCapButt = 0, kCapRound = 1, kCapSquare = 2 };
enum : int { kRuleNonZero = 0, kRuleEvenOdd = 1 };

struct RasterPlanOptions {
  double flatten_tolerance_px = 0.1;  // max distance of a flattened chord from its curve
  int max_segments_per_cubic = 64;
  // When > 0, every cubic gets at least one chord per this many pixels of its control polygon,
  // whatever its curvature at rest. The fitter needs it: a segment straight at rest gets one
  // chord from Wang's bound, and that chord depends on the segment's end points only, so the
  // loss never sees its handles, which are then free to bulge where no one looks (the exported
  // curve does not draw what was fitted). Enough chords let the loss see a segment bend.
  double max_chord_px = 0;
  // Gradient paints as per-pixel paint images (RasterPlan::paint) while they take at most this
  // many bytes; beyond it (a large render of many gradients) draws keep their mean colour.
  size_t max_paint_bytes = size_t{256} << 20;
};

struct StrokeSubpath {
  int first_vertex = 0;  // index of its polyline's first flattened vertex
  int vertex_count = 0;  // N
  int first_out = 0;     // where its outline points start in the point buffer
  int closed = 0;
  int cap = kCapButt;
  int join_points = 1;   // J
  int cap_points = 0;    // C
  int join = kJoinMiter; // the path's join kind
  float half_width = 0;  // pixels
  float miter_limit = 4;
};

// Lines are grouped in chunks of consecutive lines of one draw (at most kChunkLines): their
// bounding boxes let a band skip most lines it cannot touch with one test per chunk.
inline constexpr int kChunkLines = 16;

struct Draw {
  int path = 0;          // index into Scene::paths
  bool is_stroke = false;
  float rgba[4] = {0, 0, 0, 1};  // straight colour; alpha already times the path's opacity
  int paint = -1;  // a gradient's paint image in RasterPlan::paint, or -1: rgba everywhere
  int rule = kRuleNonZero;
  int first_line = 0, line_count = 0;
  int first_chunk = 0, chunk_count = 0;
};

struct RasterPlan {
  int width = 0, height = 0;

  // Control points of the rest pose in pixel space, (x, y) pairs; 3 zero points of padding at
  // the end so a vertex's 4-point window never reads past the array.
  int n_cp = 0;
  std::vector<float> rest_cp;
  // Per path: its first control point index and count (for motion and export later).
  std::vector<int> path_cp_first, path_cp_count;

  // Flattening: vertex v = sum_j w[4v + j] * cp[vert_cp[v] + j].
  int n_flat = 0;
  std::vector<int> vert_cp;
  std::vector<float> vert_w;
  std::vector<uint8_t> vert_join;  // join kind at each vertex (kJoinInterior inside a cubic)

  std::vector<StrokeSubpath> strokes;
  int n_pts = 0;  // flattened vertices followed by stroke outline points

  int n_lines = 0;
  std::vector<int> line_ab;    // point index pairs
  std::vector<int> line_draw;  // draw index of each line (non-decreasing)
  std::vector<Draw> draws;
  // Paint images of the draws painted with gradients: per image, height * width straight RGBA
  // floats sampled at the pixel centres (raster/gradient_paint.h), alpha times the path's
  // opacity; alpha 0 where a radial gradient leaves a pixel unpainted. The gradient stays where
  // the document puts it (canvas space), as an exported animation whose path data moves draws
  // it; its own motion has no gradient (only the boundary's).
  std::vector<float> paint;
  std::vector<int> chunk_lines;  // (first line, count) pairs
  // Edges as a browser rasterises them: every line's end points rounded to a quarter pixel in y
  // (kernels/lines.cl says why). For renders people watch, which also draw strokes as the
  // browser outlines them (raster/browser_stroke.h, applied to the scene before planning);
  // plan_raster leaves it off, and the fitter, which differentiates coverage, needs it off.
  bool browser_edges = false;
  std::vector<int> line_chunk;   // chunk index of every line

  // Transposed tables for the backward pass (CSR: entries of item i are [first[i], first[i+1])).
  // Point p's lines: entry 2 * line + end (end 0 = the line's first point).
  std::vector<int> pt_first, pt_entries;
  // Control point c's flattened vertices: entry 4 * vertex + j, c = vert_cp[vertex] + j.
  std::vector<int> cp_first, cp_entries;
};

// Plans the rendering of `scene` at width x height pixels, with `view` mapping canvas space to
// pixel space.
RasterPlan plan_raster(const Scene& scene, const Affine& view, int width, int height,
                       const RasterPlanOptions& options = {});

// A y coordinate where browser_edges puts it: the nearest quarter pixel (kernels/lines.cl).
inline double browser_edge_y(double y) { return std::floor(4.0 * y + 0.5) * 0.25; }

// Number of outline points a stroke subpath writes (the formula stroke.cl follows).
int stroke_point_count(const StrokeSubpath& s);

}  // namespace svgm
