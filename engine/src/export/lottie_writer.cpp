// The Lottie writer (see lottie_writer.h). The JSON is written as text rather than through a
// JSON library's number formatting so that every coordinate carries exactly the decimals asked
// for (the file's size is mostly these numbers).
#include "export/lottie_writer.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "export/compact_motion.h"
#include "export/keyframe_reduce.h"
#include "svg/svg_number.h"
#include "svgmotion/atomic_file.h"
#include "svgmotion/error.h"
#include "svgmotion/utf8_text.h"

namespace svgm {

namespace {

// The reader's warning for a gradient drawn with its mean stop colour (svg_reader.cpp,
// resolve_paint): the scene keeps only that colour, so the export says so once.
constexpr std::string_view kGradientWarning = "gradient paint drawn with its mean stop colour in Lottie exports";
// Colours are written to 1/10000 (far below one 8-bit level), opacities (0..100) to 1/100,
// frame times to 1/1000 of a frame.
constexpr double kColourScale = 1e4, kOpacityScale = 1e2, kFrameScale = 1e3;
// Two on-curve points this close (canvas pixels) are the same point: a closed subpath that
// returns exactly to its start is written without the zero-length closing segment.
constexpr double kSamePoint = 1e-9;

class JsonText {
 public:
  explicit JsonText(int decimals) : coord_scale_(std::pow(10.0, decimals)) {}
  JsonText& raw(std::string_view t) {
    s_ += t;
    return *this;
  }
  JsonText& num(double v, double scale) {
    svg::append_rounded(s_, v, scale);
    return *this;
  }
  JsonText& coord(double v) { return num(v, coord_scale_); }
  void set_decimals(int decimals) { coord_scale_ = std::pow(10.0, decimals); }
  JsonText& str(const std::string& t) { return raw(json_text(nlohmann::json(t))); }
  // {"a":0,"k":v}
  JsonText& fixed(double v, double scale) {
    raw("{\"a\":0,\"k\":");
    num(v, scale);
    return raw("}");
  }
  std::string& text() { return s_; }

