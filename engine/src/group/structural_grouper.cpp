// The structural grouper (see structural_grouper.h): flattened outlines, pairwise relations
// (containment, overlap, gap, colour) between nearby paths, then single-linkage merging.
#include "group/structural_grouper.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>
#include <string>
#include <unordered_map>
#include <utility>

#include "scene/backdrop.h"

namespace svgm {

namespace {

struct Box {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0;
  double x1 = -std::numeric_limits<double>::infinity(), y1 = x1;
  void add(Vec2 p) {
    x0 = std::min(x0, p.x), y0 = std::min(y0, p.y);
    x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
  }
  bool empty() const { return !(x0 <= x1); }
  double area() const { return empty() ? 0 : (x1 - x0) * (y1 - y0); }
  bool contains(Vec2 p) const { return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1; }
};

double box_gap(const Box& a, const Box& b) {
  if (a.empty() || b.empty()) return std::numeric_limits<double>::infinity();
  const double dx = std::max({0.0, a.x0 - b.x1, b.x0 - a.x1});
  const double dy = std::max({0.0, a.y0 - b.y1, b.y0 - a.y1});
  return std::hypot(dx, dy);
}

struct Segment {
  Vec2 a, b;
};

// One path, flattened.
struct Geom {
  std::vector<std::vector<Vec2>> region;  // rings bounding the fill region (closed implicitly)
  std::vector<Segment> outline;           // every drawn edge (closing edges of the region too)
  std::vector<Vec2> samples;              // boundary samples for the inside tests
  FillRule rule = FillRule::NonZero;
  Box box;                                // of the outline, grown by half the stroke width
  double half_stroke = 0;
  double area = 0;                        // of `box`
  Rgba colour;
};

Vec2 cubic_at(const Vec2* p, double t) {
  const double u = 1 - t;
  const double b0 = u * u * u, b1 = 3 * u * u * t, b2 = 3 * u * t * t, b3 = t * t * t;
  return {b0 * p[0].x + b1 * p[1].x + b2 * p[2].x + b3 * p[3].x,
          b0 * p[0].y + b1 * p[1].y + b2 * p[2].y + b3 * p[3].y};
}

Geom build_geom(const Path& path, const GroupingOptions& opt) {
  Geom g;
  g.rule = path.fill_rule;
  g.half_stroke = path.has_stroke ? 0.5 * path.stroke.width : 0;
  g.colour = path.has_fill ? path.fill : path.stroke.color;
  const int chords = std::max(1, opt.chords_per_cubic);
  std::vector<Vec2> all;
  for (const Subpath& sp : path.subpaths) {
    if (sp.points.empty()) continue;
    std::vector<Vec2> ring{sp.points[0]};
    for (size_t s = 0; s < sp.segment_count(); ++s)
      for (int k = 1; k <= chords; ++k)
        ring.push_back(cubic_at(&sp.points[3 * s], static_cast<double>(k) / chords));
    for (size_t i = 0; i + 1 < ring.size(); ++i) g.outline.push_back({ring[i], ring[i + 1]});
    if (ring.size() == 1) g.outline.push_back({ring[0], ring[0]});
    const bool region = ring.size() >= 3 && (path.has_fill || sp.closed);
    if (region && !(ring.front() == ring.back())) g.outline.push_back({ring.back(), ring.front()});
    for (const Vec2& p : ring) g.box.add(p), all.push_back(p);
    if (region) g.region.push_back(std::move(ring));
  }
  if (!g.box.empty()) {
    g.box.x0 -= g.half_stroke, g.box.y0 -= g.half_stroke;
    g.box.x1 += g.half_stroke, g.box.y1 += g.half_stroke;
  }
  g.area = g.box.area();
  const size_t m = std::min(all.size(), static_cast<size_t>(std::max(1, opt.max_boundary_samples)));
  for (size_t i = 0; i < m; ++i) g.samples.push_back(all[i * all.size() / m]);
  return g;
}

// Point in the fill region, with the path's fill rule: winding number (non-zero) or the
// parity of the crossings to the right of p (even-odd), every ring closed implicitly.
bool inside(const Geom& g, Vec2 p) {
  if (g.region.empty() || !g.box.contains(p)) return false;
  int winding = 0, crossings = 0;
  for (const auto& ring : g.region) {
    const size_t n = ring.size();
    for (size_t i = 0; i < n; ++i) {
      const Vec2 a = ring[i], b = ring[(i + 1) % n];
      if ((a.y <= p.y) == (b.y <= p.y)) continue;  // does not cross the line through p
      const double side = (b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y);
      const bool up = a.y <= p.y;  // upward edge
      if (up ? side > 0 : side < 0) {  // the crossing is to the right of p
        winding += up ? 1 : -1;
        ++crossings;
      }
    }
  }
  return g.rule == FillRule::EvenOdd ? crossings % 2 == 1 : winding != 0;
}

double inside_fraction(const Geom& a, const Geom& b) {
  if (a.samples.empty() || b.region.empty()) return 0;
  int n = 0;
  for (const Vec2& p : a.samples) n += inside(b, p);
  return static_cast<double>(n) / static_cast<double>(a.samples.size());
}

double point_segment(Vec2 p, const Segment& s) {
  const Vec2 d = s.b - s.a;
  const double len2 = d.x * d.x + d.y * d.y;
  double t = len2 > 0 ? ((p.x - s.a.x) * d.x + (p.y - s.a.y) * d.y) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (s.a.x + t * d.x), p.y - (s.a.y + t * d.y));
}

double cross(Vec2 o, Vec2 a, Vec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

double segment_segment(const Segment& s, const Segment& t) {
  const double d1 = cross(s.a, s.b, t.a), d2 = cross(s.a, s.b, t.b);
  const double d3 = cross(t.a, t.b, s.a), d4 = cross(t.a, t.b, s.b);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return 0;
  return std::min({point_segment(s.a, t), point_segment(s.b, t), point_segment(t.a, s),
                   point_segment(t.b, s)});
}

// Minimum distance between the outlines (no further than `cutoff` matters: returns a value
// > cutoff when they are farther apart).
double outline_distance(const Geom& a, const Geom& b, double cutoff) {
  double best = std::numeric_limits<double>::infinity();
  std::vector<const Segment*> near;
  const double reach = std::isfinite(cutoff) ? cutoff : std::numeric_limits<double>::max();
  for (const Segment& t : b.outline) {
    Box tb;
    tb.add(t.a), tb.add(t.b);
    Box ab = a.box;
    ab.x0 -= reach, ab.y0 -= reach, ab.x1 += reach, ab.y1 += reach;
    if (std::isfinite(cutoff) && box_gap(tb, ab) > 0) continue;
    near.push_back(&t);
  }
  for (const Segment& s : a.outline)
    for (const Segment* t : near) {
      best = std::min(best, segment_segment(s, *t));
      if (best == 0) return 0;
    }
  return best;
}

struct Relation {
  double gap = 0;        // canvas units; 0 for overlap, crossing or containment
  bool contain = false;  // one contains the other
  double in_ab = 0, in_ba = 0;
};

// `exact`: compute the outline distance whatever the boxes say (for check_group).
Relation relate(const Geom& a, const Geom& b, double far, bool exact) {
  Relation r;
  const double bg = box_gap(a.box, b.box);
  if (!std::isfinite(bg)) {
    r.gap = std::numeric_limits<double>::infinity();
    return r;
  }
  if (bg > far && !exact) {
    r.gap = bg;
    return r;
  }
  r.in_ab = inside_fraction(a, b);
  r.in_ba = inside_fraction(b, a);
  if (r.in_ab > 0 || r.in_ba > 0) {
    r.gap = 0;
    return r;
  }
  r.gap = std::max(0.0, outline_distance(a, b, exact ? std::numeric_limits<double>::infinity()
                                                     : far + a.half_stroke + b.half_stroke) -
                            a.half_stroke - b.half_stroke);
  return r;
}

double colour_similarity(const Rgba& a, const Rgba& b) {
  const double d = std::sqrt((a.r - b.r) * (a.r - b.r) + (a.g - b.g) * (a.g - b.g) +
                             (a.b - b.b) * (a.b - b.b));
  return 1 - d / std::sqrt(3.0);
}

// Above this many paths group_paths skips the pairwise analysis (outline distances and inside
// tests cost nearby pairs x segments: minutes and gigabytes at 20,000 paths) for coarse_groups.
// The drawings of the aniclipart bench have at most 51 paths.
constexpr size_t kExactPaths = 2000;
// Clusters compared densely (k x k scores, k^3 scans) once only far-apart pairs are left. Such
// clusters are pairwise farther apart than far_fraction of the diagonal: a few hundred at most
// on a canvas, more only for paths strewn far outside it (then coarse_groups merges them).
constexpr size_t kDenseClusters = 1024;
// Cells per axis of the neighbour grid, at most: bounds the cells one large box is listed in.
constexpr double kGridCells = 64;

Box hull(const std::vector<Box>& boxes) {
  Box all;
  for (const Box& b : boxes)
    if (!b.empty()) all.add({b.x0, b.y0}), all.add({b.x1, b.y1});
  return all;
}

double canvas_diagonal(const Scene& scene, const std::vector<Box>& boxes) {
  double d = std::hypot(scene.width, scene.height);
  if (d > 0 && std::isfinite(d)) return d;
  const Box all = hull(boxes);
  d = all.empty() ? 0 : std::hypot(all.x1 - all.x0, all.y1 - all.y0);
  return d > 0 ? d : 1;
}

// Every pair (i < j) of boxes at most `reach` apart (box_gap), sorted. A uniform grid with
// cells of at least `reach` lists each box in every cell it covers; a box's candidates are the
// boxes listed in the cells its box grown by `reach` covers. Plain code, quadratic:
//   for i < j: if (box_gap(b[i], b[j]) <= reach) pairs.push_back({i, j});
std::vector<std::pair<int, int>> near_box_pairs(const std::vector<Box>& boxes, double reach) {
  std::vector<std::pair<int, int>> pairs;
  const Box all = hull(boxes);
  if (all.empty()) return pairs;
  reach = std::max(0.0, reach);
  const double extent = std::max(all.x1 - all.x0, all.y1 - all.y0);
  double cell = std::max(reach, extent / kGridCells);
  if (!(cell > 0) || !std::isfinite(cell)) cell = 1;
  const auto cells_x = static_cast<size_t>(std::floor((all.x1 - all.x0) / cell)) + 1;
  const auto cells_y = static_cast<size_t>(std::floor((all.y1 - all.y0) / cell)) + 1;
  auto cell_range = [&](double lo, double hi, double origin, size_t count) {
    const auto clampi = [&](double v) {
      return static_cast<size_t>(std::clamp(std::floor((v - origin) / cell), 0.0,
                                            static_cast<double>(count - 1)));
    };
    return std::pair{clampi(lo), clampi(hi)};
  };
  std::vector<std::vector<int>> grid(cells_x * cells_y);
  for (size_t i = 0; i < boxes.size(); ++i) {
    const Box& b = boxes[i];
    if (b.empty()) continue;
    const auto [x0, x1] = cell_range(b.x0, b.x1, all.x0, cells_x);
    const auto [y0, y1] = cell_range(b.y0, b.y1, all.y0, cells_y);
    for (size_t y = y0; y <= y1; ++y)
      for (size_t x = x0; x <= x1; ++x) grid[y * cells_x + x].push_back(static_cast<int>(i));
  }
  std::vector<size_t> stamp(boxes.size(), boxes.size());
  std::vector<int> found;
  for (size_t i = 0; i < boxes.size(); ++i) {
    const Box& b = boxes[i];
    if (b.empty()) continue;
    const auto [x0, x1] = cell_range(b.x0 - reach, b.x1 + reach, all.x0, cells_x);
    const auto [y0, y1] = cell_range(b.y0 - reach, b.y1 + reach, all.y0, cells_y);
    found.clear();
    for (size_t y = y0; y <= y1; ++y)
      for (size_t x = x0; x <= x1; ++x)
        for (int j : grid[y * cells_x + x]) {
          const auto uj = static_cast<size_t>(j);
          if (uj <= i || stamp[uj] == i) continue;
          stamp[uj] = i;
          if (box_gap(b, boxes[uj]) <= reach) found.push_back(j);
        }
    std::sort(found.begin(), found.end());
    for (int j : found) pairs.emplace_back(static_cast<int>(i), j);
  }
  return pairs;
}

struct UnionFind {
  std::vector<size_t> parent;
  explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), size_t{0}); }
  size_t find(size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  bool unite(size_t a, size_t b) {
    a = find(a), b = find(b);
    if (a == b) return false;
    parent[std::max(a, b)] = std::min(a, b);
    return true;
  }
};

