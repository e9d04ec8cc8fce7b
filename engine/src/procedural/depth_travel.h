// A thing seen head-on that goes away or comes nearer (issue 35: "the bus drives away", "the
// ship sails away", "the train comes towards us"). A vehicle drawn bow-on or from the front
// (many emoji ships, buses, trams, trains, cars) has no sideways way to go: sent off as a side
// view is (leave_way.h), it slid sideways, a bus going crabwise. A designer draws such a going as
// a RECEDE: the thing shrinks towards a vanishing point on its horizon (so its foot rises a
// little towards it) while its ground (the sea, the track) stays; coming nearer is the same run
// backwards, growing from far to its drawn size.
//
// Seen head-on, from the drawing (not the words): its shape (flight_axis.h's grid, its ground
// band left out) is mirrored about the vertical line through its middle (kHeadOnMirror of it,
// IoU) and not long (at most kHeadOnWide times as wide as tall: a railway carriage drawn from the
// side is mirrored too, but long). Which words: a clause whose verb gets its figure somewhere
// (gait_travel.h's locomotes) and that tells no side ("to the left" keeps a sideways travel), of
// a thing, not a creature (a person walking away turns, which a shrink does not show):
//   - going away: it leaves ("away", "off": travel_words.h's says_leaving) or goes "into the
//     distance", and is seen head-on;
//   - coming nearer: "towards us", "towards the viewer", seen any way (a car drawn side-on
//     coming towards us grows as well).
// The vanishing point: above the middle of its figure, on the top of its ground band (the sea's
// surface, the far end of a track drawn in perspective), or with no band kHorizonRise of its
// height above its foot. Its time course is a launch's going (travel_profile.h's launch_at: it
// pulls away gathering speed and settles back) and a landing's coming (land_at: it comes in
// slowing down, and stays); at its farthest it is kFarScale of its size.
#pragma once

#include <string>

#include "procedural/motion_plan.h"
#include "procedural/part_rig.h"
#include "procedural/prompt_parse.h"

namespace svgm {

constexpr double kHeadOnMirror = 0.8;   // mirror cover (IoU) about the vertical of a head-on view
constexpr double kHeadOnWide = 1.6;     // a head-on view is at most this much wider than tall
constexpr double kHorizonRise = 0.35;   // of its height: the horizon above a foot with no ground drawn
constexpr double kFarScale = 0.45;      // its size at its farthest

// Whether the rig's figure is seen head-on (or from behind): see above; `why` says the measure.
bool seen_head_on(const Rig& rig, std::string* why);

// The way clause `c` of `prompt` sends its figure in depth: -1 away (a recede), +1 nearer, 0
// neither (a sideways travel, a creature, or a side view leaving). `why` says how.
int depth_way(const ParsedPrompt& prompt, const Clause& c, const Rig& rig, std::string* why);

// The point the figure recedes towards or comes from (see above).
Vec2 vanishing_point(const Rig& rig);

// Replaces the whole figure's slides of `plan` from action `from` on (a glide's own slide, a
// leaving's) by a travel in depth of verb `verb`, words `words`: a Pulse of the whole figure that
// goes (PlannedAction::goes, vanish, direction `way`).
void travel_in_depth(MotionPlan& plan, size_t from, int way, const Rig& rig, const std::string& verb, const std::string& words,
                     const std::string& why);

// The scale of a travel in depth `a` at loop time u (in cycles), for amplitude `amp` (its
// share of the size it loses at its farthest: 1 - kFarScale as planned).
double depth_scale(const PlannedAction& a, double amp, double u);

}  // namespace svgm
