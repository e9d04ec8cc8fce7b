// Building the fitter's tables (see fit_plan.h).
#include "fit/plan/fit_plan.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "fit/plan/coincident_paths.h"

namespace svgm {

void quadratic_bspline_weights(double u, int* j0, double w[3]) {
  const int c = static_cast<int>(std::lround(u));
  const double t = u - c;  // in [-0.5, 0.5]: distance from the nearest knot
  *j0 = c - 1;
  w[0] = 0.5 * (0.5 - t) * (0.5 - t);
  w[1] = 0.75 - t * t;
  w[2] = 0.5 * (0.5 + t) * (0.5 + t);
}

namespace {

// The field tables of `f` (see FitPlan): per group, knots every `h` pixels from the group's
// rest bounding box corner; a node exists only where some point has weight on it. Then each
// node's bending neighbours.
void plan_field(FitPlan& f, const std::vector<float>& rest_cp, double h) {
  std::vector<std::vector<std::pair<int, float>>> cp_nodes(f.n_cp);
  std::vector<std::vector<std::pair<int, float>>> node_cps;
  if (h > 0) {
    std::map<std::tuple<int, int, int>, int> node_of;  // (group, knot x, knot y) -> node
    for (int g = 0; g < f.n_groups; ++g) {
      double x0 = 1e300, y0 = 1e300;
      for (int e = f.group_first[g]; e < f.group_first[g + 1]; ++e) {
        x0 = std::min(x0, static_cast<double>(rest_cp[2 * f.group_cps[e]]));
        y0 = std::min(y0, static_cast<double>(rest_cp[2 * f.group_cps[e] + 1]));
      }
      for (int e = f.group_first[g]; e < f.group_first[g + 1]; ++e) {
        const int i = f.group_cps[e];
        if (f.cp_offset[i] != i) continue;  // a closing copy reads its first point's slot
        int jx, jy;
        double wx[3], wy[3];
        quadratic_bspline_weights((rest_cp[2 * i] - x0) / h, &jx, wx);
        quadratic_bspline_weights((rest_cp[2 * i + 1] - y0) / h, &jy, wy);
        for (int b = 0; b < 3; ++b)
          for (int a = 0; a < 3; ++a) {
            const auto key = std::make_tuple(g, jx + a, jy + b);
            auto it = node_of.find(key);
            if (it == node_of.end()) {
              it = node_of.emplace(key, f.n_nodes++).first;
              node_cps.emplace_back();
              f.node_pos.push_back(static_cast<float>(x0 + (jx + a) * h));
              f.node_pos.push_back(static_cast<float>(y0 + (jy + b) * h));
            }
            const float w = static_cast<float>(wx[a] * wy[b]);
            cp_nodes[i].push_back({it->second, w});
            node_cps[it->second].push_back({i, w});
          }
      }
    }
    // Bending neighbours: the knot before and after along each axis, where the group has nodes.
    f.node_bend.assign(static_cast<size_t>(f.n_nodes) * 4, -1);
    for (const auto& [key, b] : node_of) {
      const auto [g, jx, jy] = key;
      auto at = [&, g = g](int x, int y) {
        const auto it = node_of.find({g, x, y});
        return it == node_of.end() ? -1 : it->second;
      };
      int* nb = f.node_bend.data() + static_cast<size_t>(b) * 4;
      nb[0] = at(jx - 1, jy), nb[1] = at(jx + 1, jy), nb[2] = at(jx, jy - 1), nb[3] = at(jx, jy + 1);
    }
  }
  f.cp_node_first.assign(f.n_cp + 1, 0);
  for (int i = 0; i < f.n_cp; ++i) {
    f.cp_node_first[i + 1] = f.cp_node_first[i] + static_cast<int>(cp_nodes[i].size());
    for (const auto& [b, w] : cp_nodes[i]) {
      f.cp_node.push_back(b);
      f.cp_node_w.push_back(w);
    }
  }
  f.node_cp_first.assign(f.n_nodes + 1, 0);
  for (int b = 0; b < f.n_nodes; ++b) {
    f.node_cp_first[b + 1] = f.node_cp_first[b] + static_cast<int>(node_cps[b].size());
    for (const auto& [i, w] : node_cps[b]) {
      f.node_cp.push_back(i);
      f.node_cp_w.push_back(w);
    }
  }
}

// The cohesion pairs of `f` (see FitPlan): for each owned point, its nearest owned points
// within `radius` (at most `max_nbrs`, found through a grid of radius-sized cells), made
// symmetric. Points at the same rest position carry no direction and are skipped.
void plan_cohesion(FitPlan& f, const std::vector<float>& rest_cp, double radius, int max_nbrs) {
  std::vector<std::vector<std::pair<int, float>>> nb(f.n_cp);
  if (radius > 0 && max_nbrs > 0) {
    std::map<std::pair<int, int>, std::vector<int>> grid;
    auto cell = [&](int i) {
      return std::make_pair(static_cast<int>(std::floor(rest_cp[2 * i] / radius)),
                            static_cast<int>(std::floor(rest_cp[2 * i + 1] / radius)));
    };
    for (int i = 0; i < f.n_cp; ++i)
      if (f.cp_group[i] >= 0 && f.cp_offset[i] == i) grid[cell(i)].push_back(i);
    std::vector<std::pair<int, int>> pairs;  // (i, j), i < j
    for (int i = 0; i < f.n_cp; ++i) {
      if (f.cp_group[i] < 0 || f.cp_offset[i] != i) continue;
      const auto [cx, cy] = cell(i);
      std::vector<std::pair<double, int>> near;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const auto it = grid.find({cx + dx, cy + dy});
          if (it == grid.end()) continue;
          for (int j : it->second) {
            if (j == i) continue;
            const double d = std::hypot(rest_cp[2 * i] - rest_cp[2 * j], rest_cp[2 * i + 1] - rest_cp[2 * j + 1]);
            if (d < radius && d > 1e-3) near.push_back({d, j});
          }
        }
      std::sort(near.begin(), near.end());
      if (near.size() > static_cast<size_t>(max_nbrs)) near.resize(max_nbrs);
      for (const auto& [d, j] : near) pairs.push_back({std::min(i, j), std::max(i, j)});
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    for (const auto& [i, j] : pairs) {
      const float d = static_cast<float>(
          std::hypot(rest_cp[2 * i] - rest_cp[2 * j], rest_cp[2 * i + 1] - rest_cp[2 * j + 1]));
      nb[i].push_back({j, d});
      nb[j].push_back({i, d});
    }
    f.n_coh_pairs = static_cast<int>(pairs.size());
  }
  f.coh_first.assign(f.n_cp + 1, 0);
  for (int i = 0; i < f.n_cp; ++i) {
    f.coh_first[i + 1] = f.coh_first[i] + static_cast<int>(nb[i].size());
    for (const auto& [j, d] : nb[i]) {
      f.coh_nbr.push_back(j);
      f.coh_len.push_back(d);
    }
  }
}

struct Box {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  void add(Vec2 p) {
    x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
  }
  bool contains(Vec2 p) const { return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1; }
  double side() const { return std::max(x1 - x0, y1 - y0); }
};

// Even-odd containment of p in the control polygons of a path's subpaths (close enough to
// the curves for choosing a host).
bool inside_control_polygons(const Path& path, Vec2 p) {
  bool in = false;
  for (const Subpath& sp : path.subpaths)
    for (size_t i = 0, n = sp.points.size(); i < n; ++i) {
      const Vec2 a = sp.points[i], b = sp.points[(i + 1) % n];
      if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
    }
  return in;
}

// A path whose bounding box is under this share of its host's counts as small beside it
// (octopus: a 13 px freckle on a 380 px body is 0.034 of it and, on its own homography, slid
// onto the head's edge and stretched 5x along it; the mouth, 0.11 of it, keeps its own).
constexpr double kTinyBesideHost = 0.05;

// Whether `path` would vanish into a white background: every paint it has, composited over
// white with its opacity, within `tol` of white in each channel (the target's mask test).
bool invisible_on_white(const Path& path, double tol) {
  auto white = [&](const Rgba& c) {
    const double a = static_cast<double>(c.a) * path.opacity;
    return std::max({1 - (c.r * a + 1 - a), 1 - (c.g * a + 1 - a), 1 - (c.b * a + 1 - a)}) <= tol;
  };
  if (!path.has_fill && !path.has_stroke) return false;
  return (!path.has_fill || white(path.fill)) && (!path.has_stroke || white(path.stroke.color));
}

// host[p]: the path whose group path p joins (see FitPlanOptions::attach_coincident,
// attach_small_px and attach_invisible_tol), or -1. Pixel-space boxes come from the raster
// plan's rest points; containment is tested in canvas space on the scene's own points.
std::vector<int> path_hosts(const Scene& scene, const RasterPlan& raster, const FitPlanOptions& opt) {
  const size_t P = scene.paths.size();
  std::vector<int> host = opt.attach_coincident ? coincident_hosts(scene) : std::vector<int>(P, -1);
  if (opt.attach_small_px <= 0 && opt.attach_invisible_tol < 0) return host;
  std::vector<Box> px(P), canvas(P);
  for (size_t p = 0; p < P; ++p) {
    for (int i = raster.path_cp_first[p]; i < raster.path_cp_first[p] + raster.path_cp_count[p]; ++i)
      px[p].add({raster.rest_cp[2 * i], raster.rest_cp[2 * i + 1]});
    for (const Subpath& sp : scene.paths[p].subpaths)
      for (const Vec2& q : sp.points) canvas[p].add(q);
  }
  for (size_t p = 0; p < P; ++p) {
    const Path& path = scene.paths[p];
    const int sg = path.group;
    const bool alone = sg < 0 || scene.groups[sg].paths.size() <= 1;  // a top-level element
    if (!alone || raster.path_cp_count[p] == 0 || host[p] >= 0) continue;
    // Small: under the absolute size, or tiny beside the path it sits on (a freckle on a
    // whole body; checked per host below).
    const bool small = px[p].side() < opt.attach_small_px;
    const bool invisible = opt.attach_invisible_tol >= 0 && invisible_on_white(path, opt.attach_invisible_tol);
    if (!small && !invisible && opt.attach_small_px <= 0) continue;
    // A small path sits on the path that contains its centre; an invisible one may be a
    // crescent (a highlight along an edge) whose centre is off it: half its points inside do.
    const Vec2 c{0.5 * (canvas[p].x0 + canvas[p].x1), 0.5 * (canvas[p].y0 + canvas[p].y1)};
    auto sits_on = [&](int q) {
      const Path& under = scene.paths[q];
      if (canvas[q].contains(c) && inside_control_polygons(under, c)) return true;
      if (!invisible) return false;
      size_t in = 0, n = 0;
      for (const Subpath& sp : path.subpaths)
        for (const Vec2& v : sp.points) in += inside_control_polygons(under, v), ++n;
      return n > 0 && 2 * in >= n;
    };
    // Hosts are visible paths: an invisible one cannot carry what the loss does not see.
    auto visible = [&](int q) {
      return opt.attach_invisible_tol < 0 || !invisible_on_white(scene.paths[q], opt.attach_invisible_tol);
    };
    for (int q = static_cast<int>(p) - 1; q >= 0; --q)
      if (raster.path_cp_count[q] > 0 && px[q].side() > px[p].side() && visible(q) &&
          (small || invisible || px[p].side() < kTinyBesideHost * px[q].side()) && sits_on(q)) {
        host[p] = q;
        break;
      }
  }
  return host;
}

}  // namespace

FitPlan plan_fit(const Scene& scene, const RasterPlan& raster, const FitPlanOptions& opt) {
  FitPlan f;
  f.n_cp = raster.n_cp;
  f.cp_group.assign(f.n_cp, -1);
  f.cp_offset.assign(f.n_cp, -1);
  const auto rest = [&](int i) { return Vec2{raster.rest_cp[2 * i], raster.rest_cp[2 * i + 1]}; };

  // Groups: the scene's, plus one per path that has none, in order of first appearance.
  std::map<int, int> scene_group_to_fit;
  std::vector<int> path_group(scene.paths.size());
  const std::vector<int> host = path_hosts(scene, raster, opt);
  for (size_t p = 0; p < scene.paths.size(); ++p) {
    if (host[p] >= 0) {  // hosts are painted earlier, so their group is known
      path_group[p] = path_group[host[p]];
      continue;
    }
    const int sg = scene.paths[p].group;
    if (sg >= 0 && scene_group_to_fit.count(sg)) {
      path_group[p] = scene_group_to_fit[sg];
      continue;
    }
    path_group[p] = f.n_groups++;
    if (sg >= 0) scene_group_to_fit[sg] = path_group[p];
    f.group_ids.push_back(sg >= 0 ? scene.groups[sg].id : scene.paths[p].id);
  }

  std::vector<std::vector<int>> members(f.n_groups);
  const double cos_max = std::cos(opt.g1_max_angle_deg * M_PI / 180.0);
  std::vector<std::vector<std::pair<int, float>>> nbrs(f.n_cp);
  auto add_pair = [&](int i, int j) {
    const Vec2 d = rest(i) - rest(j);
    const float w = static_cast<float>(std::exp(-std::hypot(d.x, d.y) / opt.smooth_sigma_px));
    nbrs[i].push_back({j, w});
    nbrs[j].push_back({i, w});
    ++f.n_pairs;
  };
  auto smooth_joint = [&](int in, int anchor, int out) {
    const Vec2 a = rest(anchor) - rest(in), b = rest(out) - rest(anchor);
    const double la = std::hypot(a.x, a.y), lb = std::hypot(b.x, b.y);
    if (la < 1e-3 || lb < 1e-3) return;
    if ((a.x * b.x + a.y * b.y) / (la * lb) >= cos_max) f.joints.insert(f.joints.end(), {in, anchor, out, 0});
  };

  for (size_t p = 0; p < scene.paths.size(); ++p) {
    const int g = path_group[p];
    int cp = raster.path_cp_first[p];
    for (const Subpath& sp : scene.paths[p].subpaths) {
      if (sp.points.empty()) continue;
      const int first = cp, count = static_cast<int>(sp.points.size());
      for (int i = first; i < first + count; ++i) {
        f.cp_group[i] = g;
        f.cp_offset[i] = i;
        members[g].push_back(i);
      }
      const int last = first + count - 1;
      const bool tied = sp.closed && count > 1 && sp.points.front() == sp.points.back();
      if (tied) f.cp_offset[last] = first;
      // Consecutive offsets (the tied copy shares the first point's offset: not a pair).
      for (int i = first; i + 1 < first + count; ++i)
        if (!(tied && i + 1 == last)) add_pair(i, i + 1);
      if (tied && count > 2) add_pair(last - 1, first);
      // Joints between consecutive cubics, and at the start of a tied closed subpath.
      const int segs = static_cast<int>(sp.segment_count());
      for (int j = 1; j < segs; ++j) smooth_joint(first + 3 * j - 1, first + 3 * j, first + 3 * j + 1);
      if (tied && segs >= 2) smooth_joint(last - 1, first, first + 1);
      cp += count;
    }
  }

  f.group_first.assign(f.n_groups + 1, 0);
  for (int g = 0; g < f.n_groups; ++g) {
    f.group_first[g + 1] = f.group_first[g] + static_cast<int>(members[g].size());
    f.group_cps.insert(f.group_cps.end(), members[g].begin(), members[g].end());
  }
  f.nbr_first.assign(f.n_cp + 1, 0);
  for (int i = 0; i < f.n_cp; ++i) {
    f.nbr_first[i + 1] = f.nbr_first[i] + static_cast<int>(nbrs[i].size());
    for (const auto& [j, w] : nbrs[i]) {
      f.nbr.push_back(j);
      f.nbr_w.push_back(w);
    }
  }
  plan_field(f, raster.rest_cp, opt.field_spacing_px);
  plan_cohesion(f, raster.rest_cp, opt.cohesion_radius_px, opt.cohesion_max_neighbours);
  return f;
}

}  // namespace svgm
