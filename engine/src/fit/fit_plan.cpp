// Building the fitter's tables (see fit_plan.h).
#include "fit/fit_plan.h"

#include <cmath>
#include <map>

namespace svgm {

FitPlan plan_fit(const Scene& scene, const RasterPlan& raster, const FitPlanOptions& opt) {
  FitPlan f;
  f.n_cp = raster.n_cp;
  f.cp_group.assign(f.n_cp, -1);
  f.cp_offset.assign(f.n_cp, -1);
  const auto rest = [&](int i) { return Vec2{raster.rest_cp[2 * i], raster.rest_cp[2 * i + 1]}; };

  // Groups: the scene's, plus one per path that has none, in order of first appearance.
  std::map<int, int> scene_group_to_fit;
  std::vector<int> path_group(scene.paths.size());
  for (size_t p = 0; p < scene.paths.size(); ++p) {
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
  return f;
}

}  // namespace svgm
