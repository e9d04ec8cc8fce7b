// Signed-area accumulation of a draw's lines (see area_coverage.h).
#include "raster/area_coverage.h"

#include <algorithm>
#include <cmath>

#include "raster/raster_ref.h"

namespace svgm {

namespace {

// Accumulates one line (x within [0, w], any y) into `acc` ((w + 2) cells per row): after a
// running sum along a row, cell x holds the signed area of pixel x to the right of the line.
void accumulate(std::vector<double>& acc, int w, int h, double x0, double y0, double x1, double y1) {
  if (y0 == y1) return;
  const double dir = y0 < y1 ? 1.0 : -1.0;
  if (y0 > y1) {
    std::swap(x0, x1);
    std::swap(y0, y1);
  }
  const double dxdy = (x1 - x0) / (y1 - y0);
  const size_t stride = static_cast<size_t>(w) + 2;
  const int row0 = std::max(0, static_cast<int>(std::floor(y0)));
  const int row1 = std::min(h, static_cast<int>(std::ceil(y1)));
  for (int y = row0; y < row1; ++y) {
    const double ya = std::max<double>(y, y0), yb = std::min<double>(y + 1, y1);
    if (yb <= ya) continue;
    // The ends' x are within [0, w] (the caller clamps them), but the interpolation between
    // them may round a hair outside, and a cell at -1 is before the row (heap corruption: a
    // fitted ground drawn from x = -0.1 crashed `render` of a clip).
    const double xa = std::clamp(x0 + (ya - y0) * dxdy, 0.0, static_cast<double>(w));
    const double xb = std::clamp(x0 + (yb - y0) * dxdy, 0.0, static_cast<double>(w));
    const double d = (yb - ya) * dir;
    double* row = acc.data() + static_cast<size_t>(y) * stride;
    const double lo = std::min(xa, xb), hi = std::max(xa, xb);
    const int i0 = static_cast<int>(std::floor(lo));
    if (hi - lo < 1e-12 || std::floor(hi) == i0 || hi == i0 + 1.0) {
      // Within one cell: the part right of the line's mean x in that cell, the rest next door.
      const double xm = 0.5 * (lo + hi) - i0;
      row[i0] += d * (1 - xm);
      row[i0 + 1] += d * xm;
      continue;
    }
    // Across cells: the covered area grows quadratically in the first and last cells and
    // linearly in between (the line's x as a function of its height is linear).
    const double s = 1.0 / (hi - lo);  // height fraction per unit of x
    const int i1 = static_cast<int>(std::ceil(hi));
    const double f0 = lo - i0, f1 = hi - (i1 - 1);
    const double a0 = 0.5 * s * (1 - f0) * (1 - f0);  // area share right of the line in cell i0
    const double am = 0.5 * s * f1 * f1;              // share left of the line in cell i1 - 1
    row[i0] += d * a0;
    if (i1 == i0 + 2) {
      row[i0 + 1] += d * (1 - a0 - am);
    } else {
      const double a1 = s * (1.5 - f0);
      row[i0 + 1] += d * (a1 - a0);
      for (int x = i0 + 2; x < i1 - 1; ++x) row[x] += d * s;
      const double a2 = a1 + (i1 - i0 - 3) * s;
      row[i1 - 1] += d * (1 - a2 - am);
    }
    row[i1] += d * am;
  }
}

}  // namespace

Coverage draw_coverage_box(const RasterPlan& plan, const std::vector<double>& pts, int draw) {
  const int w = plan.width, h = plan.height;
  const Draw& d = plan.draws[draw];
  // The lines' bounding box, clamped to the canvas (left of it, lines are projected onto x = 0).
  double bx0 = INFINITY, by0 = INFINITY, bx1 = -INFINITY, by1 = -INFINITY;
  for (int l = d.first_line; l < d.first_line + d.line_count; ++l)
    for (int e = 0; e < 2; ++e) {
      const int p = plan.line_ab[2 * l + e];
      bx0 = std::min(bx0, pts[2 * p]); bx1 = std::max(bx1, pts[2 * p]);
      by0 = std::min(by0, pts[2 * p + 1]); by1 = std::max(by1, pts[2 * p + 1]);
    }
  Coverage c;
  if (!(bx0 <= bx1)) return c;
  c.x0 = std::clamp(static_cast<int>(std::floor(bx0)), 0, w);
  c.y0 = std::clamp(static_cast<int>(std::floor(by0)), 0, h);
  const int x1 = std::clamp(static_cast<int>(std::floor(bx1)) + 1, 0, w);
  const int y1 = std::clamp(static_cast<int>(std::floor(by1)) + 1, 0, h);
  if (x1 <= c.x0 || y1 <= c.y0) return c;
  c.w = x1 - c.x0;
  c.h = y1 - c.y0;
  // Accumulated in box coordinates: a box of c.w columns (plus 2 cells) and c.h rows.
  const size_t stride = static_cast<size_t>(c.w) + 2;
  std::vector<double> acc(stride * c.h, 0.0);
  const double ox = c.x0, oy = c.y0;
  // Clips a line to x in [0, c.w] of the box: parts left of it are projected onto its left
  // side (they still wind every pixel to their right), parts right of it onto its right side
  // (they wind none).
  auto add = [&](double ax, double ay, double bx, double by) {
    ax -= ox; bx -= ox; ay -= oy; by -= oy;
    // Split parameters: 0, the crossings of the box's sides in increasing t, 1.
    double ts[4] = {0, 1, 1, 1};
    int n = 1;
    if (ax != bx)
      for (const double edge : {0.0, static_cast<double>(c.w)}) {
        const double t = (edge - ax) / (bx - ax);
        if (t > 0 && t < 1) ts[n++] = t;
      }
    if (n == 3 && ts[1] > ts[2]) std::swap(ts[1], ts[2]);
    ts[n++] = 1;
    for (int i = 0; i + 1 < n; ++i) {
      const double ta = ts[i], tb = ts[i + 1];
      if (tb <= ta) continue;
      auto cl = [&](double x) { return std::clamp(x, 0.0, static_cast<double>(c.w)); };
      accumulate(acc, c.w, c.h, cl(ax + ta * (bx - ax)), ay + ta * (by - ay), cl(ax + tb * (bx - ax)),
                 ay + tb * (by - ay));
    }
  };
  for (int l = d.first_line; l < d.first_line + d.line_count; ++l) {
    const int a = plan.line_ab[2 * l], b = plan.line_ab[2 * l + 1];
    add(pts[2 * a], pts[2 * a + 1], pts[2 * b], pts[2 * b + 1]);
  }
  c.a.resize(static_cast<size_t>(c.w) * c.h);
  for (int y = 0; y < c.h; ++y) {
    double sum = 0;
    const double* row = acc.data() + static_cast<size_t>(y) * stride;
    for (int x = 0; x < c.w; ++x) {
      sum += row[x];
      c.a[static_cast<size_t>(y) * c.w + x] = static_cast<float>(ref::fill_rule_coverage(sum, d.rule));
    }
  }
  return c;
}

std::vector<float> draw_coverage(const RasterPlan& plan, const std::vector<double>& pts, int draw) {
  const Coverage c = draw_coverage_box(plan, pts, draw);
  std::vector<float> out(static_cast<size_t>(plan.width) * plan.height, 0.0f);
  for (int y = 0; y < c.h; ++y)
    for (int x = 0; x < c.w; ++x)
      out[static_cast<size_t>(y + c.y0) * plan.width + x + c.x0] = c.a[static_cast<size_t>(y) * c.w + x];
  return out;
}

}  // namespace svgm