// The check of one group. Only pairs whose boxes are within reach = max(far, touch) can link
// at the touch or far distance (a gap is never below the gap between the grown boxes), so those
// pairs decide components_at_touch and, when they connect the group, the bottleneck (Kruskal).
// Otherwise the bottleneck exceeds reach: Prim over all pairs gives it exactly for groups up to
// kExactPaths paths (time n^2, memory n); beyond that largest_gap is the lower bound reach.
GroupCheck check_geoms(const std::vector<const Geom*>& gs, double diag, const GroupingOptions& opt) {
  GroupCheck c;
  const size_t n = gs.size();
  if (n <= 1) return c;
  const double far = opt.far_fraction * diag, touch = opt.touch_fraction * diag;
  const double reach = std::max(far, touch);
  std::vector<Box> boxes;
  for (const Geom* g : gs) boxes.push_back(g->box);
  struct Edge {
    double gap;
    int i, j;
  };
  std::vector<Edge> edges;
  for (const auto& [i, j] : near_box_pairs(boxes, reach))
    edges.push_back(
        {relate(*gs[static_cast<size_t>(i)], *gs[static_cast<size_t>(j)], far, true).gap, i, j});
  UnionFind touching(n);
  int comps = static_cast<int>(n);
  for (const Edge& e : edges)
    if (e.gap <= touch) comps -= touching.unite(static_cast<size_t>(e.i), static_cast<size_t>(e.j));
  c.components_at_touch = comps;
  std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) {
    return a.gap != b.gap ? a.gap < b.gap : std::pair{a.i, a.j} < std::pair{b.i, b.j};
  });
  UnionFind linked(n);
  size_t joined = 1;
  for (const Edge& e : edges)
    if (linked.unite(static_cast<size_t>(e.i), static_cast<size_t>(e.j)))
      ++joined, c.largest_gap = std::max(c.largest_gap, e.gap);
  if (joined < n || c.largest_gap > reach) {
    if (n <= kExactPaths) {  // Prim's minimum spanning tree, gaps computed as needed
      c.largest_gap = 0;
      std::vector<double> dist(n, std::numeric_limits<double>::infinity());
      std::vector<char> done(n, 0);
      dist[0] = 0;
      for (size_t it = 0; it < n; ++it) {
        size_t u = n;
        for (size_t v = 0; v < n; ++v)
          if (!done[v] && (u == n || dist[v] < dist[u])) u = v;
        done[u] = 1;
        c.largest_gap = std::max(c.largest_gap, dist[u]);
        for (size_t v = 0; v < n; ++v)
          if (!done[v]) dist[v] = std::min(dist[v], relate(*gs[u], *gs[v], far, true).gap);
      }
    } else {
      c.largest_gap = reach;
    }
  }
  c.largest_gap_fraction = c.largest_gap / diag;
  c.far_mix = c.largest_gap > far;
  return c;
}

