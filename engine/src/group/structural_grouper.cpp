// The structural grouper (see structural_grouper.h): flattened outlines, pairwise relations
// (containment, overlap, gap, colour), then single-linkage agglomerative merging.
#include "group/structural_grouper.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

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

double canvas_diagonal(const Scene& scene, const std::vector<Geom>& geoms) {
  double d = std::hypot(scene.width, scene.height);
  if (d > 0 && std::isfinite(d)) return d;
  Box all;
  for (const Geom& g : geoms)
    if (!g.box.empty()) all.add({g.box.x0, g.box.y0}), all.add({g.box.x1, g.box.y1});
  d = all.empty() ? 0 : std::hypot(all.x1 - all.x0, all.y1 - all.y0);
  return d > 0 ? d : 1;
}

double colour_similarity(const Rgba& a, const Rgba& b) {
  const double d = std::sqrt((a.r - b.r) * (a.r - b.r) + (a.g - b.g) * (a.g - b.g) +
                             (a.b - b.b) * (a.b - b.b));
  return 1 - d / std::sqrt(3.0);
}

GroupCheck check_geoms(const std::vector<const Geom*>& gs, double diag, const GroupingOptions& opt) {
  GroupCheck c;
  const size_t n = gs.size();
  if (n <= 1) return c;
  const double far = opt.far_fraction * diag, touch = opt.touch_fraction * diag;
  std::vector<double> gap(n * n, 0);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j) {
      const Relation r = relate(*gs[i], *gs[j], far, true);
      gap[i * n + j] = gap[j * n + i] = r.gap;
    }
  // Prim's minimum spanning tree: its largest edge is the bottleneck gap.
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
      if (!done[v]) dist[v] = std::min(dist[v], gap[u * n + v]);
  }
  // Components with links no longer than the touch distance (union-find).
  std::vector<size_t> parent(n);
  std::iota(parent.begin(), parent.end(), size_t{0});
  auto find = [&](size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  int comps = static_cast<int>(n);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j)
      if (gap[i * n + j] <= touch) {
        const size_t a = find(i), b = find(j);
        if (a != b) parent[std::max(a, b)] = std::min(a, b), --comps;
      }
  c.components_at_touch = comps;
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

}  // namespace

GroupCheck check_group(const Scene& scene, const std::vector<int>& group,
                       const GroupingOptions& options) {
  std::vector<Geom> geoms;
  geoms.reserve(group.size());
  for (int i : group) geoms.push_back(build_geom(scene.paths.at(static_cast<size_t>(i)), options));
  std::vector<const Geom*> ptrs;
  for (const Geom& g : geoms) ptrs.push_back(&g);
  // The diagonal is the canvas's (the union of these paths' boxes if the canvas has no size).
  const double diag = canvas_diagonal(scene, geoms);
  return check_geoms(ptrs, diag, options);
}

