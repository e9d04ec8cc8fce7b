// A blaze's tongues licking up (issue 35): the flames over a thing burning (flame_core.h) drawn
// as one shape, several tongues side by side. Turned as one lobe about the middle of the burning
// thing's top, the blaze's far sides swung down into the thing and up, and through the mesh the
// inside of that turn folded: fit_plan's fold check held the flicker to 7.7 % of the figure's
// size (the openmoji heart on fire), under the floor a viewer sees. And a turn moves the
// blaze's lower sides about as much as its tips, where a viewer sees tongues move.
//
// Here each column of the blaze rises and falls by its tongue's phase (half a cycle from one
// tongue to the next: neighbours lick in turn; tongue_phase), by the square of its
// height over the base (the base holds, the tips move most), then the blaze sways as a whole,
// each row by the same square of its new height. Both steps are one-to-one whatever the
// amplitude and whatever the phase across the columns, so the blaze can never fold:
//  - the lick moves each point along its own column only, and keeps the column's order as long as
//    d y'/d y = 1 + 2 B v P stays positive (v in 0..1 the height share, |P| <= 2 the phase
//    term): kLickMax = 0.2 keeps it at least 0.2;
//  - the sway moves each row along itself by one offset: a translation of the row.
// No mesh: the closed form is the bend (region_bend.h skips blaze lobes).
#pragma once

#include <vector>

#include "procedural/motion_plan.h"
#include "procedural/outline_lobes.h"

namespace svgm {

// The lick's largest rise per unit of the phase term, in shares of the blaze's height (see
// above: the column's order holds while 4 B < 1).
inline constexpr double kLickMax = 0.2;
// A tip of the blaze's top edge stands out of the notches either side of it by at least this
// share of the blaze's height (a wiggle of its outline is no tongue).
inline constexpr double kTongueProminence = 0.12;
// The top edge is read in this many columns across the blaze.
inline constexpr int kTongueColumns = 32;

// The spacing of the tongues of a blaze whose points (above its base) are `pts`: the mean
// distance between neighbouring tips of its top edge; 0 when it has one tip.
double tongue_spacing(const std::vector<Vec2>& pts);

// The lick's phase (in cycles) at x for tongues `spacing` apart, one of them at `tip`: half a
// cycle from one tongue to the next, the same over each tongue (a thin tongue rises whole: a
// phase running across it sheared its tip into a hook), changing over the middle half of the gap
// between two tips. 0 everywhere when spacing is 0 (one tongue).
double tongue_phase(double spacing, double tip, double x);

// Point q of a blaze lobe (LobeKind::Blaze: its tip the tip of a tongue) at amplitude `amp`
// (degrees: tan(amp) of the blaze's height, half of it the sway's lean at the tips, half the
// lick's rise, that capped at kLickMax) and time t; q below the lobe's pivot holds.
Vec2 flame_lick(const ArmLobe& lobe, const PlannedAction& a, double amp, double t, Vec2 q);

}  // namespace svgm
