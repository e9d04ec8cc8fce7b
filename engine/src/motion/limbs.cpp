// Body core, limbs and their labels from a silhouette skeleton (limbs.h says the rules).
#include "motion/limbs.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace svgm::motion {

namespace {

constexpr double kCoreGrow = 0.5;     // an internal branch joins the core at half its thickness
constexpr double kBendShare = 0.1;    // a bend a tenth of the chord off it is a real elbow
constexpr double kGroundShare = 0.05; // ground tolerance: a twentieth of the figure's height
constexpr double kTailThick = 1.6;    // a tail's branch this much thicker than the tail is the body

double len(Vec2 v) { return std::hypot(v.x, v.y); }
double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
Vec2 unit(Vec2 v) {
  const double l = len(v);
  return l > 0 ? (1.0 / l) * v : Vec2{};
}

int component_of(const Skeleton& s, const SkeletonEdge& e) { return s.nodes[e.a].component; }

// The component's terminal branch that holds the body, if one does (a trunk): thicker on average
// than `thick` (1 / kCoreGrow times the internal branch the core would start from, kTailThick
// times the junction a star's core would be) and with more body (mean radius squared times
// length) than `body`. A whale whose tail fluke forks off a thin stalk: its skeleton is a star,
// one junction at the fork with three branches (the fluke's two lobes, and the body through the
// stalk to the head); the junction was the core and the body hung from it as a leg, so a tail
// beat swung the whole whale about its tail. -1 when none.
int body_branch(const Skeleton& s, const Figure& f, double thick, double body) {
  int best = -1;
  for (size_t i = 0; i < s.edges.size(); ++i) {
    const SkeletonEdge& E = s.edges[i];
    if (component_of(s, E) != f.component || !E.terminal || E.mean_radius < thick) continue;
    const double b = E.mean_radius * E.mean_radius * E.length;
    if (b > body && (best < 0 || b > s.edges[best].mean_radius * s.edges[best].mean_radius * s.edges[best].length))
      best = static_cast<int>(i);
  }
  return best;
}

void pick_core(const Skeleton& s, Figure& f) {
  std::vector<int> internal;
  for (size_t i = 0; i < s.edges.size(); ++i)
    if (component_of(s, s.edges[i]) == f.component && !s.edges[i].terminal) internal.push_back(static_cast<int>(i));
  std::vector<char> in_core(s.nodes.size(), 0);
  auto add_node = [&](int n) {
    if (!in_core[n]) f.core_nodes.push_back(n);
    in_core[n] = 1;
  };
  auto body = [&](int e) { return s.edges[e].mean_radius * s.edges[e].mean_radius * s.edges[e].length; };
  int seed = -1;
  for (int e : internal)
    if (seed < 0 || body(e) > body(seed)) seed = e;
  int star = -1;  // without internal branches: the thickest junction
  for (size_t n = 0; n < s.nodes.size() && seed < 0; ++n)
    if (s.nodes[n].component == f.component && s.nodes[n].junction() && (star < 0 || s.nodes[n].radius > s.nodes[star].radius))
      star = static_cast<int>(n);
  if (seed >= 0 || star >= 0) {
    // A terminal branch far thicker than that holds the body: the core starts from it.
    const int trunk = seed >= 0 ? body_branch(s, f, s.edges[seed].mean_radius / kCoreGrow, body(seed))
                                : body_branch(s, f, kTailThick * s.nodes[star].radius, 0);
    if (trunk >= 0) seed = trunk;
  }
  if (seed >= 0) {
    std::vector<char> taken(s.edges.size(), 0);
    f.core_edges.push_back(seed);
    taken[seed] = 1;
    add_node(s.edges[seed].a);
    add_node(s.edges[seed].b);
    for (bool grew = true; grew;) {
      grew = false;
      for (int e : internal) {
        const auto& E = s.edges[e];
        if (taken[e] || !(in_core[E.a] || in_core[E.b]) || E.mean_radius < kCoreGrow * s.edges[seed].mean_radius)
          continue;
        taken[e] = grew = true;
        f.core_edges.push_back(e);
        add_node(E.a);
        add_node(E.b);
      }
    }
    return;
  }
  if (star >= 0) return add_node(star);
  for (size_t e = 0; e < s.edges.size(); ++e)  // one branch (or a loop): the longest is the core
    if (component_of(s, s.edges[e]) == f.component &&
        (f.single_branch < 0 || s.edges[e].length > s.edges[f.single_branch].length))
      f.single_branch = static_cast<int>(e);
  if (f.single_branch >= 0) {
    f.core_edges.push_back(f.single_branch);
    add_node(s.edges[f.single_branch].a);
    add_node(s.edges[f.single_branch].b);
    return;
  }
  for (size_t n = 0; n < s.nodes.size(); ++n)
    if (s.nodes[n].component == f.component) return add_node(static_cast<int>(n));
}

void core_geometry(const Skeleton& s, Figure& f) {
  std::vector<Vec2> pts;
  for (int e : f.core_edges) pts.insert(pts.end(), s.edges[e].points.begin(), s.edges[e].points.end());
  for (int n : f.core_nodes) {
    pts.push_back(s.nodes[n].pos);
    f.core_radius = std::max(f.core_radius, s.nodes[n].radius);
  }
  for (int e : f.core_edges) f.core_radius = std::max(f.core_radius, s.edges[e].max_radius);
  if (pts.empty()) return;
  Vec2 c;
  for (const auto& p : pts) c = c + p;
  c = (1.0 / static_cast<double>(pts.size())) * c;
  double sxx = 0, sxy = 0, syy = 0;
  for (const auto& p : pts) {
    const Vec2 d = p - c;
    sxx += d.x * d.x, sxy += d.x * d.y, syy += d.y * d.y;
  }
  const double angle = 0.5 * std::atan2(2 * sxy, sxx - syy);  // principal direction
  Vec2 axis{std::cos(angle), std::sin(angle)};
  double lo = 0, hi = 0;
  for (const auto& p : pts) lo = std::min(lo, dot(p - c, axis)), hi = std::max(hi, dot(p - c, axis));
  f.core_centre = c;
  f.core_length = hi - lo;
  if (f.core_length > 2 * f.core_radius)
    f.upright = std::fabs(axis.y) >= std::cos(M_PI / 4);
  else
    f.upright = f.y1 - f.y0 >= f.x1 - f.x0;
  if (f.upright ? axis.y < 0 : axis.x < 0) axis = -1.0 * axis;
  f.core_axis = axis;
}

// The path (edge indices) from `from` to `to` inside a sub-tree's edges, shortest by length.
std::vector<int> path_edges(const Skeleton& s, const std::vector<int>& edges, int from, int to) {
  return shortest_paths(s, from, &edges).edges_to(s, to);
}

double path_length(const Skeleton& s, const std::vector<int>& edges) {
  double l = 0;
  for (int e : edges) l += s.edges[e].length;
  return l;
}

void limb_geometry(const Skeleton& s, const Figure& f, Limb& L, const std::vector<int>& path) {
  int at = L.joint;
  for (int e : path) {
    const auto& E = s.edges[e];
    const bool forward = E.a == at;
    for (size_t k = 0; k < E.points.size(); ++k) {
      const size_t i = forward ? k : E.points.size() - 1 - k;
      if (k == 0 && !L.path.empty()) continue;
      L.path.push_back(E.points[i]);
      L.radius.push_back(E.radius[i]);
    }
    at = forward ? E.b : E.a;
  }
  const SkeletonNode& joint = s.nodes[L.joint];
  L.base_index = L.path.size() / 2;
  for (size_t i = 0; i < L.path.size(); ++i)
    if (len(L.path[i] - joint.pos) >= joint.radius) {
      L.base_index = std::min(i, L.path.size() - 1);
      break;
    }
  L.base = L.path[L.base_index];
  L.tip_pos = L.path.back();
  L.tip_radius = s.nodes[L.tip].radius;
  for (size_t i = L.base_index + 1; i < L.path.size(); ++i) L.length += len(L.path[i] - L.path[i - 1]);
  L.relative_length = L.length / std::max(1.0, std::max(f.x1 - f.x0, f.y1 - f.y0));
  L.direction = unit(L.tip_pos - (L.length > 0 ? L.base : joint.pos));
  const Vec2 chord = L.tip_pos - L.base;
  const double chord_len = len(chord);
  double far = 0;
  L.bend = 0.5 * (L.base + L.tip_pos);
  for (size_t i = L.base_index; i < L.path.size() && chord_len > 0; ++i) {
    const Vec2 d = L.path[i] - L.base;
    const double off = std::fabs(d.x * chord.y - d.y * chord.x) / chord_len;
    if (off > far) far = off, L.bend = L.path[i];
  }
  L.bent = far >= kBendShare * chord_len && chord_len > 0;
}

// A limb hanging from a trunk's neck (find_limbs) starts down the trunk, where it is last as thin
// as kCoreGrow of the trunk's thickest: that thin stretch (a whale's tail stalk) is the limb's,
// its base at the stalk's root, and the neck's disc is no longer the body's (limb_regions tells a
// stalk by its points: on the core's edges, none of the limb's own).
void with_stalk(const SkeletonEdge& T, int neck, Limb& L) {
  std::vector<Vec2> pts;
  std::vector<double> rad;
  const bool from_a = T.a == neck;
  for (size_t k = 1; k < T.points.size(); ++k) {  // from the neck inward, the neck's own point left out
    const size_t i = from_a ? k : T.points.size() - 1 - k;
    if (T.radius[i] >= kCoreGrow * T.max_radius) break;
    pts.push_back(T.points[i]);
    rad.push_back(T.radius[i]);
  }
  std::reverse(pts.begin(), pts.end());
  std::reverse(rad.begin(), rad.end());
  L.path.insert(L.path.begin(), pts.begin(), pts.end());
  L.radius.insert(L.radius.begin(), rad.begin(), rad.end());
  L.base_index = 0;
  L.base = L.path[0];
  L.length = 0;
  for (size_t i = 1; i < L.path.size(); ++i) L.length += len(L.path[i] - L.path[i - 1]);
  if (L.length > 0) L.direction = unit(L.tip_pos - L.base);
}

// A core shorter than it is thick is a point: a star of limbs (a plus sign, a bird's wings and
// head round one junction) has no axis to place them along.
bool point_core(const Figure& f) { return f.core_length < std::max(2.0, f.core_radius); }

// Where a limb's joint lies along the core axis: 0 at the top (upright) or left end, 1 at the
// other; a point core places limbs by direction (down-pointing limbs in the lower half).
// Where `p` lies along the core axis, 0 at the core's first end and 1 at its other (not clamped).
double axis_t(const Skeleton& s, const Figure& f, Vec2 p) {
  double lo = 1e300, hi = -1e300;
  for (int e : f.core_edges)
    for (const auto& q : s.edges[e].points) lo = std::min(lo, dot(q, f.core_axis)), hi = std::max(hi, dot(q, f.core_axis));
  for (int n : f.core_nodes) lo = std::min(lo, dot(s.nodes[n].pos, f.core_axis)), hi = std::max(hi, dot(s.nodes[n].pos, f.core_axis));
  return (dot(p, f.core_axis) - lo) / std::max(1e-9, hi - lo);
}

double joint_t(const Skeleton& s, const Figure& f, const Limb& L) {
  if (point_core(f)) return L.direction.y > 0.3 ? 1.0 : 0.0;
  return std::clamp(axis_t(s, f, s.nodes[L.joint].pos), 0.0, 1.0);
}

void label(const Skeleton& s, Figure& f) {
  const double tol = std::max(3.0, kGroundShare * (f.y1 - f.y0));
  f.ground_y = f.y1;
  double lowest = -1e300;
  for (const auto& L : f.limbs) lowest = std::max(lowest, L.tip_pos.y + L.tip_radius);
  if (!f.limbs.empty()) f.ground_y = lowest;
  for (auto& L : f.limbs) {
    L.grounded = lowest >= f.y1 - tol && L.tip_pos.y + L.tip_radius >= lowest - tol && L.direction.y > 0.2;
    const double dx = L.tip_pos.x - f.core_centre.x, w = std::max(4.0, 0.1 * (f.x1 - f.x0));
    L.side = dx < -w ? -1 : dx > w ? 1 : 0;
  }
  std::vector<double> t;
  for (const auto& L : f.limbs) t.push_back(joint_t(s, f, L));
  auto set = [](Limb& L, LimbKind k, const char* why) { L.kind = k, L.why = why; };
  if (f.upright || point_core(f)) {
    int head = -1;
    for (size_t i = 0; i < f.limbs.size(); ++i) {
      Limb& L = f.limbs[i];
      if (L.grounded) set(L, LimbKind::Leg, "its tip is on the ground line");
      else if (t[i] >= 0.5 && L.direction.y > 0.3) set(L, LimbKind::Leg, "down from the lower body");
      else if (t[i] >= 0.5 && L.direction.y > -0.5) set(L, LimbKind::Tail, "sideways from the lower body");
      else {
        set(L, LimbKind::Arm, "from the upper body");
        const double off = std::fabs(L.tip_pos.x - f.core_centre.x);
        if (L.direction.y < -0.6 && (head < 0 || off < std::fabs(f.limbs[head].tip_pos.x - f.core_centre.x))) head = static_cast<int>(i);
      }
    }
    if (head >= 0) set(f.limbs[head], LimbKind::Head, "the most central limb up from the upper body");
    return;
  }
  int end[2] = {-1, -1};  // the longest limb out of each end of the core: head or tail
  const bool stands = std::any_of(f.limbs.begin(), f.limbs.end(), [](const Limb& L) { return L.grounded; });
  for (size_t i = 0; i < f.limbs.size(); ++i) {
    Limb& L = f.limbs[i];
    const double along = dot(L.direction, f.core_axis);
    // A limb hanging down off the ground from an end of a body that stands on legs, from the
    // body's upper half or out beyond its end, is a tail (a cow's, a tiger's), not a leg.
    const double tip_t = axis_t(s, f, L.tip_pos), beyond = std::max(-tip_t, tip_t - 1) * f.core_length;
    const bool hangs = stands && !L.grounded && (t[i] <= 0.25 || t[i] >= 0.75) &&
                       (L.base.y < f.core_centre.y || beyond > f.core_radius);
    if (hangs) {
      set(L, LimbKind::Other, "hangs from the top of an end of the body, off the ground");
      int& e = end[t[i] >= 0.5];
      if (e < 0 || L.length > f.limbs[e].length) e = static_cast<int>(i);
    } else if (L.grounded || L.direction.y > 0.5) set(L, LimbKind::Leg, L.grounded ? "its tip is on the ground line" : "down from the body");
    else if ((t[i] <= 0.25 && along < -0.3) || (t[i] >= 0.75 && along > 0.3)) {
      set(L, LimbKind::Other, "out of an end of the body");
      int& e = end[along > 0];
      if (e < 0 || L.length > f.limbs[e].length) e = static_cast<int>(i);
    } else if (L.direction.y < -0.3) set(L, LimbKind::Arm, "rising from the body");
    else set(L, LimbKind::Other, "beside the body");
  }
  if (end[0] >= 0 && end[1] >= 0) {
    const Limb &a = f.limbs[end[0]], &b = f.limbs[end[1]];
    const bool a_head = a.tip_radius > 1.2 * b.tip_radius || (b.tip_radius <= 1.2 * a.tip_radius && a.tip_pos.y < b.tip_pos.y);
    set(f.limbs[end[a_head ? 0 : 1]], LimbKind::Head, "the end limb with the larger or higher tip");
    set(f.limbs[end[a_head ? 1 : 0]], LimbKind::Tail, "the other end limb");
  } else if (end[0] >= 0 || end[1] >= 0) {
    Limb& L = f.limbs[std::max(end[0], end[1])];
    const bool head = L.tip_radius >= 0.4 * f.core_radius;
    set(L, head ? LimbKind::Head : LimbKind::Tail, head ? "the one end limb, a big tip" : "the one end limb, thin");
  }
}

// The forks of each limb off the ground whose end stands on the ground line (as label() finds
// feet): their own stretch (off the path to the limb's tip) is left to the body.
void standing_forks(const Skeleton& s, Figure& f) {
  const double tol = std::max(3.0, kGroundShare * (f.y1 - f.y0));
  // No limb's tip reaches the figure's bottom: there is no ground line to stand on (label's
  // rule; the lowest tip of a fluke held up over a whale's body is no floor for its other lobe).
  if (f.ground_y < f.y1 - tol) return;
  for (Limb& L : f.limbs) {
    if (L.grounded || L.more_tips.empty()) continue;
    const std::vector<int> main = path_edges(s, L.edges, L.joint, L.tip);
    for (int t : L.more_tips) {
      const SkeletonNode& n = s.nodes[t];
      if (n.pos.y + n.radius < f.ground_y - tol) continue;
      for (int e : path_edges(s, L.edges, L.joint, t))
        if (std::find(main.begin(), main.end(), e) == main.end() &&
            std::find(L.standing_edges.begin(), L.standing_edges.end(), e) == L.standing_edges.end())
          L.standing_edges.push_back(e);
    }
  }
}

// A tail's branch starts where the skeleton leaves the core, often deep in a thick rump (a
// tiger's hind quarters, which its hind leg hangs from): swung from there, the tail carried the
// rump and the leg. The tail is what is thin: its own thickness is the median inscribed radius
// of its outer half, and its base moves out to where the branch first gets that thin (within
// kTailThick of it); the thicker stretch before it is the body's (limb_regions).
void thin_tail_bases(Figure& f) {
  for (Limb& L : f.limbs) {
    const size_t n = L.path.size();
    if (L.kind != LimbKind::Tail || n < 4 || L.base_index + 2 >= n) continue;
    std::vector<double> outer(L.radius.begin() + static_cast<long>(L.base_index + (n - L.base_index) / 2), L.radius.end());
    std::nth_element(outer.begin(), outer.begin() + static_cast<long>(outer.size() / 2), outer.end());
    const double own = std::max(outer[outer.size() / 2], 0.5);
    size_t i = L.base_index;
    while (i + 1 < n && L.radius[i] > kTailThick * own) ++i;
    if (i == L.base_index) continue;
    L.body_radius = kTailThick * own;
    L.base_index = i;
    L.base = L.path[i];
    L.length = 0;
    for (size_t k = i + 1; k < n; ++k) L.length += len(L.path[k] - L.path[k - 1]);
    if (L.length > 0) L.direction = unit(L.tip_pos - L.base);
  }
}

// A tail whose branch runs through a foot on its way out (limbs.h): the hind foot touched by a
// tail drawn down the rump has no branch of its own (the pruning took its short spur), so the
// pixels of the ground line under it fall to the tail's branch, and the tail swung the foot.
// The stretch up to the last branch point that owns ground-line pixels (by the regions' rule,
// nearest disc edge) is the body's; the tail starts where the branch is thin again beyond it.
// Only for a figure standing on legs, a tail whose tip is off the ground, and when the rest is
// at least kTailRest of the tail (a tail lying along the ground is all on the ground line).
constexpr double kTailRest = 0.25;

void tails_through_feet(const Skeleton& s, Figure& f) {
  if (std::none_of(f.limbs.begin(), f.limbs.end(), [](const Limb& L) { return L.grounded; })) return;
  const double tol = std::max(3.0, kGroundShare * (f.y1 - f.y0));
  std::vector<Vec2> ground;
  for (int y = std::max(0, static_cast<int>(std::floor(f.ground_y - tol))); y < s.height; ++y)
    for (int x = 0; x < s.width; ++x)
      if (s.labels.at<int>(y, x) == f.component) ground.push_back({double(x), double(y)});
  for (Limb& L : f.limbs) {
    const size_t n = L.path.size();
    if (L.kind != LimbKind::Tail || L.grounded || n < 4 || L.tip_pos.y + L.tip_radius >= f.ground_y - tol) continue;
    size_t last = 0;
    bool through = false;
    for (const Vec2& p : ground) {
      double other = std::numeric_limits<double>::infinity(), own = other;
      size_t at = 0;
      for (const auto& E : s.edges)
        if (component_of(s, E) == f.component)
          for (size_t i = 0; i < E.points.size(); ++i) other = std::min(other, len(p - E.points[i]) - E.radius[i]);
      for (size_t i = L.base_index; i < n; ++i)
        if (const double d = len(p - L.path[i]) - L.radius[i]; d < own) own = d, at = i;
      if (own <= other) last = std::max(last, at), through = true;
    }
    if (!through) continue;
    double rest = 0;
    for (size_t k = last + 1; k < n; ++k) rest += len(L.path[k] - L.path[k - 1]);
    if (rest < kTailRest * L.length) continue;
    // The tail's own thickness: the median radius of the rest's outer half.
    std::vector<double> outer(L.radius.begin() + static_cast<long>(last + (n - last) / 2), L.radius.end());
    std::nth_element(outer.begin(), outer.begin() + static_cast<long>(outer.size() / 2), outer.end());
    const double thin = kTailThick * std::max(outer[outer.size() / 2], 0.5);
    size_t i = last + 1;
    while (i + 1 < n && L.radius[i] > thin) ++i;
    L.body_until = L.base_index = i;
    L.base = L.path[i];
    // The edges of its sub-tree that hold none of the tail's own points (a loop round a gap
    // between tail and rump, the stretch to the foot) are the body's too.
    for (int e : L.edges) {
      const auto& P = s.edges[e].points;
      const bool own = std::any_of(L.path.begin() + static_cast<long>(i), L.path.end(), [&](Vec2 q) {
        return std::any_of(P.begin(), P.end(), [&](Vec2 r) { return r.x == q.x && r.y == q.y; });
      });
      if (!own && std::find(L.standing_edges.begin(), L.standing_edges.end(), e) == L.standing_edges.end()) L.standing_edges.push_back(e);
    }
    L.length = 0;
    for (size_t k = i + 1; k < n; ++k) L.length += len(L.path[k] - L.path[k - 1]);
    if (L.length > 0) L.direction = unit(L.tip_pos - L.base);
  }
}

}  // namespace

