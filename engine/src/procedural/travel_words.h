// Whether a prompt sends its figure across the canvas, read from the words alone, before any
// drawing is read (issue 35: the pipeline gives such a figure room to travel in,
// pipeline/canvas_room.h). A clause whose verb gets the figure somewhere (a gait, hops, a crawl,
// a body's wave: gait_travel.h) sends it across when it says "to the left" or "to the right",
// or, when its verb is a gait (not a rider's pedalling: gait_travel.h's is_gait), says no way at
// all while no clause keeps it where it is ("on the spot") nor names the limbs that move: then
// untold_travel sends it the way it faces. Apart from gait_travel.h, whose
// motion_plan.h the pipeline cannot include beside the exporters' PathMotion.
#pragma once

#include "procedural/prompt_parse.h"

namespace svgm {

bool sends_figure_across(const ParsedPrompt& prompt);

// Whether a prompt tells its figure a way to go ("to the left", "to the right") by a verb that
// gets it somewhere or a slide of its own (a drive, a glide: gait_travel.h's locomotes), not
// kept where it is: a figure drawn facing the other way turns round and makes its whole trip on
// the told side (travel_profile.h's turned_going_at), so it needs the room there twice over.
bool sends_figure_one_way(const ParsedPrompt& prompt);

// Whether a prompt carries its whole figure about in the air, read from the words alone: a
// clause whose verb (as an insect's flight reads it: self_movers.h's insect_flight) is a hover,
// a buzz (carried_flight.h) or a float, said of the figure, not of a part ("its rotor
// whirring"). Such a figure moves whole by kCarriedTravel of its size (a float by the visible
// floor), which a figure filling most of its canvas has no room for: given none under
// kFillsCanvas, a drone hovering and a balloon drifting were held to 5.5 and 5.9 % of their
// size (pipeline/canvas_room.h gives them room from kTravelFills).
bool carries_figure_about(const ParsedPrompt& prompt);

// Whether a prompt launches or lands its figure (a clause whose verb is a takeoff: "takes off",
// "blasts off", "launches"; or a landing): it goes off along its nose (flight_axis.h), or comes
// in along it, by a quarter of its size, which a figure filling its canvas had no room for at
// kAutoRoom (an arriving plane came in from 12 % of its length); pipeline/canvas_room.h gives it
// kTurnRoom from kTravelFills of the canvas's width or height.
bool launches_figure(const ParsedPrompt& prompt);

// Whether clause `c` says its figure leaves: a verb by which it gets somewhere (gait_travel.h's
// locomotes: a drive, a sail, a flight, a gait) with "away" or "off" as its particle ("sails
// away", "flies off into the sky"; not "off the table", where "off" says where from). It goes
// the way it faces (leave_way.h), across the canvas: sends_figure_across counts it.
bool says_leaving(const Clause& c);

}  // namespace svgm
