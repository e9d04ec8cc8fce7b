// The fitter's fixed tables: which group moves each control point (small paths join the path
// they sit on), which offsets are tied, the smoothness neighbours, the G1 joints, the cohesion
// pairs, and the displacement-field basis that turns a group's few field coefficients into
// smooth offsets of its points. Built once on the host
// from the scene and its raster plan (pixel space at the fitting resolution), uploaded once.
#pragma once

#include <vector>

#include "raster/raster_plan.h"
#include "svgmotion/scene.h"

namespace svgm {

struct FitPlanOptions {
  double smooth_sigma_px = 2.56;  // σ of the smoothness weights: 1% of the canvas width
  double g1_max_angle_deg = 10;   // joints smoother than this at rest keep G1 continuity
  // Knot spacing (pixels) of each group's displacement field (a uniform quadratic B-spline
  // over the group's rest bounding box, kernels/field.cl); 0: no field.
  double field_spacing_px = 0;
  // A path alone in its scene group (or in none) whose rest bounding box is smaller than this (pixels, both
  // sides) joins the group of the path it sits on (the topmost path painted beneath it that
  // contains its centre): a freckle, a pupil or a button then moves exactly as the surface
  // under it instead of drifting on a homography of its own that the loss barely sees.
  // 0: every such path keeps its own group.
  double attach_small_px = 0;
  // A path alone in its group that vanishes into a white background (every paint within this
  // of white, per channel, as the target's mask sees it: a highlight, a glint, teeth) joins
  // the path it sits on the same way (its centre, or half its points, inside): outside that
  // path the image loss cannot see it, and on a group of its own it grows there unseen
  // (octopus: a white highlight 4-5x its size). Negative: off.
  double attach_invisible_tol = -1;
  // A path alone in its group whose outline is an earlier path's (fit/plan/coincident_paths.h: a
  // gradient overlay, a bevel or a highlight stacked on a shape) joins that path's group, so the
  // two cannot part.
  bool attach_coincident = false;
  // Cohesion pairs: each control point with its nearest other control points (any path,
  // any group) closer than this at rest (pixels); 0: no cohesion term.
  double cohesion_radius_px = 0;
  int cohesion_max_neighbours = 8;  // per point, before the pairs are made symmetric
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

  // The displacement field: Δ_i = Σ_b w_ib c_b over the field nodes b of point i's group (3 x 3
  // quadratic B-spline weights at the point's rest position). Only points that own their offset
  // slot (cp_offset[i] == i) have weights. Both directions as CSR so the forward map and its
  // transpose are gathers (deterministic, no atomics).
  int n_nodes = 0;
  std::vector<int> cp_node_first, cp_node;     // CSR: the nodes of each control point
  std::vector<float> cp_node_w;                //      and their weights
  std::vector<int> node_cp_first, node_cp;     // CSR: the control points of each node
  std::vector<float> node_cp_w;                //      and their weights
  std::vector<float> node_pos;                 // rest position (x, y) of every node's knot
  // Bending of the field (the warm start's regulariser, fit/optimise/field_warm_start.h): per node, the
  // node one knot before and one after it along x, then along y, -1 where its group has none
  // ([n_nodes][4]).
  std::vector<int> node_bend;

  // Cohesion (kernels/regularise.cl): pairs of control points close at rest, whatever their
  // path or group, keep their distance. Only points that own their offset slot take part.
  std::vector<int> coh_first, coh_nbr;         // CSR, symmetric: the pairs of each point
  std::vector<float> coh_len;                  //      and their rest distances (pixels)
  int n_coh_pairs = 0;                         // each counted once
};

// The uniform quadratic B-spline: weights of the three knots nearest to u (in knot units)
// at knots j0, j0 + 1, j0 + 2 with j0 = round(u) - 1. They sum to 1 and reproduce linear
// functions, so a field can hold any translation or affine map of its part exactly.
void quadratic_bspline_weights(double u, int* j0, double w[3]);

FitPlan plan_fit(const Scene& scene, const RasterPlan& raster, const FitPlanOptions& options);

}  // namespace svgm
