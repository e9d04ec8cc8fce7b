// Where a figure goes when the prompt says it leaves (issue 35: "the ship sails away", "the
// bullet train speeds away", "the satellite flies off"). "away" was read as a depth (going into
// the distance) that nothing drew, and it kept a gait's untold travel from starting too, so the
// ship rocked in place, the train slid 10 % of its width back and forth, the satellite bobbed.
// A designer reads "away" and "off" after a verb by which a figure gets somewhere
// (gait_travel.h's locomotes: a drive, a sail's glide, a flight, a float, a gait) as leaving:
// it goes steadily towards the frame's edge the way it faces, its nose first, and glides back
// (travel_profile.h: the loop a told travel makes, which the fitter follows). Which way:
//   - the way it faces (limb_qualifiers.h's facing_side: its eye, its head, a vehicle's low
//     front);
//   - else, for a thing (not a creature), the side its nose points to (flight_axis.h: the
//     narrower end of its mirror line or long axis), when it points more sideways than up or
//     down (|x| >= kLeaveSideways);
//   - else to the right, as a reader reads (gait_travel.h's untold rule).
// Not when a clause keeps it where it is ("on the spot").
#pragma once

#include <string>

#include "procedural/part_rig.h"
#include "procedural/prompt_parse.h"

namespace svgm {

constexpr double kLeaveSideways = 0.5;  // the nose's horizontal share (cos 60 degrees) that picks a side

// The viewer's side (-1 left, +1 right) clause `c` of `prompt` sends its figure when it says the
// figure leaves (travel_words.h's says_leaving) and no way; 0 otherwise. `why` says how.
int leaving_side(const ParsedPrompt& prompt, const Clause& c, const Rig& rig, std::string* why);

}  // namespace svgm
