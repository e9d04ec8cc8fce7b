// Two motions that go round rather than back and forth (issue 35): a juggler's cascade (the
// tossed things fly from hand to hand, tossed_things.h) and a swimmer's strokes (the arms turn
// over about the shoulders in whole turns: a windmill). Here the prompt's words are read as
// them, and they are planned; motion_frames.cpp draws them.
//
// Strokes: "freestyle" and "backstroke" always; "crawl", "butterfly" and "stroke" only in a
// clause that swims (a swim verb, or a word in swim-: "the swimmer does the front crawl"). A
// baby or a snail that crawls keeps its crawl (gait_travel.h). The front crawl's arms turn in
// turn, half a turn apart unless the drawing has them apart already (pointing more than a
// quarter turn apart: the loop then starts at the drawing); the backstroke's turn the other
// way; the butterfly's together. Over the top the arm goes the way the swimmer faces (its eye,
// else its head's side of the body; else the seed's way). A figure with no arm parts of its
// own (arms drawn in its outline) cannot turn them round without tearing the outline: its arms
// swing wide in turn instead (kStrokeSwingDeg).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "procedural/motion_plan.h"

namespace svgm {

inline constexpr double kStrokeSwingDeg = 60;

// The stroke verb clause `c` means ("stroke", "backstroke", "butterfly"), or null.
const Verb* stroke_reading(const Clause& c);

// The planned action of a Toss or Windmill action `base` of `verb`, or nothing: then `instead`
// is what the clause does (an arm swing), `target` its target, and `why` says so.
std::optional<PlannedAction> plan_round_motion(const Rig& rig, const Verb& verb, const Action& base, const Modifiers& mods,
                                               const std::string& words, uint32_t coin, Action& instead, Target& target, std::string& why);

}  // namespace svgm
