// Strokes drawn as Chromium draws them, for renders people watch (`render --edges browser`,
// previews), never for the fitter.
//
// Chromium's rasteriser (Skia) does not offset a finely flattened centre line as our kernel
// does (kernels/stroke.cl). It outlines a stroke with quadratic Béziers that approximate each
// side's offset curve only to a quarter pixel (SkStroke), joins and caps built from conics, and
// then fills that outline after cutting every quadratic into a power-of-two number of chords
// chosen from its bulge, with the chords' inner vertices snapped to whole or quarter pixels in
// y (SkAnalyticQuadraticEdge). On a 2-6 px stroke those choices move the edges by up to a
// quarter pixel, which is most of an edge pixel's coverage: drawing our exact stroke is 34-37 dB
// from Chromium's on curves and circles. So the browser mode rebuilds every stroke the same way
// and hands the rasteriser a filled polygon: the stroke becomes a fill.
//
// browser_stroke.cpp builds the outline (lines, quadratics, conics); browser_edges.cpp turns it
// into polygons and a scene into one whose strokes are such fills. Strokes at most one device
// pixel wide are no outline in Chromium but anti-aliased hairlines: browser_hairline.cpp draws
// them (through the CPU layer compositor).
#pragma once

#include <vector>

#include "svgmotion/affine.h"
#include "svgmotion/scene.h"

namespace svgm {

// One closed contour of a stroke outline in pixel space: a start point and its verbs.
struct OutlineVerb {
  enum Kind { Line, Quad, Conic } kind = Line;
  Vec2 c;       // control point (Quad, Conic)
  Vec2 p;       // end point
  double w = 1; // conic weight
};
struct OutlineContour {
  Vec2 start;
  std::vector<OutlineVerb> verbs;
};

// The outline of `path`'s stroke in pixel space (`view` maps canvas to pixels), filled with the
// nonzero rule, built as Skia's stroker builds it (browser_stroke.cpp says how).
std::vector<OutlineContour> browser_stroke_outline(const Path& path, const Affine& view);

// The chords Skia's edge builder draws for one quadratic whose y is monotonic (pixel space),
// from its start to its end inclusive: 2^k + 1 points, k from the quadratic's bulge, inner
// points snapped in y (browser_edges.cpp).
std::vector<Vec2> browser_quad_chords(const Vec2 q[3]);

// Every contour of an outline as a polygon, as the browser fills it: conics cut into
// quadratics, quadratics split at their y extrema and cut into chords (browser_quad_chords).
std::vector<std::vector<Vec2>> browser_outline_polygons(const std::vector<OutlineContour>& outline);

// The conic control point of a cubic that approximates a quarter ellipse (where its end
// tangents meet), or false for a straight cubic (browser_stroke.cpp).
bool quarter_arc_conic(const Vec2* cubic, Vec2* ctrl);

// A conic as the quadratics Skia fills it with (3 points each; browser_edges.cpp).
std::vector<Vec2> browser_conic_quads(Vec2 p0, Vec2 p1, Vec2 p2, double w);

// Whether the browser draws `path`'s stroke as a hairline: at most one pixel wide once `view`
// scales it (browser_hairline.cpp), and that hairline's coverage over a w x h frame.
bool browser_hairline(const Path& path, const Affine& view);
std::vector<float> browser_hairline_coverage(const Path& path, const Affine& view, int w, int h);

// `scene` with each visible stroke wider than a hairline replaced by a nonzero fill of its browser outline (in paint
// order right after the path's own fill, with the stroke's paint, opacity and layer), so any
// renderer draws strokes as the browser does. Paths without strokes are unchanged.
Scene with_browser_strokes(const Scene& scene, const Affine& view);

}  // namespace svgm
