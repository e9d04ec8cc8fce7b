// Wheels whose spin cannot be seen. A wheel drawn as plain discs and rings about its centre (no
// spoke, no valve, no gradient) looks the same at every angle: spinning it in place changes no
// pixel, and the pixel ranker rightly calls every such candidate 'no motion' ("the car's wheels
// spin" on a car with plain wheels ended with exit 4). Such a spin rolls instead: the figure
// slides with its wheels turning by the distance (PlannedAction::rolls), which is what spinning
// wheels on the ground look like.
#pragma once

#include "procedural/motion_plan.h"
#include "procedural/part_rig.h"
#include "svgmotion/scene.h"

namespace svgm {

// True when every path of `parts` (and of what hangs from them) keeps its distance from its
// part's centre within kRoundTolerance of the radius all round (in the wheel's plane), is painted
// without a gradient or dashes, every open subpath ends where it began, and `parts` is not
// empty.
bool looks_same_turned(const Scene& scene, const Rig& rig, const std::vector<int>& parts);

// Wheels roll with the figure's slide of the same words (a car driving: the drive's slide and
// its wheels' spin): their turn follows the distance it goes, not a steady rate. Sets
// PlannedAction::rolls (plan_from_prompt).
void roll_wheels_with_slides(MotionPlan& plan);

// For every Spin of wheels that neither rolls nor shows (looks_same_turned) and is all its words
// move (no other action of the same words): adds the drive's slide of the whole figure with the spin's words,
// makes the spin roll with it, and says so in a warning.
void roll_invisible_spins(const Scene& scene, const Rig& rig, MotionPlan& plan);

// A point's distance from the centre may vary by this share of the radius on a "round" path
// (a circle written as four cubics is within 0.03 %; a wheel's hexagonal nut, 13 %).
inline constexpr double kRoundTolerance = 0.04;

}  // namespace svgm