std::vector<std::vector<int>> normalised(std::vector<std::vector<int>> groups) {
  for (auto& g : groups) std::sort(g.begin(), g.end());
  std::erase_if(groups, [](const std::vector<int>& g) { return g.empty(); });
  std::sort(groups.begin(), groups.end(),
            [](const std::vector<int>& a, const std::vector<int>& b) { return a[0] < b[0]; });
  return groups;
}

// Whether the document's top-level groups cover every path exactly once; `multi` tells whether
// one of them has several paths.
bool groups_cover(const Scene& scene, bool& multi) {
  const size_t n = scene.paths.size();
  bool covers = true;
  multi = false;
  std::vector<int> seen(n, 0);
  for (const Group& g : scene.groups) {
    multi = multi || g.paths.size() > 1;
    for (int i : g.paths)
      if (i < 0 || static_cast<size_t>(i) >= n || seen[static_cast<size_t>(i)]++) covers = false;
  }
  return covers && std::all_of(seen.begin(), seen.end(), [](int s) { return s == 1; });
}

// Coarse grouping: units (groups of paths kept whole) go to the cell of a grid of at most
// max_groups cells, shaped like the units' extent, that holds the centre of their box. When the
// units fall in fewer than min_groups cells they are split in paint order instead.
std::vector<std::vector<int>> grid_groups(const std::vector<std::vector<int>>& units,
                                          const std::vector<Box>& boxes, int min_groups,
                                          int max_groups, int& cols, int& rows) {
  std::vector<Vec2> centre(units.size());
  Box extent;
  for (size_t u = 0; u < units.size(); ++u) {
    Box b;
    for (int i : units[u]) {
      const Box& p = boxes[static_cast<size_t>(i)];
      if (!p.empty()) b.add({p.x0, p.y0}), b.add({p.x1, p.y1});
    }
    if (b.empty()) continue;  // no geometry: the first cell
    centre[u] = {0.5 * (b.x0 + b.x1), 0.5 * (b.y0 + b.y1)};
    extent.add(centre[u]);
  }
  const double w = extent.empty() ? 1 : extent.x1 - extent.x0;
  const double h = extent.empty() ? 1 : extent.y1 - extent.y0;
  const double aspect = (w + 1e-9) / (h + 1e-9);
  cols = std::clamp(static_cast<int>(std::lround(std::sqrt(max_groups * aspect))), 1, max_groups);
  rows = std::max(1, max_groups / cols);
  auto index = [](double v, double lo, double span, int count) {
    const double t = span > 0 ? (v - lo) / span : 0;
    return std::clamp(static_cast<int>(std::floor(t * count)), 0, count - 1);
  };
  std::vector<std::vector<int>> cells(static_cast<size_t>(cols * rows));
  for (size_t u = 0; u < units.size(); ++u) {
    const int x = extent.empty() ? 0 : index(centre[u].x, extent.x0, w, cols);
    const int y = extent.empty() ? 0 : index(centre[u].y, extent.y0, h, rows);
    auto& cell = cells[static_cast<size_t>(y * cols + x)];
    cell.insert(cell.end(), units[u].begin(), units[u].end());
  }
  std::erase_if(cells, [](const std::vector<int>& g) { return g.empty(); });
  if (static_cast<int>(cells.size()) < min_groups && static_cast<int>(units.size()) >= min_groups) {
    cells.assign(static_cast<size_t>(min_groups), {});
    for (size_t u = 0; u < units.size(); ++u) {
      auto& cell = cells[u * static_cast<size_t>(min_groups) / units.size()];
      cell.insert(cell.end(), units[u].begin(), units[u].end());
    }
  }
  return normalised(std::move(cells));
}

