// A browser stroke outline (browser_stroke.cpp) turned into the polygons Chromium fills, and a
// scene whose strokes are those fills; see browser_stroke.h.
//
// Skia's edge builder, which feeds its analytic rasteriser, cuts every conic into 2^k
// quadratics (k the smallest with the conic's bulge error, divided by 4 per halving, within a
// quarter pixel), splits quadratics at their y extrema, and draws each y-monotonic quadratic as
// 2^k chords at uniform t with k = floor(bits(d) / 2), d its bulge (the distance from its chord's
// midpoint to its own midpoint, |p0 - 2 p1 + p2| / 4, measured max + min/2 in eighths of a
// pixel, rounded), at least 2 and at most 64 chords: chords up to ~0.24 px from the curve. Its
// end points are stored in 1/256 px (truncated) with y rounded to a quarter pixel; each inner
// vertex is rounded in y to the whole pixel, slid along the chord that reaches it, when that
// chord rises 2 px or more (and is not nearly horizontal), else to a quarter pixel
// (SkAnalyticQuadraticEdge::updateQuadratic). Those inner vertices are stepped from the start
// point after its own y snap, so all of them carry that snap, and a chord whose ends snap to
// one y is skipped (the next starts from the last kept vertex). Modelling both, with each curve
// starting from the outline's own point (not a snapped chord end), took circle and
// curve strokes of 2-6 px from 38-45 dB to 50-54 dB against Chromium (stroke_agreement.py).
// The rasteriser's browser edges (kernels/lines.cl)
// then put every end point on quarter pixels in y, which leaves these points where they are.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "raster/browser_stroke.h"

