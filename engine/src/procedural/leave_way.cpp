// Where a figure that leaves goes (see leave_way.h).
#include "procedural/leave_way.h"

#include <cmath>

#include "procedural/flight_axis.h"
#include "procedural/gait_travel.h"
#include "procedural/limb_qualifiers.h"
#include "procedural/travel_words.h"

namespace svgm {

int leaving_side(const ParsedPrompt& prompt, const Clause& c, const Rig& rig, std::string* why) {
  if (c.mods.travel != 0 || !says_leaving(c)) return 0;
  for (const Clause& other : prompt.clauses)
    if (stays_put(other.text)) return 0;
  std::string how;
  int side = facing_side(rig, c.figure, &how);
  if (side != 0) {
    how = "the way it faces (" + how + ")";
  } else if (!is_creature(c.figure)) {
    const FlightAxis axis = flight_axis(rig);
    if (axis.found && std::fabs(axis.nose.x) >= kLeaveSideways) side = axis.nose.x < 0 ? -1 : 1, how = "its nose first (" + axis.why + ")";
  }
  if (side == 0) side = 1, how = "its facing not known: to the right, as a reader reads";
  if (why) *why = std::string("it leaves ('away', 'off'): it goes ") + (side < 0 ? "left" : "right") + ", " + how + ", steadily, and glides back";
  return side;
}

}  // namespace svgm
