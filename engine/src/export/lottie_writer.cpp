// The Lottie writer (see lottie_writer.h). The JSON is written as text rather than through a
// JSON library's number formatting so that every coordinate carries exactly the decimals asked
// for (the file's size is mostly these numbers).
#include "export/lottie_writer.h"

#include <algorithm>
#include <cmath>

#include "export/dotlottie.h"
#include "export/lottie_compositing.h"
#include "export/lottie_json.h"
#include "export/lottie_motion.h"
#include "export/lottie_paint.h"
#include "export/lottie_unsupported.h"
#include "svgmotion/atomic_file.h"
#include "svgmotion/error.h"

namespace svgm {

using namespace lottie;

namespace {

// The shape layers of lottie_animation, one path at a time, and what they share (named as
// lottie_animation names them).
struct ShapeLayers {
  const Scene& scene;
  const RasterPlan& plan;
  const std::vector<double>& points;
  const LottieOptions& options;
  const ExportMap* map;
  const AnimationPass& pass;
  const double frames, tol;
  const int static_decimals;
  const size_t P;
  const std::vector<int>& order;
  const std::vector<int>& group_ind;
  const std::vector<Scene>& samples;
  const std::vector<int>& sample_of_value;
  const std::vector<double>& value_frames;
  JsonText& j;
  std::vector<std::string>& approximate;
  std::vector<std::pair<size_t, size_t>>& layer_span;
  std::vector<double>& rest;
  bool& first_layer;

