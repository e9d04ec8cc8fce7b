// The fitter's fixed tables: which group moves each control point, which offsets are tied,
// the smoothness neighbours, the G1 joints. Built once on the host from the scene and its
// raster plan (pixel space at the fitting resolution), uploaded once.
#pragma once

#include <vector>

#include "raster/raster_plan.h"
#include "svgmotion/scene.h"

namespace svgm {

struct FitPlanOptions {
  double smooth_sigma_px = 2.56;  // σ of the smoothness weights: 1% of the canvas width
  double g1_max_angle_deg = 10;   // joints smoother than this at rest keep G1 continuity
};

struct FitPlan {
  int n_cp = 0;                  // as the raster plan (including its 3 padding points)
  int n_groups = 0;
  std::vector<int> cp_group;     // group of every control point (-1: padding)
  // The offset parameter each control point reads: itself, or the first point of its closed
  // subpath when it is that subpath's closing copy (so a closed outline never opens a gap).
  std::vector<int> cp_offset;
  std::vector<int> group_first, group_cps;   // CSR: the control points of each group
  std::vector<int> nbr_first, nbr;           // CSR: smoothness neighbours of each offset
  std::vector<float> nbr_w;                  //      and their weights
  int n_pairs = 0;                           // smoothness pairs (each counted once)
  std::vector<int> joints;                   // (in-handle, anchor, out-handle, 0) quadruples
  int n_joints() const { return static_cast<int>(joints.size() / 4); }
  std::vector<std::string> group_ids;
};

FitPlan plan_fit(const Scene& scene, const RasterPlan& raster, const FitPlanOptions& options);

}  // namespace svgm
