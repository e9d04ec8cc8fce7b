// The ground band a figure moves on (support_band.h).
#include "procedural/support_band.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "geometry/curve_samples.h"
#include "motion/lexicon.h"
#include "procedural/gait_travel.h"
#include "procedural/motion_plan_internal.h"
#include "procedural/part_rig_internal.h"
#include "procedural/travel_words.h"

namespace svgm {

namespace {

// The band spans at least this share of the figure's width, reaches within kBottom of the
// figure's height from its bottom and starts below kTop of it from its top (a sea, a road, a
// lawn; not the boat's hull above the water, nor the body). A rowing boat's sea is nearly half
// the drawing's height.
constexpr double kWide = 0.6, kBottom = 0.05, kTop = 0.4;
// Paths within the band, or reaching at most this share of the figure's height above it (the
// crest line of its waves), belong to it.
constexpr double kCrest = 0.05;
// A ground as wide as the figure is a slab: its fill covers at least this share of its box (of
// its widest path; measured on both emoji sets: the water a polo player stands in 0.68 and 0.92,
// a rower's sea 0.83 to 0.93, boats' seas 0.89 to 1, beaches 0.68 and 0.90, an island's shore
// 0.46, a surfer's wave 0.52). A figure's own part lying along its bottom curves and leaves its
// box mostly empty: the tail twemoji's merfolk curl under them as wide as the figure 0.33, the
// whales' bellies 0.19 and 0.28. Read as ground, the mermaid's tail was left out of her
// silhouette and "flicks her tail" bent the far end of her body instead.
constexpr double kSlab = 0.4;
// A band starting above kTop is still the ground when the rest of the figure stands on it
// (rest_stands_on): what stands on it reaches at most this share of its height into it.
constexpr double kSunk = 0.5;

}  // namespace

bool names_ground(const std::string& p) {
  return p == "on" || p == "onto" || p == "along" || p == "across" || p == "over" || p == "through" || p == "off";
}

// Where the figure moves ("bobs on the waves"; support_band.h): "on the waves" for the first
// noun after a preposition of place that names no part of the figure; empty when none does.
// A launch leaves a ground ("takes off from the runway"), named or not ("off the ground"): the
// runway drawn under a plane rose with it (the support band, when the drawing has one, stays).
// So does a landing come down on one (an arriving plane's runway rocked with it).
std::string ground_words(const ParsedPrompt& prompt, const Rig& rig) {
  using motion_plan_internal::parts_for;
  bool launch = false, goes = false;
  for (const Clause& c : prompt.clauses) {
    const bool leaves = std::any_of(c.verbs.begin(), c.verbs.end(), [](const Verb* v) { return v && (v->name == "takeoff" || v->name == "land"); });
    // A figure that leaves untold which way ("the ship sails away": leave_way.h) leaves its
    // ground as a launch does: the sea stays while the ship goes.
    // So does a thing going into the distance or coming nearer (depth_travel.h: the sea and
    // the track stay as the ship recedes).
    launch = launch || leaves || (c.mods.travel == 0 && (says_leaving(c) || (c.mods.depth != 0 && !is_creature(c.figure))));
    // A thing sent a way told ("the ship sails away to the left", "glides across the water",
    // "the train pulls away to the left") leaves the ground it goes on as well: the sea and the
    // track went along with the ship and the train, as if painted on them. Not a creature's gait,
    // whose skis, board or skates are drawn as wide bands under it and go with it.
    goes = goes || (!is_creature(c.figure) && c.mods.travel != 0 &&
                    std::any_of(c.verbs.begin(), c.verbs.end(), [](const Verb* v) { return v && (locomotes(*v) || v->name == "move"); }));
    for (const auto& n : c.nouns) {
      if (!n.object_of_preposition || n.target != Target::Named || !(names_ground(n.preposition) || (leaves && n.preposition == "from")))
        continue;
      // "on his skis", "on its board": the figure's own gear goes with it (seat_support.h); left
      // as ground, the skis stayed while the skier glided off them.
      if (n.owned && n.preposition != "from") continue;
      std::string ignore;
      if (parts_for(rig, Target::Named, n.word, &ignore).empty()) return n.preposition + " the " + n.word;
    }
  }
  return launch ? "off the ground" : goes ? kAlongGround : "";
}

namespace {

// Whether the figure's paths other than `band` stand on the band whose box is B: more of them
// lie above it (reaching at most kSunk of its height into it: a hull sits in the water) than
// within it, and none hangs lower. A tall sea (62 % of a motorboat's drawing) starts above
// kTop; a vehicle's body reaching its bottom holds most of its paths (windows, wheels) within.
bool rest_stands_on(const std::vector<RigBox>& box, const std::function<bool(size_t)>& figure_path, size_t band, double eps) {
  const RigBox& B = box[band];
  int above = 0, within = 0;
  for (size_t i = 0; i < box.size(); ++i) {
    const RigBox& b = box[i];
    if (i == band || !figure_path(i) || b.empty()) continue;
    if (b.y0 >= B.y0 - eps && b.x0 >= B.x0 - eps && b.x1 <= B.x1 + eps) ++within;
    else if (b.y1 <= B.y0 + kSunk * B.h()) ++above;
    else return false;
  }
  return above > within;
}

// The band at least `wide` of the figure's width among the paths whose boxes are `box` and
// whose widest connected pieces are `piece` wide (see support_band.h), per path.
std::vector<char> band_of(const std::vector<RigBox>& box, const std::vector<double>& piece, const Rig& rig, double wide, bool stood_on = false) {
  const size_t n = box.size();
  std::vector<char> out(n, 0);
  const RigBox& F = rig.figure;
  if (F.empty()) return out;
  const double W = F.w(), H = F.h();
  const double eps = kCrest * H;
  const std::function<bool(size_t)> figure_path = [&](size_t i) {
    const int g = i < rig.part_of_path.size() ? rig.part_of_path[i] : -1;
    return g < 0 || rig.parts[g].role != Role::Background;
  };
  int band = -1;
  for (size_t i = 0; i < n; ++i) {
    const RigBox& b = box[i];
    if (!figure_path(i) || b.empty()) continue;
    if (b.w() < wide * W || b.y1 < F.y1 - kBottom * H) continue;
    // A ground is one piece across: two wheels drawn as one path span the width in two.
    if (i < piece.size() && piece[i] < wide * W) continue;
    if (b.y0 < F.y0 + kTop * H && !rest_stands_on(box, figure_path, i, eps)) continue;
    if (band < 0 || b.w() > box[band].w()) band = static_cast<int>(i);
  }
  if (band < 0 || (stood_on && !rest_stands_on(box, figure_path, band, eps))) return out;
  const RigBox& B = box[band];
  bool above = false;  // something of the figure stands above the band
  for (size_t i = 0; i < n; ++i) {
    const RigBox& b = box[i];
    if (!figure_path(i) || b.empty()) continue;
    const bool within = b.y0 >= B.y0 - eps && b.x0 >= B.x0 - eps && b.x1 <= B.x1 + eps;
    out[i] = within;
    above = above || (!within && b.y1 <= B.y1);
  }
  if (!above) std::fill(out.begin(), out.end(), 0);
  return out;
}

}  // namespace

static std::vector<RigBox> path_boxes(const Scene& scene) {
  std::vector<RigBox> box(scene.paths.size());
  for (size_t i = 0; i < box.size(); ++i) box[i] = part_rig_internal::path_box(scene.paths[i]);
  return box;
}

// The width of each path's widest subpath (its control points' box).
static std::vector<double> piece_widths(const Scene& scene) {
  std::vector<double> out(scene.paths.size(), 0);
  for (size_t i = 0; i < out.size(); ++i)
    for (const Subpath& s : scene.paths[i].subpaths) {
      RigBox b;
      for (const Vec2& p : s.points) b.add(p);
      out[i] = std::max(out[i], b.w());
    }
  return out;
}

std::vector<char> support_paths(const Scene& scene, const Rig& rig, const std::string& words) {
  return band_of(path_boxes(scene), piece_widths(scene), rig, kWide, words == kAlongGround);
}

// The fill of path p over its box: the control polygons' signed areas added (a hole takes its
// share away), or -1 for a path with no fill (a stroke says nothing of a slab).
static double fill_share(const Path& p, const RigBox& box) {
  if (!p.has_fill || box.area() <= 0) return -1;
  double area = 0;
  for (const Subpath& s : p.subpaths) area += shoelace(s.points);
  return std::fabs(area) / box.area();
}

std::vector<char> ground_band_paths(const Scene& scene, const Rig& rig) {
  const std::vector<RigBox> box = path_boxes(scene);
  std::vector<char> out = band_of(box, piece_widths(scene), rig, kGroundWide);
  // Its widest path is a slab, or the band is the figure's own (kSlab).
  int widest = -1;
  for (size_t i = 0; i < out.size(); ++i)
    if (out[i] && (widest < 0 || box[i].w() > box[widest].w())) widest = static_cast<int>(i);
  if (widest >= 0) {
    const double share = fill_share(scene.paths[widest], box[widest]);
    if (share >= 0 && share < kSlab) std::fill(out.begin(), out.end(), 0);
  }
  return out;
}

std::vector<char> support_paths(const Rig& rig) {
  std::vector<RigBox> box(rig.part_of_path.size());
  std::vector<double> piece(box.size(), 0);
  for (const RigElement& e : rig.elements)
    if (e.path >= 0 && static_cast<size_t>(e.path) < box.size()) {
      box[e.path].add(e.box);
      piece[e.path] = std::max(piece[e.path], e.box.w());
    }
  return band_of(box, piece, rig, kWide);
}

}  // namespace svgm
