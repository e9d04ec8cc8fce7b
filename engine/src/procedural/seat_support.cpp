// What a figure sits in or on (seat_support.h).
#include "procedural/seat_support.h"

#include <algorithm>
#include <cmath>

#include "geometry/curve_samples.h"
#include "procedural/motion_plan_internal.h"
#include "procedural/part_rig_internal.h"

namespace svgm {

namespace {

// The seat's body reaches the lowest kLow of the figure (a tub, a shell, a horse's body on its
// legs). A sitter's fill covers at least kBlob of its box (a body, a head; a shower's pipe curling
// over a tub covers little of its box and belongs to the tub). It stands at least kRise of the
// figure's height above the seat's top where it stands and reaches down to within kTouch of it
// (a shower head above the tub reaches nothing). A head within kGap of the body's top, over it,
// goes with it.
constexpr double kLow = 0.25, kBlob = 0.3, kRise = 0.05, kTouch = 0.03, kGap = 0.08;

// The fill's area of a path (its control polygons' signed areas added; a hole takes its share
// away); 0 for a path with no fill.
double fill_area(const Path& p) {
  if (!p.has_fill) return 0;
  double area = 0;
  for (const Subpath& s : p.subpaths) area += shoelace(s.points);
  return std::fabs(area);
}

// The top of path p over the x-range [x0, x1]: its highest control point there, or its box's top
// when it has none there.
double top_over(const Path& p, const RigBox& box, double x0, double x1) {
  double top = 1e300;
  for (const Subpath& s : p.subpaths)
    for (const Vec2& q : s.points)
      if (q.x >= x0 && q.x <= x1) top = std::min(top, q.y);
  return top < 1e300 ? top : box.y0;
}

}  // namespace

std::string seat_words(const ParsedPrompt& prompt, const Rig& rig) {
  using motion_plan_internal::parts_for;
  for (const Clause& c : prompt.clauses) {
    if (std::any_of(c.verbs.begin(), c.verbs.end(), [](const Verb* v) { return v && (v->name == "takeoff" || v->name == "land"); }))
      continue;
    for (const auto& n : c.nouns) {
      const std::string& p = n.preposition;
      if (!n.object_of_preposition || !(p == "in" || p == "into" || p == "on" || p == "onto")) continue;
      // "in its shell": a seat may be the figure's own; a part the rig has is none ("on its back").
      std::string ignore;
      if (n.target != Target::Named || parts_for(rig, Target::Named, n.word, &ignore).empty()) return p + " the " + n.word;
    }
  }
  return "";
}

SeatSupport seat_support(const Scene& scene, const Rig& rig) {
  SeatSupport out;
  const size_t n = scene.paths.size();
  out.seat.assign(n, 0);
  const RigBox& F = rig.figure;
  if (F.empty()) return out;
  const double H = F.h();
  auto figure_path = [&](size_t i) {
    const int g = i < rig.part_of_path.size() ? rig.part_of_path[i] : -1;
    return g < 0 || rig.parts[g].role != Role::Background;
  };
  std::vector<RigBox> box(n);
  std::vector<double> area(n, 0);
  int body = -1;  // the seat's body
  for (size_t i = 0; i < n; ++i) {
    if (!figure_path(i)) continue;
    box[i] = part_rig_internal::path_box(scene.paths[i]);
    area[i] = fill_area(scene.paths[i]);
    if (box[i].empty() || box[i].y1 < F.y1 - kLow * H) continue;
    if (area[i] > 0 && (body < 0 || area[i] > area[body])) body = static_cast<int>(i);
  }
  if (body < 0) return out;
  const Path& S = scene.paths[body];
  const RigBox& SB = box[body];
  std::vector<char> sitter(n, 0);
  RigBox R;
  double sitter_area = 0;
  for (size_t i = 0; i < n; ++i) {
    const RigBox& b = box[i];
    if (static_cast<int>(i) == body || !figure_path(i) || b.empty() || area[i] < kBlob * b.area()) continue;
    const double top = top_over(S, SB, b.x0, b.x1);
    if (b.y0 > top - kRise * H || b.y1 < top - kTouch * H || b.x1 < SB.x0 || b.x0 > SB.x1) continue;
    sitter[i] = 1, R.add(b), sitter_area += area[i];
  }
  if (R.empty()) return out;
  // What lies inside the sitter's box (its eyes, its outline), and what stands on the seat over
  // it near its top (a head drawn apart from the body), goes with it; twice, for a head's details.
  const double eps = kTouch * H;
  for (int pass = 0; pass < 2; ++pass)
    for (size_t i = 0; i < n; ++i) {
      const RigBox& b = box[i];
      if (sitter[i] || static_cast<int>(i) == body || !figure_path(i) || b.empty()) continue;
      const bool inside = b.x0 >= R.x0 - eps && b.x1 <= R.x1 + eps && b.y0 >= R.y0 - eps && b.y1 <= R.y1 + eps;
      const bool over = b.x0 >= R.x0 - eps && b.x1 <= R.x1 + eps && b.y1 <= top_over(S, SB, b.x0, b.x1) + eps && b.y1 >= R.y0 - kGap * H;
      if (inside || over) sitter[i] = 1, R.add(b), sitter_area += area[i];
    }
  // A sitter no smaller than its seat is the figure itself (a bed's covers over its frame).
  double seat_area = 0;
  for (size_t i = 0; i < n; ++i)
    if (figure_path(i) && !sitter[i]) seat_area += area[i];
  if (sitter_area >= seat_area) return out;
  for (size_t i = 0; i < n; ++i) out.seat[i] = figure_path(i) && !sitter[i];
  out.sitter = R;
  out.found = true;
  return out;
}

bool seat_goes(const PlannedAction& a) {
  return a.primitive == Primitive::Slide || a.primitive == Primitive::Turn || a.turns_round || a.travel != 0;
}

std::vector<std::vector<int>> seat_apart(const SeatSupport& seat, std::vector<std::vector<int>> rides_on) {
  if (!seat.found) return rides_on;
  for (size_t p = 0; p < rides_on.size() && p < seat.seat.size(); ++p)
    for (int& h : rides_on[p])
      if (h >= 0 && static_cast<size_t>(h) < seat.seat.size() && seat.seat[h] != seat.seat[p]) h = -1;
  return rides_on;
}

void rise_from_seat(const Scene& scene, const Rig& rig, MotionPlan& plan) {
  if (plan.seat.empty() || !seat_support(scene, rig).found) return;
  for (auto& a : plan.actions)
    if (a.primitive == Primitive::Bob && a.target == Target::Whole && a.parts.empty() && a.vertical == 0 && a.amp > 0 && a.heading == Vec2{}) {
      a.vertical = 1;
      plan.notes.push_back(a.verb + " rises from " + plan.seat.substr(plan.seat.find(' ') + 1) + " and settles back: down, it would sink into it");
    }
}

}  // namespace svgm
