// report.html's "The motion" section: what the procedural video made of the prompt, from the
// run's motion.json (procedural/motion_plan.h motion_report): the prompt, each planned action as a
// numbered row in its own colour (verb, the parts it moves, amplitude in degrees or in % of the
// figure, direction, cycles, why those parts), the drawing in its own colours with each action's
// parts outlined in that colour and number, the words not understood, a warning when the motion
// is only the fallback sway, the words read through the lexicon, the warnings and notes.
// Everything taken from the file is escaped (html_text.h).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace svgm {

// The section's HTML. `drawing_uri`: a data: URI of the drawing at rest (may be empty: no
// outlines then). A run without motion.json (a video the user brought) gets a one-line section.
std::string motion_section(const nlohmann::json& motion, const std::string& drawing_uri);

// Why the motion is not all the prompt asked, in one line for the page's summary: the fallback
// sway (no motion word understood), else the words not understood; `line` empty when neither.
struct MotionCaveat {
  bool fallback = false;
  std::string line;
};
MotionCaveat motion_caveat(const nlohmann::json& motion);

}  // namespace svgm