std::vector<std::vector<int>> group_paths(const Scene& scene, const GroupingOptions& opt) {
  const size_t n = scene.paths.size();
  if (n == 0) return {};
  const int min_groups = std::max(1, opt.min_groups);
  const int max_groups = std::max(min_groups, opt.max_groups);
  std::vector<Geom> geoms;
  geoms.reserve(n);
  for (const Path& p : scene.paths) geoms.push_back(build_geom(p, opt));
  const double diag = canvas_diagonal(scene, geoms);
  auto group_ok = [&](const std::vector<int>& g) {
    std::vector<const Geom*> gs;
    for (int i : g) gs.push_back(&geoms[static_cast<size_t>(i)]);
    return !check_geoms(gs, diag, opt).far_mix;
  };

  // 1. The document's own top-level groups.
  std::vector<std::vector<int>> seeds;
  if (opt.keep_existing_groups) {
    bool covers = true, multi = false;
    std::vector<int> seen(n, 0);
    for (const Group& g : scene.groups) {
      multi = multi || g.paths.size() > 1;
      for (int i : g.paths) {
        if (i < 0 || static_cast<size_t>(i) >= n || seen[static_cast<size_t>(i)]++) covers = false;
      }
    }
    covers = covers && std::all_of(seen.begin(), seen.end(), [](int s) { return s == 1; });
    const int count = static_cast<int>(scene.groups.size());
    if (covers && multi && count >= min_groups) {
      std::vector<char> ok(scene.groups.size(), 1);
      bool all_ok = true;
      for (size_t k = 0; k < scene.groups.size(); ++k) {
        if (scene.groups[k].paths.size() > 1) ok[k] = group_ok(scene.groups[k].paths);
        all_ok = all_ok && ok[k];
      }
      if (all_ok && count <= max_groups) {
        std::vector<std::vector<int>> out;
        for (const Group& g : scene.groups) out.push_back(g.paths);
        return normalised(std::move(out));
      }
      // Too many groups, or some mix far-apart parts: keep the good ones as seeds.
      for (size_t k = 0; k < scene.groups.size(); ++k) {
        if (ok[k]) seeds.push_back(scene.groups[k].paths);
        else
          for (int i : scene.groups[k].paths) seeds.push_back({i});
      }
      if (static_cast<int>(seeds.size()) < min_groups) seeds.clear();
    }
  }
  if (seeds.empty())
    for (size_t i = 0; i < n; ++i) seeds.push_back({static_cast<int>(i)});
  seeds = normalised(std::move(seeds));

  // 2. Pairwise relations between paths.
  const double far = opt.far_fraction * diag;
  std::vector<double> score(n * n, 0);
  std::vector<char> strong(n * n, 0);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j) {
      const Geom &a = geoms[i], &b = geoms[j];
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
      score[i * n + j] = score[j * n + i] = s;
      strong[i * n + j] = strong[j * n + i] =
          contain || (r.gap <= 0 && overlap >= opt.strong_overlap);
    }

  // 3. Single-linkage agglomeration over the seeds.
  const size_t k0 = seeds.size();
  std::vector<double> cs(k0 * k0, -std::numeric_limits<double>::infinity());
  std::vector<char> cstrong(k0 * k0, 0);
  for (size_t a = 0; a < k0; ++a)
    for (size_t b = a + 1; b < k0; ++b) {
      double s = -std::numeric_limits<double>::infinity();
      bool st = false;
      for (int i : seeds[a])
        for (int j : seeds[b]) {
          s = std::max(s, score[static_cast<size_t>(i) * n + static_cast<size_t>(j)]);
          st = st || strong[static_cast<size_t>(i) * n + static_cast<size_t>(j)];
        }
      cs[a * k0 + b] = cs[b * k0 + a] = s;
      cstrong[a * k0 + b] = cstrong[b * k0 + a] = st;
    }
  std::vector<char> alive(k0, 1);
  int count = static_cast<int>(k0);
  auto merge = [&](size_t a, size_t b) {  // b into a
    seeds[a].insert(seeds[a].end(), seeds[b].begin(), seeds[b].end());
    seeds[b].clear();
    alive[b] = 0;
    --count;
    for (size_t c = 0; c < k0; ++c) {
      if (!alive[c] || c == a) continue;
      cs[a * k0 + c] = cs[c * k0 + a] = std::max(cs[a * k0 + c], cs[b * k0 + c]);
      cstrong[a * k0 + c] = cstrong[c * k0 + a] = cstrong[a * k0 + c] || cstrong[b * k0 + c];
    }
  };
  // The best pair (first in index order on ties), among strong links only if asked.
  auto best_pair = [&](bool strong_only, size_t& ba, size_t& bb) {
    bool found = false;
    double best = 0;
    for (size_t a = 0; a < k0; ++a) {
      if (!alive[a]) continue;
      for (size_t b = a + 1; b < k0; ++b) {
        if (!alive[b] || (strong_only && !cstrong[a * k0 + b])) continue;
        if (!found || cs[a * k0 + b] > best) found = true, best = cs[a * k0 + b], ba = a, bb = b;
      }
    }
    return found;
  };
  size_t a = 0, b = 0;
  while (count > min_groups && best_pair(true, a, b)) merge(a, b);
  while (count > max_groups && best_pair(false, a, b)) merge(a, b);
  return normalised(std::move(seeds));
}

}  // namespace svgm