  // One path's shape layer, compact when asked and possible; returns whether it was compact.
  bool write_layer(std::vector<int>::const_reverse_iterator it, bool try_compact);
};

}  // namespace

LottieDocument lottie_animation(const Scene& scene, const RasterPlan& plan,
                                const std::vector<double>& points, const AnimationTiming& timing,
                                const LottieOptions& options, const ExportMap* map) {
  check_animation_inputs(scene, plan, points, timing, map, std::max(0, options.decimals));
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

  // Compact: a static coordinate rounded by at most a quarter of the tolerance when measured.
  const double tol = options.tolerance_px > 0 ? options.tolerance_px : compact_tolerance(scene.width, scene.height);
  const int static_decimals = options.decimals >= 0 ? options.decimals
                                                    : std::clamp(static_cast<int>(std::ceil(std::log10(2.9 / tol))), 0, kMaxDecimals);
  JsonText j(static_decimals);
  j.raw("{\"v\":\"5.7.0\",\"fr\":").num(options.fps, 1e6).raw(",\"ip\":0,\"op\":").num(frames, kFrameScale);
  j.raw(",\"w\":").num(std::max(1.0, std::round(scene.width)), 1).raw(",\"h\":");
  j.num(std::max(1.0, std::round(scene.height)), 1).raw(",\"nm\":").str(options.name);
  j.raw(",\"ddd\":0,\"assets\":[],\"meta\":{\"g\":\"svgmotion ").raw(SVGM_VERSION).raw("\",\"d\":");
  j.str(std::string("loop: ") + loop_mode_name(timing.loop) +
        (timing.loop == LoopMode::Once ? " (play with the player's loop off)" : ""));
  j.raw("},\"layers\":[");

  // Gradients as the exported SVG draws them at each keyframe (they follow their shapes there).
  std::vector<int> sample_of_value;
  std::vector<double> value_frames, sample_times(static_cast<size_t>(timing.keyframes), 0.0);
  for (size_t i = 0; i < pass.seq.size(); ++i) {
    sample_of_value.push_back(pass.seq[i]);
    value_frames.push_back(pass.times[i] * frames);
    if (i < static_cast<size_t>(timing.keyframes) && pass.seq[i] == static_cast<int>(i))
      sample_times[i] = pass.times[i] * pass.duration_s;
  }
  const std::vector<Scene> samples = !scene.gradients.empty() && pass.seq.size() > 1
                                         ? sample_exported_svg(options.exported_svg, scene, sample_times)
                                         : std::vector<Scene>{};
  std::vector<std::string> approximate;
  const size_t layers_begin = j.text().size();
  std::vector<std::pair<size_t, size_t>> layer_span(P), null_span(scene.groups.size());
  std::vector<double> rest;  // a static path's own points, in the layout of the fitted ones
  bool first_layer = true;
  ShapeLayers shape_layers{scene, plan, points, options, map, pass, frames, tol, static_decimals, P, order, group_ind,
                           samples, sample_of_value, value_frames, j, approximate, layer_span, rest, first_layer};
  for (auto it = order.crbegin(); it != order.crend(); ++it) {  // Lottie lists the top layer first
    const size_t at = j.text().size(), approximate_at = approximate.size();
    const bool was_first = first_layer;
    if (!shape_layers.write_layer(it, options.compact)) continue;
    // A path the fit deforms beyond the tolerance at nearly every value (its jitter above it) is
    // written per value when that is shorter than its compact form.
    const std::string compact_text = j.text().substr(at);
    const auto compact_span = layer_span[static_cast<size_t>(*it)];
    j.text().resize(at);
    approximate.resize(approximate_at);
    first_layer = was_first;
    shape_layers.write_layer(it, false);
    if (j.text().size() - at <= compact_text.size()) continue;
    j.text().resize(at);
    j.text() += compact_text;
    layer_span[static_cast<size_t>(*it)] = compact_span;
  }
  for (size_t g = 0; g < scene.groups.size(); ++g) {
    if (!group_ind[g]) continue;
    j.raw(first_layer ? "" : ",");
    null_span[g].first = j.text().size();
    j.raw("{\"ind\":").num(group_ind[g], 1);
    j.raw(",\"ty\":3,\"nm\":").str(scene.groups[g].id).raw(",\"ks\":{").raw(kLayerTransformAfterOpacity);
    j.raw(",\"ip\":0,\"op\":").num(frames, kFrameScale).raw(",\"st\":0,\"bm\":0}");
    null_span[g].second = j.text().size();
    first_layer = false;
  }
  // Group opacity, clip-paths and masks as precompositions and mattes (lottie_compositing.h).
  CompositionInputs comp;
  comp.scene = &scene;
  comp.order = order;
  for (size_t p = 0; p < P; ++p) {
    comp.path_layers.push_back(j.text().substr(layer_span[p].first, layer_span[p].second - layer_span[p].first));
    const int g = scene.paths[p].group;
    comp.path_group.push_back(g >= 0 && static_cast<size_t>(g) < scene.groups.size() && group_ind[static_cast<size_t>(g)] ? g : -1);
  }
  for (size_t g = 0; g < scene.groups.size(); ++g)
    comp.group_nulls.push_back(j.text().substr(null_span[g].first, null_span[g].second - null_span[g].first));
  comp.next_ind = next_ind;
  comp.frames = frames;
  comp.decimals = static_decimals;
  const CompositionText layers = compose_layers(comp, approximate);
  j.text().resize(layers_begin);
  j.raw(layers.layers).raw("]}\n");
  std::string assets;
  for (const std::string& a : layers.assets) assets += (assets.empty() ? "" : ",") + a;
  doc.json = std::move(j.text());
  doc.json.insert(doc.json.find("\"assets\":[]") + 10, assets);
  if (const std::string w = cannot_express_line(scene, approximate); !w.empty()) doc.warnings.push_back(w);
  return doc;
}

namespace {

bool ShapeLayers::write_layer(std::vector<int>::const_reverse_iterator it, bool try_compact) {
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
  // Compact: the group's transform carries the path's affine motion, the shape keyframed only
  // for its residual, at the kept keys (lottie_motion.h).
  const size_t count = f >= 0 ? static_cast<size_t>(plan.path_cp_count[static_cast<size_t>(f)]) : 0;
  const bool compact = try_compact && animated && rest.size() == 2 * count;
  CompactPathMotion motion;
  if (compact) {
    std::vector<const double*> values;
    for (int k : pass.seq) values.push_back(&points[(static_cast<size_t>(k) * plan.n_cp + first) * 2]);
    motion = compact_path_motion(rest, values, pass.times, frames, tol, options.decimals, options.residual_scale);
    if (motion.residual) j.set_decimals(motion.shape_decimals);
  }
  const bool shape_animated = compact ? motion.residual : animated;
  std::vector<size_t> shape_keys;
  if (shape_animated && compact) shape_keys = motion.shape_keys.keys;
  else if (shape_animated)
    for (size_t i = 0; i < pass.seq.size(); ++i) shape_keys.push_back(i);
  // The points of value `i` of the pass for this path (in the moving group's frame).
  auto value_points = [&](size_t i) {
    if (!shape_animated) return static_cast<const double*>(rest.data());
    return compact ? &motion.local[i * 2 * count] : &points[(static_cast<size_t>(pass.seq[i]) * plan.n_cp + first) * 2];
  };

  if (!first_layer) j.raw(",");
  first_layer = false;
  layer_span[p].first = j.text().size();
  j.raw("{\"ind\":").num(static_cast<double>(P - (it - order.rbegin())), 1);
  j.raw(",\"ty\":4,\"nm\":").str(path.id).raw(",");
  if (path.group >= 0 && static_cast<size_t>(path.group) < scene.groups.size() && group_ind[static_cast<size_t>(path.group)])
    j.raw("\"parent\":").num(group_ind[static_cast<size_t>(path.group)], 1).raw(",");
  // Inside a compositing layer the layer carries the group opacity (lottie_compositing.h).
  j.raw("\"ks\":{\"o\":").fixed((path.layer >= 0 ? path.local_opacity : path.opacity) * 100.0, kOpacityScale).raw(kLayerTransformAfterOpacity);
  j.raw(",\"shapes\":[{\"ty\":\"gr\",\"nm\":").str(path.id).raw(",\"it\":[");
  const size_t shapes_begin = j.text().size();
  // Compact, moving: the shapes in a group of their own carrying the motion; the paints after
  // it apply to them in the canvas' frame (gradients where animation.svg draws them, stroke
  // widths unscaled, as the full export).
  if (motion.moves) j.raw("{\"ty\":\"gr\",\"nm\":\"motion\",\"it\":[");
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
    for (size_t i = 0; merge && i < (shape_animated ? pass.seq.size() : 1); ++i) {
      const double* q = value_points(i) + 2 * cp;
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
      for (size_t k = 0; k < shape_keys.size(); ++k) {
        const size_t i = shape_keys[k];
        if (k) j.raw(",");
        j.raw("{\"t\":").num(pass.times[i] * frames, kFrameScale).raw(",\"s\":[");
        write_bezier(j, value_points(i) + 2 * cp, n_points, sp.closed, merge);
        j.raw("]");
        // Linear in time as SMIL's calcMode="linear", or the compact export's easing.
        if (k + 1 < shape_keys.size()) write_easing(j, compact ? motion.shape_keys.easing[k] : Easing{});
        j.raw("}");
      }
      j.raw("]}}");
    }
    cp += n_points;
  }
  if (motion.moves) j.raw(first_item ? "" : ",").raw(motion.transform).raw("]}");
  // Stroke and fill, their gradients following the shape (lottie_paint.h).
  PaintInputs paint;
  for (size_t i = 0; i < (animated ? pass.seq.size() : 1); ++i)
    paint.points.push_back(motion.moves ? &points[(static_cast<size_t>(pass.seq[i]) * plan.n_cp + first) * 2] : value_points(i));
  const std::vector<Scene>& paint_samples = animated ? samples : std::vector<Scene>{};
  paint.fill = gradient_track(scene, paint_samples, p, false, sample_of_value, value_frames);
  paint.stroke = gradient_track(scene, paint_samples, p, true, sample_of_value, value_frames);
  // Compact: gradients at their fewest keys.
  if (compact) paint.fill.tolerance_px = paint.stroke.tolerance_px = tol;
  j.set_decimals(static_decimals);  // widths, dashes and gradients at the static decimals
  write_paint_items(j, shapes_begin, path, paint, approximate);
  first_item = j.text().size() == shapes_begin;
  j.raw(first_item ? "" : ",").raw(kGroupTransform).raw("]}]");
  j.raw(",\"ip\":0,\"op\":").num(frames, kFrameScale).raw(",\"st\":0,\"bm\":0}");
  layer_span[p].second = j.text().size();
  return compact;
}

}  // namespace

std::vector<std::string> write_lottie(const std::filesystem::path& out, const Scene& scene,
                                      const RasterPlan& plan, const std::vector<double>& points,
                                      const AnimationTiming& timing, const LottieOptions& options,
                                      const ExportMap* map) {
  LottieDocument doc = lottie_animation(scene, plan, points, timing, options, map);
  write_file_atomic(out, doc.json);
  if (!options.dotlottie.empty()) write_dotlottie(options.dotlottie, doc.json, timing.loop != LoopMode::Once);
  for (std::string& w : doc.warnings) w = out.string() + ": " + w;
  return doc.warnings;
}

}  // namespace svgm
