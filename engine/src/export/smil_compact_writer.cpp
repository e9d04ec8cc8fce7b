// The compact SMIL export (see smil_writer.h, write_compact_animation_svg, and
// export/compact_motion.h): each moving part in a wrapper <g> whose transform carries its affine
// motion at the fewest keys, its `d` animated only for what is left.
#include "export/smil_writer.h"

#include <pugixml.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>

#include "export/compact_motion.h"
#include "export/keyframe_reduce.h"
#include "export/relative_path_data.h"
#include "export/smil_writer_internal.h"
#include "svg/document_order.h"
#include "svg/transform_list.h"
#include "svgmotion/atomic_file.h"
#include "svgmotion/error.h"
#include "svgmotion/log.h"

namespace svgm {

namespace fs = std::filesystem;

using namespace smil_internal;

namespace {

// "0;0.25;1" of the kept keys' times (1/10000 of a pass; the last exactly 1).
std::string key_times_text(const std::vector<double>& times, const std::vector<size_t>& keys) {
  std::string out;
  for (size_t i = 0; i < keys.size(); ++i) {
    if (i) out += ';';
    const double t = i + 1 == keys.size() ? 1.0 : i == 0 ? 0.0 : std::round(times[keys[i]] * 1e4) / 1e4;
    append_number(out, t, 4);
  }
  return out;
}

// calcMode and keySplines of the reduced keys: linear when every segment is.
void append_key_timing(pugi::xml_node anim, const std::vector<double>& times, const ReducedKeys& r) {
  const bool linear = std::all_of(r.easing.begin(), r.easing.end(), [](const Easing& e) { return e.is_linear(); });
  anim.append_attribute("calcMode") = linear ? "linear" : "spline";
  anim.append_attribute("keyTimes") = key_times_text(times, r.keys).c_str();
  if (linear) return;
  std::string splines;
  for (size_t i = 0; i < r.easing.size(); ++i) {
    if (i) splines += ';';
    splines += "0.3333 ";
    append_number(splines, r.easing[i].y1, 4);
    splines += " 0.6667 ";
    append_number(splines, r.easing[i].y2, 4);
  }
  anim.append_attribute("keySplines") = splines.c_str();
}

// The additive animateTransforms (translate, rotate about `centre`, skewX, scale) of reduced
// wrapper keys on `node`'s `attribute`; a component identity at every key is left out. With
// `replace_first` the first one written replaces the attribute's own value (a gradient's
// gradientTransform, which the keys include) and the others add to it. The centre is written
// at `centre_decimals` (< 0: the translation's).
void append_keyed_transform(pugi::xml_node node, const std::string& prefix, const WrapperKeys& w, Vec2 centre,
                            const std::vector<double>& times, const std::function<void(pugi::xml_node)>& repeat_attrs,
                            const char* attribute, bool replace_first, int centre_decimals = -1) {
  const int cd = std::max(centre_decimals, w.translate_decimals);
  const std::vector<double>& trajectory = w.trajectory;
  struct Component {
    const char* type;
    WrapperChannel channel;
    int decimals;
    double identity;
  };
  bool first = true;
  for (const Component& c : {Component{"translate", kTranslate, w.translate_decimals, 0}, Component{"rotate", kRotate, w.rotate_decimals, 0},
                             Component{"skewX", kSkew, w.skew_decimals, 0}, Component{"scale", kScale, w.scale_decimals, 1}}) {
    // The channel's own keys; a constant (one key) is written as two equal ones over the pass.
    ReducedKeys tk = w.channel[c.channel];
    if (tk.keys.size() == 1 && times.size() > 1) {
      tk.keys = {tk.keys[0], tk.keys[0]};
      tk.easing = {Easing{}};
    }
    const size_t at = kChannelAt[c.channel], n = kChannelSize[c.channel];
    std::string text;
    bool identity = true;
    for (size_t i = 0; i < tk.keys.size(); ++i) {
      if (i) text += ';';
      for (size_t j = 0; j < n; ++j) {
        const double v = trajectory[6 * tk.keys[i] + at + j];
        identity = identity && v == c.identity;
        if (j) text += ' ';
        append_number(text, v, c.decimals);
      }
      if (c.channel == kRotate) {  // rotate about the part's pivot
        text += ' ';
        append_number(text, centre.x, cd);
        text += ' ';
        append_number(text, centre.y, cd);
      }
    }
    if (identity) continue;
    pugi::xml_node anim = node.append_child((prefix + "animateTransform").c_str());
    anim.append_attribute("attributeName") = attribute;
    anim.append_attribute("type") = c.type;
    if (!(first && replace_first)) anim.append_attribute("additive") = "sum";
    first = false;
    repeat_attrs(anim);
    append_key_timing(anim, times, tk);
    anim.append_attribute("values") = text.c_str();
  }
}

// The numbers a wrapper's animateTransforms write: per key its time and values (a rotation's
// with its centre); a channel with one key is written once or not at all.
size_t written_numbers(const WrapperKeys& w) {
  size_t n = 0;
  for (size_t c = 0; c < kWrapperChannels; ++c)
    if (w.channel[c].keys.size() > 1) n += w.channel[c].keys.size() * (1 + kChannelSize[c] + (c == kRotate ? 2 : 0));
  return n;
}

// One compact export's inputs and running counts, shared by the steps that write a moving part
// (named as write_compact_animation_svg names them).
struct CompactWriter {
  const Scene& scene;
  const RasterPlan& plan;
  const std::vector<double>& points;
  const AnimationTiming& timing;
  const CompactExport& options;
  const AnimationPass& pass;
  const double tol;
  const std::function<void(pugi::xml_node)> repeat_attrs;
  CompactStats& st;

