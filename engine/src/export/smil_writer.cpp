// The SMIL animation writer (see smil_writer.h).
#include "export/smil_writer.h"
#include "svgmotion/atomic_file.h"

#include <Eigen/Dense>
#include <pugixml.hpp>

#include <charconv>
#include <cmath>
#include <cstring>
#include <functional>
#include <algorithm>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>


#include "export/compact_motion.h"
#include "export/keyframe_reduce.h"
#include "svg/document_order.h"
#include "fit/optimise/warm_start.h"
#include "raster/gradient_paint.h"
#include "svg/transform_list.h"
#include "svg/svg_number.h"
#include "svgmotion/error.h"
#include "svgmotion/log.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

void append_number(std::string& s, double v, int decimals) {
  svg::append_rounded(s, v, std::pow(10.0, decimals));
}

std::string_view local_name(const char* name) {
  const char* colon = std::strchr(name, ':');
  return colon ? std::string_view(colon + 1) : std::string_view(name);
}

// The output file: the user's own bytes before and after the root element (declaration,
// comments, doctype and the whitespace between them, which pugixml does not keep at the
// document level) around the root element as changed. `root_begin` is where the root's '<'
// stands in `original`.
std::string with_original_prolog(const std::string& original, size_t root_begin, pugi::xml_node root) {
  const std::string close = std::string("</") + root.name();
  size_t root_end = original.rfind(close);
  if (root_end != std::string::npos) root_end = original.find('>', root_end);
  std::ostringstream body;
  root.print(body, "", pugi::format_raw, pugi::encoding_utf8);
  if (root_end == std::string::npos || root_end < root_begin) return body.str();
  return original.substr(0, root_begin) + body.str() + original.substr(root_end + 1);
}

constexpr const char* kShapeGeometry[] = {"x", "y", "width", "height", "rx", "ry", "cx",
                                          "cy", "r", "x1", "y1", "x2", "y2", "points"};

// Decimal places of written angles (degrees) and scale factors: finer than the coordinates'
// so that a rotation or scale about a far origin still lands within a coordinate's rounding
// (1e-4 degrees moves a point 1000 units away by 0.002; 1e-6 of scale, by 0.001).
constexpr int kAngleDecimals = 4, kScaleDecimals = 6;

// A gradient is carried with its shape only when the shape's outline shows at least this much
// of its motion along the gradient's colour direction (colour_visibility: 0.5 for a round
// outline, sin² of the half-angle for a wedge along a radial ramp).
constexpr double kMinColourVisibility = 0.1;
constexpr int kVisibilitySamples = 8;  // per cubic segment

double rounded(double v, int decimals) {
  const double f = std::pow(10.0, decimals);
  const double r = std::round(v * f) / f;
  return r == 0 ? 0.0 : r;  // no "-0"
}

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

// The document's gradient elements by id, and how many times each id is named as a paint or
// link target (url(#id) in any attribute or <style> text, href="#id" with or without xlink:),
// read in one walk. A gradient named once paints one shape and no other gradient inherits it.
struct GradientIndex {
  std::map<std::string, pugi::xml_node, std::less<>> gradients;
  std::map<std::string, int, std::less<>> references;
};
GradientIndex index_gradients(const pugi::xml_document& doc) {
  GradientIndex out;
  auto count_urls = [&](std::string_view text) {
    for (size_t at = text.find("url(#"); at != std::string_view::npos; at = text.find("url(#", at + 1)) {
      const size_t end = text.find(')', at);
      if (end == std::string_view::npos) break;
      ++out.references[std::string(text.substr(at + 5, end - at - 5))];
    }
  };
  std::function<void(pugi::xml_node)> walk = [&](pugi::xml_node node) {
    const std::string_view tag = local_name(node.name());
    if (tag == "linearGradient" || tag == "radialGradient")
      if (const char* id = node.attribute("id").value(); *id) out.gradients.emplace(id, node);
    for (pugi::xml_attribute a : node.attributes()) {
      const std::string_view value = a.value();
      if (local_name(a.name()) == "href") {
        if (value.starts_with('#')) ++out.references[std::string(value.substr(1))];
      } else {
        count_urls(value);
      }
    }
    if (tag == "style") count_urls(node.child_value());
    for (pugi::xml_node c = node.first_child(); c; c = c.next_sibling())
      if (c.type() == pugi::node_element) walk(c);
  };
  walk(doc.document_element());
  return out;
}