// The fallback for scenes above kExactPaths paths: the document's top-level groups when they
// are between min_groups and max_groups with one of several paths, else a coarse grid over the
// top-level groups (or over the paths when those are fewer than min_groups).
std::vector<std::vector<int>> coarse_groups(const Scene& scene, int min_groups, int max_groups,
                                            bool keep_existing, std::string& note) {
  const size_t n = scene.paths.size();
  std::vector<Box> boxes(n);
  for (size_t i = 0; i < n; ++i) {
    const Path& p = scene.paths[i];
    for (const Subpath& sp : p.subpaths)
      for (const Vec2& v : sp.points) boxes[i].add(v);  // control points: the hull holds the curve
  }
  bool multi = false;
  const bool covers = keep_existing && groups_cover(scene, multi);
  const int count = static_cast<int>(scene.groups.size());
  const std::string size = std::to_string(n) + " paths (above " + std::to_string(kExactPaths) +
                           ", no overlap analysis): ";
  if (covers && multi && count >= min_groups && count <= max_groups) {
    note = size + "kept the " + std::to_string(count) + " top-level groups";
    std::vector<std::vector<int>> out;
    for (const Group& g : scene.groups) out.push_back(g.paths);
    return normalised(std::move(out));
  }
  std::vector<std::vector<int>> units;
  const bool by_groups = covers && count >= min_groups;
  if (by_groups)
    for (const Group& g : scene.groups) units.push_back(g.paths);
  else
    for (size_t i = 0; i < n; ++i) units.push_back({static_cast<int>(i)});
  units = normalised(std::move(units));
  int cols = 1, rows = 1;
  auto out = grid_groups(units, boxes, min_groups, max_groups, cols, rows);
  note = size + (by_groups ? "top-level groups" : "paths") + " grouped by a " +
         std::to_string(cols) + "x" + std::to_string(rows) + " grid of their box centres";
  return out;
}