  // The part's user-space gradient `gr` (element `gn`, its own gradientTransform `own`) under
  // the part's wrapper `w`.
  void animate_gradient(pugi::xml_node gn, const Affine& own, const Path& path, const Gradient& gr, int f,
                        const std::vector<const double*>& values, const WrapperKeys& w,
                        const std::vector<double>& rest) {
    const auto gparts =
        gradient_motion(path, gr, {scene.width, scene.height}, plan, f, points, timing.keyframes, own, kMaxDecimals);
    // Per value, in the canvas: P X P^-1 for the gradientTransform X = P^-1 D^-1 P S own (P the
    // element's user space, D the wrapper as drawn, S own the full export's gradientTransform).
    const Affine P = path.to_canvas, Pinv = P.inverse();
    std::vector<Affine> maps;
    for (size_t v = 0; v < values.size(); ++v) {
      const Affine full = gparts ? compose_affine((*gparts)[static_cast<size_t>(pass.seq[v])]) : own;
      maps.push_back(w.drawn[v].inverse() * P * full * Pinv);
    }
    // Measured where the gradient paints the part: its rest points carried back by the first map.
    std::vector<double> probe;
    const Affine back = maps[0].inverse();
    for (size_t k = 0; k + 1 < rest.size(); k += 2) {
      const Vec2 q = back.apply({rest[k], rest[k + 1]});
      probe.insert(probe.end(), {q.x, q.y});
    }
    const Vec2 gc = rest_centre(probe, P);
    const WrapperKeys gw = wrapper_keys(maps, P, probe, pass.times, tol, options.decimals, gc, WrapperForm::Smil);
    remove_gradient_animations(gn);
    const std::string gprefix(gn.name(), gn.name() + (std::strlen(gn.name()) - local_name(gn.name()).size()));
    append_keyed_transform(gn, gprefix, gw, gc, pass.times, repeat_attrs, "gradientTransform", true);
    st.keys += gw.key_count();
  }