// The gradient's own href (with or without xlink:), empty when none.
std::string_view href_of(pugi::xml_node n) {
  for (pugi::xml_attribute a : n.attributes())
    if (local_name(a.name()) == "href") return a.value();
  return {};
}

// The user-space gradients a writer moves with their shapes, each element once: a gradient
// this shape alone paints with (named once, not inheriting through its href without a
// transform of its own), with its own gradientTransform. Shared ones are counted for the
// writer's one warning (moving them for this shape would move them wrongly elsewhere).
struct UserGradients {
  const pugi::xml_document& doc;
  std::optional<GradientIndex> index;  // read on the first user-space gradient
  std::set<std::string> seen;
  int shared = 0;
  struct Own {
    pugi::xml_node node;
    Affine transform;  // its gradientTransform (identity when none)
  };
  std::optional<Own> claim(const Gradient& g) {
    if (!g.user_space || g.id.empty()) return std::nullopt;
    if (!index) index = index_gradients(doc);
    const auto found = index->gradients.find(g.id);
    if (found == index->gradients.end() || !seen.insert(g.id).second) return std::nullopt;
    const pugi::xml_node gn = found->second;
    const pugi::xml_attribute own_attr = gn.attribute("gradientTransform");
    const auto refs = index->references.find(g.id);
    if (refs == index->references.end() || refs->second != 1 || (own_attr.empty() && !href_of(gn).empty())) {
      ++shared;
      return std::nullopt;
    }
    Own own{gn, {}};
    if (!own_attr.empty()) {
      const std::optional<Affine> t = svg::parse_transform(own_attr.value());
      if (!t) return std::nullopt;
      own.transform = *t;
    }
    return own;
  }
};

// Which way a gradient's colour changes at point x: the unit gradient of its parameter (a
// linear gradient's vector; a radial one's direction from its centre, focal point aside), zero
// where it has none. `to_gradient` maps x's space to gradient space.
Vec2 colour_direction(const Gradient& g, const Affine& to_gradient, Vec2 x) {
  const Affine& m = to_gradient;  // ∇_x t = mᵀ ∇_u t for u = m(x)
  const Vec2 du = g.radial ? m.apply(x) - g.center : g.p2 - g.p1;
  const Vec2 dx{m.a * du.x + m.b * du.y, m.c * du.x + m.d * du.y};
  const double len = std::hypot(dx.x, dx.y);
  return len > 1e-12 ? (1.0 / len) * dx : Vec2{};
}

// The similarity M (x ↦ [a −b; b a] x + t) that carries a gradient with a moving shape: least
// squares over the shape's points of (m_i · (M x_i − y_i))² + μ |M x_i − y_i|², m_i the colour
// direction at x_i turned by M's own turn. A gradient shows a point's motion only along its
// colour direction, so that component is what must be right; across it (the length of a ray
// under a radial gradient centred far off, a ramp's own direction) μ only keeps the solution
// near the shape's plain fit. Umeyama's fit (all directions alike) lets a ray that bends or
// thickens pull its scale, which a far centre multiplies into a colour shift along the ray.
// Started from that fit; two passes turn the m_i with M.
std::optional<Similarity> fit_colour_similarity(const std::vector<Vec2>& from, const std::vector<Vec2>& to,
                                                const std::vector<Vec2>& directions, const std::vector<double>& weight,
                                                const Similarity& start) {
  constexpr double kAcross = 0.05;  // μ: weight of the error across the colour direction
  Similarity s = start;
  for (int pass = 0; pass < 2; ++pass) {
    const double c = std::cos(s.angle), sn = std::sin(s.angle);
    Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
    Eigen::Vector4d rhs = Eigen::Vector4d::Zero();
    for (size_t i = 0; i < from.size(); ++i) {
      const Vec2 n = directions[i];
      const Vec2 m{c * n.x - sn * n.y, sn * n.x + c * n.y};
      Eigen::Matrix2d Q;
      Q << m.x * m.x + kAcross, m.x * m.y, m.x * m.y, m.y * m.y + kAcross;
      Q *= weight[i];
      Eigen::Matrix<double, 2, 4> J;
      J << from[i].x, -from[i].y, 1, 0, from[i].y, from[i].x, 0, 1;
      A += J.transpose() * Q * J;
      rhs += J.transpose() * Q * Eigen::Vector2d(to[i].x, to[i].y);
    }
    const Eigen::Vector4d p = A.ldlt().solve(rhs);
    if (!p.allFinite()) return std::nullopt;
    const double scale = std::hypot(p[0], p[1]);
    if (!(scale > 0.5 && scale < 2.0)) return std::nullopt;
    s = Similarity{scale, std::atan2(p[1], p[0]), Vec2{p[2], p[3]}};
  }
  return s;
}

