// A figure's body core and limbs, read from its silhouette skeleton (skeleton.h), and which
// part of the drawing each limb covers.
//
// The core is the thick part the limbs hang from: the skeleton's internal branches (between
// two junctions) led by the one with the most body (mean radius squared times length: the
// torso beats a long thin forearm), grown over adjacent internal branches at least half as
// thick. A skeleton without internal branches has its thickest junction as core (a star), or
// its one branch (a snake, a bar: no limbs). A limb is a sub-tree hanging from the core that
// ends in end points: its joint is the core junction, its base is where it leaves the inscribed
// disc there (the shoulder, the hip), its tip is its farthest end, and its bend is the path
// point farthest from the chord base-tip (the elbow or the knee).
//
// Labels (image coordinates, y down; side is the image's left/right, not the figure's own):
// feet are the tips whose discs reach a common ground line (the figure's lowest); an upright
// core (its axis within 45 degrees of vertical) has legs from its lower half or on the ground,
// a head as the most vertical limb up from its upper half, arms for the rest of the upper half
// and a tail for sideways limbs from the lower half (a point core, shorter than it is thick,
// places limbs by direction the same way: down is a leg, the most central up is the head,
// the rest are arms); a lying core (quadruped, bird, fish) has
// legs pointing down, a head and a tail along its axis at its two ends (the head has the larger
// tip disc, else the higher tip) and arms (wings, fins) rising from its middle.
//
// A limb off the ground does not own a fork of its sub-tree that stands on the ground: a hind
// leg whose outline runs into the root of the tail (one branch of the skeleton leaving the
// rump, two ends) is a leg of the body, and a tail's lash would swing it with the tail. Nor
// does a tail own a foot its branch runs through without forking (a tail drawn down the rump
// and touching the hind foot, whose own short branch the pruning removed): the tail starts
// past the last point of its branch that owns a piece of the ground line.
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "motion/skeleton.h"

namespace svgm::motion {

enum class LimbKind { Head, Arm, Leg, Tail, Other };  // Arm: any upper limb (arm, wing, fin)
const char* limb_kind_name(LimbKind k);

struct Limb {
  LimbKind kind = LimbKind::Other;
  int side = 0;              // -1 image left of the core, +1 right, 0 in line with it
  int joint = -1;            // the core's skeleton node it hangs from
  int tip = -1;              // its farthest skeleton end node
  std::vector<int> more_tips;  // its other end nodes (fingers, ears), if it forks
  std::vector<int> standing_edges;  // the stretches of its forks that stand on the ground while
                                    // it does not (the body's legs, not the limb's), and a tail's
                                    // way through a foot: the body's (limb_regions)
  std::vector<int> edges;    // every skeleton edge of its sub-tree
  std::vector<Vec2> path;    // skeleton points, joint to tip
  std::vector<double> radius;  // inscribed radius at each path point
  double body_radius = 0;    // > 0 (tails): a skeleton point this thick or more is the body's
                             // (a rump the tail's branch runs through), not the limb's
  size_t body_until = 0;     // (tails) path[0 .. body_until) is the body's: a foot the tail's
                             // branch runs through on its way out of the rump (limb_regions)
  size_t base_index = 0;     // path[base_index] = base
  Vec2 base, bend, tip_pos;  // shoulder/hip, elbow/knee, hand/foot
  bool bent = false;         // the bend is at least a tenth of the chord off it
  double length = 0;         // px along the path, base to tip
  double relative_length = 0;  // length over the figure's larger side
  double tip_radius = 0;     // inscribed radius at the tip: a head or a wheel is a big disc
  Vec2 direction;            // unit, base to tip
  bool grounded = false;     // its tip's disc reaches the ground line
  std::string why;           // how its kind was found
};

struct Figure {
  int component = -1;            // the mask component read (the largest)
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // its bounding box, px
  double ground_y = 0;           // the lowest tip disc's bottom (the box's bottom without tips)
  std::vector<int> core_edges;   // skeleton edges of the core (empty for a star core)
  std::vector<int> core_nodes;   // skeleton nodes on the core
  Vec2 core_centre, core_axis;   // centroid and unit principal direction (y >= 0 if vertical)
  double core_radius = 0;        // largest inscribed radius on the core
  double core_length = 0;        // extent of the core along its axis, px
  bool upright = true;
  std::vector<Limb> limbs;       // ordered by joint position along the core, then angle
  int single_branch = -1;        // the skeleton edge when the figure is one branch, else -1
};

Figure find_limbs(const Skeleton& s);

// Which limb covers each point (mask pixel coordinates): the nearest skeleton point by the
// distance to its inscribed disc's edge (|p - q| - r(q)), a limb's own skeleton points from its
// base on and the core's (with the limbs' stretch inside the body) for -1. Points outside every
// component's reach still get the nearest.
std::vector<int> assign_points(const Skeleton& s, const Figure& f, const std::vector<Vec2>& points);

// One limb (or -1 for the core) per path from its control points (path_of_point[i] is the path
// of points[i]): the limb most of its points fall to; paths without points get -1.
std::vector<int> assign_paths(const Skeleton& s, const Figure& f, const std::vector<Vec2>& points,
                              const std::vector<int>& path_of_point, int paths);

// The same rule over pixels: CV_32S image of the mask's size, limb index per figure pixel, -1
// core, -2 outside the figure's component.
cv::Mat limb_regions(const Skeleton& s, const Figure& f);

// One limb (or -1) per path from per-path masks (CV_8U, the skeleton's size): most pixels.
std::vector<int> assign_path_masks(const cv::Mat& regions, int limbs, const std::vector<cv::Mat>& path_masks);

}  // namespace svgm::motion
