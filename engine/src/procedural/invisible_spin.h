// Wheels whose spin cannot be seen. A wheel drawn as plain discs and rings about its centre (no
// spoke, no valve, no gradient) looks the same at every angle: spinning it in place changes no
// pixel, and the pixel ranker rightly calls every such candidate 'no motion' ("the car's wheels
// spin" on a car with plain wheels ended with exit 4). Such a spin shows through the body: sent
// somewhere ("spin to the right") the figure rolls there, its wheels turning by the distance
// (PlannedAction::rolls); sent nowhere, the wheels spin in place and the body bounces on them
// (an engine revving), so that what the prompt names moves most and the roof holds nearly
// still.
#pragma once

#include "procedural/motion_plan.h"
#include "procedural/part_rig.h"
#include "svgmotion/scene.h"

namespace svgm {

// True when every path of `parts` (and of what hangs from them within the wheel: kInsideWheel) keeps its distance from its
// part's centre within kRoundTolerance of the radius all round (in the wheel's plane), is painted
// without a gradient or dashes, every open subpath ends where it began, and `parts` is not
// empty.
bool looks_same_turned(const Scene& scene, const Rig& rig, const std::vector<int>& parts);

// Wheels roll with the figure's slide of the same words (a car driving: the drive's slide and
// its wheels' spin): their turn follows the distance it goes, not a steady rate. Sets
// PlannedAction::rolls (plan_from_prompt).
void roll_wheels_with_slides(MotionPlan& plan);

// For every Spin of wheels that neither rolls nor shows (looks_same_turned) and is all its words
// move (no other action of the same words): with a travel word (PlannedAction::travel), adds the
// drive's slide of the whole figure that way with the spin's words and makes the spin roll with
// it; without, adds a bounce of the body (a Bob of the whole figure, kIdleBounce of its height,
// kIdleBounces times) with the spin's words. Says so in a warning.
void roll_invisible_spins(const Scene& scene, const Rig& rig, MotionPlan& plan);

// The body's bounce on wheels spinning in place: a share of the figure's height (a car 22 px
// tall: 0.7 px, 5 px in the 512 px target video, a tenth of what its wheels' rims travel) and
// how many times.
inline constexpr double kIdleBounce = 0.03;
inline constexpr int kIdleBounces = 4;

// A point's distance from the centre may vary by this share of the radius on a "round" path
// (a circle written as four cubics is within 0.03 %; a wheel's hexagonal nut, 13 %).
inline constexpr double kRoundTolerance = 0.04;

// A part hanging from a wheel is judged with it when at least this share of its box lies within
// the wheel's (a hub, a tyre's tread; not a fork reaching up to the handlebar).
inline constexpr double kInsideWheel = 0.5;

}  // namespace svgm
