// Gradient paint items for the Lottie export (see lottie_paint.h).
#include "export/lottie_paint.h"

#include <algorithm>
#include <cmath>
#include <array>
#include <functional>
#include <optional>

#include "svgmotion/svg_reader.h"

namespace svgm::lottie {

namespace {

// A radial gradient's map is a similarity (its circle stays a circle) when its linear part is
// a scaled rotation or reflection to this relative tolerance: 1e-4 of the radius is far below
// a pixel for any gradient that fits a canvas.
constexpr double kSimilarityTolerance = 1e-4;
// A repeating gradient is written over at most this many periods (a pad spread beyond them).
constexpr int kMaxPeriods = 64;
// Lottie's highlight length is a percentage of the radius; players clamp it below 100 %.
constexpr double kMaxHighlight = 99;
constexpr double kDegrees = 180.0 / M_PI;

bool is_similarity(const Affine& m) {
  const double scale = std::max(std::hypot(m.a, m.b), std::hypot(m.c, m.d));
  const double tol = kSimilarityTolerance * scale;
  const bool rotation = std::fabs(m.a - m.d) <= tol && std::fabs(m.b + m.c) <= tol;
  const bool reflection = std::fabs(m.a + m.d) <= tol && std::fabs(m.b - m.c) <= tol;
  return rotation || reflection;
}

// Where a gradient is written, for one value.
struct Placement {
  Vec2 s, e;              // start and end (radial: centre and a point on the end circle)
  double highlight = 0;   // radial: focal distance, % of the radius
  double angle = 0;       // radial: focal direction from the s->e direction, degrees
  Affine ellipse;         // elliptical radial: gradient space -> canvas (s, e in gradient space)
};

// The parameter t of a point (the stop offset it shows before spreading) for the range a
// repeating gradient must cover; focal points aside (an approximation named by the caller).
double parameter_at(const Gradient& g, const Affine& to_gradient, Vec2 p) {
  const Vec2 q = to_gradient.apply(p);
  if (!g.radial) {
    const Vec2 d = g.p2 - g.p1, v = q - g.p1;
    return (v.x * d.x + v.y * d.y) / (d.x * d.x + d.y * d.y);
  }
  return std::hypot(q.x - g.center.x, q.y - g.center.y) / g.r;
}

// The gradient's stops over parameters [t0, t1] (whole periods), rescaled to [0, 1]: the
// repeated (reflect: mirrored every other period) stops a pad spread draws the same.
std::vector<GradientStop> spread_stops(const Gradient& g, int t0, int t1) {
  if (g.spread == Spread::Pad || (t0 == 0 && t1 == 1)) return g.stops;
  std::vector<GradientStop> out;
  const double span = t1 - t0;
  for (int k = t0; k < t1; ++k) {
    const bool mirrored = g.spread == Spread::Reflect && (k % 2 != 0);
    for (size_t i = 0; i < g.stops.size(); ++i) {
      const GradientStop& s = mirrored ? g.stops[g.stops.size() - 1 - i] : g.stops[i];
      const double local = mirrored ? 1.0 - s.offset : s.offset;
      out.push_back({static_cast<float>((k - t0 + local) / span), s.color});
    }
  }
  return out;
}

// Between two stops of different opacity, players differ: SVG, lottie-web and ThorVG blend the
// straight colours, rlottie the premultiplied ones (a fade to transparent looks lighter there).
// Stops in between, on the straight blend, make both agree: their gap shrinks as the square of
// the span. One stop per this much change of opacity (0.4 -> 4 spans: 20 levels -> ~1).
constexpr double kOpacityPerSpan = 0.1;
constexpr int kMaxSpans = 10;

std::vector<GradientStop> densify_translucent(const std::vector<GradientStop>& stops) {
  std::vector<GradientStop> out;
  for (size_t i = 0; i < stops.size(); ++i) {
    if (i > 0) {
      const GradientStop &a = stops[i - 1], &b = stops[i];
      const int spans = std::min(kMaxSpans, static_cast<int>(std::ceil(std::fabs(b.color.a - a.color.a) / kOpacityPerSpan)));
      for (int k = 1; k < spans; ++k) {
        const float u = static_cast<float>(k) / static_cast<float>(spans);
        out.push_back({a.offset + u * (b.offset - a.offset),
                       Rgba{a.color.r + u * (b.color.r - a.color.r), a.color.g + u * (b.color.g - a.color.g),
                            a.color.b + u * (b.color.b - a.color.b), a.color.a + u * (b.color.a - a.color.a)}});
      }
    }
    out.push_back(stops[i]);
  }
  return out;
}

// {"p":n,"k":{"a":0,"k":[offset,r,g,b ... offset,alpha ...]}}: colour stops, then opacity
// stops when any stop is not opaque.
void write_stops(JsonText& j, const std::vector<GradientStop>& stops) {
  j.raw("{\"p\":").num(static_cast<double>(stops.size()), 1).raw(",\"k\":{\"a\":0,\"k\":[");
  bool first = true;
  auto item = [&](double v) {
    if (!first) j.raw(",");
    first = false;
    j.num(v, kColourScale);
  };
  bool translucent = false;
  for (const GradientStop& s : stops) {
    item(s.offset), item(s.color.r), item(s.color.g), item(s.color.b);
    translucent = translucent || s.color.a < 1;
  }
  if (translucent)
    for (const GradientStop& s : stops) item(s.offset), item(s.color.a);
  j.raw("]}}");
}

struct GradientPlan {
  std::vector<Placement> placements;  // per value
  std::vector<RotateScaleRotate> parts;  // elliptical: the map's split per value, unwrapped
  std::vector<GradientStop> stops;
  bool elliptical = false;
  bool animated = false;
  std::optional<ReducedKeys> keys;  // compact: the values written (GradientTrack::tolerance_px)
};

// The numbers a player interpolates for one value: [s.x, s.y, e.x, e.y, highlight, angle], an
// elliptical gradient's [origin.x, origin.y, rotate1, sx, sy, rotate2] (its groups' transforms).
std::vector<double> placement_numbers(const GradientPlan& plan) {
  std::vector<double> out;
  for (size_t i = 0; i < plan.placements.size(); ++i) {
    const Placement& p = plan.placements[i];
    if (plan.elliptical) {
      const RotateScaleRotate& r = plan.parts[i];
      out.insert(out.end(), {p.ellipse.e, p.ellipse.f, r.rotate1, r.sx, r.sy, r.rotate2});
    } else {
      out.insert(out.end(), {p.s.x, p.s.y, p.e.x, p.e.y, p.highlight, p.angle});
    }
  }
  return out;
}

// Where 6 such numbers put the gradient: its start, end and focal point (elliptical: its
// centre and the ends of two radii), in the gradient's coordinates.
std::array<Vec2, 3> placed_points(const double* v, bool elliptical, const Gradient& g) {
  if (elliptical) {
    const Affine m =
        Affine::translate(v[0], v[1]) * Affine::rotate_deg(v[2]) * Affine::scale(v[3], v[4]) * Affine::rotate_deg(v[5]);
    return {m.apply(g.center), m.apply(g.center + Vec2{g.r, 0}), m.apply(g.center + Vec2{0, g.r})};
  }
  const Vec2 s{v[0], v[1]}, e{v[2], v[3]};
  const double h = v[4] / 100.0 * std::hypot(e.x - s.x, e.y - s.y);
  const double dir = std::atan2(e.y - s.y, e.x - s.x) + v[5] / kDegrees;
  return {s, e, s + Vec2{h * std::cos(dir), h * std::sin(dir)}};
}

// The compact export's keys of a moving gradient (GradientTrack::tolerance_px): none (static,
// its first value) when every value places it within the tolerance of the first.
void reduce_gradient(GradientPlan& plan, const GradientTrack& track) {
  const std::vector<double> numbers = placement_numbers(plan);
  const Gradient& g = *track.values[0];
  const SampleError error = [&](size_t i, double u, const double* approx) {
    // Between values the full export's player interpolates these numbers linearly.
    double blend[6];
    for (size_t k = 0; k < 6; ++k) blend[k] = numbers[6 * i + k] + (u > 0 ? u * (numbers[6 * (i + 1) + k] - numbers[6 * i + k]) : 0);
    const std::array<Vec2, 3> a = placed_points(blend, plan.elliptical, g);
    const std::array<Vec2, 3> b = placed_points(approx, plan.elliptical, g);
    double worst = 0;
    for (size_t k = 0; k < a.size(); ++k) worst = std::max(worst, std::hypot(a[k].x - b[k].x, a[k].y - b[k].y));
    return worst;
  };
  double moved = 0;
  for (size_t i = 1; i < plan.placements.size(); ++i) moved = std::max(moved, error(i, 0, numbers.data()));
  if (moved <= track.tolerance_px) {
    plan.animated = false;
    return;
  }
  plan.keys = reduce_keyframes(track.frames, numbers, 6, track.tolerance_px, error);
}

GradientPlan plan_gradient(const Path& path, const GradientTrack& track, const std::vector<const double*>& points,
                           bool stroke, std::vector<std::string>& approximate) {
  GradientPlan plan;
  const Gradient& rest = *track.values[0];
  for (const Gradient* g : track.values)
    plan.elliptical = plan.elliptical || (g->radial && !is_similarity(g->to_canvas));
  if (plan.elliptical && stroke) {
    approximate.push_back("elliptical radial gradient stroke on #" + path.id + " (drawn circular)");
    plan.elliptical = false;
  }
  if (rest.radial && rest.fr > 0) approximate.push_back("focal radius of the gradient on #" + path.id + " (drawn as 0)");
  // The whole periods a repeating gradient covers over every value's control points (their
  // hull holds the outline; a stroke's half width is added in parameter units).
  int t0 = 0, t1 = 1;
  if (rest.spread != Spread::Pad) {
    if (rest.radial && rest.focal != rest.center)
      approximate.push_back("repeating radial gradient with a focal point on #" + path.id + " (drawn from its centre)");
    double lo = 0, hi = 1;
    for (size_t v = 0; v < points.size(); ++v) {
      const Gradient& g = *track.values[std::min(v, track.values.size() - 1)];
      const Affine to_gradient = g.to_canvas.inverse();
      const double pad = stroke ? 0.5 * path.stroke.width * std::sqrt(std::fabs(to_gradient.det())) : 0.0;
      const double unit = g.radial ? g.r : std::hypot(g.p2.x - g.p1.x, g.p2.y - g.p1.y);
      size_t n = 0;
      for (const Subpath& sp : path.subpaths) n += sp.points.size();
      for (size_t i = 0; i < n; ++i) {
        const double t = parameter_at(g, to_gradient, {points[v][2 * i], points[v][2 * i + 1]});
        lo = std::min(lo, t - pad / unit), hi = std::max(hi, t + pad / unit);
      }
    }
    t0 = std::max(-kMaxPeriods / 2, static_cast<int>(std::floor(lo)));
    t1 = std::min(t0 + kMaxPeriods, static_cast<int>(std::ceil(hi)));
    if (rest.radial) t0 = 0;
    if (t1 <= t0) t1 = t0 + 1;
  }
  plan.stops = densify_translucent(spread_stops(rest, t0, t1));

  for (const Gradient* gp : track.values) {
    const Gradient& g = *gp;
    const Affine& m = g.to_canvas;
    Placement p;
    if (!g.radial) {
      // t(x) = w . (x - S): w = m^-T d / |d|^2 in canvas space, S = m(p1); the end is where
      // t = 1 along w.
      const Vec2 d = g.p2 - g.p1;
      const double dd = d.x * d.x + d.y * d.y;
      const Affine inv = m.inverse();
      const Vec2 w{(inv.a * d.x + inv.b * d.y) / dd, (inv.c * d.x + inv.d * d.y) / dd};
      const double ww = w.x * w.x + w.y * w.y;
      const Vec2 s = m.apply(g.p1), step = (1.0 / ww) * w;
      p.s = s + static_cast<double>(t0) * step;
      p.e = s + static_cast<double>(t1) * step;
    } else if (plan.elliptical) {
      p.ellipse = m;
      p.s = g.center;
      p.e = g.center + Vec2{g.r * t1, 0};
      const Vec2 f = g.focal - g.center;
      p.highlight = std::min(kMaxHighlight, 100.0 * std::hypot(f.x, f.y) / (g.r * t1));
      p.angle = std::hypot(f.x, f.y) > 0 ? std::atan2(f.y, f.x) * kDegrees : 0.0;
    } else {
      const double radius = g.r * m.mean_scale() * t1;
      p.s = m.apply(g.center);
      p.e = p.s + Vec2{radius, 0};
      const Vec2 f = m.apply(g.focal) - p.s;
      p.highlight = std::min(kMaxHighlight, 100.0 * std::hypot(f.x, f.y) / radius);
      p.angle = std::hypot(f.x, f.y) > 1e-12 * radius ? std::atan2(f.y, f.x) * kDegrees : 0.0;
    }
    plan.placements.push_back(p);
  }
  for (const Placement& p : plan.placements) {
    const Placement& q = plan.placements[0];
    plan.animated = plan.animated || p.s != q.s || p.e != q.e || p.highlight != q.highlight ||
                    p.angle != q.angle || !(p.ellipse == q.ellipse);
  }
  if (plan.elliptical) {
    for (const Placement& p : plan.placements) plan.parts.push_back(split_affine(p.ellipse));
    for (size_t i = 1; i < plan.parts.size(); ++i) {  // no turn through +-180 between values
      auto unwrap = [](double a, double prev) { return a + 360.0 * std::round((prev - a) / 360.0); };
      plan.parts[i].rotate1 = unwrap(plan.parts[i].rotate1, plan.parts[i - 1].rotate1);
      plan.parts[i].rotate2 = unwrap(plan.parts[i].rotate2, plan.parts[i - 1].rotate2);
    }
  }
  if (plan.animated && track.tolerance_px > 0) reduce_gradient(plan, track);
  return plan;
}

// The gradient item's body after its "ty": opacity, stops, geometry (and a stroke's width,
// caps and joins are written by the caller after it).
void write_gradient_body(JsonText& j, const Gradient& g, const GradientPlan& plan, const GradientTrack& track) {
  const size_t n = plan.placements.size();
  j.raw(",\"o\":").fixed(g.opacity * 100.0, kOpacityScale).raw(",\"g\":");
  write_stops(j, plan.stops);
  j.raw(",\"t\":").raw(g.radial ? "2" : "1").raw(",\"s\":");
  // An elliptical gradient's geometry is fixed in gradient space; its motion is the groups'.
  const bool moving = plan.animated && !plan.elliptical;
  const ReducedKeys* keys = plan.keys ? &*plan.keys : nullptr;
  write_property(j, track.frames, n, [&](size_t i) { j.pair(plan.placements[i].s.x, plan.placements[i].s.y); }, moving,
                 false, keys);
  j.raw(",\"e\":");
  write_property(j, track.frames, n, [&](size_t i) { j.pair(plan.placements[i].e.x, plan.placements[i].e.y); }, moving,
                 false, keys);
  if (g.radial) {
    j.raw(",\"h\":");
    write_property(j, track.frames, n, [&](size_t i) { j.num(plan.placements[i].highlight, kOpacityScale); }, moving, true,
                   keys);
    j.raw(",\"a\":");
    write_property(j, track.frames, n, [&](size_t i) { j.num(plan.placements[i].angle, kOpacityScale); }, moving, true,
                   keys);
  }
}

// The stroke's dash pattern ("d": dash, gap, ..., offset), when it has one.
void write_dashes(JsonText& j, const Stroke& s) {
  if (s.dashes.empty()) return;
  j.raw(",\"d\":[");
  for (size_t i = 0; i < s.dashes.size(); ++i) {
    j.raw(i ? "," : "").raw(i % 2 ? "{\"n\":\"g\",\"nm\":\"gap\",\"v\":" : "{\"n\":\"d\",\"nm\":\"dash\",\"v\":");
    j.fixed(s.dashes[i], j.coord_scale()).raw("}");
  }
  j.raw(",{\"n\":\"o\",\"nm\":\"offset\",\"v\":").fixed(s.dash_offset, j.coord_scale()).raw("}]");
}

void write_flat_stroke(JsonText& j, const Stroke& s, const Rgba& colour) {
  j.raw("{\"ty\":\"st\",\"c\":");
  write_colour(j, colour);
  j.raw(",\"o\":").fixed(colour.a * 100.0, kOpacityScale).raw(",\"w\":").fixed(s.width, j.coord_scale());
  j.raw(",\"lc\":").num(lottie_cap(s.cap), 1).raw(",\"lj\":").num(lottie_join(s.join), 1);
  j.raw(",\"ml\":").num(s.miter_limit, 1e4);
  write_dashes(j, s);
  j.raw(",\"bm\":0}");
}

void write_stroke(JsonText& j, const Path& path, const GradientTrack& track, const std::vector<const double*>& points,
                  std::vector<std::string>& approximate) {
  const Stroke& s = path.stroke;
  if (track.values.empty() || track.values[0]->stops.size() == 1) {
    Rgba c = s.color;
    if (!track.values.empty()) c = track.values[0]->stops[0].color, c.a *= track.values[0]->opacity;
    write_flat_stroke(j, s, c);
    return;
  }
  const GradientPlan plan = plan_gradient(path, track, points, true, approximate);
  j.raw("{\"ty\":\"gs\"");
  write_gradient_body(j, *track.values[0], plan, track);
  j.raw(",\"w\":").fixed(s.width, j.coord_scale());
  j.raw(",\"lc\":").num(lottie_cap(s.cap), 1).raw(",\"lj\":").num(lottie_join(s.join), 1);
  j.raw(",\"ml\":").num(s.miter_limit, 1e4);
  write_dashes(j, s);
  j.raw(",\"bm\":0}");
}

// A group transform item: position, rotation, scale (and anchor), static or per value.
void write_transform(JsonText& j, const std::vector<double>& frames, size_t n, bool animated, const ReducedKeys* keys,
                     const std::function<Vec2(size_t)>& position, const std::function<double(size_t)>& rotation,
                     const std::function<Vec2(size_t)>& scale, const std::function<Vec2(size_t)>& anchor) {
  // A property that is the same at every value is written static.
  auto varies = [&](const auto& f) {
    for (size_t i = 1; animated && i < n; ++i)
      if (f(i) != f(0)) return true;
    return false;
  };
  j.raw("{\"ty\":\"tr\",\"p\":");
  write_property(j, frames, n, [&](size_t i) { const Vec2 v = position(i); j.pair(v.x, v.y); }, varies(position), false, keys);
  j.raw(",\"a\":");
  write_property(j, frames, n, [&](size_t i) { const Vec2 v = anchor(i); j.pair(v.x, v.y); }, varies(anchor), false, keys);
  j.raw(",\"s\":");
  write_property(j, frames, n, [&](size_t i) {
    const Vec2 v = scale(i);
    j.raw("[").num(100 * v.x, 1e6).raw(",").num(100 * v.y, 1e6).raw("]");
  }, varies(scale), false, keys);
  j.raw(",\"r\":");
  write_property(j, frames, n, [&](size_t i) { j.num(rotation(i), 1e6); }, varies(rotation), true, keys);
  j.raw(",\"o\":{\"a\":0,\"k\":100},\"sk\":{\"a\":0,\"k\":0},\"sa\":{\"a\":0,\"k\":0}}");
}

}  // namespace

RotateScaleRotate split_affine(const Affine& m) {
  // m = [a c; b d]; E, F, G, H as in the closed-form 2x2 SVD.
  const double E = (m.a + m.d) / 2, F = (m.a - m.d) / 2, G = (m.b + m.c) / 2, H = (m.b - m.c) / 2;
  const double Q = std::hypot(E, H), R = std::hypot(F, G);
  const double a1 = std::atan2(G, F), a2 = std::atan2(H, E);
  return {(a2 + a1) / 2 * kDegrees, Q + R, Q - R, (a2 - a1) / 2 * kDegrees};
}

std::vector<Scene> sample_exported_svg(const std::filesystem::path& svg, const Scene& scene,
                                       const std::vector<double>& times) {
  std::vector<Scene> out;
  if (svg.empty()) return out;
  for (const double t : times) {
    SvgReadLimits limits;
    limits.animation_time = t;
    Scene s;
    try {
      s = read_svg_file(svg, limits);
    } catch (const std::exception&) {
      return {};
    }
    if (s.paths.size() != scene.paths.size()) return {};
    for (size_t p = 0; p < s.paths.size(); ++p)
      if (s.paths[p].id != scene.paths[p].id || (s.paths[p].fill_gradient < 0) != (scene.paths[p].fill_gradient < 0) ||
          (s.paths[p].stroke_gradient < 0) != (scene.paths[p].stroke_gradient < 0))
        return {};
    out.push_back(std::move(s));
  }
  return out;
}

GradientTrack gradient_track(const Scene& scene, const std::vector<Scene>& samples, size_t path, bool stroke,
                             const std::vector<int>& sample_of_value, const std::vector<double>& frames) {
  GradientTrack track;
  const int rest = stroke ? scene.paths[path].stroke_gradient : scene.paths[path].fill_gradient;
  if (rest < 0) return track;
  if (samples.empty() || sample_of_value.size() < 2) {
    track.values.push_back(&scene.gradients[static_cast<size_t>(rest)]);
    track.frames.push_back(0);
    return track;
  }
  for (size_t i = 0; i < sample_of_value.size(); ++i) {
    const Scene& s = samples[static_cast<size_t>(sample_of_value[i])];
    const int g = stroke ? s.paths[path].stroke_gradient : s.paths[path].fill_gradient;
    track.values.push_back(&s.gradients[static_cast<size_t>(g)]);
    track.frames.push_back(frames[i]);
  }
  return track;
}

void write_paint_items(JsonText& j, size_t shapes_begin, const Path& path, const PaintInputs& in,
                       std::vector<std::string>& approximate) {
  const bool fill_gradient = path.has_fill && !in.fill.values.empty() && in.fill.values[0]->stops.size() > 1;
  std::optional<GradientPlan> fill_plan;
  if (fill_gradient) fill_plan = plan_gradient(path, in.fill, in.points, false, approximate);
  const bool first_item = j.text().size() == shapes_begin;
  if (!fill_plan || !fill_plan->elliptical) {
    // Shapes, stroke, fill in one group (the caller closes it).
    if (path.has_stroke) {
      j.raw(first_item ? "" : ",");
      write_stroke(j, path, in.stroke, in.points, approximate);
    }
    if (path.has_fill) {
      j.raw(first_item && !path.has_stroke ? "" : ",");
      if (fill_plan) {
        j.raw("{\"ty\":\"gf\"");
        write_gradient_body(j, *in.fill.values[0], *fill_plan, in.fill);
        j.raw(",\"r\":").raw(path.fill_rule == FillRule::EvenOdd ? "2" : "1").raw(",\"bm\":0}");
      } else {
        Rgba c = path.fill;
        if (!in.fill.values.empty()) c = in.fill.values[0]->stops[0].color, c.a *= in.fill.values[0]->opacity;
        j.raw("{\"ty\":\"fl\",\"c\":");
        write_colour(j, c);
        j.raw(",\"o\":").fixed(c.a * 100.0, kOpacityScale);
        j.raw(",\"r\":").raw(path.fill_rule == FillRule::EvenOdd ? "2" : "1").raw(",\"bm\":0}");
      }
    }
    return;
  }
  // An elliptical radial fill: [stroke group,] fill group A(p, rotate1, scale) > A2(rotate2) >
  // [X(rotate -rotate2, 1/scale) > Y(rotate -rotate1, anchor p) > shapes, gf]: the shapes are
  // mapped by the inverse of the gradient's map and back, the fill's geometry is the gradient's
  // own.
  const std::string shapes = j.text().substr(shapes_begin);
  j.text().resize(shapes_begin);
  const size_t n = fill_plan->placements.size();
  const std::vector<RotateScaleRotate>& parts = fill_plan->parts;
  const bool animated = fill_plan->animated;
  const ReducedKeys* keys = fill_plan->keys ? &*fill_plan->keys : nullptr;
  const auto& frames = in.fill.frames;
  auto origin = [&](size_t i) { const Affine& m = fill_plan->placements[i].ellipse; return Vec2{m.e, m.f}; };
  auto zero = [](size_t) { return Vec2{}; };
  auto unit = [](size_t) { return Vec2{1, 1}; };
  if (path.has_stroke) {
    j.raw("{\"ty\":\"gr\",\"it\":[").raw(shapes).raw(",");
    write_stroke(j, path, in.stroke, in.points, approximate);
    j.raw(",").raw(kGroupTransform).raw("]},");
  }
  j.raw("{\"ty\":\"gr\",\"it\":[{\"ty\":\"gr\",\"it\":[{\"ty\":\"gr\",\"it\":[{\"ty\":\"gr\",\"it\":[").raw(shapes).raw(",");
  write_transform(j, frames, n, animated, keys, zero, [&](size_t i) { return -parts[i].rotate1; }, unit, origin);  // Y
  j.raw("]},");
  write_transform(j, frames, n, animated, keys, zero, [&](size_t i) { return -parts[i].rotate2; },
                  [&](size_t i) { return Vec2{1 / parts[i].sx, 1 / parts[i].sy}; }, zero);  // X
  j.raw("]},{\"ty\":\"gf\"");
  write_gradient_body(j, *in.fill.values[0], *fill_plan, in.fill);
  j.raw(",\"r\":").raw(path.fill_rule == FillRule::EvenOdd ? "2" : "1").raw(",\"bm\":0},");
  write_transform(j, frames, n, animated, keys, zero, [&](size_t i) { return parts[i].rotate2; }, unit, zero);  // A2
  j.raw("]},");
  write_transform(j, frames, n, animated, keys, origin, [&](size_t i) { return parts[i].rotate1; },
                  [&](size_t i) { return Vec2{parts[i].sx, parts[i].sy}; }, zero);  // A
  j.raw("]}");
}

}  // namespace svgm::lottie
