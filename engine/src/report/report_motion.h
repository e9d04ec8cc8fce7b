// report.html's "The motion" section: what the procedural video made of the prompt, from the
// run's motion.json (video/motion_plan.h motion_report): each planned action (verb, motion,
// parts, amplitude, cycles, one-sided, why), the moving parts outlined on the drawing, the
// keyframes the motion asks of the fitter, the words read through the lexicon, the words not
// understood, the warnings and notes. Everything taken from the file is escaped (html_text.h).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace svgm {

// The section's HTML. `drawing_uri`: a data: URI of the drawing at rest (may be empty: no
// outlines then). A run without motion.json (a video the user brought) gets a one-line section.
std::string motion_section(const nlohmann::json& motion, const std::string& drawing_uri);

}  // namespace svgm