// How much of its motion along its colour direction a shape's outline shows: over the visible
// outline at rest (length-weighted samples, each counting with the paint's opacity there, none
// off the canvas), the mean of (n · m)², n the outline's normal and m the colour direction. An
// edge shows only its motion across itself, so an outline running along its ramp (a sun ray
// under a radial ramp centred at its base: its long sides follow the ramp, its tip has faded
// out and its base hides behind the sun) shows none of the motion its ramp would need, and the
// fit never placed it along the ramp either (it fitted the shape under a gradient that stayed
// put). 0.5 for a round outline under any gradient. `cp`: the path's rest points, canvas space.
double colour_visibility(const Path& path, const Gradient& g, const double* cp, Vec2 canvas) {
  const Affine m = g.to_canvas.inverse();  // canvas -> gradient space; ∇_x t = mᵀ ∇_u t
  double seen = 0, total = 0;
  for (const Subpath& sp : path.subpaths) {
    for (size_t s = 0; s + 3 < sp.points.size(); s += 3) {
      const Vec2 p0{cp[2 * s], cp[2 * s + 1]}, p1{cp[2 * s + 2], cp[2 * s + 3]}, p2{cp[2 * s + 4], cp[2 * s + 5]},
          p3{cp[2 * s + 6], cp[2 * s + 7]};
      for (int j = 0; j < kVisibilitySamples; ++j) {
        const double t = (j + 0.5) / kVisibilitySamples, u = 1 - t;
        const Vec2 b = (u * u * u) * p0 + (3 * u * u * t) * p1 + (3 * u * t * t) * p2 + (t * t * t) * p3;
        const Vec2 d = (3 * u * u) * (p1 - p0) + (6 * u * t) * (p2 - p1) + (3 * t * t) * (p3 - p2);
        const double len = std::hypot(d.x, d.y);
        if (!(len > 1e-12) || b.x < 0 || b.y < 0 || b.x > canvas.x || b.y > canvas.y) continue;
        const std::optional<Rgba> c = gradient_color(g, m, b);
        const double w = (c ? c->a : 0.0) * len;
        if (!(w > 0)) continue;
        const Vec2 dir = colour_direction(g, m, b);
        if (dir.x == 0 && dir.y == 0) continue;
        const double along = (-d.y * dir.x + d.x * dir.y) / len;  // n · m, n = perp(d) / |d|
        seen += w * along * along;
        total += w;
      }
    }
    cp += 2 * sp.points.size();
  }
  return total > 0 ? seen / total : 0.5;
}

