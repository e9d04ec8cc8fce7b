// Rotors (issue 35): a propeller, a fan's or a wind turbine's blades, a drone's rotors. What the
// prompt names is found as blades about a hub, and spinning is how they move, whatever the verb
// ("the blades turn in the breeze", "the propeller whirs"); turned about the whole figure's base,
// a small plane swung nose up and down and its propeller stood still on it.
//
// The blades are elongated elements of the figure (a fill and the outline drawn over it each
// count; the body, the largest, does not) with one end at a common point, the hub; the hub is
// where the most blade directions meet (a fill and its outline point the same way: one
// direction) and the blades are those alike in length (not the nose a propeller sits on, nor a
// helicopter's mast). Seen edge on (the blades all in one line, held at the hub by something
// running square to it: a side view's nose behind its propeller, a helicopter's mast under its
// main rotor; the spin's axis lies in the picture's plane) a turning blade shows only its length
// along that line shrinking and growing as |cos| of its angle, about the hub: a squeeze along
// the blade's axis (region_turn in motion_frames.cpp), never to nothing (kEdgeOnMin). Turned in
// the picture's plane instead, a helicopter's rotor swung down through its cabin and the ranker
// flagged every candidate. Seen face on (three blades or more, two not in line, or two in line
// with nothing across them: a fan, a turbine, a helicopter's tail rotor) they turn about the hub
// in the picture's plane: a spin.
#pragma once

#include "procedural/part_locator.h"

namespace svgm {

// The blades of a rotor on the rig's figure, one lobe per blade direction, each with the hub as
// its pivot and its tip the blade's far end; lobes empty when no two blade ends meet. `body`:
// the element the rest hangs on (part_locator.cpp's body_of), never a blade.
LocatedPart rotor_blades(const Rig& rig, int body);

// Whether a located rotor is seen edge on: its blades all lie along one line through the hub
// and an elongated element of the rig's figure other than them (the body included: a nose, a
// mast) has an end at the hub and runs within kSameDirection of square to that line.
bool rotor_edge_on(const Rig& rig, const LocatedPart& rotor);

// How a located rotor moves (motion_plan.cpp's recast): face on, a Spin of whole turns about the
// hub (PlannedAction::amp in turns); edge on, a Stretch whose amp is how deep the blades' length
// squeezes (1 - kEdgeOnMin at most).
void rotor_motion(const Rig& rig, const LocatedPart& rotor, Primitive& primitive, double& amp);

inline constexpr double kBladeElongation = 2.2;  // a blade is at least this many times longer than wide
inline constexpr double kBladeMinLength = 0.05;  // and at least this share of the figure's longer side
inline constexpr double kHubMeet = 0.12;         // blade ends within this share of the figure's longer side of a hub meet there
inline constexpr double kSameDirection = 25;     // degrees: blades this close in direction are one (fill, outline)
inline constexpr double kSameLength = 0.15;      // blades of one rotor: lengths within this share of each other
inline constexpr double kThroughMiddle = 0.25;  // a shape across the hub: its middle within this share of its length of it
inline constexpr double kEdgeOnMin = 0.15;       // an edge-on blade's length never below this share of its own

}  // namespace svgm
