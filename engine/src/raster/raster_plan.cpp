// Building the raster plan (see raster_plan.h): segment counts, weights, stroke layout, draws.
#include "raster/raster_plan.h"

#include "raster/gradient_paint.h"

#include <algorithm>
#include <cmath>

#include "raster/gradient_paint.h"
#include "svgmotion/error.h"

namespace svgm {

namespace {

// Wang's bound: a cubic flattened into n uniform-t chords deviates at most `tol` from the curve
// when n >= sqrt(3/4 * max|second difference| / tol) (Wang 1984; as used by vello and Skia).
int wang_segments(const Vec2* p, double tol, int max_n) {
  const Vec2 a = p[0] - 2.0 * p[1] + p[2], b = p[1] - 2.0 * p[2] + p[3];
  const double m = std::max(std::hypot(a.x, a.y), std::hypot(b.x, b.y));
  const double n = std::ceil(std::sqrt(0.75 * m / tol));
  return std::clamp(static_cast<int>(std::isfinite(n) ? n : max_n), 1, max_n);
}

// Points strictly inside a half-turn arc of radius r so that chords stay within tol.
int arc_points(double r, double tol) {
  if (r <= tol) return 1;
  const double step = 2.0 * std::acos(std::max(-1.0, 1.0 - tol / r));
  const int m = static_cast<int>(std::ceil(M_PI / step));
  return std::clamp(m - 1, 1, 64);
}

uint8_t join_kind(LineJoin j) {
  switch (j) {
    case LineJoin::Miter: return kJoinMiter;
    case LineJoin::MiterClip: return kJoinMiterClip;
    case LineJoin::Round: return kJoinRound;
    case LineJoin::Bevel: return kJoinBevel;
  }
  return kJoinMiter;
}

int cap_kind(LineCap c) {
  switch (c) {
    case LineCap::Butt: return kCapButt;
    case LineCap::Round: return kCapRound;
    case LineCap::Square: return kCapSquare;
  }
  return kCapButt;
}

// A subpath's flattened vertices: plan_raster's pass 1 makes them, pass 2 draws them.
struct SubRange { int first_vertex, vertex_count; bool closed; };

// Pass 1 of plan_raster: every subpath's control points (in pixels) and its flattened vertices
// as weights of them, per path the vertex range of each of its subpaths.
std::vector<std::vector<SubRange>> flatten_paths(const Scene& scene, const Affine& view, const RasterPlanOptions& opt,
                                                 RasterPlan& plan) {
  const double tol = opt.flatten_tolerance_px;
  std::vector<std::vector<SubRange>> subs(scene.paths.size());
  for (size_t pi = 0; pi < scene.paths.size(); ++pi) {
    const Path& path = scene.paths[pi];
    plan.path_cp_first.push_back(plan.n_cp);
    const uint8_t jk = path.has_stroke ? join_kind(path.stroke.join) : uint8_t{kJoinMiter};
    for (const Subpath& sp : path.subpaths) {
      if (sp.points.empty()) continue;
      const int cp0 = plan.n_cp;
      std::vector<Vec2> px(sp.points.size());
      for (size_t i = 0; i < sp.points.size(); ++i) {
        px[i] = view.apply(sp.points[i]);
        plan.rest_cp.push_back(static_cast<float>(px[i].x));
        plan.rest_cp.push_back(static_cast<float>(px[i].y));
      }
      plan.n_cp += static_cast<int>(sp.points.size());
      SubRange r{plan.n_flat, 0, sp.closed};
      // The first vertex is t = 0 of the first cubic (or the lone point).
      plan.vert_cp.push_back(cp0);
      plan.vert_w.insert(plan.vert_w.end(), {1.f, 0.f, 0.f, 0.f});
      plan.vert_join.push_back(jk);
      ++plan.n_flat;
      for (size_t c = 0; c < sp.segment_count(); ++c) {
        int n = wang_segments(&px[3 * c], tol, opt.max_segments_per_cubic);
        if (opt.max_chord_px > 0) {  // at least one chord per max_chord_px of control polygon
          const Vec2* q = &px[3 * c];
          const double len = std::hypot(q[1].x - q[0].x, q[1].y - q[0].y) +
                             std::hypot(q[2].x - q[1].x, q[2].y - q[1].y) +
                             std::hypot(q[3].x - q[2].x, q[3].y - q[2].y);
          const double chords = std::ceil(len / opt.max_chord_px);
          if (std::isfinite(chords))
            n = std::max(n, static_cast<int>(std::min<double>(chords, opt.max_segments_per_cubic)));
        }
        for (int j = 1; j <= n; ++j) {
          const double t = static_cast<double>(j) / n, u = 1.0 - t;
          plan.vert_cp.push_back(cp0 + static_cast<int>(3 * c));
          plan.vert_w.insert(plan.vert_w.end(),
                             {static_cast<float>(u * u * u), static_cast<float>(3 * t * u * u),
                              static_cast<float>(3 * t * t * u), static_cast<float>(t * t * t)});
          plan.vert_join.push_back(j == n ? jk : uint8_t{kJoinInterior});
          ++plan.n_flat;
        }
      }
      r.vertex_count = plan.n_flat - r.first_vertex;
      subs[pi].push_back(r);
    }
    plan.path_cp_count.push_back(plan.n_cp - plan.path_cp_first.back());
  }
  // Padding so the flatten kernel's 4-point window stays inside the buffer.
  plan.rest_cp.insert(plan.rest_cp.end(), 6, 0.f);
  plan.n_cp += 3;
  plan.n_pts = plan.n_flat;
  return subs;
}

// Chunks: consecutive lines of one draw, kChunkLines at most.
void lay_out_chunks(RasterPlan& plan) {
  for (Draw& d : plan.draws) {
    d.first_chunk = static_cast<int>(plan.chunk_lines.size() / 2);
    for (int j = d.first_line; j < d.first_line + d.line_count; j += kChunkLines)
      plan.chunk_lines.insert(plan.chunk_lines.end(),
                              {j, std::min(kChunkLines, d.first_line + d.line_count - j)});
    d.chunk_count = static_cast<int>(plan.chunk_lines.size() / 2) - d.first_chunk;
  }
  plan.line_chunk.resize(plan.n_lines);
  for (size_t c = 0; c < plan.chunk_lines.size() / 2; ++c)
    for (int j = 0; j < plan.chunk_lines[2 * c + 1]; ++j)
      plan.line_chunk[plan.chunk_lines[2 * c] + j] = static_cast<int>(c);
}

// The backward pass's transposed tables (RasterPlan::pt_first, cp_first): each point's lines,
// each control point's flattened vertices.
void transpose_weights(RasterPlan& plan) {
  // Transposes, in increasing entry order so that sums are taken in a fixed order.
  auto csr = [](int n, const std::vector<std::pair<int, int>>& pairs, std::vector<int>& first,
                std::vector<int>& entries) {
    first.assign(n + 1, 0);
    for (const auto& [row, e] : pairs) ++first[row + 1];
    for (int i = 0; i < n; ++i) first[i + 1] += first[i];
    entries.assign(pairs.size(), 0);
    std::vector<int> fill(first.begin(), first.end() - 1);
    for (const auto& [row, e] : pairs) entries[fill[row]++] = e;
  };
  std::vector<std::pair<int, int>> pairs;
  for (int j = 0; j < plan.n_lines; ++j) {
    pairs.emplace_back(plan.line_ab[2 * j], 2 * j);
    pairs.emplace_back(plan.line_ab[2 * j + 1], 2 * j + 1);
  }
  csr(plan.n_pts, pairs, plan.pt_first, plan.pt_entries);
  pairs.clear();
  for (int v = 0; v < plan.n_flat; ++v)
    for (int j = 0; j < 4; ++j)
      if (plan.vert_w[4 * v + j] != 0.f) pairs.emplace_back(plan.vert_cp[v] + j, 4 * v + j);
  csr(plan.n_cp, pairs, plan.cp_first, plan.cp_entries);
}

}  // namespace

int stroke_point_count(const StrokeSubpath& s) {
  const int N = s.vertex_count, J = s.join_points, C = s.cap_points;
  if (s.closed) return 2 * N * (2 + J);
  const int S = std::max(N - 1, 1);
  return 2 * (2 * S + J * (S - 1)) + 2 * C;
}

RasterPlan plan_raster(const Scene& scene, const Affine& view, int width, int height,
                       const RasterPlanOptions& opt) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
    throw Error("render size " + std::to_string(width) + "x" + std::to_string(height) +
                " is outside 1..16384");
  RasterPlan plan;
  plan.width = width;
  plan.height = height;
  const double tol = opt.flatten_tolerance_px;
  const double view_scale = view.mean_scale();