// The gradient transform that carries a user-space gradient `g` along with its path's shape,
// per written value: the similarity from the path's points at rest to its points in that value
// that keeps their colours (fit_colour_similarity), in the path's own coordinates, before the
// gradient's own transform `own`. Nothing when the shape only ever moves by less than the
// written precision, or when its outline does not show its motion along the ramp
// (colour_visibility): the gradient then stays where the document and the fit put it.
std::optional<std::vector<TransformParts>> gradient_motion(const Path& path, const Gradient& g, Vec2 canvas,
                                                           const RasterPlan& plan, int f, const std::vector<double>& points, int keyframes,
                                                           const Affine& own, int decimals) {
  const size_t first = plan.path_cp_first[static_cast<size_t>(f)];
  const size_t count = static_cast<size_t>(plan.path_cp_count[static_cast<size_t>(f)]);
  const Affine to_local = path.to_canvas.inverse();
  auto local_points = [&](int v) {
    std::vector<Vec2> out(count);
    const double* cp = &points[(static_cast<size_t>(v) * plan.n_cp + first) * 2];
    for (size_t i = 0; i < count; ++i) out[i] = to_local.apply({cp[2 * i], cp[2 * i + 1]});
    return out;
  };
  size_t outline_points = 0;
  for (const Subpath& sp : path.subpaths) outline_points += sp.points.size();
  if (outline_points == count && colour_visibility(path, g, &points[first * 2], canvas) < kMinColourVisibility)
    return std::nullopt;
  const std::vector<Vec2> rest = local_points(0);
  const Affine local_to_gradient = (to_local * g.to_canvas).inverse();
  std::vector<Vec2> directions;
  for (const Vec2& r : rest) directions.push_back(colour_direction(g, local_to_gradient, r));
  // A point where the paint is transparent, or off the canvas, was never seen by the fit: it
  // says nothing of where the shape went (a sun ray fading out before its tip leaves the tip's
  // points free to wander, and they tilted and shrank the ray's fit). Each point counts with
  // the paint's opacity there; all alike when fewer than three are seen.
  std::vector<double> weight(count, 0.0);
  const Affine canvas_to_gradient = g.to_canvas.inverse();
  int seen = 0;
  for (size_t i = 0; i < count; ++i) {
    const Vec2 p{points[(first + i) * 2], points[(first + i) * 2 + 1]};
    if (p.x < 0 || p.y < 0 || p.x > canvas.x || p.y > canvas.y) continue;
    const std::optional<Rgba> c = gradient_color(g, canvas_to_gradient, p);
    weight[i] = c ? c->a : 0.0;
    seen += weight[i] > 0.05;
  }
  if (seen < 3) std::fill(weight.begin(), weight.end(), 1.0);
  std::vector<TransformParts> out;
  double moved = 0;
  for (int v = 0; v < keyframes; ++v) {
    Affine s;  // identity at rest
    if (v > 0) {
      const std::vector<Vec2> moved_points = local_points(v);
      const std::optional<Similarity> plain = fit_similarity(rest, moved_points, weight);
      if (!plain) return std::nullopt;
      const std::optional<Similarity> sim = fit_colour_similarity(rest, moved_points, directions, weight, *plain);
      if (!sim) return std::nullopt;
      const double c = sim->scale * std::cos(sim->angle), d = sim->scale * std::sin(sim->angle);
      s = Affine{c, d, -d, c, sim->shift.x, sim->shift.y};
      for (const Vec2& r : rest) {
        const Vec2 m = s.apply(r) - r;
        moved = std::max({moved, std::fabs(m.x), std::fabs(m.y)});
      }
    }
    TransformParts p = decompose_affine(s * own);
    if (v > 0) {
      p.rotate_deg = unwrap_degrees(p.rotate_deg, out.back().rotate_deg);
      p.skew_x_deg = unwrap_degrees(p.skew_x_deg, out.back().skew_x_deg);
    }
    out.push_back({rounded(p.tx, decimals), rounded(p.ty, decimals), rounded(p.rotate_deg, kAngleDecimals),
                   rounded(p.skew_x_deg, kAngleDecimals), rounded(p.sx, kScaleDecimals), rounded(p.sy, kScaleDecimals)});
  }
  if (moved <= std::pow(10.0, -decimals)) return std::nullopt;
  return out;
}

}  // namespace

LoopMode parse_loop_mode(const std::string& text, const std::string& what) {
  if (text == "loop") return LoopMode::Loop;
  if (text == "once") return LoopMode::Once;
  if (text == "mirror") return LoopMode::Mirror;
  throw Error(what + " must be loop, once or mirror, not '" + text + "'");
}

const char* loop_mode_name(LoopMode m) {
  switch (m) {
    case LoopMode::Loop: return "loop";
    case LoopMode::Once: return "once";
    case LoopMode::Mirror: return "mirror";
  }
  return "loop";
}