const char* limb_kind_name(LimbKind k) {
  switch (k) {
    case LimbKind::Head: return "head";
    case LimbKind::Arm: return "arm";
    case LimbKind::Leg: return "leg";
    case LimbKind::Tail: return "tail";
    case LimbKind::Other: return "other";
  }
  return "other";
}

Figure find_limbs(const Skeleton& s) {
  Figure f;
  for (size_t c = 0; c < s.component_area.size(); ++c)
    if (f.component < 0 || s.component_area[c] > s.component_area[f.component]) f.component = static_cast<int>(c);
  if (f.component < 0) return f;
  f.x0 = f.y0 = 1e300;
  f.x1 = f.y1 = -1e300;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x)
      if (s.labels.at<int>(y, x) == f.component)
        f.x0 = std::min<double>(f.x0, x), f.x1 = std::max<double>(f.x1, x), f.y0 = std::min<double>(f.y0, y),
        f.y1 = std::max<double>(f.y1, y);
  pick_core(s, f);
  core_geometry(s, f);
  if (f.single_branch >= 0) return f;
  std::vector<char> core_node(s.nodes.size(), 0), used(s.edges.size(), 0);
  for (int n : f.core_nodes) core_node[n] = 1;
  for (int e : f.core_edges) used[e] = 1;
  // A core that is a trunk (pick_core) narrowing to a neck where it joins the rest: what hangs
  // from the neck is one limb, however it forks (a whale's fluke, its two lobes off one stalk,
  // beats as one tail).
  int neck = -1;
  if (!f.core_edges.empty() && s.edges[f.core_edges[0]].terminal) {
    const SkeletonEdge& T = s.edges[f.core_edges[0]];
    const int n = s.nodes[T.a].end() ? T.b : T.a;
    // ... and only when every end behind it lies ahead of the neck, out of the body's end (a
    // fluke, a forked fin): not limbs folding back along the body (a scooter's handlebar and
    // wheels), which stay limbs of their own.
    const Vec2 out = -1.0 * (T.a == n ? T.dir_a : T.dir_b);
    bool ahead = s.nodes[n].radius < kCoreGrow * T.max_radius;
    for (size_t m = 0; m < s.nodes.size() && ahead; ++m)
      if (static_cast<int>(m) != n && s.nodes[m].component == f.component && s.nodes[m].end() && static_cast<int>(m) != T.a && static_cast<int>(m) != T.b)
        ahead = dot(s.nodes[m].pos - s.nodes[n].pos, out) > 0;
    if (ahead) neck = n;
  }
  for (int c : f.core_nodes)
    for (int first : s.nodes[c].edges) {
      if (used[first]) continue;
      // The sub-tree behind `first`, not crossing the core (behind every branch of a neck).
      Limb L;
      L.joint = c;
      std::vector<int> stack = {first};
      used[first] = 1;
      if (c == neck)
        for (int other : s.nodes[c].edges)
          if (!used[other]) used[other] = 1, stack.push_back(other);
      std::vector<int> ends;
      while (!stack.empty()) {
        const int e = stack.back();
        stack.pop_back();
        L.edges.push_back(e);
        for (int n : {s.edges[e].a, s.edges[e].b}) {
          if (core_node[n]) continue;
          if (s.nodes[n].end() && std::find(ends.begin(), ends.end(), n) == ends.end()) ends.push_back(n);
          for (int next : s.nodes[n].edges)
            if (!used[next]) used[next] = 1, stack.push_back(next);
        }
      }
      if (ends.empty()) continue;
      std::sort(ends.begin(), ends.end());
      std::vector<int> best;
      for (int tip : ends) {
        std::vector<int> p = path_edges(s, L.edges, c, tip);
        if (L.tip < 0 || path_length(s, p) > path_length(s, best)) L.tip = tip, best = p;
      }
      for (int tip : ends)
        if (tip != L.tip) L.more_tips.push_back(tip);
      if (best.empty()) continue;
      limb_geometry(s, f, L, best);
      if (c == neck) with_stalk(s.edges[f.core_edges[0]], c, L);
      f.limbs.push_back(std::move(L));
    }
  label(s, f);
  standing_forks(s, f);
  thin_tail_bases(f);
  tails_through_feet(s, f);
  std::vector<std::pair<double, size_t>> order;
  for (size_t i = 0; i < f.limbs.size(); ++i)
    order.push_back({joint_t(s, f, f.limbs[i]) * 10 + std::atan2(f.limbs[i].direction.y, f.limbs[i].direction.x), i});
  std::sort(order.begin(), order.end());
  std::vector<Limb> sorted;
  for (const auto& o : order) sorted.push_back(std::move(f.limbs[o.second]));
  f.limbs = std::move(sorted);
  return f;
}

}  // namespace svgm::motion
