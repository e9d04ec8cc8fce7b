// Where a launch or a landing of the whole figure goes (motion_plan.cpp's Builder::add), from the
// figure's axis and nose (flight_axis.h).
//
// A launch goes along the nose, at least kMinClimb above the level (a plane drawn level climbs
// forward off the ground); the launch's sideways slide and its shrink (away into the sky: on a
// rocket on a slant it read as going away, not off) have no place in it. Its rumble stays
// sideways, on the ground. With no nose read, or one pointing down by more than kNoseDown (a
// launch never goes down), it climbs straight up, shrinking towards its top, as before. A
// creature (a bird taking off) keeps its climb: its wings and head, not its outline, say where it
// goes. A landing comes in along the nose when it points level or down (an arriving plane), else
// straight down (a plane drawn climbing, a parachute).
#pragma once

#include <optional>
#include <string>

#include "motion/lexicon.h"
#include "procedural/flight_axis.h"
#include "procedural/motion_plan.h"
#include "procedural/part_rig.h"

namespace svgm {

struct FlightAim {
  std::optional<FlightAxis> axis;  // the figure's axis and nose, read at its first launch

  // Aims `a` (an action of `verb` on the whole figure of class `figure`): its heading for a
  // launch's climb or a landing's descent, `why` saying which. False: `a` is left out (a
  // launch's slide or shrink when it goes along its nose). Other verbs: true, `a` unchanged.
  bool aim(const Rig& rig, FigureClass figure, PlannedAction& a, const std::string& verb, std::string& why);
};

}  // namespace svgm
