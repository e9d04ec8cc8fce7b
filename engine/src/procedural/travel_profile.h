// How a figure sent somewhere moves along its way over one loop (issue 35: "the turtle plods
// along", "the snail crawls to the left"). A loop must end where it began, so the figure cannot
// only go forward; moved there and back about where it stands (a sine), it rocked: a viewer saw
// it sway, not go. Here it goes forward at a steady pace for kForwardShare of the loop, from
// behind where it stands to as far ahead, passing its rest place at the loop's start, and glides
// back (eased) in the rest of the loop: most of what is seen is the going.
//
// A crawl (a caterpillar, a snail, a worm: an inchworm's or a slug's gait) goes by steps: its
// body stretches forward with its rear planted, then gathers with its front planted, so each
// step carries it one stretch ahead. The forward run is kCrawlSteps such steps; the figure's
// slide is then a staircase (the rear moves only while the body gathers) and its stretch the
// extension, both from crawl_at, so the ends stay put in turn when the stretch's size equals
// the slide's (motion_plan.cpp sets them so).
//
// A figure sent against the way it faces (a zebra drawn facing left told to trot to the right)
// went there tail first. It turns round instead (turned_going_at): a quick turn about its
// vertical axis through edge-on (kTurnShare of the loop), then it goes the told way facing it
// to as far as it goes, turns back, and comes home facing its own way, ending at rest: a walk
// there and back, all of it forwards. Its reach is on the told side only (the way home is the
// way out), so the same sweep as the steady loop's lies wholly on that side.
//
// A launch (flight_axis.h: a rocket, a plane going off along its nose) has no way home in a
// loop but back: it stands through its ignition (kIgnitionShare of the loop, its rumble), goes
// off gathering speed to kLaunchOut of the loop, and settles back, eased, in the rest: the going
// quick, the return slow, so what is seen is the launch.
#pragma once

#include "svgmotion/affine.h"

namespace svgm {

inline constexpr double kForwardShare = 2.0 / 3;  // of the loop spent going forward
inline constexpr int kCrawlSteps = 2;             // stretch-and-gather steps in one forward run
inline constexpr double kIgnitionShare = 0.12;    // of a launch's loop spent at rest, rumbling
inline constexpr double kLaunchOut = 0.55;        // of a launch's loop when it is farthest out

// Where a figure travelling steadily is at loop time u (in cycles; any real): -1 (behind its
// rest place) to +1 (ahead), 0 at u = 0.
double going_at(double u);

struct CrawlPose {
  double rear = 0;     // the rear's place, -1 to +1 as going_at's
  double stretch = 0;  // the body's extension, 0 to 1 step (a step: 2 / kCrawlSteps of rear's unit)
};

// How far out a launch is at loop time u (in cycles; any real): 0 at rest through the ignition,
// out to 1 at kLaunchOut (x^3 (4 - 3x) of the way's time x: speeding up most of the way, still at
// the far end), back to 0 by the loop's end (a half cosine).
double launch_at(double u);

// How far back along its way in a landing is at loop time u: 0 (landed) at u = 0, eased back
// out to 1 by kLandBack, then coming in, slowing down ((1 - x)^2), to rest at kLandDown, and
// resting there to the loop's end: the arrival is the quick, seen part, the rest the stay.
double land_at(double u);
inline constexpr double kLandBack = 0.4;   // of a landing's loop when it is farthest back
inline constexpr double kLandDown = 0.8;   // of a landing's loop when it is down

// Where a figure launched (`lands` false) or landing is along its heading at loop time u:
// launch_at, or minus land_at (behind it).
double flight_at(bool lands, double u);

// A crawl's pose at loop time u: the rear's place and the body's stretch, the front at rear +
// stretch * 2 / kCrawlSteps. Rest (0, 0) at u = 0.
CrawlPose crawl_at(double u);

// Of the loop, each of the two turns of a figure turning round to go, and the share of its width
// it keeps edge on (turned_width). The pixel ranker reads 16 frames of a loop (one each 1/15 of
// it) and flags a colour whose area changes by 55 % between two of them (a 'continuity' break);
// the width falls to kTurnRoundEdge and grows back at a steady rate of its logarithm, so the
// largest change between two of its frames is 1 - kTurnRoundEdge^(2 / 15 / kTurnShare): 37 %
// here. Over 1/8 of the loop to a pirouette's 0.3 edge on, the camel's area fell 73 % between
// two of them and every candidate was flagged; over 0.18 to 0.4 (47 % for the whole figure) a
// hopping rabbit's small patches (40 px of the ranker's 128 px frame) lost 65 %.
inline constexpr double kTurnShare = 0.2;
inline constexpr double kTurnRoundEdge = 0.5;

struct TurnedPose {
  double along = 0;  // how far along its way out: 0 at rest, 1 as far as it goes
  double turns = 0;  // of a whole turn about its vertical axis: 0 facing its own way, 0.5 turned
                     // round (mirrored), 1 back (turned_width's argument)
};

// A figure's pose at loop time u (in cycles; any real) when it turns round to go the way it does
// not face: turning round (u in [0, kTurnShare)), going out steadily (to 1/2), turning back (to
// 1/2 + kTurnShare), coming home steadily. Rest {0, 0} at u = 0.
TurnedPose turned_going_at(double u);

// The signed width factor (negative: mirrored) of a figure `turns` of a whole turn round (its
// TurnedPose): 1 facing its own way, -1 turned round, kTurnRoundEdge (either sign) edge on, a
// steady share of the width lost or won per time between. Never narrower than kTurnRoundEdge: a
// flat drawing edge on has no width, and a colour vanishing is a continuity break to the ranker.
double turned_width(double turns);

// The map of a figure turning round to go at loop time u: mirrored by turned_width about the
// vertical line x = `middle` (its own middle), carried `reach` (signed: the told way) times its
// TurnedPose's along. motion_frames.cpp gives it a reach of twice the steady loop's: the same
// sweep, all on the told side.
Affine turned_going_map(double reach, double middle, double u);

}  // namespace svgm