AnimationPass animation_pass(const AnimationTiming& timing) {
  const int K = timing.keyframes;
  AnimationPass pass;
  for (int k = 0; k < K; ++k) {
    pass.seq.push_back(timing.close_loop && K > 1 && k == K - 1 ? 0 : k);
    pass.times.push_back(!timing.key_times.empty() ? timing.key_times[static_cast<size_t>(k)]
                         : K > 1 ? static_cast<double>(k) / (K - 1) : 0.0);
  }
  pass.duration_s = timing.duration_s;
  if (timing.loop == LoopMode::Mirror && K > 1) {
    for (int k = K - 2; k >= 0; --k) {
      pass.seq.push_back(pass.seq[static_cast<size_t>(k)]);
      pass.times.push_back(2.0 - pass.times[static_cast<size_t>(k)]);
    }
    for (double& t : pass.times) t /= 2;
    pass.duration_s *= 2;
  }
  return pass;
}

std::string path_data(const Path& path, const double* cp, const Affine& to_local, int decimals) {
  std::string d;
  for (const Subpath& sp : path.subpaths) {
    if (sp.points.empty()) continue;
    for (size_t i = 0; i < sp.points.size(); ++i) {
      const Vec2 q = to_local.apply({cp[2 * i], cp[2 * i + 1]});
      if (i == 0) d += d.empty() ? "M" : " M";
      else if (i % 3 == 1) d += " C";
      d += ' ';
      append_number(d, q.x, decimals);
      d += ' ';
      append_number(d, q.y, decimals);
    }
    if (sp.closed) d += " Z";
    cp += 2 * sp.points.size();
  }
  return d;
}

void check_animation_inputs(const Scene& scene, const RasterPlan& plan, const std::vector<double>& points,
                            const AnimationTiming& timing, const ExportMap* map, int decimals) {
  const int K = timing.keyframes;
  if (decimals < 0 || decimals > kMaxDecimals) throw Error("internal: export precision out of range");
  if (K < 1 || points.size() != static_cast<size_t>(K) * plan.n_cp * 2)
    throw Error("internal: animation points do not match the plan");
  if (!timing.key_times.empty() && timing.key_times.size() != static_cast<size_t>(K))
    throw Error("internal: key times do not match the keyframes");
  if (map && map->fitted_of.size() != scene.paths.size())
    throw Error("internal: export map does not match the document");
}

