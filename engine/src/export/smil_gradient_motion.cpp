// User-space gradients carried with their moving shapes by the SMIL writers (see
// smil_writer_internal.h): which gradients one shape alone paints, and the colour-weighted
// similarity that keeps each one on its part.
#include <Eigen/Dense>
#include <pugixml.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

#include "export/smil_writer_internal.h"
#include "fit/optimise/warm_start.h"
#include "raster/gradient_paint.h"
#include "svg/transform_list.h"

namespace svgm::smil_internal {

namespace {

// A gradient is carried with its shape only when the shape's outline shows at least this much
// of its motion along the gradient's colour direction (colour_visibility: 0.5 for a round
// outline, sin² of the half-angle for a wedge along a radial ramp).
constexpr double kMinColourVisibility = 0.1;
constexpr int kVisibilitySamples = 8;  // per cubic segment

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

}  // namespace

std::optional<UserGradients::Own> UserGradients::claim(const Gradient& g) {
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

namespace {

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

}  // namespace

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

}  // namespace svgm::smil_internal
