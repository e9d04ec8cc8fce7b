// The full SMIL export (see smil_writer.h, write_animation_svg): every keyframe's shape as a
// value of the path's `d` animation, a group's motion as animateTransforms.
#include "export/smil_writer.h"

#include <pugixml.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>

#include "export/smil_writer_internal.h"
#include "svg/document_order.h"
#include "svgmotion/atomic_file.h"
#include "svgmotion/error.h"

namespace svgm {

namespace fs = std::filesystem;

using namespace smil_internal;

namespace {

// One path's group motion in its own coordinates, per written value: the element's local map
// to_canvas^-1 A to_canvas decomposed, angles unwrapped along the values, numbers rounded as
// they are written (so the `d` values are computed against exactly the written transform).
std::vector<TransformParts> local_motion(const PathMotion& motion, int f, const Affine& to_canvas, int decimals) {
  const Affine from_canvas = to_canvas.inverse();
  std::vector<TransformParts> out;
  for (int v = 0; v < motion.values; ++v) {
    TransformParts p = decompose_affine(from_canvas * motion.at(v, f) * to_canvas);
    if (v > 0) {
      p.rotate_deg = unwrap_degrees(p.rotate_deg, out.back().rotate_deg);
      p.skew_x_deg = unwrap_degrees(p.skew_x_deg, out.back().skew_x_deg);  // only ever within +-90
    }
    out.push_back({rounded(p.tx, decimals), rounded(p.ty, decimals), rounded(p.rotate_deg, kAngleDecimals),
                   rounded(p.skew_x_deg, kAngleDecimals), rounded(p.sx, kScaleDecimals), rounded(p.sy, kScaleDecimals)});
  }
  return out;
}

// The additive animateTransform children (translate, rotate, skewX, scale, in the order SVG
// post-multiplies them) of a path whose group moves as a transform; a component that stays the
// identity is not written.
// `attribute`: transform, or a gradient's gradientTransform. `replace_first`: the translate is
// always written and replaces the attribute's own value (the parts are then the whole
// transform, not a motion added to it).
void append_transform_animations(pugi::xml_node el, const std::vector<TransformParts>& parts,
                                 const std::vector<int>& seq, const std::function<void(pugi::xml_node)>& timing_attrs,
                                 int decimals, const char* attribute = "transform", bool replace_first = false) {
  struct Component {
    const char* type;
    std::function<std::string(const TransformParts&)> text;
    std::function<bool(const TransformParts&)> identity;
  };
  auto num = [](double v, int places) {
    std::string s;
    append_number(s, v, places);
    return s;
  };
  const Component components[] = {
      {"translate", [&](const TransformParts& p) { return num(p.tx, decimals) + " " + num(p.ty, decimals); },
       [](const TransformParts& p) { return p.tx == 0 && p.ty == 0; }},
      {"rotate", [&](const TransformParts& p) { return num(p.rotate_deg, kAngleDecimals); },
       [](const TransformParts& p) { return p.rotate_deg == 0; }},
      {"skewX", [&](const TransformParts& p) { return num(p.skew_x_deg, kAngleDecimals); },
       [](const TransformParts& p) { return p.skew_x_deg == 0; }},
      {"scale", [&](const TransformParts& p) { return num(p.sx, kScaleDecimals) + " " + num(p.sy, kScaleDecimals); },
       [](const TransformParts& p) { return p.sx == 1 && p.sy == 1; }},
  };
  for (const Component& c : components) {
    const bool first = &c == &components[0];
    if (!(first && replace_first) && std::all_of(parts.begin(), parts.end(), c.identity)) continue;
    std::string values;
    for (size_t i = 0; i < seq.size(); ++i) {
      if (i) values += ';';
      values += c.text(parts[static_cast<size_t>(seq[i])]);
    }
    pugi::xml_node anim = el.append_child("animateTransform");
    anim.append_attribute("attributeName") = attribute;
    anim.append_attribute("type") = c.type;
    if (!(first && replace_first)) anim.append_attribute("additive") = "sum";
    timing_attrs(anim);
    anim.append_attribute("values") = values.c_str();
  }
}

// The keyTimes of every value of the pass.
std::string smil_key_times(const std::vector<double>& times) {
  std::string key_times;
  for (size_t i = 0; i < times.size(); ++i) {
    if (i) key_times += ';';
    // 1/10000 of a pass: finer than any frame, and the last is exactly 1 as SMIL requires.
    const double t = i + 1 == times.size() ? 1.0 : std::round(times[i] * 1e4) / 1e4;
    char buf[32];
    auto [p, ec] = std::to_chars(buf, buf + sizeof buf, t);
    key_times.append(buf, ec == std::errc() ? p : buf);
  }
  return key_times;
}

}  // namespace

std::vector<std::string> write_animation_svg(const fs::path& source, const Scene& scene,
                                             const RasterPlan& plan,
                                             const std::vector<double>& points,
                                             const AnimationTiming& timing, const fs::path& out,
                                             const ExportMap* map, int decimals, const PathMotion* motion) {
  check_animation_inputs(scene, plan, points, timing, map, decimals);
  if (motion && (motion->values != timing.keyframes || motion->as_transform.size() != plan.path_cp_first.size()))
    throw Error("internal: group motion does not match the animation");
  std::string original;
  pugi::xml_document doc;
  const ptrdiff_t root_name_at = reread_source(source, original, doc);

  const AnimationPass pass = animation_pass(timing);
  const std::vector<int>& seq = pass.seq;
  const std::vector<double>& times = pass.times;
  const double duration = pass.duration_s;
  const std::string key_times = smil_key_times(times);
  char dur[32];
  std::snprintf(dur, sizeof dur, "%.4gs", duration);

  std::vector<std::string> warnings;
  int skipped_use = 0;
  UserGradients user_gradients{doc, {}, {}, 0};
  // Find every element before changing any: turning a <rect> into a <path> renumbers the
  // locators of the paths after it.
  std::vector<pugi::xml_node> elements = find_elements(doc, scene, source);
  for (size_t p = 0; p < scene.paths.size(); ++p) {
    const Path& path = scene.paths[p];
    const int f = map ? map->fitted_of[p] : static_cast<int>(p);
    if (f < 0 || plan.path_cp_count[static_cast<size_t>(f)] == 0) continue;
    const size_t first = plan.path_cp_first[static_cast<size_t>(f)];
    pugi::xml_node el = elements[p];
    const std::string_view tag = local_name(el.name());
    if (tag == "use") {
      ++skipped_use;
      continue;
    }
    // Each written value's shape in the element's coordinates: with the group's motion as a
    // transform, in the frame that transform moves (group_transform.h).
    const bool moving = motion && motion->as_transform[static_cast<size_t>(f)];
    const std::vector<TransformParts> parts =
        moving ? local_motion(*motion, f, path.to_canvas, decimals) : std::vector<TransformParts>{};
    std::vector<std::string> shapes;
    // How far the residual moves from the first value's (element units): with none beyond the
    // last written place (float noise of the motion can flip a rounding), no <animate> is needed.
    double residual_motion = 0;
    const size_t count = static_cast<size_t>(plan.path_cp_count[static_cast<size_t>(f)]);
    for (int v = 0; v < timing.keyframes; ++v) {
      const Affine to_local = moving ? (path.to_canvas * compose_affine(parts[static_cast<size_t>(v)])).inverse()
                                     : path.to_canvas.inverse();
      const double* cp = &points[(static_cast<size_t>(v) * plan.n_cp + first) * 2];
      shapes.push_back(path_data(path, cp, to_local, decimals));
      if (moving && v > 0) {
        const Affine to_local0 = (path.to_canvas * compose_affine(parts[0])).inverse();
        const double* cp0 = &points[first * 2];
        for (size_t i = 0; i < count; ++i) {
          const Vec2 d = to_local.apply({cp[2 * i], cp[2 * i + 1]}) - to_local0.apply({cp0[2 * i], cp0[2 * i + 1]});
          residual_motion = std::max({residual_motion, std::fabs(d.x), std::fabs(d.y)});
        }
      }
    }
    std::string values;
    for (size_t i = 0; i < seq.size(); ++i) {
      if (i) values += ';';
      values += shapes[static_cast<size_t>(seq[i])];
    }
    // A residual that does not change at the written precision needs no <animate>.
    const bool still = moving && residual_motion <= std::pow(10.0, -decimals);
    if (tag != "path") {
      // Only <path> has a `d`: turn the shape into one, keeping id, paint and transform.
      for (const char* a : kShapeGeometry) el.remove_attribute(a);
      const std::string prefix(el.name(), el.name() + (std::strlen(el.name()) - tag.size()));
      el.set_name((prefix + "path").c_str());
      el.append_attribute("d") = shapes[0].c_str();
    } else if (still) {
      el.attribute("d").set_value(shapes[0].c_str());
    }
    // Replace an earlier fit's animation.
    for (pugi::xml_node a = el.first_child(); a;) {
      pugi::xml_node next = a.next_sibling();
      const std::string_view name = local_name(a.name()), attr = a.attribute("attributeName").value();
      if ((name == "animate" && attr == "d") || (moving && name == "animateTransform" && attr == "transform"))
        el.remove_child(a);
      a = next;
    }
    auto timing_attrs = [&](pugi::xml_node anim) {
      append_repeat(anim, dur, timing.loop);
      anim.append_attribute("calcMode") = "linear";
      anim.append_attribute("keyTimes") = key_times.c_str();
    };
    if (moving) append_transform_animations(el, parts, seq, timing_attrs, decimals);
    if (still) continue;
    pugi::xml_node anim = el.append_child("animate");
    anim.append_attribute("attributeName") = "d";
    timing_attrs(anim);
    anim.append_attribute("values") = values.c_str();
    // A gradient in the path's user space stays where the document puts it while the `d`
    // animation moves the shape through it; a video moves it with the part (a flame's yellow
    // tip turned orange as it travelled down its own ramp). Carried along by the shape's
    // similarity, the gradient stays on the part. A group transform (moving) carries it already.
    if (moving) continue;
    for (const int gi : {path.fill_gradient, path.stroke_gradient}) {
      if (gi < 0) continue;
      const Gradient& g = scene.gradients[static_cast<size_t>(gi)];
      const auto claimed = user_gradients.claim(g);
      if (!claimed) continue;
      pugi::xml_node gn = claimed->node;
      const Affine& own = claimed->transform;
      const auto gparts = gradient_motion(path, g, {scene.width, scene.height}, plan, f, points, timing.keyframes, own, decimals);
      if (!gparts) continue;
      remove_gradient_animations(gn);
      append_transform_animations(gn, *gparts, seq, timing_attrs, decimals, "gradientTransform", true);
    }
  }
  if (user_gradients.shared)
    warnings.push_back(source.string() + ": " + std::to_string(user_gradients.shared) +
                       " gradients shared by several shapes stay where the document puts them");
  if (map && !map->order.empty()) {
    const ReorderResult r = reorder_elements(elements, scene, map->order);
    if (r.refused) throw Error(source.string() + ": cannot apply the paint order: " + *r.refused);
  }
  if (skipped_use)
    warnings.push_back(source.string() + ": " + std::to_string(skipped_use) +
                       " shapes drawn through <use> left static (shared definitions)");

  // Raw format with the parsed whitespace kept: the user's document comes back as they wrote
  // it, plus our <animate> children.
  write_file_atomic(out, with_original_prolog(original, static_cast<size_t>(std::max<ptrdiff_t>(1, root_name_at) - 1),
                                              doc.document_element()));
  return warnings;
}

}  // namespace svgm