// Links between two clusters: the best pair score and whether some pair links strongly.
struct Tie {
  double score = -std::numeric_limits<double>::infinity();
  bool strong = false;
};

// A candidate merge of slots a < b; the heap's top is the best score, then the first (a, b),
// as the plain scan "for a < b: if (cs[a][b] > best) ..." finds it.
struct Candidate {
  double score;
  int a, b;
  bool operator<(const Candidate& o) const {
    if (score != o.score) return score < o.score;
    return a != o.a ? a > o.a : b > o.b;
  }
};


// Pairwise relations, only between paths whose boxes are within the far distance: every
// other pair scores -box_gap / diag (far apart), computed when needed (step 3).
struct Link {
  int i, j;
  double gap, score;
  bool strong;
};

// Backdrops: a path covering much of the canvas, at two of its edges, painted early (a hill,
// a sky, a wave under a surfer) contains or overlaps the whole figure, and merged by those
// links it would make the figure's limbs one part with it: its links score below every pair
// of far-apart paths, so it joins a group last, only when there are too many.
std::vector<char> find_backdrops(const Scene& scene, const std::vector<Box>& boxes) {
  const size_t n = scene.paths.size();
  std::vector<char> backdrop(n, 0);
  for (size_t i = 0; i < n; ++i)
    backdrop[i] = is_backdrop(scene, {static_cast<int>(i)}, boxes[i].x0, boxes[i].y0, boxes[i].x1, boxes[i].y1,
                              static_cast<double>(i) / static_cast<double>(n));
  return backdrop;
}

