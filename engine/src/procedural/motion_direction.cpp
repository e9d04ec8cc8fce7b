// Which way a planned action moves, in words (see motion_direction.h).
#include "procedural/motion_direction.h"

#include <algorithm>
#include <cmath>

namespace svgm {

namespace {

const char* turn(double sign) { return sign > 0 ? "clockwise" : "counter-clockwise"; }

// How the parts of a turning action move together (pair_up: mirrored signs, alternating phases).
std::string pairing(const PlannedAction& a) {
  if (a.region != Region::None) {
    if (a.region_side != 0) return std::string(", the viewer's ") + (a.region_side < 0 ? "left" : "right") + " side only";
    return a.alternating ? ", the two sides in turn" : "";
  }
  if (a.parts.size() < 2 || a.sign.size() != a.parts.size() || a.phase.size() != a.parts.size()) return "";
  const bool in_turn = std::any_of(a.phase.begin(), a.phase.end(), [&](double p) { return p != a.phase[0]; });
  const bool mirrored = std::any_of(a.sign.begin(), a.sign.end(), [&](double s) { return s != a.sign[0]; });
  return in_turn ? ", in turn" : mirrored ? ", mirrored (together, opposite turns)" : ", together the same way";
}

}  // namespace

std::string direction_words(const PlannedAction& a) {
  // animate_plan's oscillation: sin (rest, one way, the other way, rest) or, one-sided, out to
  // one side and back; a single part turns by its sign.
  const double sign = a.sign.size() == 1 ? a.sign[0] : 0;
  switch (a.primitive) {
    case Primitive::Spin: return a.rolls ? "rolling with the figure's slide" : std::string(turn(a.direction)) + ", whole turns";
    case Primitive::Turn: return "about its vertical axis, whole turns (mirrored while its back is shown)";
    case Primitive::Slide:
      if (a.turns_round)  // travel_profile.h
        return std::string("turns round, goes ") + (a.direction > 0 ? "right" : "left") + " steadily, turns back and comes home";
      if (a.goes || a.inches)  // travel_profile.h
        return std::string(a.inches ? "crawls " : "goes ") + (a.direction > 0 ? "right" : "left") + (a.inches ? " in steps" : " steadily") +
               ", then glides back";
      return a.direction > 0 ? "right first, then left" : "left first, then right";
    case Primitive::Hop: return "up in an arc and back down";
    case Primitive::Toss: return "from hand to hand along arcs, each thing in its own phase (a cascade)";
    case Primitive::Windmill: return std::string(turn(a.direction)) + ", whole turns about the shoulders" + pairing(a);
    case Primitive::Bob:
      if ((a.heading.x != 0 || a.heading.y != 0) && a.vertical < 0)
        return "comes in from behind along " + std::to_string(static_cast<int>(std::lround(std::atan2(-a.heading.y, a.heading.x) * 180 / M_PI))) + " degrees above the right, slowing, and stays down";
      if (a.heading.x != 0 || a.heading.y != 0) return "off along its nose, " + std::to_string(static_cast<int>(std::lround(std::atan2(-a.heading.y, a.heading.x) * 180 / M_PI))) + " degrees above the right, speeding up, and settles back";
      return a.vertical > 0 ? "up from rest and back" : a.vertical < 0 ? "down from rest and back" : "up and down";
    case Primitive::Squash: return "down, squashed, and back up";
    case Primitive::Fall: return "down, each element in its own phase";
    case Primitive::Shake: return "a small jitter";
    case Primitive::Pulse:
      if (a.goes) return a.direction > 0 ? "grows from far off on its horizon to its size (coming nearer)" : "shrinks towards its horizon (going away) and comes back";
      return a.vertical == 1 && a.amp < 0 ? "smaller toward its top and back (away)" : "larger and smaller about its centre";
    case Primitive::Stretch:
      return a.inches ? std::string("longer ") + (a.direction > 0 ? "right" : "left") + " ahead of its rear, then gathered up"
                      : "longer along its length and back";
    case Primitive::Undulate: {
      static const char* from[] = {"", " from the pole at its left", " from the pole at its right", " from the pole at its top",
                                   " from the pole at its bottom"};
      return std::string("a wave along its length") + (a.anchored >= 1 && a.anchored <= 4 ? from[a.anchored] : "");
    }
    case Primitive::Sway:
      return a.one_sided != 0 ? std::string("leans ") + (a.one_sided * a.direction > 0 ? "right" : "left") + " only, and back"
                              : std::string("side to side, ") + (a.direction > 0 ? "right" : "left") + " first";
    case Primitive::Rock:
      if (a.vertical == 2) return std::string("leans ") + turn(a.direction) + " and back";
      [[fallthrough]];
    case Primitive::Swing:
    case Primitive::Bend: {
      std::string s = a.one_sided != 0 ? "out to one side only and back" : "back and forth";
      if (sign != 0 && a.region == Region::None) s += std::string(", ") + turn(a.one_sided != 0 ? a.one_sided * sign : sign) + " first";
      return s + pairing(a);
    }
  }
  return "";
}

}  // namespace svgm
