// The things a juggler keeps in the air and the cascade they fly (see tossed_things.h).
#include "procedural/tossed_things.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace svgm {

namespace {

// Whether q lies inside the polygon through `pts` (even-odd; the control points stand in for
// the outline: close enough to tell an eye inside a face from a ball beside a hand).
bool inside(const std::vector<Vec2>& pts, Vec2 q) {
  bool in = false;
  for (size_t i = 0, j = pts.size() - 1; i < pts.size(); j = i++)
    if ((pts[i].y > q.y) != (pts[j].y > q.y) && q.x < (pts[j].x - pts[i].x) * (q.y - pts[i].y) / (pts[j].y - pts[i].y) + pts[i].x)
      in = !in;
  return in;
}

bool same_box(const RigBox& a, const RigBox& b) {
  const double tol = 0.15 * std::max({a.w(), a.h(), b.w(), b.h()});
  return std::fabs(a.x0 - b.x0) <= tol && std::fabs(a.x1 - b.x1) <= tol && std::fabs(a.y0 - b.y0) <= tol && std::fabs(a.y1 - b.y1) <= tol;
}

bool figure_element(const Rig& rig, const RigElement& e) {
  if (e.path < 0 || e.path >= static_cast<int>(rig.part_of_path.size())) return false;
  const int g = rig.part_of_path[static_cast<size_t>(e.path)];
  return g < 0 || rig.parts[static_cast<size_t>(g)].role != Role::Background;
}

// Whether element e is small, compact and round enough to be tossed.
bool round_and_small(const Rig& rig, const RigElement& e) {
  const double big = std::max(rig.figure.w(), rig.figure.h()), w = e.box.w(), h = e.box.h();
  if (e.thin || std::max(w, h) > kTossMaxSize * big || std::max(w, h) < kTossMinSize * big) return false;
  if (std::max(w, h) > kTossAspect * std::max(std::min(w, h), 1e-9)) return false;
  return std::fabs(e.area / std::max(0.25 * M_PI * w * h, 1e-12) - 1) <= kTossRound;
}

}  // namespace

std::vector<TossedThing> find_tossed_things(const Rig& rig) {
  const auto& E = rig.elements;
  const RigBox& F = rig.figure;
  std::vector<size_t> cand;
  for (size_t i = 0; i < E.size(); ++i) {
    if (!figure_element(rig, E[i]) || !round_and_small(rig, E[i])) continue;
    const Vec2 c = E[i].box.centre();
    if (c.y > F.y0 + kTossLowest * F.h()) continue;
    // Not drawn inside a larger element's outline (an eye, a button); holding at most one other
    // (a highlight; a face holds its eyes and mouth).
    bool detail = false;
    int holds = 0;
    for (size_t j = 0; j < E.size() && !detail; ++j) {
      if (j == i || !figure_element(rig, E[j]) || same_box(E[i].box, E[j].box)) continue;
      if (E[j].box.area() > 2 * E[i].box.area() && inside(E[j].points, c)) detail = true;
      if (E[j].box.area() < 0.5 * E[i].box.area() && E[j].box.within(E[i].box)) ++holds;
    }
    if (!detail && holds <= 1) cand.push_back(i);
  }
  // One thing per box (a fill and the outline drawn over it).
  std::vector<TossedThing> out;
  for (size_t i : cand) {
    auto it = std::find_if(out.begin(), out.end(), [&](const TossedThing& t) { return same_box(t.box, E[i].box); });
    if (it != out.end()) continue;
    out.push_back({{}, E[i].box, 0});
  }
  if (out.size() < 2) return {};
  // Of about one size: within kTossSizeRatio of the middle one.
  std::vector<double> sizes;
  for (const auto& t : out) sizes.push_back(std::max(t.box.w(), t.box.h()));
  std::vector<double> sorted = sizes;
  std::sort(sorted.begin(), sorted.end());
  const double mid = sorted[sorted.size() / 2];
  std::vector<TossedThing> kept;
  for (size_t k = 0; k < out.size(); ++k)
    if (sizes[k] <= kTossSizeRatio * mid && sizes[k] >= mid / kTossSizeRatio) kept.push_back(out[k]);
  if (kept.size() < 2) return {};
  // Every element drawn over a thing goes with it: its own fill and outlines, its highlights.
  for (auto& t : kept) {
    for (const RigElement& e : E)
      if (figure_element(rig, e) && (same_box(t.box, e.box) || (e.box.within(t.box, 0.05 * t.box.w()) && e.box.area() < t.box.area())))
        t.pieces.push_back({e.path, e.subpath});
  }
  std::sort(kept.begin(), kept.end(), [](const TossedThing& a, const TossedThing& b) { return a.box.centre().x < b.box.centre().x; });
  return kept;
}

Vec2 cascade_point(const TossArc& arc, double v) {
  v -= std::floor(v);
  const double dir = v < 0.5 ? 1 : -1, w = (v < 0.5 ? v : v - 0.5) / 0.5;
  if (w < kTossAir) {
    // In the air: from the inner point on one side up over to the outer point of the other.
    const double s = w / kTossAir;
    return {arc.centre + dir * (-arc.inner + (arc.inner + arc.outer) * s), arc.hand - arc.rise * 4 * s * (1 - s)};
  }
  // Caught and carried in by that hand, dipping a little, to be thrown back.
  const double s = (w - kTossAir) / (1 - kTossAir);
  return {arc.centre + dir * (arc.outer - (arc.outer - arc.inner) * s), arc.hand + kTossScoop * arc.outer * std::sin(M_PI * s)};
}

