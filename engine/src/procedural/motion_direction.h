// Which way a planned action (motion_plan.h) moves, in words for motion.json and report.html:
// "clockwise", "right first, then left", "the pair in turn", "up from rest and back". Read from
// the same fields animate_plan moves by (SVG's y points down, so a positive turn is clockwise
// on the screen), so the words say what the frames show.
#pragma once

#include <string>

#include "procedural/motion_plan.h"

namespace svgm {

std::string direction_words(const PlannedAction& a);

}  // namespace svgm
