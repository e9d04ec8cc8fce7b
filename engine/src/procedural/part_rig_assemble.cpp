// The rig's assembly (see part_rig.h): given the paths of each part (part_rig_units.cpp), their
// boxes and names, the background, the root, each part's parent and pivot, the roles of the
// parts hanging from the root, a line drawing's strokes, arm lobes, the silhouette's limbs,
// wheels, default names and repeated elements, as a list of steps on the state they share.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "scene/backdrop.h"
#include "procedural/part_rig_internal.h"
#include "procedural/repeated_elements.h"
#include "procedural/shape_overlap.h"
#include "procedural/skeleton_lobes.h"
#include "procedural/stroke_rig.h"
#include "procedural/support_band.h"

namespace svgm::part_rig_internal {

namespace {

// A part above the root more than this many times as tall as wide is a raised limb, not the
// head (a bird's wing raised above its back; heads in the bench drawings are 0.6-1.5).
constexpr double kHeadMaxAspect = 2.0;
// In a line drawing (stroke_rig.h): the head's middle lies above this share of the body's height
// from its top (its strokes sit on the shoulders; an arm stroke drawn from the shoulder out and
// up is no head), strokes alongside the root lie within this share of the figure's extent across
// the root's middle, and a stroke's end touches another's curve within this share of the
// figure's diagonal.
constexpr double kLineHeadTop = 0.1;
constexpr double kLineAcross = 0.2;
constexpr double kLineTouch = 0.03;
// The rest of a drawing with one backdrop, all of it together under this share of the
// backdrop's fill area, is details drawn on it, not a figure before it: twemoji's snake (1f40d),
// its body winding across the canvas and cut by its right edge (0.69 of it), has an eye and a
// tongue of 3.7 % of its area. A scene with a figure (the suites' climber on a rock face) keeps
// its backdrops: it has two, and its figure is far larger.
constexpr double kDetailsOnly = 0.05;
constexpr const char* kBackdropWhy = "large, at the canvas edges, painted first";

// Each hanging part's chain top: the part its chain hangs from the root by (the guard stops a
// cycle of parents).
void set_chain_tops(Rig& rig) {
  const int G = static_cast<int>(rig.parts.size());
  for (int g = 0; g < G; ++g) {
    RigPart& P = rig.parts[g];
    if (P.parent < 0) continue;
    int top = g, guard = 0;
    while (rig.parts[top].parent != rig.root && rig.parts[top].parent >= 0 && guard++ < G) top = rig.parts[top].parent;
    P.chain_top = top;
  }
}

// The state the steps of assemble share: the parts to be, the rig being built, and what one
// step measures for the next (each step's comment says what it adds).
struct Assembly {
  Assembly(const Scene& s, const SourceNames& n, const std::vector<std::string>& gn, const Units& u)
      : scene(s), names(n), group_names(gn), U(u), unit_paths(u.paths), unit_group(u.group), unit_split(u.split),
        wheel_paths(u.wheels), G(static_cast<int>(u.paths.size())), n_paths(s.paths.size()), CW(s.width), CH(s.height) {}

  const Scene& scene;
  const SourceNames& names;
  const std::vector<std::string>& group_names;
  const Units& U;
  const std::vector<std::vector<int>>& unit_paths;
  const std::vector<int>& unit_group;
  const std::vector<char>& unit_split;
  const std::set<int>& wheel_paths;
  const int G;
  const size_t n_paths;
  const double CW, CH;

  Rig rig;
  std::vector<double> mean_index;  // mean path index of each part (measure_parts)
  // As drawn (measure_as_drawn): a line drawing's parts by their curves, others by their points.
  bool line = false;
  std::vector<RigBox> cbox;
  std::vector<double> size;
  RigBox cfigure;
  double fdiag = 0, cdiag = 0;  // the figure's diagonals (choose_root)
  // The body the limbs are placed against (place_body).
  RigBox body;
  std::vector<char> in_body;
  double head_top = 0.25;
  Vec2 rc;
  double rw = 0, rh = 0;

