// Limbs of a part read from its silhouette's skeleton, as lobes the motion bends (outline_lobes.h).
//
// A region bend (motion_plan.h's Region) that has no limb drawn as a part of its own used to
// bend a share of the part's box: the far 30 % of a lying body for a tail (which end was the
// seed's coin: half the cats wagged their heads), the top 30 % for a head, everything beyond a
// vertical line for arms. The part's silhouette knows better: its medial axis (motion/skeleton.h)
// has the tail, the head, the legs and the arms as branches hanging from a thick core, labelled
// by motion/limbs.h. Each becomes a lobe: it turns about its base (where it leaves the core's
// inscribed disc), and a point belongs to it when it lies beyond the base and inside one of the
// discs along its axis (lobe_depth), so a shape lying across the joint bends with the limb
// rather than being cut at a line.
//
// A piece drawn apart from the silhouette but within kHeldGap of a limb's far half (a fencer's
// foil beside his glove, a racket, a balloon's string) is what the limb holds: it joins that
// limb's lobe and moves with it (the thinning reads the largest piece only, so it stayed put
// while the arm thrust).
//
// A head drawn apart (a disc above the shoulders across a gap, as openmoji draws its people) is
// a piece the thinning does not read: the one limb rising from the upper body, which the
// skeleton labels the head, is then a raised arm (skeleton_lobes.cpp, head_drawn_apart).
//
// The mask: every filled path of the part drawn as polygons (its cubics sampled), every stroked
// one as polylines of its width, at kSkeletonSize pixels on the box's long side; the same paths
// give the same lobes (OpenCV's fills and the thinning are deterministic).
#pragma once

#include <vector>

#include "svgmotion/scene.h"
#include "procedural/outline_lobes.h"

namespace svgm {

constexpr int kSkeletonSize = 160;       // px on the long side of the part's box
constexpr double kLimbMinLength = 0.12;  // of the figure's larger side: shorter branches are nubs
constexpr double kHeadApartMin = 0.02;  // of the figure's pixels: a piece apart this large may be
                                        // its head (smaller: a speck, a drop of sweat)
constexpr double kHeldGap = 0.03;        // of the mask's long side: a hand and what it holds are
                                         // drawn this close (an openmoji glove and foil: 0.02)

// The limbs of the shape `paths` draw (canvas space), in find_limbs' order; empty when the
// shape has no core with limbs (a disc, a bar, nothing drawn).
std::vector<ArmLobe> skeleton_lobes(const Scene& scene, const std::vector<int>& paths);

}  // namespace svgm
