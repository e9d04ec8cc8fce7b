// What a turning wheel carries (a ferris wheel drawn as one group with its stand and cabins):
// the paths inside its circle that reach in towards its hub (spokes, the hub) or that are rings
// about its centre turn with it; small parts with their middle on its rim (cabins) ride round
// with it upright; riders stacked one under another (a cabin's roof and its body drawn as two
// shapes) ride as one, hanging from the top of the stack; and riders evenly spaced round the
// rim make the wheel look the same after one spacing of a turn (rider_symmetry), so a slow turn
// of one spacing loops. The rig splits a wheel's group by these rules (part_rig.cpp) and the
// motion moves by them (motion_plan.cpp).
#pragma once

#include <vector>

#include "procedural/part_rig.h"

namespace svgm {

// A path whose control points are `pts` (box `box`) turns with a wheel of box `wheel`: all of
// it within the wheel's circle (its radius half the box's width, widened by kWheelInsidePad
// of it: a rim drawn as two rings, the outer a little larger) and either reaching in to
// within kRimShare of the radius (a spoke, the hub) or centred on the wheel (a ring).
bool turns_with_wheel(const RigBox& box, const std::vector<Vec2>& pts, const RigBox& wheel);

// A part of box `part` rides round a wheel of box `wheel` upright: small beside it (at most
// kRideMaxArea of its box) with its middle on the rim (at least kRimShare of the radius out,
// and within kRideReach of it or inside the wheel's box: in a corner of the box a cabin's
// middle may lie beyond the radius).
bool rides_wheel(const RigBox& part, const RigBox& wheel);

// Riders come in sets (a ferris wheel's cabins, or their roofs and their bodies): of the boxes
// of the parts that ride a wheel (rides_wheel, or stacked under one that does), those with at
// least kMinSymmetricRiders - 1 others of about their size (width and height each within
// kRiderSimilar) ride, all of them when there are fewer than kMinSymmetricRiders; a piece of the rim's shading or a bracket near the hub drawn once does
// not (ridden round upright, a dark arc under the bottom cabin stood out of the rim as a bar).
std::vector<char> in_rider_sets(const std::vector<RigBox>& boxes);

// Two riders stack (one hangs under the other, a cabin's roof and its body): their x-ranges
// overlap by at least half the narrower width and their y-ranges meet.
bool riders_stack(const RigBox& a, const RigBox& b);

// For riders' boxes, each one's stack: the union of the boxes stacked with it (transitively).
std::vector<RigBox> rider_stacks(const std::vector<RigBox>& riders);

// The number of distinct stacks `stacks` (rider_stacks' output, one entry per rider) when at
// least kMinSymmetricRiders of them hang (from the middle of their tops) at evenly spaced
// angles round the wheel's centre (each gap within half a spacing of 360/n degrees), else 0.
int rider_symmetry(const std::vector<RigBox>& stacks, const RigBox& wheel);

constexpr double kRideMaxArea = 0.1;
constexpr double kRimShare = 0.7;
constexpr double kRideReach = 1.05;
constexpr double kWheelInsidePad = 0.1;
constexpr int kMinSymmetricRiders = 3;
constexpr double kRiderSimilar = 1.3;

}  // namespace svgm