  void measure_parts();
  void name_parts();
  bool find_background();
  void measure_as_drawn();
  void choose_root();
  void hang_parts();
  void place_body();
  int roles_from_root();
  void settle_heads(int head);
  void find_tail();
  void hang_line_strokes();
  void roles_from_chains_and_names();
  void pivot_stroke_limbs();
  void find_arm_lobes();
  void find_silhouette_limbs();
  void find_wheels();
  void default_names();
  void find_repeated();
};

// Each part's box, fill area, base width and paint order (its paths' mean index).
void Assembly::measure_parts() {
  rig.canvas.add(Vec2{0, 0});
  rig.canvas.add(Vec2{scene.width, scene.height});
  rig.parts.resize(G);
  rig.part_of_path.assign(n_paths, -1);
  mean_index.assign(G, 0);
  for (int g = 0; g < G; ++g) {
    RigPart& P = rig.parts[g];
    P.group = unit_group[g];
    for (int pi : unit_paths[g]) {
      rig.part_of_path[pi] = g;
      mean_index[g] += pi;
      for (const auto& sp : scene.paths[pi].subpaths) {
        for (const Vec2& q : sp.points) P.box.add(q);
        P.area += std::fabs(shoelace(sp.points));
      }
    }
    if (!unit_paths[g].empty()) mean_index[g] /= static_cast<double>(unit_paths[g].size());
    P.base_x0 = P.box.x1;
    P.base_x1 = P.box.x0;
    for (int pi : unit_paths[g])
      for (const auto& sp : scene.paths[pi].subpaths)
        for (const Vec2& q : sp.points)
          if (q.y >= P.box.y1 - 0.25 * P.box.h()) {
            P.base_x0 = std::min(P.base_x0, q.x);
            P.base_x1 = std::max(P.base_x1, q.x);
          }
  }
}

// Names from the grouper or the document, and the words a prompt or a plan pattern matches.
void Assembly::name_parts() {
  // Names: the named element that best covers the part's paths (precision times recall).
  std::map<std::string, int> element_total;
  for (const Path& p : scene.paths)
    if (auto it = names.find(p.id); it != names.end())
      for (const auto& e : it->second) ++element_total[e.locator];
  for (int g = 0; g < G; ++g) {
    RigPart& P = rig.parts[g];
    if (!unit_split[g] && P.group < static_cast<int>(group_names.size()) && meaningful(group_names[P.group])) {
      P.name = group_names[P.group];
      P.named = true;
    } else {
      std::map<std::string, std::pair<int, std::string>> in_part;
      for (int pi : unit_paths[g])
        if (auto it = names.find(scene.paths[pi].id); it != names.end())
          for (const auto& e : it->second) {
            auto& slot = in_part[e.locator];
            ++slot.first;
            slot.second = e.name;
          }
      double best = 0.25;  // at least half the part's paths and half the element's
      for (const auto& [loc, hit] : in_part) {
        const double score = static_cast<double>(hit.first) / unit_paths[g].size() *
                             hit.first / std::max(1, element_total[loc]);
        if (score > best || (score == best && P.named && loc.size() > 0)) {
          best = score;
          P.name = hit.second;
          P.named = true;
        }
      }
    }
    // A wheel split from a named group is that group's wheel ("bicycle_wheel").
    if (P.named && unit_paths[g].size() == 1 && wheel_paths.count(unit_paths[g][0]) && !has_word(name_words(P.name), {"wheel", "tire", "tyre"}))
      P.name += "_wheel";
    for (const auto& w : name_words(P.name))
      if (!is_generic_word(w)) P.words.push_back(w);
  }
}

// The background parts (named, or a backdrop); false when nothing is left for the figure.
bool Assembly::find_background() {
  // Background.
  int figure_parts = 0;
  for (int g = 0; g < G; ++g) {
    RigPart& P = rig.parts[g];
    if (P.box.empty()) continue;
    if (has_word(P.words, {"background", "bg", "sky", "ground", "floor", "backdrop", "scenery", "landscape", "hill", "mountain",
                             "mud", "grass", "road", "terrain", "field", "wall"})) {
      P.role = Role::Background;
      P.why = "named as background";
    } else if (U.scenery.count(unit_paths[g].front())) {
      P.role = Role::Background;
      P.why = "the scenery around the scene's subject";
    } else if (is_backdrop(scene, unit_paths[g], P.box.x0, P.box.y0, P.box.x1, P.box.y1, mean_index[g] / static_cast<double>(n_paths))) {
      P.role = Role::Background;
      P.why = kBackdropWhy;
    } else {
      ++figure_parts;
    }
  }
  // Nothing left to animate, or only details drawn on one large shape the box rule took for a
  // backdrop (a snake winding across its canvas, its eye and tongue): there is no background.
  double backdrop_area = 0, figure_area = 0;
  int backdrops = 0;
  for (const auto& P : rig.parts) {
    if (P.box.empty()) continue;
    if (P.role != Role::Background) figure_area += P.area;
    else if (P.why == kBackdropWhy) backdrop_area = std::max(backdrop_area, P.area), ++backdrops;
  }
  if (figure_parts == 0 || (backdrops == 1 && figure_area < kDetailsOnly * backdrop_area))
    for (auto& P : rig.parts)
      if (P.role == Role::Background) { P.role = Role::Detail; P.why.clear(); }
  for (const auto& P : rig.parts)
    if (P.role != Role::Background) rig.figure.add(P.box);
  return !rig.figure.empty();
}

// The parts as drawn: a line drawing's by their curves.
void Assembly::measure_as_drawn() {
  // A line drawing (stroke_rig.h): each part one stroke, sized by its curve's length and
  // placed by its curve's box; elsewhere the part's area and its control points' box.
  line = is_line_drawing(scene);
  cbox.assign(G, RigBox());
  size.assign(G, 0);
  for (int g = 0; g < G; ++g) {
    cbox[g] = rig.parts[g].box;
    size[g] = rig.parts[g].area;
    if (!line || unit_paths[g].size() != 1) continue;
    cbox[g] = stroke_box(scene.paths[unit_paths[g][0]]);
    size[g] = stroke_length(scene.paths[unit_paths[g][0]]);
    if (rig.parts[g].role != Role::Background) cfigure.add(cbox[g]);
  }
  if (!line) cfigure = rig.figure;
}

// The root, its role and its pivot.
void Assembly::choose_root() {
  // Root: a part named body/torso, else the largest central part.
  const Vec2 fc = cfigure.centre();
  fdiag = std::hypot(rig.figure.w(), rig.figure.h());
  cdiag = std::hypot(cfigure.w(), cfigure.h());
  double best = -1;
  for (int g = 0; g < G; ++g) {
    const RigPart& P = rig.parts[g];
    if (P.role == Role::Background || P.box.empty()) continue;
    const Vec2 c = cbox[g].centre();
    const double d = std::hypot(c.x - fc.x, c.y - fc.y) / (0.25 * cdiag);
    double score = std::max(size[g], 1e-9) / (1 + d * d);
    if (has_word(P.words, {"body", "torso", "trunk"})) score = 1e300;
    if (g == U.root) score = 1e301;
    // What a wheel carries hangs from the wheel: it is never the root (its wheel may be).
    if (U.carried_by.count(unit_paths[g].front())) score = 0;
    if (score > best) { best = score; rig.root = g; }
  }
  RigPart& R = rig.parts[rig.root];
  R.role = Role::Root;
  R.why = R.why.empty() ? "largest central part" : R.why;
  R.pivot = {R.box.centre().x, R.box.y1};
  R.chain_top = rig.root;
}

// Each part's parent and pivot, and the chains they make.
void Assembly::hang_parts() {
  const RigPart& R = rig.parts[rig.root];
  // Parents and pivots. A part hangs from the larger part whose shape it overlaps most
  // (procedural/shape_overlap.h: boxes let a trident across the head take the horn from the hood).
  std::vector<PartShape> shape(static_cast<size_t>(G));
  for (int g = 0; g < G; ++g) shape[static_cast<size_t>(g)] = part_shape(scene, unit_paths[g]);
  for (int g = 0; g < G; ++g) {
    RigPart& P = rig.parts[g];
    if (g == rig.root || P.role == Role::Background || P.box.empty()) continue;
    int parent = rig.root;
    double best_overlap = shape_overlap(shape[g], shape[rig.root]), best_gap = gap(P.box, R.box);
    // What turns with a wheel hangs from it (split_wheel_loads), not from the stand whose box
    // holds its box. A limb split from the root's group hangs from the root (the grouper drew
    // it with the body, not with a raised arm's neighbour, the head).
    int wheel = -1;
    if (const auto it = U.carried_by.find(unit_paths[g].front()); it != U.carried_by.end())
      for (int h = 0; h < G; ++h)
        if (h != g && unit_paths[h].size() == 1 && unit_paths[h][0] == it->second) wheel = h;
    int arm = -1;
    if (const auto it = U.held_by.find(unit_paths[g].front()); it != U.held_by.end())
      for (int h = 0; h < G; ++h)
        if (h != g && !unit_paths[h].empty() && unit_paths[h].front() == it->second) arm = h;
    if (wheel >= 0) {
      parent = wheel;
      P.carried = true;
    }
    else if (arm >= 0) parent = arm;  // hands taken from the head hang from their arm (split_head_holds)
    else if (!line && P.area < R.area && !U.from_root.count(g))
      for (int h = 0; h < G; ++h) {
        const RigPart& Q = rig.parts[h];
        if (h == g || h == rig.root || Q.role == Role::Background || Q.box.empty()) continue;
        // A wheel does not hang from what it carries.
        if (const auto it = U.carried_by.find(unit_paths[h].front()); it != U.carried_by.end() && it->second == unit_paths[g].front())
          continue;
        if (!(Q.area > P.area || (Q.area == P.area && h < g))) continue;
        const double o = shape_overlap(shape[g], shape[h]), gp = gap(P.box, Q.box);
        if (o > best_overlap || (best_overlap == 0 && o == 0 && gp < best_gap)) {
          best_overlap = o;
          best_gap = gp;
          parent = h;
        }
      }
    P.parent = parent;
    const RigBox& pb = rig.parts[parent].box;
    const double pad = 0.01 * fdiag;
    Vec2 sum;
    int count = 0;
    Vec2 nearest;
    double nd = 1e300;
    for (int pi : unit_paths[g])
      for (const auto& sp : scene.paths[pi].subpaths)
        for (const Vec2& q : sp.points) {
          if (q.x >= pb.x0 - pad && q.x <= pb.x1 + pad && q.y >= pb.y0 - pad && q.y <= pb.y1 + pad) {
            sum = sum + q;
            ++count;
          }
          const double d = std::hypot(q.x - pb.centre().x, q.y - pb.centre().y);
          if (d < nd) { nd = d; nearest = q; }
        }
    // Points inside the parent's box: their centroid, pulled towards the parent's centre a
    // little when the part lies wholly inside the box (so a detail turns about its middle).
    P.pivot = count > 0 ? (1.0 / count) * sum : nearest;
  }
  // Chains: a limb's segments move with it.
  set_chain_tops(rig);
}

// The body the limbs are placed against, and its middle and size.
void Assembly::place_body() {
  // The body the limbs are placed against: the root; in a line drawing the root with the
  // strokes alongside it (a torso drawn as a bundle of hairpins), which hold still with it.
  body = line ? cbox[rig.root] : rig.parts[rig.root].box;
  in_body.assign(G, 0);
  if (line) {
    const bool upright = cbox[rig.root].h() >= cbox[rig.root].w();
    const double across = kLineAcross * (upright ? cfigure.w() : cfigure.h());
    for (int g = 0; g < G; ++g)
      if (g != rig.root && rig.parts[g].role != Role::Background && lies_alongside(cbox[g], cbox[rig.root], across)) {
        in_body[g] = 1;
        body.add(cbox[g]);
      }
  }
  head_top = line ? kLineHeadTop : 0.25;
  rc = body.centre();
  rw = std::max(body.w(), 1e-9);
  rh = std::max(body.h(), 1e-9);
}

// The roles of the parts hanging from the root by where they lie; returns the largest head.
int Assembly::roles_from_root() {
  // Roles of the parts hanging from the root, then names decide where they say something.
  int head = -1;
  for (int g = 0; g < G; ++g) {
    RigPart& P = rig.parts[g];
    if (P.parent != rig.root) continue;
    const RigBox& pbox = cbox[g];
    const Vec2 c = pbox.centre();
    const double dx = c.x - rc.x;
    const bool inside = overlap(pbox, body) >= 0.8 * pbox.area();
    if (in_body[g]) { P.role = Role::Detail; P.why = "a stroke alongside the root (the body)"; }
    else if (inside) { P.role = Role::Detail; P.why = "inside the root"; }
    else if (std::fabs(dx) < 0.35 * rw && c.y < body.y0 + head_top * rh && pbox.h() > kHeadMaxAspect * pbox.w()) {
      P.role = Role::UpperLimb;
      P.why = "above the root, tall and thin (a raised wing or arm)";
    } else if (std::fabs(dx) < 0.35 * rw && c.y < body.y0 + head_top * rh) {
      P.role = Role::Head;
      P.why = "central, above the root";
      if (head < 0 || P.area > rig.parts[head].area) head = g;
    } else if (c.y <= rc.y + 0.1 * rh && std::fabs(dx) >= 0.2 * rw) { P.role = Role::UpperLimb; P.why = "beside the root, upper half"; }
    else if (c.y > rc.y + 0.1 * rh) { P.role = Role::LowerLimb; P.why = "below the root's middle"; }
    else { P.role = Role::Detail; P.why = "near the root's middle"; }
    P.side = std::fabs(dx) < 0.1 * rw ? 0 : (dx < 0 ? 1 : -1);  // figure's own side: mirrored
  }
  return head;
}

void Assembly::settle_heads(int head) {
  // Only the largest head is the head; a smaller part above the root with its middle beside
  // the head is an arm raised above the shoulders, the others details of the head.
  for (int g = 0; g < G; ++g) {
    RigPart& P = rig.parts[g];
    if (P.role != Role::Head || g == head) continue;
    const RigBox& hb = cbox[head];
    if (cbox[g].centre().x < hb.x0 || cbox[g].centre().x > hb.x1) { P.role = Role::UpperLimb; P.why = "above the root, beside the head (a raised arm)"; }
    else { P.role = Role::Detail; P.why = "above the root (a smaller head part)"; }
  }
}

void Assembly::find_tail() {
  // Tail: the attached part reaching farthest sideways at the root's height, not the head.
  int tail = -1;
  double reach = 0.5 * rw;
  for (int g = 0; g < G; ++g) {
    const RigPart& P = rig.parts[g];
    if (P.parent != rig.root || P.role == Role::Head || P.role == Role::Detail) continue;
    const RigBox& pbox = cbox[g];
    const Vec2 c = pbox.centre();
    const double far = std::max(std::fabs(pbox.x0 - rc.x), std::fabs(pbox.x1 - rc.x));
    if (c.y >= body.y0 && c.y <= body.y1 && far > reach && cfigure.w() > cfigure.h()) { reach = far; tail = g; }
  }
  if (tail >= 0) { rig.parts[tail].role = Role::Tail; rig.parts[tail].why = "reaches farthest sideways at the root's height"; }
}

// A line drawing's limb strokes turn about their end nearer the body (stroke_body_end), and
// hang from a longer stroke of the same limb whose curve one of their ends touches (a shin
// drawn on from a thigh, a foot from a shin, the strokes of one leg meeting at its foot), else
// from the root. Hung from the stroke its box overlaps most, a torso stroke swung with a
// smaller arm stroke and the arms hung from a detail; a runner's back-leg strokes, meeting at
// the foot but each turning about its own end, crossed each other and the target tore (the
// ranker flagged a stroke's visible area falling from 40 to 11 px in a frame).
void Assembly::hang_line_strokes() {
  const double touch = kLineTouch * cdiag;
  for (int g = 0; g < G; ++g) {
    RigPart& P = rig.parts[g];
    if (g == rig.root || P.parent != rig.root || in_body[g] || unit_paths[g].size() != 1 ||
        (P.role != Role::UpperLimb && P.role != Role::LowerLimb && P.role != Role::Tail))
      continue;
    const Vec2 joint = {body.centre().x, P.role == Role::UpperLimb ? body.y0 : body.y1};
    P.pivot = stroke_body_end(scene.paths[unit_paths[g][0]], body, joint);
    P.why += "; one stroke, turns about its end nearer the body";
    double nearest = touch;
    const auto ends = stroke_ends(scene.paths[unit_paths[g][0]]);
    for (int h = 0; h < G; ++h) {
      const RigPart& Q = rig.parts[h];
      if (h == g || h == rig.root || in_body[h] || Q.role != P.role || unit_paths[h].size() != 1 || size[h] <= size[g]) continue;
      for (const Vec2& e : ends) {
        const double d = distance_to_stroke(e, scene.paths[unit_paths[h][0]]);
        if (d <= nearest) { nearest = d; P.parent = h; }
      }
    }
  }
  set_chain_tops(rig);
}

// A part down a chain takes its chain top's role and side; names overrule geometry.
void Assembly::roles_from_chains_and_names() {
  for (int g = 0; g < G; ++g) {
    RigPart& P = rig.parts[g];
    if (P.role == Role::Background || g == rig.root) continue;
    if (P.parent != rig.root && P.chain_top >= 0) { P.role = rig.parts[P.chain_top].role; P.side = rig.parts[P.chain_top].side; P.why = "hangs from " + rig.parts[P.parent].name; }
    if (has_word(P.words, {"head", "face"})) { P.role = Role::Head; P.why = "named"; }
    else if (has_word(P.words, {"arm", "hand", "wing", "forearm", "fist"})) { P.role = Role::UpperLimb; P.why = "named"; }
    else if (has_word(P.words, {"leg", "foot", "feet", "shin", "thigh"})) { P.role = Role::LowerLimb; P.why = "named"; }
    else if (has_word(P.words, {"tail"})) { P.role = Role::Tail; P.why = "named"; }
    if (has_word(P.words, {"right"})) P.side = 1;
    else if (has_word(P.words, {"left"})) P.side = -1;
  }
}

// A limb drawn as one open stroke (a line drawing's arm or leg) turns about its end nearest
// the body's joints: the root's top centre (shoulders) for an upper limb, its bottom centre
// (hips) for a lower limb (stroke_limb_pivot). The centroid of its points inside the root's
// box took a stroke hanging from the shoulder to the hip by its lower end: its top swung
// across the neck (a runner sketch's arm strokes).
void Assembly::pivot_stroke_limbs() {
  const RigPart& R = rig.parts[rig.root];
  for (int g = 0; g < G; ++g) {
    RigPart& P = rig.parts[g];
    if (line || P.parent != rig.root || unit_paths[g].size() != 1 || (P.role != Role::UpperLimb && P.role != Role::LowerLimb))
      continue;
    const Vec2 joint = {R.box.centre().x, P.role == Role::UpperLimb ? R.box.y0 : R.box.y1};
    if (const auto end = stroke_limb_pivot(scene.paths[unit_paths[g][0]], joint)) {
      P.pivot = *end;
      P.why += "; one stroke, turns about its end nearest the root's " + std::string(P.role == Role::UpperLimb ? "top" : "bottom");
    }
  }
}

// Arms drawn in a part's largest filled, closed outline (outline_lobes.h).
void Assembly::find_arm_lobes() {
  for (int g = 0; g < G; ++g) {
    RigPart& P = rig.parts[g];
    if (P.role == Role::Background) continue;
    int largest = -1;
    double most = 0;
    for (int pi : unit_paths[g]) {
      const Path& p = scene.paths[pi];
      if (!(p.has_fill && p.fill.a > 0) || p.subpaths.empty() || !p.subpaths[0].closed) continue;
      const double a = std::fabs(shoelace(p.subpaths[0].points));
      if (a > most) { most = a; largest = pi; }
    }
    if (largest >= 0) P.arm_lobes = arm_lobes(scene.paths[largest]);
  }
}

// The limbs of the figure's silhouette, without the ground band it stands in (support_band.h:
// the water's ends were a polo player's arms).
void Assembly::find_silhouette_limbs() {
  std::vector<int> figure_paths;
  for (int g = 0; g < G; ++g)
    if (rig.parts[g].role != Role::Background) figure_paths.insert(figure_paths.end(), unit_paths[g].begin(), unit_paths[g].end());
  std::sort(figure_paths.begin(), figure_paths.end());
  const std::vector<char> ground = ground_band_paths(scene, rig);
  std::vector<int> above;
  for (int pi : figure_paths)
    if (!ground[pi]) above.push_back(pi);
  if (!above.empty()) figure_paths = std::move(above);
  rig.limbs = skeleton_lobes(scene, figure_paths);
}

// Round parts (wheels).
void Assembly::find_wheels() {
  for (int g = 0; g < G; ++g) {
    RigPart& P = rig.parts[g];
    if (P.box.empty() || P.role == Role::Background) continue;
    double outline = 0;
    for (int pi : unit_paths[g])
      if (!scene.paths[pi].subpaths.empty())
        outline = std::max(outline, std::fabs(shoelace(scene.paths[pi].subpaths[0].points)));
    // A part named a wheel is round when its box could hold one seen at a slant: a flat band
    // (the ground under a bicycle, named with it) spun as a wheel tilted out of the picture.
    const double flat = std::max(P.box.w(), P.box.h()) / std::max(std::min(P.box.w(), P.box.h()), 1e-9);
    P.round = (has_word(P.words, {"wheel", "tire", "tyre"}) && flat <= kWheelFlatMax) || round_outline(P.box, outline, 0.005 * CW * CH);
    // A wheel split from its group turns; it is no limb to swing.
    if (unit_paths[g].size() == 1 && wheel_paths.count(unit_paths[g][0]) && g != rig.root) {
      P.role = Role::Detail;
      P.why = "a round path of its group (a wheel)";
    }
    // A line drawing's stroke that winds once round an oval (a sketched bicycle's wheel) is
    // round too, and no limb: the rig took a wheel below the body for a leg, and pedalling
    // swung it about its top like a shin. Its box is its curve's: a wheel spins about the middle
    // of the oval drawn, not of the cubic's handles (18 units off in livesketch's biking).
    if (line && g != rig.root && unit_paths[g].size() == 1 && is_loop_stroke(scene.paths[unit_paths[g][0]]) &&
        std::max(cbox[g].w(), cbox[g].h()) <= kWheelFlatMax * std::min(cbox[g].w(), cbox[g].h())) {
      P.box = cbox[g];
      P.wheel_plane = loop_plane(scene.paths[unit_paths[g][0]]);
      P.round = true;
      P.role = Role::Detail;
      P.why = "a stroke drawn round an oval (a wheel)";
    }
  }
}

// Default names from roles.
void Assembly::default_names() {
  std::map<std::string, int> used;
  for (int g = 0; g < G; ++g) {
    RigPart& P = rig.parts[g];
    if (!P.name.empty()) continue;
    std::string base = P.role == Role::Root ? "root" : P.role == Role::Head ? "head" : P.role == Role::Tail ? "tail"
                     : P.role == Role::Background ? "background" : P.role == Role::UpperLimb ? "limb_upper"
                     : P.role == Role::LowerLimb ? "limb_lower" : P.round ? "wheel" : "detail";
    if ((P.role == Role::UpperLimb || P.role == Role::LowerLimb) && P.side != 0) base += P.side > 0 ? "_right" : "_left";
    const int k = used[base]++;
    P.name = k == 0 ? base : base + "_" + std::to_string(k + 1);
  }
  // Names seen twice get a number, so a plan pattern can tell them apart.
  std::map<std::string, int> count, seen;
  for (const auto& P : rig.parts) ++count[P.name];
  for (auto& P : rig.parts)
    if (count[P.name] > 1 && P.named) P.name += "_" + std::to_string(++seen[P.name]);
}

// Repeated elements (repeated_elements.h), not in the background.
void Assembly::find_repeated() {
  std::vector<char> skip(n_paths, 0);
  for (size_t i = 0; i < n_paths; ++i) {
    const int g = rig.part_of_path[i];
    skip[i] = g >= 0 && rig.parts[g].role == Role::Background;
  }
  RepeatedElements r = find_repeated_elements(scene, skip);
  rig.repeated = std::move(r.elements);
  rig.repeated_why = std::move(r.why);
}

}  // namespace

Rig assemble(const Scene& scene, const SourceNames& names, const std::vector<std::string>& group_names, const Units& U) {
  Assembly a(scene, names, group_names, U);
  a.measure_parts();
  a.name_parts();
  if (!a.find_background()) return std::move(a.rig);
  a.measure_as_drawn();
  a.choose_root();
  a.hang_parts();
  a.place_body();
  a.settle_heads(a.roles_from_root());
  a.find_tail();
  if (a.line) a.hang_line_strokes();
  a.roles_from_chains_and_names();
  a.pivot_stroke_limbs();
  a.find_arm_lobes();
  a.find_silhouette_limbs();
  a.find_wheels();
  a.default_names();
  a.find_repeated();
  return std::move(a.rig);
}

}  // namespace svgm::part_rig_internal
