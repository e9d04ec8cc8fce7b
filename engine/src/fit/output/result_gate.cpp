// The result gate (see result_gate.h).
#include "fit/output/result_gate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

#include "fit/target/compact_raw.h"
#include "raster/area_coverage.h"
#include "raster/raster_ref.h"

namespace svgm {

namespace {

struct Box {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  void add(double x, double y) {
    x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
  }
  bool empty() const { return !(x1 >= x0); }
  double diagonal() const { return empty() ? 0 : std::hypot(x1 - x0, y1 - y0); }
};

std::string format(const char* fmt, double a, double b = 0, double c = 0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, a, b, c);
  return buf;
}

// A pixel of the fit "shows what the target shows" when no channel of the fit over white differs
// from the cleaned target by more than this: the same paint, allowing for antialiasing and the
// target's compression, not a different colour.
constexpr float kShownTolerance = 0.2f;

// The share of path p's coverage at one keyframe, weighted by coverage, where the fit's render
// shows what the target shows (kShownTolerance). A path that grew because the target's own
// motion stretched it (a warp that pulls an eye into a long line) scores near 1: its pixels
// are where the target has that paint. A path that exploded into a spike or a sheet scores
// low: it covers pixels where the target has background or other paint. A path drawn
// entirely under others scores high too, and is invisible in this keyframe as it is.
// `cp`: the keyframe's n_cp canvas points; `render`, `target`: RGBA frames at the plan's size.
double shown_share(const RasterPlan& plan, const double* cp, const Affine& view, int path,
                   const float* render, const float* target) {
  std::vector<double> px(static_cast<size_t>(plan.n_cp) * 2);
  for (int i = 0; i < plan.n_cp; ++i) {
    const Vec2 q = view.apply({cp[2 * i], cp[2 * i + 1]});
    px[2 * static_cast<size_t>(i)] = q.x, px[2 * static_cast<size_t>(i) + 1] = q.y;
  }
  std::vector<double> pts = ref::flatten(plan, px);
  ref::stroke(plan, pts);
  double covered = 0, shown = 0;
  for (size_t d = 0; d < plan.draws.size(); ++d) {
    if (plan.draws[d].path != path) continue;
    const Coverage c = draw_coverage_box(plan, pts, static_cast<int>(d));
    for (int y = 0; y < c.h; ++y)
      for (int x = 0; x < c.w; ++x) {
        const float a = c.a[static_cast<size_t>(y) * c.w + x];
        if (!(a > 0)) continue;
        const size_t i = static_cast<size_t>(c.y0 + y) * plan.width + (c.x0 + x);
        float diff = 0;
        for (int ch = 0; ch < 3; ++ch)
          diff = std::max(diff, std::fabs(render[4 * i + ch] + (1 - render[4 * i + 3]) - target[4 * i + ch]));
        covered += a;
        shown += diff <= kShownTolerance ? a : 0;
      }
  }
  return covered > 0 ? shown / covered : 1;
}

// The signed area enclosed by path p's fills at one keyframe (`q`: its control points): the
// flattened outline's lines, vertex v = sum_j w[4v + j] * cp[vert_cp[v] + j], by the shoelace
// formula. Holes wound the other way subtract; a shape folded flat encloses next to nothing.
double fill_area(const RasterPlan& plan, const double* q, int p) {
  auto vertex = [&](int v) {
    double x = 0, y = 0;
    for (int j = 0; j < 4; ++j) {
      const double w = plan.vert_w[4 * static_cast<size_t>(v) + j];
      const size_t c = static_cast<size_t>(plan.vert_cp[static_cast<size_t>(v)] + j);
      x += w * q[2 * c], y += w * q[2 * c + 1];
    }
    return Vec2{x, y};
  };
  double twice = 0;
  for (const Draw& d : plan.draws) {
    if (d.path != p || d.is_stroke) continue;
    for (int l = d.first_line; l < d.first_line + d.line_count; ++l) {
      const int a = plan.line_ab[2 * static_cast<size_t>(l)], b = plan.line_ab[2 * static_cast<size_t>(l) + 1];
      if (a >= plan.n_flat || b >= plan.n_flat) continue;  // not an outline vertex
      const Vec2 u = vertex(a), w = vertex(b);
      twice += u.x * w.y - u.y * w.x;
    }
  }
  return twice / 2;
}

// Path p's middle (the mean of its control points `q`, canvas units) lies within
// kEdgeShare of the canvas's larger side from an edge, or beyond it: the path is leaving the
// frame, where the target shows nothing of it, and the fit presses it flat against the edge
// (emoji_u1f46b: a shoe the warp carries below the canvas, its box 0.6 px tall at y = 128,
// warned of as a fold though nobody can see it).
constexpr double kEdgeShare = 0.01;
bool at_canvas_edge(const RasterPlan& plan, const double* q, int p, const Scene& scene) {
  const int first = plan.path_cp_first[static_cast<size_t>(p)], count = plan.path_cp_count[static_cast<size_t>(p)];
  if (count <= 0) return false;
  double x = 0, y = 0;
  for (int i = first; i < first + count; ++i) x += q[2 * i] / count, y += q[2 * i + 1] / count;
  const double m = kEdgeShare * std::max(scene.width, scene.height);
  return x < m || y < m || x > scene.width - m || y > scene.height - m;
}

// "2-5, 7, 9-10" for increasing keyframe indices.
std::string ranges(const std::vector<int>& ks) {
  std::string s;
  for (size_t i = 0; i < ks.size();) {
    size_t j = i;
    while (j + 1 < ks.size() && ks[j + 1] == ks[j] + 1) ++j;
    if (!s.empty()) s += ", ";
    s += std::to_string(ks[i]) + (j > i ? "-" + std::to_string(ks[j]) : "");
    i = j + 1;
  }
  return s;
}

}  // namespace