// The scored links of the pairs within the far distance: containment above overlap above a
// gap, nearer first, colour as a tie-breaker.
std::vector<Link> score_links(const std::vector<Geom>& geoms, const std::vector<Box>& boxes,
                              const std::vector<char>& backdrop, double far, double diag,
                              const GroupingOptions& opt) {
  std::vector<Link> links;
  for (const auto& [i, j] : near_box_pairs(boxes, far)) {
    if (backdrop[static_cast<size_t>(i)] || backdrop[static_cast<size_t>(j)]) {
      links.push_back({i, j, 0, -far / diag - 1, false});
      continue;
    }
    const Geom &a = geoms[static_cast<size_t>(i)], &b = geoms[static_cast<size_t>(j)];
    const Relation r = relate(a, b, far, false);
    const bool contain = (r.in_ab >= opt.containment_fraction && a.area <= b.area) ||
                         (r.in_ba >= opt.containment_fraction && b.area <= a.area);
    const double smaller_in = a.area <= b.area ? r.in_ab : r.in_ba;
    const double overlap = std::max(r.in_ab, r.in_ba);
    double s;
    if (contain) s = 4 + smaller_in;
    else if (r.gap <= 0) s = 2 + overlap;
    else if (r.gap <= far) s = 1 - r.gap / far;
    else s = -r.gap / diag;  // far apart: nearest first, and only when needed
    if (r.gap <= far) s += 0.2 * colour_similarity(a.colour, b.colour);
    links.push_back({i, j, r.gap, s, contain || (r.gap <= 0 && overlap >= opt.strong_overlap)});
  }
  return links;
}

// 1. The document's own top-level groups. A group mixes far-apart parts (check_group's
// far_mix) when its links no longer than the far distance leave it in several pieces.
// True when they are kept as they are (`seeds` holds them); else `seeds` holds the good ones
// and the paths of the others one by one (or nothing, then every path is a seed).
bool seeds_from_document(const Scene& scene, const std::vector<Link>& links, double far,
                         int min_groups, int max_groups, const GroupingOptions& opt,
                         std::vector<std::vector<int>>& seeds) {
  const size_t n = scene.paths.size();
  bool multi = false;
  const int count0 = static_cast<int>(scene.groups.size());
  if (opt.keep_existing_groups && groups_cover(scene, multi) && multi && count0 >= min_groups) {
    std::vector<size_t> owner(n);
    for (size_t k = 0; k < scene.groups.size(); ++k)
      for (int i : scene.groups[k].paths) owner[static_cast<size_t>(i)] = k;
    UnionFind pieces(n);
    for (const Link& l : links)
      if (owner[static_cast<size_t>(l.i)] == owner[static_cast<size_t>(l.j)] && l.gap <= far)
        pieces.unite(static_cast<size_t>(l.i), static_cast<size_t>(l.j));
    std::vector<char> ok(scene.groups.size(), 1);
    bool all_ok = true;
    for (size_t k = 0; k < scene.groups.size(); ++k) {
      const auto& g = scene.groups[k].paths;
      for (int i : g)
        if (pieces.find(static_cast<size_t>(i)) != pieces.find(static_cast<size_t>(g[0])))
          ok[k] = 0;
      all_ok = all_ok && ok[k];
    }
    if (all_ok && count0 <= max_groups) {
      for (const Group& g : scene.groups) seeds.push_back(g.paths);
      return true;
    }
    // Too many groups, or some mix far-apart parts: keep the good ones as seeds.
    for (size_t k = 0; k < scene.groups.size(); ++k) {
      if (ok[k]) seeds.push_back(scene.groups[k].paths);
      else
        for (int i : scene.groups[k].paths) seeds.push_back({i});
    }
    if (static_cast<int>(seeds.size()) < min_groups) seeds.clear();
  }
  return false;
}

// 2. Single-linkage agglomeration over the seeds (slots in seed order; a merge keeps the
// lower slot). Cluster ties are sparse: only clusters with linked paths have one.
struct Agglomeration {
  std::vector<std::vector<int>> seeds;  // per slot, the paths of its cluster (empty: merged)
  std::vector<int> slot_of;             // per path
  std::vector<std::unordered_map<int, Tie>> ties;
  std::vector<char> alive;
  int count = 0;
  std::priority_queue<Candidate> queue;
  bool strong_only = true;

