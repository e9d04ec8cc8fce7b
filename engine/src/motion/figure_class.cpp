// The figure's class from its shape, its names and the prompt's words (figure_class.h).
#include "motion/figure_class.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace svgm::motion {

namespace {

constexpr double kSpineSpread = 0.35;  // a snake's width varies by a third of its mean at most
constexpr double kThinLeg = 0.3;       // a bird's leg: under a third of its body's inscribed radius
constexpr double kStem = 0.5;          // a plant's stem: under half the thickness it holds up

struct Score {
  FigureClass cls = FigureClass::Object;
  double score = 0;
  std::string why;
};

std::string fmt(const char* f, double a = 0, double b = 0) {
  char buf[160];
  std::snprintf(buf, sizeof buf, f, a, b);
  return buf;
}

// The longest end-to-end path of the figure's skeleton (its length, and the mean and spread of
// the inscribed radius along it), and the skeleton's whole length, in the figure's component.
struct Spine {
  double length = 0, mean_radius = 0, radius_spread = 0, total = 0;  // spread: std dev / mean
};

Spine spine(const Skeleton& s, const Figure& f) {
  Spine out;
  for (const auto& e : s.edges)
    if (s.nodes[e.a].component == f.component) out.total += e.length;
  std::vector<int> best_path;  // edges
  for (size_t from = 0; from < s.nodes.size(); ++from) {
    if (s.nodes[from].component != f.component || s.nodes[from].degree() > 1) continue;
    const SkeletonPaths p = shortest_paths(s, static_cast<int>(from));
    for (size_t u = 0; u < s.nodes.size(); ++u)
      if (p.dist[u] < std::numeric_limits<double>::infinity() && p.dist[u] > out.length) {
        out.length = p.dist[u];
        best_path = p.edges_to(s, static_cast<int>(u));
      }
  }
  if (best_path.empty())  // a loop or a dot: its longest branch
    for (size_t e = 0; e < s.edges.size(); ++e)
      if (s.nodes[s.edges[e].a].component == f.component &&
          (best_path.empty() || s.edges[e].length > s.edges[best_path[0]].length))
        best_path = {static_cast<int>(e)}, out.length = s.edges[e].length;
  double sum = 0, sum2 = 0, n = 0;
  for (int e : best_path)
    for (double r : s.edges[e].radius) sum += r, sum2 += r * r, ++n;
  if (n > 0) {
    out.mean_radius = sum / n;
    out.radius_spread = out.mean_radius > 0 ? std::sqrt(std::max(0.0, sum2 / n - out.mean_radius * out.mean_radius)) / out.mean_radius : 0;
  }
  return out;
}

// Width of the figure's lowest tenth over its widest row: a stem or a trunk is narrow.
double base_share(const Skeleton& s, const Figure& f) {
  double widest = 0, base = 0;
  const int band = std::max(1, static_cast<int>(0.1 * (f.y1 - f.y0)));
  for (int y = static_cast<int>(f.y0); y <= static_cast<int>(f.y1); ++y) {
    int lo = s.width, hi = -1;
    for (int x = 0; x < s.width; ++x)
      if (s.labels.at<int>(y, x) == f.component) lo = std::min(lo, x), hi = std::max(hi, x);
    const double w = hi >= lo ? hi - lo + 1 : 0;
    widest = std::max(widest, w);
    if (y > f.y1 - band) base = std::max(base, w);
  }
  return widest > 0 ? base / widest : 1;
}

void consider(Score& best, FigureClass c, double score, std::string why) {
  if (score > best.score) best = {c, score, std::move(why)};
}

}  // namespace

const char* figure_class_name(FigureClass c) {
  switch (c) {
    case FigureClass::Biped: return "biped";
    case FigureClass::Quadruped: return "quadruped";
    case FigureClass::Bird: return "bird";
    case FigureClass::FishOrSnake: return "fish_or_snake";
    case FigureClass::Plant: return "plant";
    case FigureClass::Wheeled: return "wheeled";
    case FigureClass::Object: return "object";
    case FigureClass::Scene: return "scene";
  }
  return "object";
}

