// The silhouette skeleton of a figure: the medial axis of its mask as a graph whose edges are
// branches (limbs, the body's axis) and whose nodes are junctions and end points.
//
// The caller renders the figure without its background into a binary mask at a working size
// (about 256 px: the thinning is linear in pixels and a figure's limbs stay several pixels
// thick there). skeletonise() thins it (Zhang-Suen), prunes spurs that boundary noise makes
// (skeleton.cpp says which and why) and traces the graph. Everything is in the mask's pixel
// coordinates (x right, y down) and is deterministic: the same mask gives the same graph, node
// and edge order included (raster order of the pixels).
#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "svgmotion/affine.h"

namespace svgm::motion {

struct SkeletonNode {
  Vec2 pos;            // centre of the node's pixels (a junction may be a few pixels)
  double radius = 0;   // distance to the background there: the inscribed disc's radius
  std::vector<int> edges;  // indices into Skeleton::edges (a self-loop is listed twice)
  int component = -1;  // index into Skeleton::component_area
  int degree() const { return static_cast<int>(edges.size()); }
  bool end() const { return edges.size() == 1; }
  bool junction() const { return edges.size() >= 3; }
};

struct SkeletonEdge {
  int a = -1, b = -1;            // node indices; points runs from a to b
  std::vector<Vec2> points;      // pixel centres, 8-connected, both nodes' pixels included
  std::vector<double> radius;    // distance to the background at each point
  double length = 0;             // arc length in pixels (1 or sqrt 2 a step)
  double mean_radius = 0, min_radius = 0, max_radius = 0;
  Vec2 dir_a, dir_b;             // unit directions leaving a (into the edge) and leaving b
  bool terminal = false;         // one of its nodes is an end point
};

struct SkeletonOptions {
  // A terminal branch is a spur (removed) when its reach (length plus the radius at its end)
  // is less than spur_ratio times the inscribed radius at its junction plus spur_slack pixels
  // (skeleton.cpp: why).
  double spur_ratio = 1.5;
  double spur_slack = 2.0;      // px: the 1-px steps of a rendered outline
  int min_component_area = 12;  // px: specks of the mask below this are ignored
};

struct Skeleton {
  int width = 0, height = 0;
  cv::Mat pixels;    // CV_8U, 255 on the pruned skeleton
  cv::Mat distance;  // CV_32F, distance of each mask pixel to the background (0 outside)
  cv::Mat labels;    // CV_32S, mask component per pixel (-1 background or ignored specks)
  std::vector<int> component_area;  // pixels of each mask component
  std::vector<SkeletonNode> nodes;
  std::vector<SkeletonEdge> edges;
  int spurs_pruned = 0;  // spurs removed, for reports and tests
};

// `mask`: CV_8U, non-zero inside the figure. Throws std::invalid_argument for another type.
Skeleton skeletonise(const cv::Mat& mask, const SkeletonOptions& options = {});

// Zhang-Suen thinning of a binary mask (non-zero in), cleaned to one pixel wide (8-connected,
// no staircase corners). Exposed for tests.
cv::Mat thin(const cv::Mat& mask);

// Shortest paths by branch length from node `from` (Dijkstra): each node's distance (infinity
// where it is not reached) and the edge it was reached by (-1 for `from` and the unreached).
// Through `edges` only when given (a sub-tree), else through every node's own edges.
struct SkeletonPaths {
  std::vector<double> dist;
  std::vector<int> via;
  // The edges from `from` to `to`, in order from `from`.
  std::vector<int> edges_to(const Skeleton& s, int to) const;
};
SkeletonPaths shortest_paths(const Skeleton& s, int from, const std::vector<int>* edges = nullptr);

}  // namespace svgm::motion