  // The part's `d` animation of what its wrapper `w` leaves (element `el`, of local name `tag`
  // and namespace prefix `prefix`).
  void animate_residual(pugi::xml_node el, std::string_view tag, const std::string& prefix, const Path& path,
                        const PartMotion& motion, const WrapperKeys& w, const std::vector<const double*>& values,
                        const std::vector<double>& rest, size_t count) {
    // The residual: each value's shape in the element's coordinates inside the moving wrapper.
    ++st.residual;
    std::vector<double> local;
    double px_per_unit = 0;
    for (size_t v = 0; v < values.size(); ++v) {
      const Affine to_canvas = w.drawn[v] * path.to_canvas;
      px_per_unit = std::max(px_per_unit, to_canvas.mean_scale());
      const Affine to_local = to_canvas.inverse();
      for (size_t i = 0; i < count; ++i) {
        const Vec2 q = to_local.apply({values[v][2 * i], values[v][2 * i + 1]});
        local.insert(local.end(), {q.x, q.y});
      }
    }
    const SampleError derr = point_error(local, 2 * count, px_per_unit);
    const double rtol = tol * options.residual_scale;  // the residual's own tolerance (kResidualScales)
    const ReducedKeys dk_keys = reduce_keyframes(pass.times, local, 2 * count, rtol, derr);
    st.keys += dk_keys.keys.size();
    st.values += values.size();
    const int dd = options.decimals >= 0 ? options.decimals
                                         : measured_decimals(local, 2 * count, dk_keys.keys, derr, rtol / 4, 0, 2 * count, kMaxDecimals);
    log::debug("compact export: %s: %zu control points, affine miss %.3f px, transform %zu keys, d %zu keys at %d decimals",
               path.id.c_str(), count, motion.affine_miss_px, w.key_count(), dk_keys.keys.size(), dd);
    std::string text;
    for (size_t i = 0; i < dk_keys.keys.size(); ++i) {
      if (i) text += ';';
      text += relative_path_data(path, &local[dk_keys.keys[i] * 2 * count], Affine{}, dd);
    }
    if (tag != "path") {
      // Only <path> has a `d`: the shape becomes one, keeping id, paint and transform.
      for (const char* a : kShapeGeometry) el.remove_attribute(a);
      el.set_name((prefix + "path").c_str());
      el.append_attribute("d") = path_data(path, rest.data(), path.to_canvas.inverse(), dd).c_str();
    }
    pugi::xml_node anim = el.append_child((prefix + "animate").c_str());
    anim.append_attribute("attributeName") = "d";
    repeat_attrs(anim);
    append_key_timing(anim, pass.times, dk_keys);
    anim.append_attribute("values") = text.c_str();
  }
};

}  // namespace

std::vector<std::string> write_compact_animation_svg(const fs::path& source, const Scene& scene, const RasterPlan& plan,
                                                     const std::vector<double>& points, const AnimationTiming& timing,
                                                     const fs::path& out, const ExportMap* map,
                                                     const CompactExport& options, CompactStats* stats) {
  check_animation_inputs(scene, plan, points, timing, map, std::max(0, options.decimals));
  std::string original;
  pugi::xml_document doc;
  const ptrdiff_t root_name_at = reread_source(source, original, doc);
  const double tol = options.tolerance_px > 0 ? options.tolerance_px : compact_tolerance(scene.width, scene.height);

  const AnimationPass pass = animation_pass(timing);
  char dur[32];
  std::snprintf(dur, sizeof dur, "%.4gs", pass.duration_s);
  auto repeat_attrs = [&](pugi::xml_node anim) {
    append_repeat(anim, dur, timing.loop);
  };
  std::vector<std::string> warnings;
  CompactStats st;
  CompactWriter writer{scene, plan, points, timing, options, pass, tol, repeat_attrs, st};
  int skipped_use = 0;
  UserGradients user_gradients{doc, {}, {}, 0};
  std::vector<pugi::xml_node> elements = find_elements(doc, scene, source);
  // The paint order first: the wrappers below are made where each element then stands.
  if (map && !map->order.empty()) {
    const ReorderResult r = reorder_elements(elements, scene, map->order);
    if (r.refused) throw Error(source.string() + ": cannot apply the paint order: " + *r.refused);
  }
  for (size_t p = 0; p < scene.paths.size(); ++p) {
    const Path& path = scene.paths[p];
    const int f = map ? map->fitted_of[p] : static_cast<int>(p);
    if (f < 0 || plan.path_cp_count[static_cast<size_t>(f)] == 0) continue;
    const size_t first = plan.path_cp_first[static_cast<size_t>(f)];
    const size_t count = static_cast<size_t>(plan.path_cp_count[static_cast<size_t>(f)]);
    pugi::xml_node el = elements[p];
    const std::string_view tag = local_name(el.name());
    if (tag == "use") {
      ++skipped_use;
      continue;
    }
    // An earlier fit's animation goes.
    for (pugi::xml_node a = el.first_child(); a;) {
      pugi::xml_node next = a.next_sibling();
      if (local_name(a.name()) == "animate" && std::string_view(a.attribute("attributeName").value()) == "d")
        el.remove_child(a);
      a = next;
    }
    std::vector<double> rest;
    for (const Subpath& sp : path.subpaths)
      for (const Vec2& q : sp.points) rest.insert(rest.end(), {q.x, q.y});
    std::vector<const double*> values;
    for (int k : pass.seq) values.push_back(&points[(static_cast<size_t>(k) * plan.n_cp + first) * 2]);
    // A document shape that does not match the fitted structure is not a base to move: its
    // motion is then all residual, from the first value.
    const bool matches = rest.size() == 2 * count;
    if (!matches) rest.assign(values[0], values[0] + 2 * count);
    PartMotion motion = analyse_part_motion(rest, values, tol, tol * options.residual_scale);
    if (!matches) motion.residual = motion.moves = true;
    st.values += values.size();
    if (!motion.moves) {
      ++st.still;
      continue;
    }
    if (motion.affine.empty()) motion.affine.assign(values.size(), Affine{});
    // The wrapper: a new <g> where the element stood, holding it; its transform is in the
    // element's parent's user space.
    Affine own;
    if (const pugi::xml_attribute t = el.attribute("transform"); !t.empty())
      if (const std::optional<Affine> parsed_t = svg::parse_transform(t.value())) own = *parsed_t;
    const Affine parent_to_canvas = path.to_canvas * own.inverse();
    const std::string prefix(el.name(), el.name() + (std::strlen(el.name()) - tag.size()));
    pugi::xml_node g = el.parent().insert_child_before((prefix + "g").c_str(), el);
    g.append_move(el);
    ++st.transformed;
    // The residual is computed against what the written (reduced, rounded) transform draws.
    // (Loosening the transform's tolerance when a residual follows moved the fit's jitter into
    // the `d` values: on the man fitted to a bent target, 217 kB -> 286 kB at 2x looser.)
    // The rotation is about the part's pivot (its joint: the point its motion moves least) when
    // that writes fewer numbers than about its rest centre: a swinging part's translate then
    // stays still where about its own centre it traces an arc (the bench parrot's wing tips: 47
    // translate keys); a part that drifts and wobbles (the bench kite) turns about its centre,
    // as a far pivot swings its wobble into large moves. The pivot is rounded to a quarter of
    // the tolerance (parent units), as it is written in every rotate key.
    const int centre_decimals =
        std::clamp(static_cast<int>(std::ceil(std::log10(4 * parent_to_canvas.mean_scale() / tol))), 0, kMaxDecimals);
    const double grid = std::pow(10.0, centre_decimals);
    Vec2 centre = rest_centre(rest, parent_to_canvas);
    WrapperKeys w =
        wrapper_keys(motion.affine, parent_to_canvas, rest, pass.times, tol, options.decimals, centre, WrapperForm::Smil);
    Vec2 pivot = motion_pivot(motion.affine, rest, parent_to_canvas);
    pivot = {std::round(pivot.x * grid) / grid, std::round(pivot.y * grid) / grid};
    WrapperKeys about_pivot =
        wrapper_keys(motion.affine, parent_to_canvas, rest, pass.times, tol, options.decimals, pivot, WrapperForm::Smil);
    if (written_numbers(about_pivot) < written_numbers(w)) {
      w = std::move(about_pivot);
      centre = pivot;
    } else {
      centre = {std::round(centre.x * grid) / grid, std::round(centre.y * grid) / grid};
      w = wrapper_keys(motion.affine, parent_to_canvas, rest, pass.times, tol, options.decimals, centre, WrapperForm::Smil);
    }
    ++(centre.x == pivot.x && centre.y == pivot.y ? st.pivoted : st.centred);
    st.keys += w.key_count();
    append_keyed_transform(g, prefix, w, centre, pass.times, repeat_attrs, "transform", false, centre_decimals);
    // A user-space gradient lies in the element's user space, which the wrapper now moves; the
    // full export moves it by the colour-weighted similarity (gradient_motion) or not at all.
    // Its gradientTransform is animated to undo the wrapper's map and apply that motion, so the
    // part is coloured as the full export colours it (moved by the wrapper's least-squares
    // affine map, a sun ray that thickens turned its far radial centre into a colour shift).
    for (const int gi : {path.fill_gradient, path.stroke_gradient}) {
      if (gi < 0) continue;
      const Gradient& gr = scene.gradients[static_cast<size_t>(gi)];
      const auto claimed = user_gradients.claim(gr);
      if (!claimed) continue;
      pugi::xml_node gn = claimed->node;
      const Affine& own = claimed->transform;
      writer.animate_gradient(gn, own, path, gr, f, values, w, rest);
    }
    if (!motion.residual) continue;
    writer.animate_residual(el, tag, prefix, path, motion, w, values, rest, count);
  }
  if (user_gradients.shared)
    warnings.push_back(source.string() + ": " + std::to_string(user_gradients.shared) +
                       " gradients shared by several shapes move with their shapes' groups");
  if (skipped_use)
    warnings.push_back(source.string() + ": " + std::to_string(skipped_use) +
                       " shapes drawn through <use> left static (shared definitions)");
  if (stats) *stats = st;
  write_file_atomic(out, with_original_prolog(original, static_cast<size_t>(std::max<ptrdiff_t>(1, root_name_at) - 1),
                                              doc.document_element()));
  return warnings;
}

}  // namespace svgm
