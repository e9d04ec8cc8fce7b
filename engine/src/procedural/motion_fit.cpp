// Fitting a motion plan to its canvas and its keyframes (fit_plan, motion_plan.h): amplitudes
// scaled down only to stay inside the frame and within the fitter's steps between keyframes, up
// to a visible travel, and parts at the canvas's edge held when nothing else lets the figure
// move.
#include "procedural/motion_plan.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <set>

#include "procedural/carried_flight.h"
#include "procedural/invisible_spin.h"
#include "procedural/motion_plan_internal.h"
#include "procedural/seat_support.h"
#include "procedural/support_band.h"

namespace svgm {

using namespace motion_plan_internal;

namespace {

// Why `pts` (frames of animate_plan) moves a point that is not `exempt` farther than kMaxStep
// between two of K keyframes, or "".
std::string limit_broken_steps(const Scene& scene, const std::vector<Vec2>& pts, const std::vector<char>& exempt, int frames, int K) {
  const double max_step = kMaxStep * std::hypot(scene.width, scene.height);
  const size_t per = pts.size() / frames;
  for (int k = 1; k < K; ++k) {
    const int fa = static_cast<int>(std::lround((k - 1) * (frames - 1.0) / (K - 1)));
    const int fb = static_cast<int>(std::lround(k * (frames - 1.0) / (K - 1)));
    for (size_t i = 0; i < per; ++i) {
      if (exempt[i]) continue;
      const Vec2 d = pts[fb * per + i] - pts[fa * per + i];
      if (std::hypot(d.x, d.y) > max_step) return "would move too far between keyframes for the fitter to follow";
    }
  }
  return "";
}

// Why `pts` (frames of animate_plan) breaks a limit of fit_plan, or "" when it does not.
std::string limit_broken(const Scene& scene, const std::vector<Vec2>& pts, const std::vector<char>& exempt,
                         const std::vector<char>& by_curve, int frames, int K) {
  const double m = kFrameMargin * std::min(scene.width, scene.height);
  const double x0 = m, y0 = m, x1 = scene.width - m, y1 = scene.height - m;
  auto outside = [&](Vec2 q) { return std::max({0.0, x0 - q.x, q.x - x1, y0 - q.y, q.y - y1}); };
  const size_t per = pts.size() / frames;
  // A control point inside the canvas at rest stays inside (a point inside the margin band at
  // rest, a drawing touching the edge, may use the band). One already outside the canvas (a
  // line drawing's handle: one 0.7 px out froze a galloping horse) may move: its curve is
  // held instead, each cubic at t = 0, 1/4, 1/2, 3/4, a point of it already outside at rest
  // going at most 0.9 of the margin farther out. The points of a spinning part are held by their
  // curves too: a turning circle stays where it is while its handles (0.55 of the radius off
  // the circle) sweep out beyond it, past the edge of a canvas the wheel fills; held by
  // the handles, no turn of a ferris wheel could stay in.
  auto allowed_for = [&](double rest) { return rest > m ? rest + kMarginUse * m : rest > 0 ? std::max(rest, kMarginUse * m) : 0.0; };
  auto at = [&](int f, size_t i, double t) {
    const Vec2* c = &pts[f * per + i];
    const double u = 1 - t;
    return u * u * u * c[0] + 3 * u * u * t * c[1] + 3 * u * t * t * c[2] + t * t * t * c[3];
  };
  size_t i = 0;
  for (const Path& p : scene.paths)
    for (const auto& sp : p.subpaths) {
      const size_t n = sp.points.size();
      for (size_t k = 0; k < n; ++k) {
        const double rest = outside(pts[i + k]);
        if (rest > m || by_curve[i + k]) {
          // The segments this point shapes: the one it starts or ends, or whose handle it is.
          const size_t s0 = k / 3 * 3, first = (k % 3 == 0 && k >= 3) ? s0 - 3 : s0;
          for (size_t s = first; s <= s0 && s + 3 < n; s += 3)
            for (double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {
              const double allowed = allowed_for(outside(at(0, i + s, t)));
              for (int f = 1; f < frames; ++f)
                if (outside(at(f, i + s, t)) > allowed + 1e-6) return "would leave the canvas";
            }
          continue;
        }
        const double allowed = allowed_for(rest);
        for (int f = 1; f < frames; ++f)
          if (outside(pts[f * per + i + k]) > allowed + 1e-6) return "would leave the canvas";
      }
      i += n;
    }
  return limit_broken_steps(scene, pts, exempt, frames, K);
}

// Why a swing of `plan` breaks the turn limit (kMaxTurn between two of the K keyframes spread
// over `frames`), or "" when none does. The angle of a swing is amplitude * sin(2 pi (cycles t +
// phase)) (rigid), so its turn between keyframes is known without the frames. Only parts: a
// part of its own turning far slides behind or out from its neighbours (its visible area jumps),
// a region of one shape bending (bend_region) keeps its outline whole; capped, a dancer's
// sleeves bent 18 degrees instead of 29 and his squat outweighed them (fitted share 0.70 -> 0.66).
std::string turn_broken(const MotionPlan& plan, int frames, int K) {
  for (const auto& a : plan.actions) {
    // A figure turning about its vertical axis turns 360 * amp degrees a loop, evenly: with too
    // few keyframes most of its pixels change between two of them, which the pixel ranker calls
    // chaotic motion (a pirouette at 15 keyframes: 24 degrees, a mean frame difference of 0.45).
    // Arms turning over (a crawl) turn evenly too, whole turns: more keyframes, never less turn.
    if (a.primitive == Primitive::Turn || a.primitive == Primitive::Windmill) {
      if (360 * plan.amplitude(a) / std::max(K - 1, 1) > kMaxTurn + 1e-9)
        return a.primitive == Primitive::Turn ? "would turn the figure too far between keyframes"
                                              : "would turn a part too far between keyframes for the tracker to follow";
      continue;
    }
    if (a.primitive != Primitive::Swing || a.region != Region::None) continue;
    const double amp = plan.amplitude(a);
    for (double phase : a.phase)
      for (int k = 1; k < K; ++k) {
        const double ta = std::lround((k - 1) * (frames - 1.0) / (K - 1)) / std::max(frames - 1.0, 1.0);
        const double tb = std::lround(k * (frames - 1.0) / (K - 1)) / std::max(frames - 1.0, 1.0);
        const double turn = amp * std::fabs(oscillation(a, a.cycles * tb + phase) - oscillation(a, a.cycles * ta + phase));
        if (turn > kMaxTurn + 1e-9) return "would turn a part too far between keyframes for the tracker to follow";
      }
  }
  return "";
}

// A verb's whole-figure accents (a gallop's rock and bob) keep their size next to its limbs'
// swing: when the turn or step limit scaled the limbs' swing down, its accents of the same
// words scale down with it. At full size beside legs cut to half, a galloping horse rocked and
// bobbed more than its legs moved (share of the motion on the legs 0.35).
void accents_follow_limbs(MotionPlan& plan) {
  for (auto& a : plan.actions) {
    // A hover's bob is the hover itself (carried_flight.h), not an accent: it keeps the floor.
    // A travel (a figure going somewhere: PlannedAction::goes, inches) is no accent either: cut
    // with a crocodile's legs (their bend folded at full size), its walk went 64 % as far as the
    // canvas allowed. Nor is a juggler's toss (the balls' arcs).
    if (a.target != Target::Whole || a.primitive == Primitive::Spin || a.primitive == Primitive::Turn ||
        a.primitive == Primitive::Toss || carried_whole(a) || a.goes || a.inches)
      continue;
    // No limbs of the same words: nothing to follow. With a default of 1 every whole-figure
    // motion raised to the visible floor (a duck's bob at 305 %) was set back to 100 %.
    double limbs = HUGE_VAL;
    for (const auto& b : plan.actions)
      if (&b != &a && b.verb == a.verb && b.words == a.words && is_limb_target(b.target) && b.primitive == Primitive::Swing)
        limbs = std::min(limbs, b.scale);
    if (limbs >= a.scale) continue;
    a.scale = limbs;
    char line[240];
    std::snprintf(line, sizeof line, "%s (%s) of the whole figure scaled to %.0f %% with its limbs' swing", a.verb.c_str(),
                  primitive_name(a.primitive), limbs * 100);
    plan.notes.push_back(line);
  }
}

// The actions scaled with action i as one: a crawl's slide and stretch (PlannedAction::inches) of
// the same words, whose steps plant the ends only while the stretch is the size of the slide's
// step (travel_profile.h); any other action alone. Scaled apart (the canvas cut the slide, which
// reaches behind the figure, and not the stretch, which reaches only ahead), the planted ends
// slipped.
std::vector<size_t> scaled_with(const MotionPlan& plan, size_t i) {
  const PlannedAction& a = plan.actions[i];
  if (!a.inches) return {i};
  std::vector<size_t> out;
  for (size_t j = 0; j < plan.actions.size(); ++j)
    if (plan.actions[j].inches && plan.actions[j].verb == a.verb && plan.actions[j].words == a.words) out.push_back(j);
  return out;
}

// Each crawl's slide and stretch at the smaller of their scales (scaled_with): smaller, the crawl
// keeps to the room either kept.
void tie_crawl_scales(MotionPlan& plan) {
  for (size_t i = 0; i < plan.actions.size(); ++i) {
    double least = plan.actions[i].scale;
    for (size_t j : scaled_with(plan, i)) least = std::min(least, plan.actions[j].scale);
    for (size_t j : scaled_with(plan, i)) plan.actions[j].scale = least;
  }
}

// The largest distance a point that is not `exempt` travels from rest over the frames `pts`.
double largest_travel(const std::vector<Vec2>& pts, const std::vector<char>& exempt, int frames) {
  const size_t per = pts.size() / frames;
  double largest = 0;
  for (int f = 1; f < frames; ++f)
    for (size_t i = 0; i < per; ++i)
      if (!exempt[i]) largest = std::max(largest, std::hypot(pts[f * per + i].x - pts[i].x, pts[f * per + i].y - pts[i].y));
  return largest;
}

// Whether `a`'s amplitude is an angle in degrees (motion_verbs.h's units).
bool turns_degrees(const PlannedAction& a) {
  return a.primitive == Primitive::Swing || a.primitive == Primitive::Rock || a.primitive == Primitive::Bend ||
         a.primitive == Primitive::Sway;
}

// Whether action i is a one-way climb of the whole figure (a launch's) and another action of
// its words shrinks the figure (the launch going away): that one shows the launch without room.
bool climbs_with_more(const MotionPlan& plan, size_t i) {
  const PlannedAction& a = plan.actions[i];
  if (a.primitive != Primitive::Bob || a.vertical != 1 || !a.parts.empty()) return false;
  for (const PlannedAction& b : plan.actions)
    if (&b != &a && b.words == a.words && b.primitive == Primitive::Pulse && b.amp < 0 && b.parts.empty()) return true;
  return false;
}

// Whether `a` is a launch along the figure's nose (a travel of its own: flight_axis.h).
bool launches(const PlannedAction& a) { return a.primitive == Primitive::Bob && (a.heading.x != 0 || a.heading.y != 0); }

bool oscillates(const PlannedAction& a) {
  return a.primitive == Primitive::Swing || a.primitive == Primitive::Rock || a.primitive == Primitive::Bend ||
         a.primitive == Primitive::Sway || a.region != Region::None;
}

// The fewest keyframes, from `K` up to `K_hi`, between which `one`'s frames break neither the
// step nor the turn limit; 0 when even `K_hi` do not.
int keyframes_to_follow(const Scene& scene, const std::vector<Vec2>& pts, const MotionPlan& one, const std::vector<char>& exempt,
                        int frames, int K, int K_hi) {
  auto follows = [&](int k) {
    return limit_broken_steps(scene, pts, exempt, frames, k).empty() && turn_broken(one, frames, k).empty();
  };
  if (!follows(K_hi)) return 0;
  for (int k = K; k < K_hi; ++k)  // searched from below: more keyframes are not always closer
    if (follows(k)) return k;       // (rounding moves them), the fewest that follow win
  return K_hi;
}

// `plan` with only the actions `keep` moving (the others at amplitude 0).
MotionPlan only(const MotionPlan& plan, const std::vector<size_t>& keep) {
  MotionPlan one = plan;
  for (size_t j = 0; j < one.actions.size(); ++j)
    if (std::find(keep.begin(), keep.end(), j) == keep.end()) one.actions[j].amp = 0;
  return one;
}

// The clauses of `plan` the visible floor measures: its actions grouped by verb and words (a
// walk's legs, arms and bob grow together), but none with a turn or a fall (whole turns are
// never scaled; falling elements leave the picture whatever their size) and none that only
// spins. A spin beside other actions (a car's drive: its slide and its wheels) is measured by
// those: the spinning points are exempt, and a spin's whole turns ignore the scale. A hover's
// or a buzz's motion of the whole figure is a clause of its own (carried_flight.h): the wings'
// beat passing the floor does not make the body's bob visible.
std::vector<std::vector<size_t>> measured_clauses(const MotionPlan& plan) {
  std::vector<std::vector<size_t>> out;
  std::vector<char> done(plan.actions.size(), 0);
  for (size_t i = 0; i < plan.actions.size(); ++i) {
    if (done[i]) continue;
    std::vector<size_t> clause;
    bool measurable = true, scalable = false;
    for (size_t j = i; j < plan.actions.size(); ++j)
      if (plan.actions[j].verb == plan.actions[i].verb && plan.actions[j].words == plan.actions[i].words &&
          carried_whole(plan.actions[j]) == carried_whole(plan.actions[i])) {
        clause.push_back(j);
        done[j] = 1;
        const Primitive p = plan.actions[j].primitive;
        measurable = measurable && p != Primitive::Turn && p != Primitive::Fall;
        scalable = scalable || (p != Primitive::Spin && p != Primitive::Windmill);
      }
    if (measurable && scalable) out.push_back(clause);
  }
  return out;
}

// How the visible floor is measured and what the fitter can follow: the points the floor and
// the step limit leave out (falling, spinning, turning), the frames, the most keyframes the
// fitter may take.
struct TravelCheck {
  const Scene& scene;
  const Rig& rig;
  const std::vector<char>& exempt;
  const std::vector<char>& by_curve;
  int frames, K_hi;
  double floor() const { return kVisibleTravel * std::hypot(rig.figure.w(), rig.figure.h()); }
  double percent(double travel) const { return 100 * travel / std::max(std::hypot(rig.figure.w(), rig.figure.h()), 1e-9); }
  // The largest travel of a point that `clause` of `plan` moves, alone.
  double travel(const MotionPlan& plan, const std::vector<size_t>& clause) const {
    return largest_travel(animate_plan(scene, rig, only(plan, clause), frames), exempt, frames);
  }
  // Whether the fitter follows `one`, animated as `pts`, between K_hi keyframes (steps and
  // turns; not the canvas).
  bool followed(const MotionPlan& one, const std::vector<Vec2>& pts) const {
    return limit_broken_steps(scene, pts, exempt, frames, K_hi).empty() && turn_broken(one, frames, K_hi).empty();
  }
  bool follows(const MotionPlan& one) const { return followed(one, animate_plan(scene, rig, one, frames)); }
  // The travel `clause` (alone in `one`) keeps once cut by 0.8 at a time until `holds(one, its
  // points)`, as fit_scales would cut it; 0 when kScaleAttempts cuts do not do.
  template <class Holds>
  double travel_cut(MotionPlan one, const std::vector<size_t>& clause, Holds holds) const {
    for (int attempt = 0; attempt <= kScaleAttempts; ++attempt) {
      const std::vector<Vec2> pts = animate_plan(scene, rig, one, frames);
      if (holds(one, pts)) return largest_travel(pts, exempt, frames);
      for (size_t j : clause) one.actions[j].scale *= 0.8;
    }
    return 0;
  }
  // The travel `clause` keeps, alone, within every limit (the canvas, the fitter's steps).
  double travel_kept(const MotionPlan& plan, const std::vector<size_t>& clause) const {
    return travel_cut(only(plan, clause), clause, [&](const MotionPlan&, const std::vector<Vec2>& pts) {
      return limit_broken(scene, pts, exempt, by_curve, frames, K_hi).empty();
    });
  }
  // The travel `clause` (alone in `one`) keeps where the fitter follows it.
  double travel_followed(MotionPlan one, const std::vector<size_t>& clause) const {
    return travel_cut(std::move(one), clause, [&](const MotionPlan& m, const std::vector<Vec2>& pts) { return followed(m, pts); });
  }
};

// A clause the fitter's steps between keyframes would cut below the floor (a stick figure's nod,
// twice a loop, raised to the floor: at 9 keyframes cut to 6.4 % of his size) is slowed instead:
// fewer cycles a loop, every action of the clause by the same factor (a walk's bob keeps two beats a stride),
// the fastest tempo that keeps the floor, else the one that keeps the most travel. The
// amplitude is what the words ask for; the tempo only how often.
void slow_to_follow(const TravelCheck& c, MotionPlan& plan, const std::vector<size_t>& clause) {
  const MotionPlan one = only(plan, clause);
  if (c.follows(one)) return;
  const double kept = c.travel_followed(one, clause);
  if (kept >= c.floor()) return;
  int g = 0;
  for (size_t j : clause) g = std::gcd(g, std::max(plan.actions[j].cycles, 1));
  int best_g = g;
  double best = kept;
  for (int h = g - 1; h >= 1; --h) {
    MotionPlan slower = one;
    for (size_t j : clause) slower.actions[j].cycles = plan.actions[j].cycles / g * h;
    const double t = c.travel_followed(slower, clause);
    if (t > best * 1.05) {
      best = t;
      best_g = h;
    }
    if (t >= c.floor()) break;
  }
  if (best_g == g) return;
  const size_t first = clause.front();
  char line[300];
  std::snprintf(line, sizeof line,
                "%s slowed to %d cycles a loop instead of %d: at %d the fitter could not follow it between keyframes unless cut to "
                "%.1f %% of the figure's size",
                plan.actions[first].verb.c_str(), plan.actions[first].cycles / g * best_g, plan.actions[first].cycles,
                plan.actions[first].cycles, c.percent(kept));
  for (size_t j : clause) plan.actions[j].cycles = plan.actions[j].cycles / g * best_g;
  plan.notes.push_back(line);
}

// A region bend whose mesh (region_bend.h) folds in some frame (a flipped triangle: the shape
// turned over on itself) or pinches (a triangle under kPinchArea of its rest area: a hand thinned
// to a sliver) is made smaller, 0.8 at a time, before any candidate is drawn; a note says how
// far, and one line per meshed bend says its worst frame. The mesh is one piece over every path
// the bend moves, so a limb that turns over the body it hangs from (a claw across a crab's
// shell, a fencer's arm across the chest) folds it where the drawing only overlaps: when
// unfolding would take the bend under kMinUnfoldScale of its size (the fencer's thrust to 3 %
// of the figure's size from 21 %, the crab's claws to 2 % from 10 %), the bend stays at its
// size in the closed form (motion_frames.cpp), as before the mesh, and a note says so. A bend
// made smaller has "would fold its mesh" in `cut` (warn_under_floor names it).
void unfold_region_bends(const Scene& scene, const Rig& rig, MotionPlan& plan, int frames, std::vector<std::string>& cut) {
  for (size_t i = 0; i < plan.actions.size(); ++i) {
    PlannedAction& a = plan.actions[i];
    if (a.region == Region::None || a.amp == 0) continue;
    const std::string what = a.verb + " (" + primitive_name(a.primitive) + ")";
    std::vector<BendFold> folds;
    BendFold first;
    const double scale_before = a.scale;
    int attempt = 0;
    for (;; ++attempt) {
      animate_plan(scene, rig, only(plan, {i}), frames, &folds);
      const BendFold& f = folds[i];
      if (attempt == 0) first = f;
      if (!f.meshed || (f.flipped == 0 && f.min_area_ratio >= kPinchArea)) break;
      if (a.scale * 0.8 < kMinUnfoldScale * scale_before) {
        a.scale = 0;  // it folds down to the least share kept: the closed form instead (below)
        break;
      }
      a.scale *= 0.8;
    }
    if (!first.meshed) continue;
    if (a.scale == 0) {
      a.scale = scale_before;
      a.closed_form = true;
      plan.notes.push_back("the bend of " + what + " would fold its mesh above " +
                           std::to_string(static_cast<int>(std::lround(kMinUnfoldScale * 100))) +
                           " % of its size: bent in closed form, at its size (parts may cross where they overlap)");
      continue;
    }
    char line[300];
    std::snprintf(line, sizeof line, "the bend of %s moves through a mesh: at full size its worst frame (%d) has %d folded triangles, the thinnest at %.0f %% of its area",
                  what.c_str(), first.frame, first.flipped, first.min_area_ratio * 100);
    plan.notes.push_back(line);
    if (attempt > 0) {
      cut[i] = "would fold its mesh";
      std::snprintf(line, sizeof line, "the amplitude of %s scaled to %.0f %%: at full size its bend %s its shape", what.c_str(),
                    a.scale * 100, first.flipped > 0 ? "folds" : "pinches");
      plan.notes.push_back(line);
    }
  }
}

// Whether `clause` is wheels spinning in place with at most the body's bounce or jitter on them.
// The spin is its motion (its points are exempt from the travel: whole turns); the bounce is an
// accent left at its size (raised to the floor, a car's body hopped 8 % of its size over its
// wheels), and no warning says it is under the floor.
bool spins_in_place(const MotionPlan& plan, const std::vector<size_t>& clause) {
  bool spins = false, accents_only = true;
  for (size_t j : clause) {
    const PlannedAction& a = plan.actions[j];
    const bool spin = a.primitive == Primitive::Spin && a.target == Target::Wheels && !a.parts.empty() && !a.rolls;
    spins = spins || spin;
    accents_only = accents_only && (spin || (a.parts.empty() && (a.primitive == Primitive::Bob || a.primitive == Primitive::Shake)));
  }
  return spins && accents_only;
}

// The actions of `clause` the visible floor raises: all of them, but for a traveller whose
// travel (its slide going somewhere, PlannedAction::goes or inches) the canvas keeps under the
// floor, those that move it on its body (its legs' steps, its bob, a swim's wave), measured
// without the travel. Measured with it, a turtle filling its canvas "plodding along" had its
// legs at the lexicon's size, under the floor, and its 15 % travel cut by the canvas to under
// the floor too: it stood nearly still. `held_by` gets why (for the note); empty when the
// clause is measured whole. A crawl's stretch goes with its slide (scaled_with): no body left.
std::vector<size_t> gait_on_body(const TravelCheck& c, const MotionPlan& plan, const std::vector<size_t>& clause, std::string* held_by) {
  std::vector<size_t> travel, body;
  for (size_t j : clause) {
    const PlannedAction& a = plan.actions[j];
    ((a.goes || a.inches) && a.parts.empty() && (a.primitive == Primitive::Slide || a.inches) ? travel : body).push_back(j);
  }
  if (travel.empty() || body.empty()) return clause;
  const double kept = c.travel_kept(plan, travel);
  if (kept >= c.floor()) return clause;
  char line[160];
  std::snprintf(line, sizeof line, " (its travel held to %.1f %% by the canvas)", c.percent(kept));
  *held_by = line;
  return body;
}

// A carried flight's body (carried_whole: a hover's bob, a buzz's dart), at `travel` once raised
// to the floor, raised on to kCarriedTravel of the figure's size as far as the whole plan stays
// in the canvas and within the fitter's steps (halved between the floor's scale and
// kCarriedTravel's, five times): raised past the room, a bee's dart beside its beating wings
// left the canvas and every motion was cut with it, the dart to 6.2 % of its size; past the
// steps, a hovering bird's wings were cut to 64 % with its bob. Returns the factor applied.
double carry_farther(const TravelCheck& c, MotionPlan& plan, const std::vector<size_t>& clause, double travel) {
  const double aim = kRaiseAim * kCarriedTravel * std::hypot(c.rig.figure.w(), c.rig.figure.h());
  if (travel <= 0 || travel >= aim || !carried_whole(plan.actions[clause.front()])) return 1;
  auto fits = [&](double f) {
    MotionPlan m = plan;
    for (size_t j : clause) m.actions[j].scale *= f;
    return limit_broken(c.scene, animate_plan(c.scene, c.rig, m, c.frames), c.exempt, c.by_curve, c.frames, c.K_hi).empty();
  };
  // The travel grows nearly in proportion to a bob's and a slide's scale (no turn to flatten it).
  double lo = 1, hi = std::min(aim / travel, kMaxBoost);
  if (!fits(hi))
    for (int k = 0; k < 5; ++k) {
      const double mid = 0.5 * (lo + hi);
      (fits(mid) ? lo : hi) = mid;
    }
  else lo = hi;
  for (size_t j : clause) plan.actions[j].scale *= lo;
  return lo;
}

// Too small to see: the moving parts travel at least kVisibleTravel of the figure's size. Each
// clause grows as a whole, by at most kMaxBoost, measured again after each raise: a swing's
// chord (2 r sin(a / 2)) and a bend's reach grow slower than their angle, and one raise by
// floor / travel left a whale's spout at 7.5 % and a bell's clapper at 7.6 %. A clause the
// fitter could not follow at its raised size is slowed (slow_to_follow); the canvas then scales
// clauses back where they would not fit (fit_scales), and warn_under_floor says so.
void raise_to_visible(const TravelCheck& c, MotionPlan& plan) {
  const double floor = c.floor();
  for (const auto& clause : measured_clauses(plan)) {
    if (spins_in_place(plan, clause)) {
      slow_to_follow(c, plan, clause);
      continue;
    }
    // A traveller the canvas holds (a figure filling its picture): its gait must read on its
    // body, its legs' steps and its bob raised to the floor without the travel (gait_on_body).
    std::string held_by;
    const std::vector<size_t> raised = gait_on_body(c, plan, clause, &held_by);
    double travel = c.travel(plan, raised), boost = 1;
    const double first = travel;
    // The largest raise the clause's turns allow (kMaxRaisedTurn), with kMaxBoost's.
    double most = kMaxBoost;
    for (size_t j : raised)
      if (turns_degrees(plan.actions[j]) && std::fabs(plan.amplitude(plan.actions[j])) > 1e-9)
        most = std::min(most, std::max(1.0, kMaxRaisedTurn / std::fabs(plan.amplitude(plan.actions[j]))));
    for (int round = 0; round < kRaiseRounds && travel > 0 && travel < floor && boost < most - 1e-9; ++round) {
      const double step = std::min(most / boost, kRaiseAim * floor / travel);
      for (size_t j : raised) plan.actions[j].scale *= step;
      boost *= step;
      travel = c.travel(plan, raised);
    }
    boost *= carry_farther(c, plan, raised, first > 0 ? travel : 0);
    if (boost > 1) {
      char line[300];
      std::snprintf(line, sizeof line, "%s%s raised to %.0f %%: it moved %.1f %% of the figure's size, too little to see%s",
                    plan.actions[clause.front()].verb.c_str(), held_by.empty() ? "" : "'s gait on the body", boost * 100,
                    c.percent(first), held_by.c_str());
      plan.notes.push_back(line);
    }
    slow_to_follow(c, plan, clause);
  }
}

// A warning for each clause that ends under the visible floor, naming what held it there (`cut`:
// why fit_scales scaled each action down): the canvas (a legitimate limit: a figure filling its
// picture), the fitter's steps, or kMaxBoost. report.html lists motion.json's warnings.
void warn_under_floor(const TravelCheck& c, MotionPlan& plan, const std::vector<std::string>& cut) {
  for (const auto& clause : measured_clauses(plan)) {
    const double travel = c.travel(plan, clause);
    if (travel <= 0 || travel >= c.floor() * (1 - 1e-3) || spins_in_place(plan, clause)) continue;
    std::string by;
    for (size_t j : clause)
      if (by.empty() && cut[j] == "would leave the canvas") by = "by the canvas";
    for (size_t j : clause)
      if (by.empty() && cut[j] == "would fold its mesh") by = "by its mesh, folding at a larger bend";
    for (size_t j : clause)
      if (by.empty() && !cut[j].empty()) by = "by the fitter's steps between keyframes";
    if (by.empty())
      by = "by the largest raise (" + std::to_string(static_cast<int>(kMaxBoost)) + " times, turns to " +
           std::to_string(static_cast<int>(kMaxRaisedTurn)) + " degrees)";
    char line[300];
    std::snprintf(line, sizeof line, "%s held to %.1f %% of the figure's size %s, under the %.0f %% a viewer can see",
                  plan.actions[clause.front()].verb.c_str(), c.percent(travel), by.c_str(), 100 * kVisibleTravel);
    plan.warnings.push_back(line);
  }
}

// fit_plan's scaling of `plan` (see motion_plan.h). True when a motion of the whole figure
// would break a limit even at its smallest scale (a warning says so).
bool fit_scales(const Scene& scene, const Rig& rig, MotionPlan& plan, int frames, int keyframes) {
  bool whole_failed = false;
  // Points exempt from the step limit: falling elements (they jump back while invisible),
  // spinning parts (whole turns cannot be scaled; rotation is what flow tracking follows best)
  // and a figure turning about its vertical axis (whole turns, or turning round to go: it is
  // mirrored at the edge-on moment, where the fitter starts from the known map).
  std::vector<char> exempt, by_curve;
  {
    bool turns = false;
    for (const auto& a : plan.actions) turns = turns || a.primitive == Primitive::Turn || (a.turns_round && a.amp != 0);
    std::set<int> spinning;
    for (const auto& a : plan.actions)
      if (a.primitive == Primitive::Spin || a.primitive == Primitive::Windmill)  // whole turns: not scaled
        for (int p : a.parts) spinning.insert(p);
    bool falls = false;
    for (const auto& a : plan.actions) falls = falls || a.primitive == Primitive::Fall;
    std::set<std::pair<int, int>> falling;  // (path, subpath); subpath -1: every subpath
    if (falls)
      for (const auto& el : rig.repeated)
        for (const ElementPiece& piece : el) falling.insert({piece.path, piece.subpath});
    for (size_t pi = 0; pi < scene.paths.size(); ++pi) {
      bool spin = false;
      for (int g = rig.part_of_path[pi], guard = 0; g >= 0 && guard < 64; g = rig.parts[g].parent, ++guard)
        spin = spin || spinning.count(g) > 0;
      const bool whole_falls = falling.count({static_cast<int>(pi), -1}) > 0;
      for (size_t si = 0; si < scene.paths[pi].subpaths.size(); ++si) {
        const auto& sp = scene.paths[pi].subpaths[si];
        const bool ex = spin || turns || whole_falls || falling.count({static_cast<int>(pi), static_cast<int>(si)}) > 0;
        exempt.insert(exempt.end(), sp.points.size(), ex);
        by_curve.insert(by_curve.end(), sp.points.size(), spin);
      }
    }
  }
  const int K = std::clamp(keyframes, 2, frames);
  // The fitter may take up to twice as many keyframes as it was given (the fitter plugin reads
  // motion.json's "keyframes"): a motion too fast for K keyframes gets more of them before its
  // amplitude is cut. Cut to follow 15 keyframes, a butterfly's wings, a snake and a skier moved
  // 11-64 % of what their verbs ask, too little to see.
  const int K_hi = std::min(frames, 2 * (K - 1) + 1);
  const TravelCheck check{scene, rig, exempt, by_curve, frames, K_hi};
  raise_to_visible(check, plan);
  std::vector<std::string> cut(plan.actions.size());  // why each action was scaled down ("": it was not)
  unfold_region_bends(scene, rig, plan, frames, cut);
  // Why `one` at its scales breaks a limit ("" when none): the canvas, then the steps and turns
  // between K_hi keyframes.
  auto broken = [&](const MotionPlan& one) {
    const std::vector<Vec2> pts = animate_plan(scene, rig, one, frames);
    std::string why = limit_broken(scene, pts, exempt, by_curve, frames, K_hi);
    if (why.empty()) why = turn_broken(one, frames, K_hi);
    return why;
  };
  // Each action alone first, then all together.
  for (size_t i = 0; i <= plan.actions.size(); ++i) {
    const bool all = i == plan.actions.size();
    if (all) {
      accents_follow_limbs(plan);
      tie_crawl_scales(plan);
    }
    if (!all && (plan.actions[i].primitive == Primitive::Spin || plan.actions[i].primitive == Primitive::Turn ||
                 plan.actions[i].primitive == Primitive::Windmill))
      continue;
    const std::string what = all ? "the motion" : plan.actions[i].verb + " (" + primitive_name(plan.actions[i].primitive) + ")";
    // The largest scale (from the current one down by 0.8) at which `one` keeps the limits, and
    // why the first scale tried did not; -1 when none of kScaleAttempts does.
    const std::vector<size_t> together = all ? std::vector<size_t>{} : scaled_with(plan, i);
    auto in = [](const std::vector<size_t>& v, size_t j) { return std::find(v.begin(), v.end(), j) != v.end(); };
    auto search = [&](MotionPlan one, double start, std::string* first_why) {
      double scale = start;
      for (int attempt = 0; attempt <= kScaleAttempts; ++attempt, scale *= 0.8) {
        for (size_t j : together) one.actions[j].scale = scale;
        if (!all) one.actions[i].scale = scale;
        else one.scale = scale;
        const std::string why = broken(one);
        if (why.empty()) return scale;
        if (first_why->empty()) *first_why = why;
      }
      return -1.0;
    };
    MotionPlan one = all ? plan : only(plan, together);
    double& scale = all ? plan.scale : plan.actions[i].scale;
    std::string first_why;
    double best = search(one, scale, &first_why);
    // A back-and-forth action the canvas stops on one side (a raised hand at the top edge of an
    // emoji swinging out past it) swings to the other side only, at full size, rather than
    // shrinking both ways to nothing.
    if (!all && best < scale && oscillates(plan.actions[i]) && first_why == "would leave the canvas")
      for (int side : {1, -1}) {
        MotionPlan sided = one;
        sided.actions[i].one_sided = side;
        std::string why;
        const double s = search(sided, scale, &why);
        if (s > best * 1.05) {
          best = s;
          plan.actions[i].one_sided = side;
        }
      }
    // A travel (a figure going somewhere: goes, inches; a launch) or a carried flight's body (a hover's
    // bob, a buzz's dart: kCarriedTravel) uses the room the canvas leaves, not the 0.8 step
    // under it: halved between the scale kept and the one broken, four times. Cut by 0.8 from a
    // reach of 15 %, an ant's march went 12 % where 13.4 % fitted. Each scale tried
    // must fit with the other motions too: alone, a rabbit's travel took the room its hops
    // needed, and the whole motion was cut to 80 %.
    if (!all && best > 0 && best < scale && (plan.actions[i].goes || plan.actions[i].inches || carried_whole(plan.actions[i]) || launches(plan.actions[i])))
      for (double hi = std::min(scale, best / 0.8), k = 0; k < 4; ++k) {
        const double mid = 0.5 * (best + hi);
        MotionPlan at = one, with_all = plan;  // alone and with the rest (a hop beside it)
        for (size_t j : together) at.actions[j].scale = with_all.actions[j].scale = mid;
        (broken(at).empty() && broken(with_all).empty() ? best : hi) = mid;
      }
    // A climb with no room above (a launch from a figure at the canvas's top) is left out when
    // its words move the figure otherwise (the launch going away, smaller): kept at the smallest
    // scale, it still left the canvas and shrank every motion with it to half.
    if (best < 0 && !all && climbs_with_more(plan, i)) {
      scale = 0;
      plan.notes.push_back(what + " left out: no room above to climb");
      continue;
    }
    if (best < 0) {
      for (size_t j = 0; j < plan.actions.size(); ++j)
        if ((all || in(together, j)) && cut[j].empty()) cut[j] = first_why;
      scale *= std::pow(0.8, kScaleAttempts);
      for (size_t j : together) plan.actions[j].scale = scale;
      plan.warnings.push_back(what + " " + first_why + " even at " + std::to_string(static_cast<int>(scale * 100)) + " % of its size");
      whole_failed = whole_failed || (!all && plan.actions[i].target == Target::Whole);
      continue;
    }
    if (!all && plan.actions[i].one_sided != 0)
      plan.notes.push_back(what + " swings to one side only: the other " + first_why);
    if (best < scale) {
      for (size_t j = 0; j < plan.actions.size(); ++j)
        if ((all || in(together, j)) && cut[j].empty()) cut[j] = first_why;
      char line[240];
      std::snprintf(line, sizeof line, "%s scaled to %.0f %%: at full size %s %s", all ? "all amplitudes" : ("the amplitude of " + what).c_str(),
                    best * 100, all ? "the motion" : "it", first_why.c_str());
      plan.notes.push_back(line);
    }
    scale = best;
    for (size_t j : together) plan.actions[j].scale = best;
  }
  // The keyframes the fitter needs for the motion as scaled.
  const int need = keyframes_to_follow(scene, animate_plan(scene, rig, plan, frames), plan, exempt, frames, K, K_hi);
  plan.keyframes = need > 0 ? need : K_hi;
  if (plan.keyframes > K)
    plan.notes.push_back("the fitter takes " + std::to_string(plan.keyframes) + " keyframes instead of " + std::to_string(K) +
                         ": between " + std::to_string(K) + " the motion moves too far to follow");
  warn_under_floor(check, plan, cut);
  return whole_failed;
}

// A figure bobbing on a ground band the prompt names ("bobs on the waves"; support_band.h)
// rises from it and settles back, unless the words say down: bobbing down it sank into the
// band, and raised to a visible size (8 % of a sailboat) its hull, 4.5 px above waves drawn in
// front of it, vanished behind them (the pixel ranker's continuity flag on every candidate).
// No band found, nothing to sink into: "on the breeze" bobs both ways.
void rise_from_ground(const Scene& scene, const Rig& rig, MotionPlan& plan) {
  if (plan.ground.empty()) return;
  const std::vector<char> band = support_paths(scene, rig, plan.ground);
  if (std::find(band.begin(), band.end(), 1) == band.end()) return;
  for (auto& a : plan.actions)
    if (a.primitive == Primitive::Bob && a.target == Target::Whole && a.vertical == 0 && a.amp > 0) {
      a.vertical = 1;
      plan.notes.push_back(a.verb + " rises from " + plan.ground.substr(plan.ground.find(' ') + 1) + " and settles back: down, it would sink into it");
    }
}

}  // namespace

void fit_plan(const Scene& scene, const Rig& rig, MotionPlan& plan, int frames, int keyframes) {
  rise_from_ground(scene, rig, plan);
  rise_from_seat(scene, rig, plan);
  roll_invisible_spins(scene, rig, plan);
  const MotionPlan asked = plan;
  if (!fit_scales(scene, rig, plan, frames, keyframes)) return;
  // The whole figure cannot move in the canvas at all: small parts of it at the canvas's edge
  // (a splash running off the picture beside a surfer who fills it) hold it there. Those parts
  // hold, as the background does, and the rest moves; kept when it then fits.
  const double m = kFrameMargin * std::min(scene.width, scene.height);
  std::vector<int> edge;
  for (size_t i = 0; i < rig.parts.size(); ++i) {
    const RigPart& P = rig.parts[i];
    if (static_cast<int>(i) == rig.root || P.role == Role::Background || P.box.empty()) continue;
    if (P.box.x0 <= m || P.box.y0 <= m || P.box.x1 >= scene.width - m || P.box.y1 >= scene.height - m) edge.push_back(static_cast<int>(i));
  }
  edge = topmost(rig, edge);
  std::vector<int> held;
  for (int e : edge)
    if (chain_box(rig, e).area() <= kHeldMaxShare * rig.figure.area()) held.push_back(e);
  if (held.empty()) return;
  MotionPlan retry = asked;
  retry.held = held;
  if (fit_scales(scene, rig, retry, frames, keyframes)) return;
  std::vector<std::string> names;
  for (int h : held) names.push_back(rig.parts[h].name);
  retry.notes.push_back("the whole figure could not move inside the canvas: " + join(names, ", ") + " at its edge hold" +
                        (held.size() > 1 ? "" : "s") + " still");
  plan = retry;
}


}  // namespace svgm