 private:
  std::string s_;
  double coord_scale_;
};

// The identity transform of a layer after its opacity (3D vectors, as bodymovin writes them),
// and a group's.
constexpr std::string_view kLayerTransformAfterOpacity =
    "\"r\":{\"a\":0,\"k\":0},\"p\":{\"a\":0,\"k\":[0,0,0]},\"a\":{\"a\":0,\"k\":[0,0,0]},"
    "\"s\":{\"a\":0,\"k\":[100,100,100]}}";
constexpr std::string_view kGroupTransform =
    "{\"ty\":\"tr\",\"p\":{\"a\":0,\"k\":[0,0]},\"a\":{\"a\":0,\"k\":[0,0]},"
    "\"s\":{\"a\":0,\"k\":[100,100]},\"r\":{\"a\":0,\"k\":0},\"o\":{\"a\":0,\"k\":100},"
    "\"sk\":{\"a\":0,\"k\":0},\"sa\":{\"a\":0,\"k\":0}}";

// One subpath's control points {p0, c1, c2, p1, ...} as a Lottie bezier: vertices with in and
// out tangents relative to them. A closed subpath ends on its start (the reader adds the
// closing line); `merge_close` drops that last vertex, folding its in-tangent into the first.
void write_bezier(JsonText& j, const double* p, size_t n_points, bool closed, bool merge_close) {
  const size_t n = (n_points - 1) / 3;  // segments
  const size_t nv = merge_close ? n : n + 1;
  auto x = [&](size_t i) { return p[2 * i]; };
  auto y = [&](size_t i) { return p[2 * i + 1]; };
  auto pair = [&](double a, double b) {
    j.raw("[").coord(a).raw(",").coord(b).raw("]");
  };
  j.raw("{\"i\":[");
  for (size_t v = 0; v < nv; ++v) {
    if (v) j.raw(",");
    const size_t at = 3 * v;
    if (v > 0) pair(x(at - 1) - x(at), y(at - 1) - y(at));
    else if (merge_close) pair(x(3 * n - 1) - x(0), y(3 * n - 1) - y(0));
    else pair(0, 0);
  }
  j.raw("],\"o\":[");
  for (size_t v = 0; v < nv; ++v) {
    if (v) j.raw(",");
    const size_t at = 3 * v;
    if (v < n) pair(x(at + 1) - x(at), y(at + 1) - y(at));
    else pair(0, 0);
  }
  j.raw("],\"v\":[");
  for (size_t v = 0; v < nv; ++v) {
    if (v) j.raw(",");
    pair(x(3 * v), y(3 * v));
  }
  j.raw("],\"c\":").raw(closed ? "true" : "false").raw("}");
}

void write_colour(JsonText& j, const Rgba& c) {
  j.raw("{\"a\":0,\"k\":[").num(c.r, kColourScale).raw(",").num(c.g, kColourScale).raw(",");
  j.num(c.b, kColourScale).raw(",1]}");
}

int lottie_cap(LineCap c) {
  switch (c) {
    case LineCap::Butt: return 1;
    case LineCap::Round: return 2;
    case LineCap::Square: return 3;
  }
  return 1;
}

// Lottie has miter (with a limit), round and bevel; SVG 2's miter-clip is written as miter.
int lottie_join(LineJoin c) {
  switch (c) {
    case LineJoin::Miter:
    case LineJoin::MiterClip: return 1;
    case LineJoin::Round: return 2;
    case LineJoin::Bevel: return 3;
  }
  return 1;
}

// A keyframe's easing towards the next: linear as SMIL's calcMode="linear", else the reducer's
// curve (keyframe_reduce.h): "o" is the first handle, "i" the second.
void write_easing(JsonText& j, const Easing& e) {
  if (e.is_linear()) {
    j.raw(",\"i\":{\"x\":1,\"y\":1},\"o\":{\"x\":0,\"y\":0}");
    return;
  }
  j.raw(",\"i\":{\"x\":0.6667,\"y\":").num(e.y2, 1e4).raw("},\"o\":{\"x\":0.3333,\"y\":").num(e.y1, 1e4).raw("}");
}

// An animated property {"a":1,"k":[...]} of `dim` numbers per key (scaled by `factor`, at
// `scale` rounding), from trajectory numbers at `at` of each `stride`-wide value.
void write_animated(JsonText& j, const std::vector<double>& trajectory, size_t stride, size_t at, size_t dim,
                    double factor, double scale, const ReducedKeys& r, const std::vector<double>& times, double frames) {
  j.raw("{\"a\":1,\"k\":[");
  for (size_t i = 0; i < r.keys.size(); ++i) {
    if (i) j.raw(",");
    j.raw("{\"t\":").num(times[r.keys[i]] * frames, kFrameScale).raw(",\"s\":[");
    for (size_t d = 0; d < dim; ++d) {
      if (d) j.raw(",");
      j.num(factor * trajectory[r.keys[i] * stride + at + d], scale);
    }
    j.raw("]");
    if (i + 1 < r.keys.size()) write_easing(j, r.easing[i]);
    j.raw("}");
  }
  j.raw("]}");
}

}  // namespace

LottieDocument lottie_animation(const Scene& scene, const RasterPlan& plan,
                                const std::vector<double>& points, const AnimationTiming& timing,
                                const LottieOptions& options, const ExportMap* map) {
  check_animation_inputs(scene, plan, points, timing, map, options.decimals);
  if (!(options.fps > 0 && std::isfinite(options.fps))) throw Error("internal: Lottie frame rate must be positive");

  const AnimationPass pass = animation_pass(timing);
  const double frames = std::max(1.0, std::round(pass.duration_s * options.fps * kFrameScale) / kFrameScale);
  LottieDocument doc;

  // Paint order, back to front: the layers stage's when it is a permutation of the document's
  // paths, else the document's own.
  const size_t P = scene.paths.size();
  std::vector<int> order;
  if (map && map->order.size() == P) {
    std::vector<int> sorted = map->order;
    std::sort(sorted.begin(), sorted.end());
    bool perm = true;
    for (size_t i = 0; i < P; ++i) perm = perm && sorted[i] == static_cast<int>(i);
    if (perm) order = map->order;
  }
  if (order.empty())
    for (size_t i = 0; i < P; ++i) order.push_back(static_cast<int>(i));

  // Null layers for the document's top-level groups; their `ind` follows the shape layers'. A
  // path outside any group is a part of its own in the scene, and gets no null layer.
  std::vector<int> group_ind(scene.groups.size(), 0);
  int next_ind = static_cast<int>(P) + 1;
  for (size_t g = 0; g < scene.groups.size(); ++g) {
    const Group& group = scene.groups[g];
    const bool lone_path = group.paths.size() == 1 && scene.paths[static_cast<size_t>(group.paths[0])].id == group.id;
    if (!group.paths.empty() && !lone_path) group_ind[g] = next_ind++;
  }

  JsonText j(options.decimals);
  j.raw("{\"v\":\"5.7.0\",\"fr\":").num(options.fps, 1e6).raw(",\"ip\":0,\"op\":").num(frames, kFrameScale);
  j.raw(",\"w\":").num(std::max(1.0, std::round(scene.width)), 1).raw(",\"h\":");
  j.num(std::max(1.0, std::round(scene.height)), 1).raw(",\"nm\":").str(options.name);
  j.raw(",\"ddd\":0,\"assets\":[],\"meta\":{\"g\":\"svgmotion ").raw(SVGM_VERSION).raw("\",\"d\":");
  j.str(std::string("loop: ") + loop_mode_name(timing.loop) +
        (timing.loop == LoopMode::Once ? " (play with the player's loop off)" : ""));
  j.raw("},\"layers\":[");

  bool any_gradient = false;
  for (const std::string& w : scene.warnings) any_gradient = any_gradient || w.find(kGradientWarning) != std::string::npos;
  const double tol = options.tolerance_px > 0 ? options.tolerance_px : compact_tolerance(scene.width, scene.height);
  // Measured decimals: a static coordinate rounded by at most a quarter of the tolerance.
  const int static_decimals = options.measured_decimals
                                  ? std::clamp(static_cast<int>(std::ceil(std::log10(2.0 / tol))), 0, kMaxDecimals)
                                  : options.decimals;
  j.set_decimals(static_decimals);
  std::vector<double> rest;  // a static path's own points, in the layout of the fitted ones
  bool first_layer = true;
  for (auto it = order.rbegin(); it != order.rend(); ++it) {  // Lottie lists the top layer first
    const size_t p = static_cast<size_t>(*it);
    const Path& path = scene.paths[p];
    const int f = map ? map->fitted_of[p] : static_cast<int>(p);
    // Shapes drawn through <use> stay static, as in animation.svg (shared definitions).
    const bool through_use = path.locator.rfind("/use[") != std::string::npos &&
                             path.locator.find('/', path.locator.rfind("/use[") + 1) == std::string::npos;
    const bool animated = f >= 0 && !through_use && plan.path_cp_count[static_cast<size_t>(f)] > 0 && pass.seq.size() > 1;
    const size_t first = f >= 0 ? plan.path_cp_first[static_cast<size_t>(f)] : 0;
    rest.clear();
    for (const Subpath& sp : path.subpaths)
      for (const Vec2& q : sp.points) {
        rest.push_back(q.x);
        rest.push_back(q.y);
      }
    // The shape's keys (indices into the pass's values) and their easing; a compact export may
    // keep fewer, move the path by its group's transform and keyframe only the residual shape.
    bool shape_animated = animated;
    std::vector<size_t> keys;
    std::vector<Easing> easing;
    std::vector<double> shape_values;  // when not empty: value i's points at [i * 2 * count]
    std::string group_transform(kGroupTransform);
    const size_t count = f >= 0 ? static_cast<size_t>(plan.path_cp_count[static_cast<size_t>(f)]) : 0;
    if (animated) {
      for (size_t i = 0; i < pass.seq.size(); ++i) keys.push_back(i);
      easing.assign(keys.size() - 1, Easing{});
    }
    if (animated && options.compact && rest.size() == 2 * count) {
      std::vector<const double*> vals;
      for (int k : pass.seq) vals.push_back(&points[(static_cast<size_t>(k) * plan.n_cp + first) * 2]);
      const PartMotion m = analyse_part_motion(rest, vals, tol);
      shape_animated = m.moves;
      if (m.moves) {
        // Lottie's skew is not SVG's skewX: a motion whose skew matters stays in the shape.
        double skew_miss = 0;
        for (size_t v = 0; v < vals.size(); ++v) {
          TransformParts with = decompose_affine(m.affine[v]), without = with;
          without.skew_x_deg = 0;
          const Affine a = compose_affine(with), b = compose_affine(without);
          for (size_t i = 0; i < count; ++i) {
            const Vec2 p = a.apply({rest[2 * i], rest[2 * i + 1]}), q = b.apply({rest[2 * i], rest[2 * i + 1]});
            skew_miss = std::max(skew_miss, std::hypot(p.x - q.x, p.y - q.y));
          }
        }
        double px_per_unit = 1;
        std::vector<Affine> drawn;
        if (skew_miss <= tol / 2) {
          const Vec2 c = rest_centre(rest, Affine{});
          const WrapperKeys w = wrapper_keys(m.affine, Affine{}, rest, pass.times, tol,
                                             options.measured_decimals ? -1 : options.decimals, c, WrapperForm::Lottie);
          std::vector<double> traj = w.trajectory;  // position = centre + t
          for (size_t v = 0; v < vals.size(); ++v) traj[6 * v] += c.x, traj[6 * v + 1] += c.y;
          const int dt = w.translate_decimals;
          JsonText t(dt);
          t.raw("{\"ty\":\"tr\",\"p\":");
          write_animated(t, traj, 6, 0, 2, 1, std::pow(10.0, dt), w.keys, pass.times, frames);
          t.raw(",\"a\":{\"a\":0,\"k\":[").coord(c.x).raw(",").coord(c.y).raw("]},\"s\":");
          write_animated(t, traj, 6, 4, 2, 100, std::pow(10.0, std::max(0, w.scale_decimals - 2)), w.keys, pass.times, frames);
          t.raw(",\"r\":");
          write_animated(t, traj, 6, 2, 1, 1, std::pow(10.0, w.rotate_decimals), w.keys, pass.times, frames);
          t.raw(",\"o\":{\"a\":0,\"k\":100},\"sk\":{\"a\":0,\"k\":0},\"sa\":{\"a\":0,\"k\":0}}");
          group_transform = std::move(t.text());
          drawn = w.drawn;
          shape_animated = m.residual;
          if (m.residual)
            for (size_t v = 0; v < vals.size(); ++v) {
              const Affine a = drawn[v];
              px_per_unit = std::max(px_per_unit, a.mean_scale());
              const Affine back = a.inverse();
              for (size_t i = 0; i < count; ++i) {
                const Vec2 q = back.apply({vals[v][2 * i], vals[v][2 * i + 1]});
                shape_values.insert(shape_values.end(), {q.x, q.y});
              }
            }
        } else {
          for (const double* v : vals) shape_values.insert(shape_values.end(), v, v + 2 * count);
        }
        if (shape_animated) {
          const SampleError derr = point_error(shape_values, 2 * count, px_per_unit);
          const ReducedKeys r = reduce_keyframes(pass.times, shape_values, 2 * count, tol, derr);
          keys = r.keys;
          easing = r.easing;
          j.set_decimals(options.measured_decimals
                             ? measured_decimals(shape_values, 2 * count, keys, derr, tol / 4, 0, 2 * count, kMaxDecimals)
                             : options.decimals);
        }
      }
    }
    // The points of value `i` of the pass for this path.
    auto value_points = [&](size_t i) {
      return !shape_animated        ? rest.data()
             : shape_values.empty() ? &points[(static_cast<size_t>(pass.seq[i]) * plan.n_cp + first) * 2]
                                    : &shape_values[i * 2 * count];
    };

    if (!first_layer) j.raw(",");
    first_layer = false;
    j.raw("{\"ddd\":0,\"ind\":").num(static_cast<double>(P - (it - order.rbegin())), 1);
    j.raw(",\"ty\":4,\"nm\":").str(path.id).raw(",\"sr\":1,");
    if (path.group >= 0 && static_cast<size_t>(path.group) < scene.groups.size() && group_ind[static_cast<size_t>(path.group)])
      j.raw("\"parent\":").num(group_ind[static_cast<size_t>(path.group)], 1).raw(",");
    j.raw("\"ks\":{\"o\":").fixed(path.opacity * 100.0, kOpacityScale).raw(",").raw(kLayerTransformAfterOpacity);
    j.raw(",\"ao\":0,\"shapes\":[{\"ty\":\"gr\",\"nm\":").str(path.id).raw(",\"it\":[");
    size_t cp = 0;  // index of the subpath's first point within the path
    bool first_item = true;
    for (const Subpath& sp : path.subpaths) {
      const size_t n_points = sp.points.size();
      if (n_points < 4) {  // a lone point has no outline (only caps, which Lottie has not)
        cp += n_points;
        continue;
      }
      const size_t n = (n_points - 1) / 3;
      bool merge = sp.closed && n >= 2;
      for (size_t i = 0; merge && i < (shape_animated ? keys.size() : 1); ++i) {
        const double* q = value_points(shape_animated ? keys[i] : 0) + 2 * cp;
        merge = std::fabs(q[6 * n] - q[0]) <= kSamePoint && std::fabs(q[6 * n + 1] - q[1]) <= kSamePoint;
      }
      if (!first_item) j.raw(",");
      first_item = false;
      j.raw("{\"ty\":\"sh\",\"ks\":");
      if (!shape_animated) {
        j.raw("{\"a\":0,\"k\":");
        write_bezier(j, value_points(0) + 2 * cp, n_points, sp.closed, merge);
        j.raw("}}");
      } else {
        j.raw("{\"a\":1,\"k\":[");
        for (size_t i = 0; i < keys.size(); ++i) {
          if (i) j.raw(",");
          j.raw("{\"t\":").num(pass.times[keys[i]] * frames, kFrameScale).raw(",\"s\":[");
          write_bezier(j, value_points(keys[i]) + 2 * cp, n_points, sp.closed, merge);
          j.raw("]");
          // Linear in time (the easing curve from (0,0) to (1,1)), as SMIL's calcMode="linear",
          // unless the compact export fitted an easing.
          if (i + 1 < keys.size()) write_easing(j, easing[i]);
          j.raw("}");
        }
        j.raw("]}}");
      }
      cp += n_points;
    }
    // SVG paints the stroke over the fill; in Lottie an item listed earlier is drawn on top.
    if (path.has_stroke) {
      const Stroke& s = path.stroke;
      j.raw(first_item ? "" : ",").raw("{\"ty\":\"st\",\"c\":");
      write_colour(j, s.color);
      j.raw(",\"o\":").fixed(s.color.a * 100.0, kOpacityScale).raw(",\"w\":").fixed(s.width, std::pow(10.0, options.decimals));
      j.raw(",\"lc\":").num(lottie_cap(s.cap), 1).raw(",\"lj\":").num(lottie_join(s.join), 1);
      j.raw(",\"ml\":").num(s.miter_limit, 1e4).raw(",\"bm\":0}");
      first_item = false;
    }
    if (path.has_fill) {
      j.raw(first_item ? "" : ",").raw("{\"ty\":\"fl\",\"c\":");
      write_colour(j, path.fill);
      j.raw(",\"o\":").fixed(path.fill.a * 100.0, kOpacityScale);
      j.raw(",\"r\":").raw(path.fill_rule == FillRule::EvenOdd ? "2" : "1").raw(",\"bm\":0}");
      first_item = false;
    }
    j.raw(first_item ? "" : ",").raw(group_transform).raw("]}]");
    j.set_decimals(static_decimals);
    j.raw(",\"ip\":0,\"op\":").num(frames, kFrameScale).raw(",\"st\":0,\"bm\":0}");
  }
  for (size_t g = 0; g < scene.groups.size(); ++g) {
    if (!group_ind[g]) continue;
    j.raw(first_layer ? "" : ",").raw("{\"ddd\":0,\"ind\":").num(group_ind[g], 1);
    j.raw(",\"ty\":3,\"nm\":").str(scene.groups[g].id).raw(",\"sr\":1,\"ks\":{\"o\":{\"a\":0,\"k\":100},").raw(kLayerTransformAfterOpacity);
    j.raw(",\"ao\":0,\"ip\":0,\"op\":").num(frames, kFrameScale).raw(",\"st\":0,\"bm\":0}");
    first_layer = false;
  }
  j.raw("]}\n");
  doc.json = std::move(j.text());
  if (any_gradient) doc.warnings.push_back("paths painted with gradients are drawn in their mean stop colour");
  return doc;
}

std::vector<std::string> write_lottie(const std::filesystem::path& out, const Scene& scene,
                                      const RasterPlan& plan, const std::vector<double>& points,
                                      const AnimationTiming& timing, const LottieOptions& options,
                                      const ExportMap* map) {
  LottieDocument doc = lottie_animation(scene, plan, points, timing, options, map);
  write_file_atomic(out, doc.json);
  for (std::string& w : doc.warnings) w = out.string() + ": " + w;
  return doc.warnings;
}

}  // namespace svgm
