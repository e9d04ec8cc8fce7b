// What a figure sits in or on, when the prompt says so ("the chick in its shell wiggles", "the
// rider bobs on the horse", "the person in the bathtub sways"): the thing drawn under or around
// the figure that its motions in place leave where it is, the figure moving about where it
// touches it (its own bottom). Without it the whole drawing moved as one: the shell rocked with
// the chick, the horse bobbed with its rider, the tub's shower swayed further than the bather.
// What goes somewhere takes its seat along (a rider's horse, a wheelchair: seat_goes).
//
// Found from the drawing, not from the word: the prompt only says that there is a seat (a noun
// after in, into, on or onto that names no part of the figure, in a clause with no launch or
// landing). The seat's body is the largest filled shape reaching the figure's bottom (the lowest
// kLow of it); the sitter is the blob-like fills (fill at least kBlob of their box) that stand
// at least kRise of the figure's height above the seat's top where they stand, and reach down to
// within kTouch of it or into it, with what lies inside their box and what stands above the
// seat over them (a head over a body). Everything else of the figure is the seat. No sitter, or
// a sitter no smaller than the seat, no seat: nothing changes.
#pragma once

#include <string>
#include <vector>

#include "procedural/motion_plan.h"
#include "procedural/part_rig.h"
#include "procedural/prompt_parse.h"
#include "svgmotion/scene.h"

namespace svgm {

// "in the bathtub": the first noun after in, into, on or onto that names no part of the figure,
// in a clause with no launch or landing; empty when none.
std::string seat_words(const ParsedPrompt& prompt, const Rig& rig);

struct SeatSupport {
  std::vector<char> seat;  // per path of the scene: 1 on the seat (stays under motions in place)
  RigBox sitter;           // the box of the rest: what moves in place, about its own bottom
  bool found = false;
};
SeatSupport seat_support(const Scene& scene, const Rig& rig);

// Whether the whole figure's action takes the seat along: it goes somewhere (a slide, a turn
// round), or says a way to go. Motions in place (a bob, a sway, a rock, a squash) leave it.
bool seat_goes(const PlannedAction& a);

// The hosts each control point rides on (motion_frames.cpp's hosts_of, -1 for its own path), with
// none across the seat's edge: a rider's leg drawn over the horse's body took the still horse's
// motion and stretched down from the rising rider.
std::vector<std::vector<int>> seat_apart(const SeatSupport& seat, std::vector<std::vector<int>> rides_on);

// A sitter bobbing on its seat rises from it and settles back (down, it would sink into it),
// as on a ground band (motion_fit.cpp's rise_from_ground); no seat found, nothing changes.
void rise_from_seat(const Scene& scene, const Rig& rig, MotionPlan& plan);

}  // namespace svgm