  Agglomeration(std::vector<std::vector<int>> seeds_in, const std::vector<Link>& links, size_t n)
      : seeds(std::move(seeds_in)), slot_of(n) {
    const size_t k0 = seeds.size();
    for (size_t k = 0; k < k0; ++k)
      for (int i : seeds[k]) slot_of[static_cast<size_t>(i)] = static_cast<int>(k);
    ties.resize(k0);
    for (const Link& l : links) {
      const int a = slot_of[static_cast<size_t>(l.i)], b = slot_of[static_cast<size_t>(l.j)];
      if (a == b) continue;
      for (Tie* t : {&ties[static_cast<size_t>(a)][b], &ties[static_cast<size_t>(b)][a]})
        t->score = std::max(t->score, l.score), t->strong = t->strong || l.strong;
    }
    alive.assign(k0, 1);
    count = static_cast<int>(k0);
  }

  void offer(int a, int b, const Tie& t) {
    if (!strong_only || t.strong) queue.push({t.score, std::min(a, b), std::max(a, b)});
  }
  // Every tie of the live clusters, each pair once.
  void offer_all() {
    for (size_t a = 0; a < seeds.size(); ++a)
      if (alive[a])
        for (const auto& [b, t] : ties[a])
          if (static_cast<int>(a) < b) offer(static_cast<int>(a), b, t);
  }
  void merge(int a, int b) {  // b into a (a < b)
    auto &sa = seeds[static_cast<size_t>(a)], &sb = seeds[static_cast<size_t>(b)];
    sa.insert(sa.end(), sb.begin(), sb.end());
    sb = {};
    alive[static_cast<size_t>(b)] = 0;
    --count;
    auto& ta = ties[static_cast<size_t>(a)];
    ta.erase(b);
    for (const auto& [c, t] : ties[static_cast<size_t>(b)]) {
      if (c == a) continue;
      auto& tc = ties[static_cast<size_t>(c)];
      tc.erase(b);
      Tie& x = ta[c];
      x.score = std::max(x.score, t.score), x.strong = x.strong || t.strong;
      tc[a] = x;
      offer(a, c, x);
    }
    ties[static_cast<size_t>(b)] = {};
  }
  // The queue's best candidate that is still current, or nullptr.
  const Candidate* best() {
    while (!queue.empty()) {
      const Candidate& q = queue.top();
      if (alive[static_cast<size_t>(q.a)] && alive[static_cast<size_t>(q.b)]) {
        const auto& ta = ties[static_cast<size_t>(q.a)];
        const auto it = ta.find(q.b);
        if (it != ta.end() && it->second.score == q.score && (!strong_only || it->second.strong))
          return &q;
      }
      queue.pop();
    }
    return nullptr;
  }
  // Strong links first, while more than min_groups clusters remain.
  void merge_strong(int min_groups) {
    offer_all();
    while (count > min_groups) {
      const Candidate* q = best();
      if (!q) break;
      const Candidate c = *q;
      queue.pop();
      merge(c.a, c.b);
    }
  }
  // Then any link, while more than max_groups remain, as long as a linked pair scores above
  // every pair of far-apart paths (-box_gap / diag < -far / diag = far_score).
  void merge_linked(int max_groups, double far_score) {
    queue = {};
    strong_only = false;
    offer_all();
    while (count > max_groups) {
      const Candidate* q = best();
      if (!q || !(q->score > far_score)) break;
      const Candidate c = *q;
      queue.pop();
      merge(c.a, c.b);
    }
  }
};