GateVerdict judge_fit(const TargetFrames& target, const std::vector<float>& renders,
                      const std::vector<double>& points, const RasterPlan& plan, const Scene& scene,
                      const Affine& view, const GateOptions& o) {
  const size_t frame = static_cast<size_t>(target.width) * target.height * 4;
  return judge_fit(target, [&](int k) {
    const auto at = renders.begin() + static_cast<std::ptrdiff_t>(static_cast<size_t>(k) * frame);
    return std::vector<float>(at, at + static_cast<std::ptrdiff_t>(frame));
  }, points, plan, scene, view, o);
}

GateVerdict judge_fit(const TargetFrames& target, const std::function<std::vector<float>(int)>& render,
                      const std::vector<double>& points, const RasterPlan& plan, const Scene& scene,
                      const Affine& view, const GateOptions& o) {
  return judge_fit(target, nullptr, render, points, plan, scene, view, o);
}

GateVerdict judge_fit(const TargetFrames& target, const CompactRaw* compact,
                      const std::function<std::vector<float>(int)>& render, const std::vector<double>& points,
                      const RasterPlan& plan, const Scene& scene, const Affine& view, const GateOptions& o,
                      const CleanedFrameReader& cleaned) {
  GateVerdict v;
  const int K = target.keyframes, W = target.width, H = target.height;
  const size_t px = static_cast<size_t>(W) * H;
  const size_t n_cp = static_cast<size_t>(plan.n_cp);
  // The target's foreground extent per keyframe, in canvas units (for "what the target shows").
  const Affine to_canvas = view.inverse();
  std::vector<double> fg_diag(static_cast<size_t>(K), 0);
  for (int k = 0; k < K; ++k) {
    Box b;
    const RawFigure f = raw_figure(target, compact, k);
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x)
        if (f.figure[static_cast<size_t>(y) * W + x]) b.add(x, y);
    if (!b.empty()) {
      const Vec2 a = to_canvas.apply({b.x0, b.y0}), c = to_canvas.apply({b.x1 + 1, b.y1 + 1});
      fg_diag[static_cast<size_t>(k)] = std::hypot(c.x - a.x, c.y - a.y);
    }
  }
  // Rest size of each path, in the plan's point layout.
  std::vector<double> rest_diag(scene.paths.size(), 0);
  for (size_t p = 0; p < scene.paths.size(); ++p) {
    Box b;
    for (const Subpath& sp : scene.paths[p].subpaths)
      for (const Vec2& q : sp.points) b.add(q.x, q.y);
    rest_diag[p] = b.diagonal();
  }
  const double canvas_diag = std::hypot(scene.width, scene.height);
  for (int k = 0; k < K; ++k) {
    const std::string at = "keyframe " + std::to_string(k) + ": ";
    // Fidelity. The figure is what differs from the frame's background (the median of its
    // border pixels), in the target and in the fit alike, so an off-white or drifting
    // background and white parts of the drawing count the same on both sides.
    const std::vector<float> rendered = render(k);
    const float* r = rendered.data();
    std::vector<float> frame;  // keyframe k's cleaned frame, when its holder keeps them packed
    if (cleaned) {
      frame.resize(px * 4);
      cleaned(k, frame.data());
    }
    const float* t = cleaned ? frame.data() : &target.rgba[static_cast<size_t>(k) * px * 4];
    const RawFigure f = raw_figure(target, compact, k);  // the target's figure and background
    double se = 0;
    size_t inter = 0, uni = 0;
    for (size_t i = 0; i < px; ++i) {
      const float a = r[4 * i + 3];
      float over[3];
      for (int c = 0; c < 3; ++c) {
        over[c] = r[4 * i + c] + (1 - a);
        const double d = over[c] - t[4 * i + c];
        se += d * d;
      }
      const bool drawn = differs_from(over[0], over[1], over[2], f.background);
      const bool fg = f.figure[i] != 0;
      inter += drawn && fg;
      uni += drawn || fg;
    }
    const double mse = se / (3.0 * px);
    const double psnr = mse > 0 ? 10 * std::log10(1 / mse) : 99;
    const double iou = uni ? static_cast<double>(inter) / uni : 1;
    v.psnr_db.push_back(psnr);
    v.iou.push_back(iou);
    if (!(psnr >= o.min_psnr_db))
      v.reasons.push_back(at + format("the fit matches the target at only %.1f dB (at least %.0f dB)", psnr, o.min_psnr_db));
    if (!(iou >= o.min_iou))
      v.reasons.push_back(at + format("the fit covers the target's figure with IoU %.2f (at least %.2f)", iou, o.min_iou));
    // Geometry.
    const double* q = &points[static_cast<size_t>(k) * n_cp * 2];
    double worst = 0;  // farthest outside the canvas, in canvas sizes
    for (size_t p = 0; p < scene.paths.size(); ++p) {
      Box b;
      for (int i = 0; i < plan.path_cp_count[p]; ++i) {
        const double x = q[2 * (plan.path_cp_first[p] + i)], y = q[2 * (plan.path_cp_first[p] + i) + 1];
        if (!std::isfinite(x) || !std::isfinite(y)) {
          worst = std::numeric_limits<double>::infinity();
          continue;
        }
        b.add(x, y);
        worst = std::max({worst, -x / scene.width, (x - scene.width) / scene.width,
                          -y / scene.height, (y - scene.height) / scene.height});
      }
      if (rest_diag[p] < 0.01 * canvas_diag || b.empty()) continue;  // specks: no stable size
      const double target_change = fg_diag[0] > 0 && fg_diag[static_cast<size_t>(k)] > 0
                                       ? fg_diag[static_cast<size_t>(k)] / fg_diag[0] : 1;
      const double ratio = b.diagonal() / rest_diag[p];
      if (ratio > o.max_growth * std::max(1.0, target_change)) {
        // The target's figure as a whole may keep its size while a warp stretches one feature:
        // growth is refused only where the grown path does not show what the target shows.
        const double shown = shown_share(plan, q, view, static_cast<int>(p), r, t);
        const std::string what = "path '" + scene.paths[p].id + "' " +
                                 format("grew %.1fx (the target's figure %.2fx), ", ratio, target_change);
        if (shown < o.min_shown)
          v.reasons.push_back(at + what + format("and only %.2f of it shows what the target shows", shown));
        else
          v.waived.push_back(at + what + format("as the target shows it (%.2f of its pixels agree)", shown));
      }
      else if (ratio < o.min_shrink * std::min(1.0, target_change))
        v.reasons.push_back(at + "path '" + scene.paths[p].id + "' " +
                            format("collapsed to %.2fx its size (the target's figure %.2fx)", ratio, target_change));
    }
    if (worst > o.max_outside)
      v.reasons.push_back(at + (std::isfinite(worst) ? format("control points lie %.1f canvas sizes outside the canvas", worst)
                                                     : std::string("control points are not finite")));
  }
  // Folded paths (GateVerdict::warnings), against keyframe 0, the drawing at rest.
  for (size_t p = 0; p < scene.paths.size(); ++p) {
    if (rest_diag[p] < 0.01 * canvas_diag) continue;  // specks
    const double a0 = std::fabs(fill_area(plan, points.data(), static_cast<int>(p)));
    if (!(a0 > 0)) continue;  // strokes only, or nothing enclosed at rest
    std::vector<int> folded;
    double least = 1;
    for (int k = 1; k < K; ++k) {
      const double target_change = fg_diag[0] > 0 ? fg_diag[static_cast<size_t>(k)] / fg_diag[0] : 1;
      const double* q = &points[static_cast<size_t>(k) * n_cp * 2];
      if (at_canvas_edge(plan, q, static_cast<int>(p), scene)) continue;
      const double share = std::fabs(fill_area(plan, q, static_cast<int>(p))) / a0;
      if (share < kFoldedArea && target_change >= 0.5) folded.push_back(k), least = std::min(least, share);
    }
    if (!folded.empty())
      v.warnings.push_back("path '" + scene.paths[p].id + "' folds flat at keyframe" + (folded.size() > 1 ? "s " : " ") +
                           ranges(folded) + format(": its enclosed area falls to %.1f%% of the first keyframe's while the "
                                                   "target's figure keeps its size", 100 * least));
  }
  v.passed = v.reasons.empty();
  return v;
}

nlohmann::json gate_json(const GateVerdict& v, const GateOptions& o) {
  return {{"passed", v.passed},
          {"reasons", v.reasons},
          {"waived", v.waived},
          {"warnings", v.warnings},
          {"keyframe_psnr_db", v.psnr_db},
          {"keyframe_iou", v.iou},
          {"thresholds",
           {{"min_psnr_db", o.min_psnr_db},
            {"min_iou", o.min_iou},
            {"max_outside", o.max_outside},
            {"max_growth", o.max_growth},
            {"min_shown", o.min_shown},
            {"min_shrink", o.min_shrink}}}};
}

}  // namespace svgm