  // Pass 1: control points and flattened vertices of every subpath.
  const std::vector<std::vector<SubRange>> subs = flatten_paths(scene, view, opt, plan);

  // Pass 2: draws in paint order, their lines, and stroke outline layouts.
  auto add_line = [&](int a, int b) {
    plan.line_ab.push_back(a);
    plan.line_ab.push_back(b);
    plan.line_draw.push_back(static_cast<int>(plan.draws.size()) - 1);
    ++plan.n_lines;
  };
  auto add_contour = [&](int first, int count) {
    for (int i = 0; i < count; ++i) add_line(first + i, first + (i + 1) % count);
  };
  // The last draw's gradient as a paint image (RasterPlan::paint), within the byte budget.
  const size_t image_floats = static_cast<size_t>(width) * height * 4;
  auto paint_draw = [&](const Path& path, int gi) {
    if ((plan.paint.size() + image_floats) * sizeof(float) > opt.max_paint_bytes) return;
    if (gi < 0 || static_cast<size_t>(gi) >= scene.gradients.size())
      throw Error("internal: path gradient " + std::to_string(gi) + " outside the scene's " +
                  std::to_string(scene.gradients.size()));
    const Gradient& g = scene.gradients[static_cast<size_t>(gi)];
    const Affine to_gradient = (view * g.to_canvas).inverse();
    const float k = g.opacity * path.opacity;
    plan.draws.back().paint = static_cast<int>(plan.paint.size() / image_floats);
    plan.paint.resize(plan.paint.size() + image_floats, 0.0f);
    float* img = plan.paint.data() + plan.paint.size() - image_floats;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const auto c = gradient_color(g, to_gradient, {x + 0.5, y + 0.5});
        if (!c) continue;  // unpainted: alpha 0
        float* o = img + 4 * (static_cast<size_t>(y) * width + x);
        o[0] = c->r, o[1] = c->g, o[2] = c->b, o[3] = c->a * k;
      }
  };
  for (size_t pi = 0; pi < scene.paths.size(); ++pi) {
    const Path& path = scene.paths[pi];
    const float fill_alpha = path.fill.a * path.opacity;
    if (path.has_fill && fill_alpha > 0) {
      Draw d;
      d.path = static_cast<int>(pi);
      d.rgba[0] = path.fill.r; d.rgba[1] = path.fill.g; d.rgba[2] = path.fill.b;
      d.rgba[3] = fill_alpha;
      d.rule = path.fill_rule == FillRule::EvenOdd ? kRuleEvenOdd : kRuleNonZero;
      d.first_line = plan.n_lines;
      plan.draws.push_back(d);
      for (const SubRange& r : subs[pi])
        if (r.vertex_count >= 2) add_contour(r.first_vertex, r.vertex_count);
      plan.draws.back().line_count = plan.n_lines - plan.draws.back().first_line;
      if (plan.draws.back().line_count == 0) plan.draws.pop_back();
      else if (path.fill_gradient >= 0) paint_draw(path, path.fill_gradient);
    }
    const float stroke_alpha = path.stroke.color.a * path.opacity;
    const double half_width = 0.5 * path.stroke.width * view_scale;
    if (path.has_stroke && stroke_alpha > 0 && half_width > 0) {
      Draw d;
      d.path = static_cast<int>(pi);
      d.is_stroke = true;
      d.rgba[0] = path.stroke.color.r; d.rgba[1] = path.stroke.color.g;
      d.rgba[2] = path.stroke.color.b; d.rgba[3] = stroke_alpha;
      d.first_line = plan.n_lines;
      plan.draws.push_back(d);
      const int round_pts = arc_points(half_width, tol);
      for (const SubRange& r : subs[pi]) {
        StrokeSubpath s;
        s.first_vertex = r.first_vertex;
        s.vertex_count = r.vertex_count;
        s.closed = r.closed && r.vertex_count >= 2;
        s.cap = cap_kind(path.stroke.cap);
        s.join = static_cast<int>(join_kind(path.stroke.join));
        s.join_points = s.join == kJoinRound ? round_pts : s.join == kJoinMiterClip ? 2 : 1;
        s.cap_points = s.cap == kCapRound ? round_pts : s.cap == kCapSquare ? 2 : 0;
        s.half_width = static_cast<float>(half_width);
        s.miter_limit = static_cast<float>(path.stroke.miter_limit);
        // A lone point with butt caps has no area: nothing to draw.
        if (r.vertex_count < 2 && s.cap == kCapButt) continue;
        s.first_out = plan.n_pts;
        const int count = stroke_point_count(s);
        plan.n_pts += count;
        if (s.closed) {
          add_contour(s.first_out, count / 2);
          add_contour(s.first_out + count / 2, count / 2);
        } else {
          add_contour(s.first_out, count);
        }
        plan.strokes.push_back(s);
      }
      plan.draws.back().line_count = plan.n_lines - plan.draws.back().first_line;
      if (plan.draws.back().line_count == 0) plan.draws.pop_back();
      else if (path.stroke_gradient >= 0) paint_draw(path, path.stroke_gradient);
    }
  }
  lay_out_chunks(plan);
  transpose_weights(plan);
  return plan;
}

}  // namespace svgm
