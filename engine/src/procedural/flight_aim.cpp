// Where a launch or a landing goes (see flight_aim.h).
#include "procedural/flight_aim.h"

#include <cmath>

namespace svgm {

namespace {

// The nose's way, raised to kMinClimb above the level on its side when it points lower.
Vec2 climbing(Vec2 nose) {
  if (-nose.y >= std::sin(kMinClimb * M_PI / 180)) return nose;
  return {(nose.x >= 0 ? 1 : -1) * std::cos(kMinClimb * M_PI / 180), -std::sin(kMinClimb * M_PI / 180)};
}

}  // namespace

bool FlightAim::aim(const Rig& rig, FigureClass figure, PlannedAction& a, const std::string& verb, std::string& why) {
  if (verb == "takeoff" && !is_creature(figure)) {
    if (!axis) {
      axis = flight_axis(rig);
      if (axis->found && axis->nose.y > kNoseDown) axis->found = false, axis->why += "; it points down: straight up instead";
    }
    if (!axis->found) return why = "a launch goes straight up: " + axis->why, true;
    if (a.primitive == Primitive::Slide || a.primitive == Primitive::Pulse) return false;
    if (a.primitive == Primitive::Bob) a.heading = climbing(axis->nose);
    why = "a launch goes along its axis towards its nose: " + axis->why;
  }
  if (verb == "land" && a.primitive == Primitive::Bob) {
    a.vertical = -1;
    const FlightAxis way = is_creature(figure) ? FlightAxis{} : flight_axis(rig);
    const bool along = way.found && way.nose.y >= -kNoseDown;
    a.heading = along ? way.nose : Vec2{0, 1};
    why = along ? "a landing comes in along its nose: " + way.why
                : "a landing comes straight down: " + (is_creature(figure) ? std::string("a creature") : way.found ? std::string("its nose points up") : way.why);
  }
  return true;
}

}  // namespace svgm
