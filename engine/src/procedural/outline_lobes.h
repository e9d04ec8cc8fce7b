// Arms drawn as part of one body outline: a ghost's stubby arms, where the path of its body goes
// out round each arm and back. No part of the drawing is the arm, so the motion bends a region of
// the outline (motion_plan.h's Sides region); which region is found here, from the outline's own
// shape, instead of everything beyond a vertical line either side of the body's middle (which
// also took a tilted ghost's hem corner and its hat's brim).
//
// The outline's concavities (where it falls in from its convex hull by at least kDefectDepth of
// its size: armpits, the neck, the gaps of a hem) cut it into lobes. A lobe is an arm when it
// leaves the body sideways (its base, the segment between the two concavities, faces left or
// right), from the body's upper part (its base's middle above kArmBaseLow of the outline's
// height), through a narrow base (at most kArmBaseMax of the outline's height: a hem corner
// joins the body along most of its side) and sticks out at least kArmReach of its base's width
// (a bump is no arm).
#pragma once

#include <vector>

#include "svgmotion/scene.h"

namespace svgm {

// What a limb read from a silhouette skeleton is (skeleton_lobes.h; motion/limbs.h's kinds), or
// a blaze's tongues over a thing burning (flame_core.h), which lick instead of turning
// (flame_lick.h).
enum class LobeKind { Arm, Leg, Head, Tail, Other, Blaze };

struct ArmLobe {
  int side = 0;               // as the viewer sees it: -1 left, +1 right
  Vec2 base0, base1;          // where the lobe leaves the body (its two concavities)
  Vec2 pivot;                 // the base's middle: the arm turns about it
  Vec2 tip;                   // the lobe's point farthest from its base
  std::vector<Vec2> outline;  // the lobe's stretch of the outline, base0 .. base1
  LobeKind kind = LobeKind::Arm;  // a limb of the silhouette's skeleton (skeleton_lobes.h),
                                  // whose outline is the contour of the silhouette it owns
  bool rigid = false;         // its paths turn whole about the pivot, no ramp and no mesh: a part
                              // that hangs free (part_locator.h's clapper), not a limb that bends
  double tongue_spacing = 0;  // a Blaze: the distance between its neighbouring tongues' tips
  std::vector<int> paths;     // a located part's lobe: the scene paths it was built from (sorted),
                              // or none (the lobe takes the points its outline holds)
};

// The arm lobes of `outline`'s first subpath (closed, at least a few cubics), left first.
std::vector<ArmLobe> arm_lobes(const Path& outline);

// How far q is into `lobe` beyond its base, 0 when q is not in the lobe: on the base's outer
// side and inside the lobe's outline, or within kLobeMargin of the base's width of it (the
// handles of its curves lie just outside the curves).
double lobe_depth(const ArmLobe& lobe, Vec2 q);

// The lobe of `lobes` built from path `path` (ArmLobe::paths), -1 when none is. Its points turn
// with it alone, by how far beyond its base they lie (lobe_owned_depth): the hulls of strands
// drawn close together overlap, and a point taking the first lobe whose outline held it tore a
// squid's arm from its outline stroke (openmoji 1F991: the ranker saw the colour under it
// appear and cut the wave to 41 %).
int owner_lobe(const std::vector<ArmLobe>& lobes, int path);
double lobe_owned_depth(const ArmLobe& lobe, Vec2 q);

}  // namespace svgm
