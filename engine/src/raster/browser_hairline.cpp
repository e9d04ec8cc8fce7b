// Strokes at most one device pixel wide drawn as Chromium draws them: as anti-aliased hairlines
// (see browser_stroke.h). Skia treats such a stroke as a hairline whose alpha is the stroke's
// width (SkDrawTreatAsHairline), flattens each cubic into 2^k lines (k the first level at which
// the handles' distance from the chord's thirds is below 1/8 px times 4^k, SkScan_Hairline) and
// each conic, via quadratics within 1/4 px, into 2^k lines from the quadratic's bulge in whole
// pixels; then draws every line on its own (SkScan_Antihair): for a line closer to horizontal,
// in each pixel column it crosses, a one-pixel-tall box centred on the line's height at the
// column's centre, split between the two rows it straddles, times the share of the column the
// line spans at its ends (transposed for steeper lines), each line blended over the last.
// Measured on tests/tools/stroke_agreement.py's straight 1-px strokes, this model is 56 dB
// from Chromium; filling a 1-px outline is 35-37 dB.
#include <algorithm>
#include <array>
#include <cmath>

#include "raster/browser_stroke.h"

namespace svgm {

namespace {

constexpr int kMaxCubicLevel = 9;  // Skia: at most 512 lines per cubic
constexpr int kMaxQuadLevel = 5;   // Skia: at most 32 lines per quadratic

// Lines of one cubic (end point excluded, start included).
void cubic_lines(const Vec2* p, std::vector<Vec2>& out) {
  const Vec2 p13 = (1.0 / 3) * (2 * p[0] + p[3]), p23 = (1.0 / 3) * (p[0] + 2 * p[3]);
  const double diff = std::max({std::fabs(p[1].x - p13.x), std::fabs(p[1].y - p13.y),
                                std::fabs(p[2].x - p23.x), std::fabs(p[2].y - p23.y)});
  int n = 1 << kMaxCubicLevel;
  double tol = 1.0 / 8;
  for (int i = 0; i < kMaxCubicLevel; ++i, tol *= 4)
    if (diff < tol) {
      n = 1 << i;
      break;
    }
  for (int i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / n, u = 1 - t;
    out.push_back(u * u * u * p[0] + 3 * u * u * t * p[1] + 3 * u * t * t * p[2] + t * t * t * p[3]);
  }
}

// Skia's test for a cubic whose handles stay within the right angles at its ends.
bool nice_cubic(const Vec2* p) {
  auto ok = [](Vec2 a, Vec2 pivot, Vec2 b) {
    return (a.x - pivot.x) * (b.x - pivot.x) + (a.y - pivot.y) * (b.y - pivot.y) >= 0;
  };
  return ok(p[1], p[0], p[3]) && ok(p[2], p[0], p[3]) && ok(p[1], p[3], p[0]) && ok(p[2], p[3], p[0]);
}

// Parameters in (0, 1) where the cubic's speed and acceleration are orthogonal (F' . F'' = 0,
// Skia's SkFindCubicMaxCurvature), found by bracketing the cubic polynomial's sign changes.
std::vector<double> max_curvature_ts(const Vec2* p) {
  double k[4] = {0, 0, 0, 0};
  for (int axis = 0; axis < 2; ++axis) {
    auto v = [&](int i) { return axis == 0 ? p[i].x : p[i].y; };
    const double a = v(1) - v(0), b = v(2) - 2 * v(1) + v(0), c = v(3) + 3 * (v(1) - v(2)) - v(0);
    k[0] += c * c, k[1] += 3 * b * c, k[2] += 2 * b * b + c * a, k[3] += a * b;
  }
  auto f = [&](double t) { return ((k[0] * t + k[1]) * t + k[2]) * t + k[3]; };
  std::vector<double> ts;
  constexpr int kSteps = 256;
  for (int i = 0; i < kSteps; ++i) {
    double lo = static_cast<double>(i) / kSteps, hi = static_cast<double>(i + 1) / kSteps;
    double flo = f(lo), fhi = f(hi);
    if (flo == 0 && i > 0) ts.push_back(lo);
    if (flo * fhi >= 0) continue;
    for (int it = 0; it < 60; ++it) {
      const double m = 0.5 * (lo + hi), fm = f(m);
      if ((fm < 0) == (flo < 0)) lo = m, flo = fm;
      else hi = m;
    }
    ts.push_back(0.5 * (lo + hi));
  }
  return ts;
}

// The cubic cut at ascending parameters ts (de Casteljau), piece by piece.
std::vector<std::array<Vec2, 4>> chop_cubic(const Vec2* p, const std::vector<double>& ts) {
  std::vector<std::array<Vec2, 4>> out;
  std::array<Vec2, 4> rest{p[0], p[1], p[2], p[3]};
  double done = 0;
  for (double t : ts) {
    const double u = (t - done) / (1 - done);
    const Vec2 a = rest[0] + u * (rest[1] - rest[0]), b = rest[1] + u * (rest[2] - rest[1]);
    const Vec2 c = rest[2] + u * (rest[3] - rest[2]), ab = a + u * (b - a), bc = b + u * (c - b);
    const Vec2 m = ab + u * (bc - ab);
    out.push_back({rest[0], a, ab, m});
    rest = {m, bc, c, rest[3]};
    done = t;
  }
  out.push_back(rest);
  return out;
}

// Lines of one quadratic (end point excluded).
void quad_lines(const Vec2* q, std::vector<Vec2>& out) {
  const Vec2 m = 0.5 * (q[0] + q[2]);
  const unsigned dx = static_cast<unsigned>(std::ceil(std::fabs(m.x - q[1].x)));
  const unsigned dy = static_cast<unsigned>(std::ceil(std::fabs(m.y - q[1].y)));
  const unsigned d = dx > dy ? dx + (dy >> 1) : dy + (dx >> 1);
  int bits = 0;
  while (bits < 32 && (d >> bits) != 0) ++bits;
  const int level = std::min((bits + 1) >> 1, kMaxQuadLevel);
  const int n = 1 << level;
  for (int i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / n, u = 1 - t;
    out.push_back(u * u * q[0] + 2 * u * t * q[1] + t * t * q[2]);
  }
}

// Source-over of coverage a into pixel (x, y).
void blend(std::vector<float>& cov, int w, int h, int x, int y, double a) {
  if (x < 0 || y < 0 || x >= w || y >= h || a <= 0) return;
  float& c = cov[static_cast<size_t>(y) * w + x];
  c = static_cast<float>(1 - (1 - c) * (1 - std::min(1.0, a)));
}

// One anti-aliased hairline from a to b.
void hairline(std::vector<float>& cov, int w, int h, Vec2 a, Vec2 b) {
  const bool flat = std::fabs(b.x - a.x) >= std::fabs(b.y - a.y);
  // Work along the major axis u (x for flat lines), with v the minor one.
  double u0 = flat ? a.x : a.y, v0 = flat ? a.y : a.x, u1 = flat ? b.x : b.y, v1 = flat ? b.y : b.x;
  if (u0 > u1) std::swap(u0, u1), std::swap(v0, v1);
  if (u1 - u0 <= 0) return;
  const double s = (v1 - v0) / (u1 - u0);
  for (int i = static_cast<int>(std::floor(u0)); i < static_cast<int>(std::ceil(u1)); ++i) {
    const double span = std::min(u1, i + 1.0) - std::max(u0, static_cast<double>(i));
    const double v = v0 + s * (i + 0.5 - u0) + 0.5;
    const int lo = static_cast<int>(std::floor(v));
    const double f = v - lo;
    if (flat) {
      blend(cov, w, h, i, lo - 1, (1 - f) * span);
      blend(cov, w, h, i, lo, f * span);
    } else {
      blend(cov, w, h, lo - 1, i, (1 - f) * span);
      blend(cov, w, h, lo, i, f * span);
    }
  }
}

}  // namespace

bool browser_hairline(const Path& path, const Affine& view) {
  return path.has_stroke && path.stroke.width > 0 && path.stroke.width * view.mean_scale() <= 1;
}

std::vector<float> browser_hairline_coverage(const Path& path, const Affine& view, int w, int h) {
  std::vector<float> cov(static_cast<size_t>(w) * h, 0.0f);
  const bool arcs = path.tag == "circle" || path.tag == "ellipse" || path.tag == "rect";
  for (const Subpath& sp : path.subpaths) {
    if (sp.points.empty()) continue;
    std::vector<Vec2> px(sp.points.size());
    for (size_t i = 0; i < px.size(); ++i) px[i] = view.apply(sp.points[i]);
    std::vector<Vec2> poly;
    for (size_t c = 0; c < sp.segment_count(); ++c) {
      const Vec2* q = &px[3 * c];
      // Straight cubics (our lines) are one line, as Skia's lines are.
      const Vec2 d = q[3] - q[0];
      const double l2 = d.x * d.x + d.y * d.y;
      auto off = [&](Vec2 p) { return l2 > 0 ? std::fabs((p.x - q[0].x) * d.y - (p.y - q[0].y) * d.x) / std::sqrt(l2) : 0.0; };
      if (off(q[1]) < 1e-9 && off(q[2]) < 1e-9) {
        poly.push_back(q[0]);
        continue;
      }
      Vec2 ctrl;
      if (arcs && quarter_arc_conic(q, &ctrl)) {
        std::vector<Vec2> quads = browser_conic_quads(q[0], ctrl, q[3], std::sqrt(0.5));
        for (size_t k = 0; k + 2 < quads.size(); k += 3) quad_lines(&quads[k], poly);
      } else if (nice_cubic(q)) {
        cubic_lines(q, poly);
      } else {  // Skia first cuts it where its curvature peaks
        for (const auto& piece : chop_cubic(q, max_curvature_ts(q))) cubic_lines(piece.data(), poly);
      }
    }
    poly.push_back(px.back());
    if (sp.closed && !(px.back() == px.front())) poly.push_back(px.front());
    for (size_t i = 0; i + 1 < poly.size(); ++i) hairline(cov, w, h, poly[i], poly[i + 1]);
  }
  const double alpha = std::min(1.0, path.stroke.width * view.mean_scale());
  if (alpha < 1)
    for (float& c : cov) c = static_cast<float>(c * alpha);
  return cov;
}

}  // namespace svgm