namespace svgm {

namespace {

constexpr double kConicTol = 0.25;  // px: Skia's conic-to-quadratic tolerance when filling
constexpr int kMaxConicPow2 = 5;    // Skia: at most 32 quadratics per conic

double snap_quarter(double y) { return std::floor(4.0 * y + 0.5) * 0.25; }

// A y-monotonic quadratic: forces the middle y between the ends, as Skia does when it cannot
// cut one (underflow) or after a cut, where both sides' middle points share the extremum's y.
int chop_at_y_extremum(const Vec2 q[3], Vec2 out[5]) {
  const double a = q[0].y, b = q[1].y, c = q[2].y;
  double ab = a - b, bc = b - c;
  if (ab < 0) bc = -bc;
  if (ab == 0 || bc < 0) {  // not monotonic
    double num = a - b, den = a - b - b + c;
    if (num < 0) num = -num, den = -den;
    if (den != 0 && num != 0 && num < den) {
      const double t = num / den;
      const Vec2 p01 = q[0] + t * (q[1] - q[0]), p12 = q[1] + t * (q[2] - q[1]);
      const Vec2 m = p01 + t * (p12 - p01);
      out[0] = q[0], out[1] = {p01.x, m.y}, out[2] = m, out[3] = {p12.x, m.y}, out[4] = q[2];
      return 1;
    }
    out[0] = q[0], out[1] = {q[1].x, std::fabs(a - b) < std::fabs(b - c) ? a : c}, out[2] = q[2];
    return 0;
  }
  out[0] = q[0], out[1] = q[1], out[2] = q[2];
  return 0;
}

// Cuts a conic into 2^k quadratics that share its control polygon's halvings (SkConic::chop).
void conic_to_quads(Vec2 p0, Vec2 p1, Vec2 p2, double w, int pow2, std::vector<Vec2>& quads) {
  if (pow2 == 0) {
    quads.insert(quads.end(), {p0, p1, p2});
    return;
  }
  const Vec2 a = (1 / (1 + w)) * (p0 + w * p1), b = (1 / (1 + w)) * (w * p1 + p2);
  const Vec2 m = (1 / (2 + 2 * w)) * (p0 + 2 * w * p1 + p2);
  const double w2 = std::sqrt(0.5 + 0.5 * w);
  conic_to_quads(p0, a, m, w2, pow2 - 1, quads);
  conic_to_quads(m, b, p2, w2, pow2 - 1, quads);
}

int conic_pow2(Vec2 p0, Vec2 p1, Vec2 p2, double w) {
  const double a = w - 1, k = a / (4 * (2 + a));
  const Vec2 e = k * (p0 - 2 * p1 + p2);
  double err = std::hypot(e.x, e.y);
  int pow2 = 0;
  for (; pow2 < kMaxConicPow2 && err > kConicTol; ++pow2) err *= 0.25;
  return pow2;
}

// Appends a quadratic's chords (without its start point) to a polygon.
void add_quad(const Vec2 q[3], std::vector<Vec2>& poly) {
  Vec2 mono[5];
  const int n = chop_at_y_extremum(q, mono);
  for (int i = 0; i <= n; ++i) {
    const std::vector<Vec2> chords = browser_quad_chords(&mono[2 * i]);
    poly.insert(poly.end(), chords.begin() + 1, chords.end());
  }
}

std::vector<Path> strokes_as_fills(const std::vector<Path>& paths, const Affine& view,
                                   std::vector<int>* new_index) {
  const Affine to_canvas = view.inverse();
  std::vector<Path> out;
  out.reserve(paths.size());
  for (const Path& p : paths) {
    if (new_index) new_index->push_back(static_cast<int>(out.size()));
    const bool visible = p.has_stroke && p.stroke.color.a * p.opacity > 0 && p.stroke.width > 0;
    if (!visible || browser_hairline(p, view)) {  // hairlines stay strokes (browser_hairline.cpp)
      out.push_back(p);
      continue;
    }
    Path fill = p;
    fill.has_stroke = false;
    out.push_back(fill);
    Path s = p;
    s.id = p.id + "-stroke";
    s.subpaths.clear();
    for (const std::vector<Vec2>& poly : browser_outline_polygons(browser_stroke_outline(p, view))) {
      // Each edge as a straight cubic (handles at thirds), so the plan flattens it to one chord.
      Subpath sp;
      sp.closed = true;
      for (size_t i = 0; i < poly.size(); ++i) {
        const Vec2 a = to_canvas.apply(poly[i]), b = to_canvas.apply(poly[(i + 1) % poly.size()]);
        if (i == 0) sp.points.push_back(a);
        sp.points.insert(sp.points.end(), {a + (1.0 / 3) * (b - a), a + (2.0 / 3) * (b - a), b});
      }
      s.subpaths.push_back(std::move(sp));
    }
    s.has_fill = true;
    s.fill = p.stroke.color;
    s.fill_rule = FillRule::NonZero;
    s.fill_gradient = p.stroke_gradient;
    s.has_stroke = false;
    s.stroke_gradient = -1;
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace

std::vector<Vec2> browser_quad_chords(const Vec2 q[3]) {
  // End points in 1/256 px, truncated as Skia stores them (SkAnalyticQuadraticEdge).
  auto fx = [](double v) { return static_cast<int64_t>(v * 256.0); };
  int64_t X0 = fx(q[0].x), Y0 = fx(q[0].y), X1 = fx(q[1].x), Y1 = fx(q[1].y);
  int64_t X2 = fx(q[2].x), Y2 = fx(q[2].y);
  const bool up = Y0 > Y2;
  if (up) std::swap(X0, X2), std::swap(Y0, Y2);
  auto px = [](int64_t v) { return static_cast<double>(v) / 256.0; };
  std::vector<Vec2> pts;
  // Both ends in the same quarter-pixel row: a zero-height edge that draws nothing.
  if (((Y0 + 32) >> 6) == ((Y2 + 32) >> 6)) {
    pts = {{px(X0), px(Y0)}, {px(X2), px(Y2)}};
  } else {
    const int64_t dx = std::llabs((2 * X1 - X0 - X2) >> 2), dy = std::llabs((2 * Y1 - Y0 - Y2) >> 2);
    int64_t dist = dx > dy ? dx + (dy >> 1) : dy + (dx >> 1);  // Skia's cheap distance
    dist = (dist + 16) >> 5;  // eighths of a pixel, rounded
    int bits = 0;
    while (bits < 63 && (dist >> bits) != 0) ++bits;
    const int shift = std::clamp(bits >> 1, 1, 6);
    const int n = 1 << shift;
    const Vec2 a{px(X0), px(Y0)}, b{px(X1), px(Y1)}, c{px(X2), px(Y2)};
    const double last_y = snap_quarter(c.y);
    Vec2 snapped{a.x, snap_quarter(a.y)}, prev = snapped;
    pts.push_back(snapped);
    // Skia steps forward differences from the start point after snapping its y, so every inner
    // point carries the start's snap (up to 1/8 px, the same for the whole quadratic).
    const double start_snap = snapped.y - a.y;
    for (int i = 1; i < n; ++i) {
      const double t = static_cast<double>(i) / n, u = 1 - t;
      Vec2 v = u * u * a + 2 * u * t * b + t * t * c;
      v.y += start_snap;
      const double step_x = v.x - prev.x, step_y = v.y - prev.y;
      Vec2 s;
      if (std::fabs(step_y) >= 2 && std::fabs(step_y) * 64 > std::fabs(step_x) && v.y != snapped.y) {
        const double slope = (v.x - snapped.x) / (v.y - snapped.y);
        s.y = std::min(last_y, std::floor(v.y + 0.5));
        s.x = v.x - slope * (v.y - s.y);
      } else {
        s = {v.x, std::min(last_y, snap_quarter(v.y))};
      }
      prev = v;
      // A chord of no height is no edge: Skia's next chord starts where the last real one ended.
      if (s.y == snapped.y) continue;
      pts.push_back(s);
      snapped = s;
    }
    pts.push_back({c.x, last_y});
  }
  if (up) std::reverse(pts.begin(), pts.end());
  return pts;
}

std::vector<Vec2> browser_conic_quads(Vec2 p0, Vec2 p1, Vec2 p2, double w) {
  std::vector<Vec2> quads;
  conic_to_quads(p0, p1, p2, w, conic_pow2(p0, p1, p2, w), quads);
  return quads;
}

std::vector<std::vector<Vec2>> browser_outline_polygons(const std::vector<OutlineContour>& outline) {
  std::vector<std::vector<Vec2>> polys;
  for (const OutlineContour& c : outline) {
    std::vector<Vec2> poly{c.start};
    Vec2 from = c.start;  // the outline's own point: the polygon's last one may be snapped
    for (const OutlineVerb& v : c.verbs) {
      if (v.kind == OutlineVerb::Line) {
        poly.push_back(v.p);
      } else if (v.kind == OutlineVerb::Quad) {
        const Vec2 q[3] = {from, v.c, v.p};
        add_quad(q, poly);
      } else {
        const std::vector<Vec2> quads = browser_conic_quads(from, v.c, v.p, v.w);
        for (size_t i = 0; i + 2 < quads.size(); i += 3) add_quad(&quads[i], poly);
      }
      from = v.p;
    }
    if (poly.size() >= 3) polys.push_back(std::move(poly));
  }
  return polys;
}

Scene with_browser_strokes(const Scene& scene, const Affine& view) {
  Scene out = scene;
  std::vector<int> index;
  out.paths = strokes_as_fills(scene.paths, view, &index);
  for (Group& g : out.groups)
    for (int& i : g.paths)
      if (i >= 0 && static_cast<size_t>(i) < index.size()) i = index[i];
  for (Mask& m : out.masks) m.paths = strokes_as_fills(m.paths, view, nullptr);
  return out;
}

}  // namespace svgm