namespace {

// The user's document again, as the writers add to it: its text (kept for what precedes the
// root element) and the parsed tree; returns the root element's name offset in the text.
ptrdiff_t reread_source(const fs::path& source, std::string& original, pugi::xml_document& doc) {
  std::ifstream in(source, std::ios::binary);
  original.assign((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in && !in.eof()) throw Error(source.string() + ": cannot re-read for export");
  const pugi::xml_parse_result parsed = doc.load_buffer(original.data(), original.size(), kKeepDocumentParse);
  if (!parsed) throw Error(source.string() + ": cannot re-read for export: " + parsed.description());
  return doc.document_element().offset_debug();
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
  std::string key_times;
  for (size_t i = 0; i < times.size(); ++i) {
    if (i) key_times += ';';
    // 1/10000 of a pass: finer than any frame, and the last is exactly 1 as SMIL requires.
    const double t = i + 1 == times.size() ? 1.0 : std::round(times[i] * 1e4) / 1e4;
    char buf[32];
    auto [p, ec] = std::to_chars(buf, buf + sizeof buf, t);
    key_times.append(buf, ec == std::errc() ? p : buf);
  }
  char dur[32];
  std::snprintf(dur, sizeof dur, "%.4gs", duration);

  std::vector<std::string> warnings;
  int skipped_use = 0;
  UserGradients user_gradients{doc, {}, {}, 0};
  // Find every element before changing any: turning a <rect> into a <path> renumbers the
  // locators of the paths after it.
  std::vector<pugi::xml_node> elements;
  for (const Path& path : scene.paths) {
    elements.push_back(find_locator(doc, path.locator));
    if (!elements.back()) throw Error("internal: " + path.locator + " not found in " + source.string());
  }
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
      anim.append_attribute("dur") = dur;
      if (timing.loop == LoopMode::Once) {
        anim.append_attribute("repeatCount") = "1";
        anim.append_attribute("fill") = "freeze";
      } else {
        anim.append_attribute("repeatCount") = "indefinite";
      }
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
      for (pugi::xml_node a = gn.first_child(); a;) {
        pugi::xml_node next = a.next_sibling();
        if (local_name(a.name()) == "animateTransform" &&
            std::string_view(a.attribute("attributeName").value()) == "gradientTransform")
          gn.remove_child(a);
        a = next;
      }
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

// ---- The compact export (see smil_writer.h, export/compact_motion.h).

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
// gradientTransform, which the keys include) and the others add to it.
void append_keyed_transform(pugi::xml_node node, const std::string& prefix, const WrapperKeys& w, Vec2 centre,
                            const std::vector<double>& times, const std::function<void(pugi::xml_node)>& repeat_attrs,
                            const char* attribute, bool replace_first) {
  const std::vector<double>& trajectory = w.trajectory;
  const ReducedKeys& tk = w.keys;
  struct Component {
    const char* type;
    size_t at, n;
    int decimals;
    double identity;
  };
  bool first = true;
  for (const Component& c : {Component{"translate", 0, 2, w.translate_decimals, 0}, Component{"rotate", 2, 1, w.rotate_decimals, 0},
                             Component{"skewX", 3, 1, w.skew_decimals, 0}, Component{"scale", 4, 2, w.scale_decimals, 1}}) {
    std::string text;
    bool identity = true;
    for (size_t i = 0; i < tk.keys.size(); ++i) {
      if (i) text += ';';
      for (size_t j = 0; j < c.n; ++j) {
        const double v = trajectory[6 * tk.keys[i] + c.at + j];
        identity = identity && v == c.identity;
        if (j) text += ' ';
        append_number(text, v, c.decimals);
      }
      if (c.at == 2) {  // rotate about the rest shape's centre
        text += ' ';
        append_number(text, centre.x, w.translate_decimals);
        text += ' ';
        append_number(text, centre.y, w.translate_decimals);
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
    anim.append_attribute("dur") = dur;
    if (timing.loop == LoopMode::Once) {
      anim.append_attribute("repeatCount") = "1";
      anim.append_attribute("fill") = "freeze";
    } else {
      anim.append_attribute("repeatCount") = "indefinite";
    }
  };
  std::vector<std::string> warnings;
  CompactStats st;
  int skipped_use = 0;
  UserGradients user_gradients{doc, {}, {}, 0};
  std::vector<pugi::xml_node> elements;
  for (const Path& path : scene.paths) {
    elements.push_back(find_locator(doc, path.locator));
    if (!elements.back()) throw Error("internal: " + path.locator + " not found in " + source.string());
  }
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
    PartMotion motion = analyse_part_motion(rest, values, tol);
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
    const Vec2 centre = rest_centre(rest, parent_to_canvas);
    const WrapperKeys w =
        wrapper_keys(motion.affine, parent_to_canvas, rest, pass.times, tol, options.decimals, centre, WrapperForm::Smil);
    st.keys += w.keys.keys.size();
    append_keyed_transform(g, prefix, w, centre, pass.times, repeat_attrs, "transform", false);
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
      for (pugi::xml_node a = gn.first_child(); a;) {
        pugi::xml_node next = a.next_sibling();
        if (local_name(a.name()) == "animateTransform" &&
            std::string_view(a.attribute("attributeName").value()) == "gradientTransform")
          gn.remove_child(a);
        a = next;
      }
      const std::string gprefix(gn.name(), gn.name() + (std::strlen(gn.name()) - local_name(gn.name()).size()));
      append_keyed_transform(gn, gprefix, gw, gc, pass.times, repeat_attrs, "gradientTransform", true);
      st.keys += gw.keys.keys.size();
    }
    if (!motion.residual) continue;
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
    const ReducedKeys dk_keys = reduce_keyframes(pass.times, local, 2 * count, tol, derr);
    st.keys += dk_keys.keys.size();
    st.values += values.size();
    const int dd = options.decimals >= 0 ? options.decimals
                                         : measured_decimals(local, 2 * count, dk_keys.keys, derr, tol / 4, 0, 2 * count, kMaxDecimals);
    log::debug("compact export: %s: %zu control points, affine miss %.3f px, transform %zu keys, d %zu keys at %d decimals",
               path.id.c_str(), count, motion.affine_miss_px, w.keys.keys.size(), dk_keys.keys.size(), dd);
    std::string text;
    for (size_t i = 0; i < dk_keys.keys.size(); ++i) {
      if (i) text += ';';
      text += path_data(path, &local[dk_keys.keys[i] * 2 * count], Affine{}, dd);
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