// 3. Only far-apart clusters (or links scoring as low) are left: compare them densely, with
// the far pairs' scores from their boxes, as many as kDenseClusters.
std::vector<std::vector<int>> merge_far_apart(Agglomeration& ag, const std::vector<Box>& boxes,
                                              double far, double diag, int min_groups,
                                              int max_groups, std::string* note) {
  const size_t n = boxes.size(), k0 = ag.seeds.size();
  std::vector<int> live;
  for (size_t a = 0; a < k0; ++a)
    if (ag.alive[a]) live.push_back(static_cast<int>(a));
  const size_t m = live.size();
  std::vector<int> index_of(k0, -1);
  for (size_t p = 0; p < m; ++p) index_of[static_cast<size_t>(live[p])] = static_cast<int>(p);
  std::vector<std::vector<int>> clusters;
  for (int a : live) clusters.push_back(std::move(ag.seeds[static_cast<size_t>(a)]));
  if (m > kDenseClusters) {
    int cols = 1, rows = 1;
    auto out = grid_groups(clusters, boxes, min_groups, max_groups, cols, rows);
    if (note)
      *note = std::to_string(m) + " far-apart clusters (above " + std::to_string(kDenseClusters) +
              ") grouped by a " + std::to_string(cols) + "x" + std::to_string(rows) +
              " grid of their box centres";
    return out;
  }
  std::vector<int>& slot_of = ag.slot_of;
  for (size_t p = 0; p < m; ++p)
    for (int i : clusters[p]) slot_of[static_cast<size_t>(i)] = static_cast<int>(p);
  std::vector<double> cs(m * m, -std::numeric_limits<double>::infinity());
  for (size_t p = 0; p < m; ++p)
    for (const auto& [b, t] : ag.ties[static_cast<size_t>(live[p])])
      cs[p * m + static_cast<size_t>(index_of[static_cast<size_t>(b)])] = t.score;
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j) {
      const auto p = static_cast<size_t>(slot_of[i]), q = static_cast<size_t>(slot_of[j]);
      if (p == q) continue;
      const double bg = box_gap(boxes[i], boxes[j]);
      if (!(bg > far)) continue;  // a linked pair, already in cs
      const double s = -bg / diag;
      cs[p * m + q] = cs[q * m + p] = std::max(cs[p * m + q], s);
    }
  std::vector<char> on(m, 1);
  int& count = ag.count;
  while (count > max_groups) {
    bool found = false;
    double top = 0;
    size_t ba = 0, bb = 0;
    for (size_t a = 0; a < m; ++a) {
      if (!on[a]) continue;
      for (size_t b = a + 1; b < m; ++b)
        if (on[b] && (!found || cs[a * m + b] > top))
          found = true, top = cs[a * m + b], ba = a, bb = b;
    }
    if (!found) break;
    clusters[ba].insert(clusters[ba].end(), clusters[bb].begin(), clusters[bb].end());
    clusters[bb].clear();
    on[bb] = 0;
    --count;
    for (size_t c = 0; c < m; ++c)
      if (on[c] && c != ba)
        cs[ba * m + c] = cs[c * m + ba] = std::max(cs[ba * m + c], cs[bb * m + c]);
  }
  return normalised(std::move(clusters));
}

}  // namespace

GroupCheck check_group(const Scene& scene, const std::vector<int>& group,
                       const GroupingOptions& options) {
  std::vector<Geom> geoms;
  geoms.reserve(group.size());
  for (int i : group) geoms.push_back(build_geom(scene.paths.at(static_cast<size_t>(i)), options));
  std::vector<const Geom*> ptrs;
  std::vector<Box> boxes;
  for (const Geom& g : geoms) ptrs.push_back(&g), boxes.push_back(g.box);
  // The diagonal is the canvas's (the union of these paths' boxes if the canvas has no size).
  const double diag = canvas_diagonal(scene, boxes);
  return check_geoms(ptrs, diag, options);
}

std::vector<std::vector<int>> group_paths(const Scene& scene, const GroupingOptions& opt,
                                          std::string* note) {
  const size_t n = scene.paths.size();
  if (note) note->clear();
  if (n == 0) return {};
  const int min_groups = std::max(1, opt.min_groups);
  const int max_groups = std::max(min_groups, opt.max_groups);
  if (n > kExactPaths) {
    std::string line;
    auto out = coarse_groups(scene, min_groups, max_groups, opt.keep_existing_groups, line);
    if (note) *note = line;
    return out;
  }
  std::vector<Geom> geoms;
  geoms.reserve(n);
  for (const Path& p : scene.paths) geoms.push_back(build_geom(p, opt));
  std::vector<Box> boxes;
  for (const Geom& g : geoms) boxes.push_back(g.box);
  const double diag = canvas_diagonal(scene, boxes);
  const double far = opt.far_fraction * diag;
  std::vector<Link> links = score_links(geoms, boxes, find_backdrops(scene, boxes), far, diag, opt);

  std::vector<std::vector<int>> seeds;
  if (seeds_from_document(scene, links, far, min_groups, max_groups, opt, seeds))
    return normalised(std::move(seeds));
  if (seeds.empty())
    for (size_t i = 0; i < n; ++i) seeds.push_back({static_cast<int>(i)});
  seeds = normalised(std::move(seeds));

  Agglomeration ag(std::move(seeds), links, n);
  links = {};
  ag.merge_strong(min_groups);
  ag.merge_linked(max_groups, -far / diag);
  if (ag.count <= max_groups) return normalised(std::move(ag.seeds));
  return merge_far_apart(ag, boxes, far, diag, min_groups, max_groups, note);
}

}  // namespace svgm
