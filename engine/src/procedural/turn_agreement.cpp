// Turns of the whole figure go the same way (turn_agreement.h).
#include "procedural/turn_agreement.h"

namespace svgm {

namespace {

// A back-and-forth turn of the whole figure: a sway or a rock of no part and no region.
bool turns_whole(const PlannedAction& a) {
  return (a.primitive == Primitive::Sway || a.primitive == Primitive::Rock) && a.parts.empty() && a.target == Target::Whole &&
         a.region == Region::None;
}

}  // namespace

bool agree_with_earlier_turns(const std::vector<PlannedAction>& earlier, PlannedAction& a, bool way_told) {
  if (way_told || !turns_whole(a)) return false;
  for (const PlannedAction& b : earlier)
    if (turns_whole(b) && b.cycles == a.cycles) {
      const bool changed = a.direction != b.direction;
      a.direction = b.direction;
      return changed;
    }
  return false;
}

double whole_turn_sign(const PlannedAction& a) { return a.primitive == Primitive::Rock && a.parts.empty() ? a.direction : 1; }

}  // namespace svgm