TossArc cascade_arc(const Rig& rig, std::vector<TossedThing>& things) {
  TossArc arc;
  if (things.empty()) return arc;
  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  for (const auto& t : things) {
    const Vec2 c = t.box.centre();
    xmin = std::min(xmin, c.x), xmax = std::max(xmax, c.x), ymin = std::min(ymin, c.y), ymax = std::max(ymax, c.y);
  }
  const RigBox& F = rig.figure;
  arc.centre = xmax - xmin >= kTossMinSpan * F.w() ? 0.5 * (xmin + xmax) : F.centre().x;
  arc.outer = std::max(0.5 * (xmax - xmin), 0.5 * kTossMinSpan * F.w());
  arc.hand = ymax;
  // The hands, when the figure has arms of its own on both sides under the things: each arm's
  // end (its box's corner farthest from its shoulder). The things are caught there and thrown
  // from there; from the lowest thing, they never came down to the hands.
  std::vector<Vec2> hands;
  for (const RigPart& P : rig.parts) {
    // Arms on the body (a ball drawn at a hand may hang from the arm as a limb of its own).
    if (P.role != Role::UpperLimb || P.box.empty() || P.parent != rig.root || rig.root < 0) continue;
    Vec2 far = P.pivot;
    for (Vec2 q : {Vec2{P.box.x0, P.box.y0}, Vec2{P.box.x1, P.box.y0}, Vec2{P.box.x0, P.box.y1}, Vec2{P.box.x1, P.box.y1}})
      if (std::hypot(q.x - P.pivot.x, q.y - P.pivot.y) > std::hypot(far.x - P.pivot.x, far.y - P.pivot.y)) far = q;
    hands.push_back(far);
  }
  if (hands.size() == 2 && hands[0].y > ymin && hands[1].y > ymin && std::fabs(hands[0].x - hands[1].x) >= kTossMinSpan * F.w() * 0.5) {
    arc.centre = 0.5 * (hands[0].x + hands[1].x);
    arc.outer = 0.5 * std::fabs(hands[0].x - hands[1].x);
    arc.hand = 0.5 * (hands[0].y + hands[1].y);
  }
  arc.inner = kTossInner * arc.outer;
  arc.rise = std::max(arc.hand - ymin, kTossMinRise * arc.outer);
  // The phases: N equal steps apart; the order and the offset that put the things nearest where
  // the drawing has them (every order for up to 6 things, else left to right).
  const size_t N = things.size();
  std::vector<size_t> order(N), best_order(N);
  std::iota(order.begin(), order.end(), 0);
  best_order = order;
  double best = 1e300, best_offset = 0;
  constexpr int kOffsets = 120;
  do {
    for (int k = 0; k < kOffsets; ++k) {
      const double off = static_cast<double>(k) / kOffsets;
      double cost = 0;
      for (size_t i = 0; i < N; ++i) {
        const Vec2 p = cascade_point(arc, off + static_cast<double>(i) / N), c = things[order[i]].box.centre();
        cost += (p.x - c.x) * (p.x - c.x) + (p.y - c.y) * (p.y - c.y);
      }
      if (cost < best - 1e-9) best = cost, best_offset = off, best_order = order;
    }
  } while (N <= 6 && std::next_permutation(order.begin(), order.end()));
  for (size_t i = 0; i < N; ++i) things[best_order[i]].phase = best_offset + static_cast<double>(i) / N;
  return arc;
}

Vec2 toss_shift(const TossArc& arc, const TossedThing& th, double amp, double u) {
  const Vec2 a = cascade_point(arc, th.phase + u), b = cascade_point(arc, th.phase), rest = th.box.centre();
  // Where the drawing has it off the curve, that offset fades out and back over each cycle.
  const double keep = 0.5 + 0.5 * std::cos(2 * M_PI * u);
  return {amp * (a.x - b.x - (1 - keep) * (rest.x - b.x)), amp * (a.y - b.y - (1 - keep) * (rest.y - b.y))};
}

TossFrame still_toss_frame(const Scene& scene) {
  TossFrame f;
  for (const Path& p : scene.paths) {
    f.on.emplace_back(p.subpaths.size(), 0);
    f.shift.emplace_back(p.subpaths.size(), Vec2{0, 0});
  }
  return f;
}

void add_toss(const std::vector<TossedThing>& things, const TossArc& arc, double amp, double u, TossFrame& frame) {
  for (const TossedThing& th : things) {
    const Vec2 d = toss_shift(arc, th, amp, u);
    for (const ElementPiece& piece : th.pieces) {
      if (piece.path < 0 || piece.path >= static_cast<int>(frame.on.size())) continue;
      auto& on = frame.on[static_cast<size_t>(piece.path)];
      for (size_t s = 0; s < on.size(); ++s)
        if (piece.subpath < 0 || piece.subpath == static_cast<int>(s)) {
          on[s] = 1;
          frame.shift[static_cast<size_t>(piece.path)][s] = d;
        }
    }
  }
}

bool reads_as_juggling(const Clause& c, const Rig& rig) {
  const Verb* thrown = find_verb_by_name("throw");
  bool throws = std::find(c.verbs.begin(), c.verbs.end(), thrown) != c.verbs.end(), several = false, keep = false, air = false;
  for (const auto& n : c.nouns) several = several || (n.plural && n.after_verb && !n.object_of_preposition);
  std::string w;
  for (size_t i = 0; i <= c.text.size(); ++i) {
    if (i < c.text.size() && c.text[i] != ' ') { w += c.text[i]; continue; }
    throws = throws || word_matches(w, "toss");
    keep = keep || w == "keep" || w == "keeps" || w == "keeping" || w == "kept";
    air = air || w == "air";
    w.clear();
  }
  return ((throws && several) || (keep && air)) && find_tossed_things(rig).size() >= 2;
}

}  // namespace svgm
