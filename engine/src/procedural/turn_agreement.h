// Two motions of a plan that turn the whole figure back and forth at the same tempo go the same
// way first. Each action drew its own way from the seed: "the sloth hangs from the branch and
// swings" is a sway (for "hangs") and a rock (for "swings"), both turning the whole sloth about
// its grip on the branch, and in the seeds where the two coins fell apart the turns cancelled
// (one candidate of four turned by 0.001 degrees: the ranker rightly flagged it "no motion").
// Each clause alone passed the visible floor (fit_plan measures clauses one at a time), so only
// the plan can keep them from cancelling: the later turn takes the earlier one's way, unless the
// prompt said which way ("sways to the left").
//
// A rock of the whole figure standing (not hung: hang_support.h's pendulum already went its way)
// turned clockwise first in every seed, whatever its direction said: it now goes its direction
// too (whole_turn_sign), so that a sway and a rock agreed in the plan agree in the frames.
#pragma once

#include <vector>

#include "procedural/motion_plan.h"

namespace svgm {

// Gives `a`, a sway or a rock of the whole figure, the direction of the first such action of
// `earlier` with the same cycles, unless `way_told` (the prompt said which way). Returns whether
// its direction changed.
bool agree_with_earlier_turns(const std::vector<PlannedAction>& earlier, PlannedAction& a, bool way_told);

// The sign rigid() turns a whole figure's rock by (+1 clockwise in the image first): its
// direction; 1 for any other action (their sign is the part's, or unused).
double whole_turn_sign(const PlannedAction& a);

}  // namespace svgm