std::optional<FigureClass> figure_class_from_name(const std::string& name) {
  for (int c = 0; c <= static_cast<int>(FigureClass::Scene); ++c)
    if (name == figure_class_name(static_cast<FigureClass>(c))) return static_cast<FigureClass>(c);
  return std::nullopt;
}

FigureVerdict classify_shape(const cv::Mat& mask, const Skeleton& s, const Figure& f) {
  Score best{FigureClass::Object, 0.3, "a compact shape"};
  FigureVerdict v;
  if (f.component < 0) {
    v.shape_cls = v.cls = FigureClass::Object;
    v.shape_confidence = v.confidence = 0;
    v.shape_reason = v.reason = "an empty mask";
    return v;
  }
  const double fw = f.x1 - f.x0 + 1, fh = f.y1 - f.y0 + 1;
  // Scene: the canvas is full, or the drawing is many large separate parts.
  const double cover = static_cast<double>(cv::countNonZero(mask)) / (mask.rows * mask.cols);
  int total = 0, large = 0;
  for (int a : s.component_area) total += a;
  for (int a : s.component_area) large += a >= 0.05 * total;
  if (cover >= 0.85) consider(best, FigureClass::Scene, 0.8, fmt("the drawing fills %.0f%% of the canvas", 100 * cover));
  if (large >= 4) consider(best, FigureClass::Scene, 0.55, fmt("%.0f large separate parts", large));

  // Wheeled: circles in the lower half of the figure standing on its ground line (the
  // drawing's lowest row), not the figure itself.
  int wheels = 0;
  double rmin = 1e300, rmax = 0, bottom = 0;
  for (int y = 0; y < mask.rows; ++y)
    if (cv::countNonZero(mask.row(y))) bottom = y;
  for (const auto& c : find_circles(mask)) {
    if (c.centre.y < f.y0 + 0.5 * fh || c.radius > 0.4 * std::max(fw, fh) || c.radius < 0.05 * std::max(fw, fh) ||
        c.centre.y + c.radius < bottom - std::max(3.0, 0.06 * fh))
      continue;
    ++wheels;
    rmin = std::min(rmin, c.radius), rmax = std::max(rmax, c.radius);
  }
  if (wheels >= 2 && rmax <= 2.5 * rmin)
    consider(best, FigureClass::Wheeled, 0.8, fmt("%.0f round wheels in the lower half", wheels));

  // Limb counts.
  int legs = 0, arms = 0, head = 0, tails = 0, up = 0, stems = 0;
  const Limb* wing[2] = {nullptr, nullptr};  // the longest free limb reaching out on each side
  for (const auto& L : f.limbs) {
    legs += L.kind == LimbKind::Leg;
    arms += L.kind == LimbKind::Arm;
    head += L.kind == LimbKind::Head;
    tails += L.kind == LimbKind::Tail;
    up += L.direction.y < -0.3;
    stems += L.grounded;
    if (L.side != 0 && !L.grounded && L.relative_length >= 0.2 && L.direction.y < 0.5) {
      const Limb*& w = wing[L.side > 0];
      if (!w || L.length > w->length) w = &L;
    }
  }
  // A bird's legs are thin under its body, a person's about as thick as the torso; a plant's
  // stem is one thin central leg on the ground.
  bool thin_legs = legs > 0, stem_central = false;
  for (const auto& L : f.limbs) {
    if (L.kind != LimbKind::Leg) continue;
    double r = 0;
    for (size_t i = L.base_index; i < L.radius.size(); ++i) r += L.radius[i];
    r /= std::max<size_t>(1, L.radius.size() - L.base_index);
    thin_legs = thin_legs && r <= kThinLeg * f.core_radius;
    stem_central = L.grounded && L.side == 0 && r <= kStem * f.core_radius;
  }
  // Wings: about as long as each other, mirrored (rising or falling alike), from one place.
  const bool wings = wing[0] && wing[1] &&
                     std::max(wing[0]->length, wing[1]->length) <= 1.6 * std::min(wing[0]->length, wing[1]->length) &&
                     std::fabs(wing[0]->direction.y - wing[1]->direction.y) <= 0.4 &&
                     wing[0]->direction.x * wing[1]->direction.x < 0 &&
                     std::hypot(s.nodes[wing[0]->joint].pos.x - s.nodes[wing[1]->joint].pos.x,
                                s.nodes[wing[0]->joint].pos.y - s.nodes[wing[1]->joint].pos.y) <= 0.3 * fw;
  // Fish or snake: one long branch carries the skeleton.
  const Spine sp = spine(s, f);
  const double carried = sp.total > 0 ? sp.length / sp.total : 0;
  const double elongation = sp.mean_radius > 0 ? sp.length / (2 * sp.mean_radius) : 0;
  // (a swan's neck on its body, a beaver's tail on its body: one branch too, but not of one width)
  if (carried >= 0.75 && elongation >= 4 && sp.radius_spread <= kSpineSpread && legs < 2 && !wings)
    consider(best, FigureClass::FishOrSnake, std::min(0.75, 0.45 + 0.03 * elongation),
             fmt("one branch %.1f times its width carries %.0f%% of the skeleton", elongation, 100 * carried));
  if (f.upright && legs >= 1 && legs <= 2 && (arms >= 1 || head))
    consider(best, FigureClass::Biped, legs == 2 ? 0.7 : 0.5,
             fmt("an upright body, %.0f legs down, %.0f arms", legs, arms) + (head ? ", a head up" : ""));
  if (legs >= 3)
    consider(best, FigureClass::Quadruped, f.upright ? 0.45 : legs == 4 ? 0.8 : 0.7,
             fmt("%.0f legs below a ", legs) + (f.upright ? "standing body" : "lying body") + (head ? ", a head at an end" : ""));
  if (wings) consider(best, FigureClass::Bird, 0.65, "two long mirrored side branches: wings");
  if (!f.upright && legs == 2 && (head || tails))
    consider(best, FigureClass::Bird, 0.5, "a lying body on two legs");
  if ((legs == 1 || legs == 2) && thin_legs)
    consider(best, FigureClass::Bird, 0.72, fmt("a body on %.0f legs under a third of its thickness", legs));
  if (stems == 1 && legs == 1 && stem_central && up >= 1)
    consider(best, FigureClass::Plant, 0.7, fmt("%.0f branches rising above one central stem", up));
  if (up >= 3 && legs <= 1)
    consider(best, FigureClass::Plant, stems == 1 ? 0.7 : 0.6,
             fmt("%.0f branches rising", up) + (stems == 1 ? " above one stem" : ""));
  const double base = base_share(s, f);
  if (base <= 0.25 && fh >= 0.8 * fw && legs <= 1)
    consider(best, FigureClass::Plant, 0.45, fmt("a narrow base (%.0f%% of the widest row) under a wide top", 100 * base));
  if (best.cls == FigureClass::Object)
    best.why = fmt("a compact shape with %.0f limbs", static_cast<double>(f.limbs.size()));
  v.shape_cls = v.cls = best.cls;
  v.shape_confidence = v.confidence = best.score;
  v.shape_reason = best.why + ": " + figure_class_name(best.cls);
  v.reason = v.shape_reason;
  return v;
}

FigureVerdict classify_figure(const cv::Mat& mask, const Skeleton& s, const Figure& f,
                              const std::optional<ClassHint>& words, const std::vector<std::string>& names) {
  FigureVerdict v = classify_shape(mask, s, f);
  auto take = [&](const ClassHint& h, const std::string& source) {
    const bool agree = h.cls == v.shape_cls;
    v.cls = h.cls;
    v.confidence = std::min(1.0, h.confidence + (agree ? 0.15 : 0.0));
    v.reason = source + " " + figure_class_name(h.cls) + (agree ? "; the shape agrees (" : "; the shape says (") +
               v.shape_reason + ")";
  };
  if (words && words->confidence > 0) {
    take(*words, "the words say");
    return v;
  }
  if (const auto named = class_from_names(names)) take(*named, "the names say");
  return v;
}

FigureVerdict classify_mask(const cv::Mat& mask, const std::optional<ClassHint>& words,
                            const std::vector<std::string>& names) {
  const Skeleton s = skeletonise(mask);
  return classify_figure(mask, s, find_limbs(s), words, names);
}

}  // namespace svgm::motion
