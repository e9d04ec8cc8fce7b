// The structural grouper: which paths of a scene move together (a head, an arm, a leg).
//
// Before animation the paths are grouped into parts; each part becomes one flat <g> whose
// paths share one homography per keyframe in the fitter. group_paths decides the parts from
// the geometry of the scene alone (canvas space), deterministically:
//
//  1. Existing structure first. When the document's top-level <g> elements (Scene::groups, in
//     which every path outside a top-level <g> is a group of its own) include at least one
//     group of several paths, give between min_groups and max_groups groups, and none of them
//     mixes far-apart unconnected paths (see GroupCheck), they are returned as they are.
//  2. Otherwise paths are clustered agglomeratively (single linkage on a pair score):
//       - containment: most (containment_fraction) of the smaller path's flattened boundary
//         samples lie inside the larger path's fill region (point in polygon on the flattened
//         cubics, with the path's own fill rule; a stroke-only path's closed subpaths count as
//         its region) -- eyes inside a head;
//       - overlap: the shapes intersect (a boundary sample of one inside the other, or the
//         outlines cross), scored by how much of the smaller one lies inside;
//       - adjacency: the gap between the shapes' outlines (minus half stroke widths) is small;
//       - colour similarity: a weak tie-breaker among nearby pairs.
//     Strong links (containment, or an overlap covering at least strong_overlap of the smaller
//     path's boundary) are merged first, as long as more than min_groups clusters remain.
//     Then, only while more than max_groups clusters remain, the best-scoring pair is merged:
//     touching and nearby clusters first, and clusters that are far apart and unconnected
//     (gap above far_fraction of the canvas diagonal, no containment) last, nearest first.
//     Top-level groups that pass the check of rule 1 are kept as seeds of the clustering
//     when they are too many (more than max_groups) but at least min_groups.
//
// Cost: only pairs whose boxes are within the far distance are related (a grid over the
// boxes finds them); clusters keep sparse links and merge through a priority queue, so time and
// memory follow the nearby pairs, not n^2.
//
// The result: groups of indices into Scene::paths, every path in exactly one group, each
// group in paint order, groups ordered by their first path. Groups may interleave in paint
// order (A below B below A'); write_grouped_svg splits such a group into runs.
#pragma once

#include <string>
#include <vector>

#include "svgmotion/scene.h"

namespace svgm {

struct GroupingOptions {
  int max_groups = 15;
  int min_groups = 2;
  // Distances are fractions of the canvas diagonal.
  double touch_fraction = 0.01;  // outlines closer than this touch (adjacency)
  double far_fraction = 0.05;    // farther than this (and no containment): far apart
  // Share of the smaller path's boundary samples inside the larger one's fill for containment.
  double containment_fraction = 0.9;
  // Share of the smaller path's boundary samples inside the other for an overlap that merges
  // regardless of the count (like containment).
  double strong_overlap = 0.5;
  int chords_per_cubic = 8;       // flattening of each cubic
  int max_boundary_samples = 96;  // boundary samples per path for the inside tests
  bool keep_existing_groups = true;
};

// `note`, when given, receives one line when a cheaper rule than the above was used (empty
// otherwise): above 2,000 paths the pairwise analysis is skipped and the parts are the
// document's top-level groups when rule 1 would keep them (without its far-mix check), else
// the top-level groups (or the paths) binned by a coarse grid of at most max_groups cells over
// their box centres; the same grid merges the clusters left when over 1,024 remain far apart.
std::vector<std::vector<int>> group_paths(const Scene& scene, const GroupingOptions& options = {},
                                          std::string* note = nullptr);

// The "no far-apart unconnected mix" check for one group. Two paths are linked with weight
// equal to the gap between their shapes: 0 when they overlap, touch or one contains the
// other, otherwise the minimum distance between their flattened outlines minus half stroke
// widths. largest_gap is the bottleneck of the group's minimum spanning tree: the smallest
// distance d such that links no longer than d connect the whole group (0 for one path).
// components_at_touch counts the connected components with links no longer than the touch
// distance. far_mix is largest_gap > far_fraction of the diagonal. Gaps are in canvas units.
// Groups of more than 2,000 paths whose links within the far distance do not connect them
// report largest_gap as that distance (a lower bound) instead of the exact bottleneck.
struct GroupCheck {
  int components_at_touch = 1;
  double largest_gap = 0;
  double largest_gap_fraction = 0;  // largest_gap / canvas diagonal
  bool far_mix = false;
};

GroupCheck check_group(const Scene& scene, const std::vector<int>& group,
                       const GroupingOptions& options = {});

}  // namespace svgm
