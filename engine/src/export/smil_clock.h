// How long an animated SVG plays and whether it repeats, for making a clip of it: the longest
// `dur` among its <animate> and <animateTransform> elements (a mirror written by the fitter is one forward-and-back
// pass), and whether any of them repeats forever (repeatCount="indefinite").
#pragma once

#include <string_view>

namespace svgm {

struct SmilClock {
  int animations = 0;      // <animate>, <animateTransform> elements with a usable dur
  double duration_s = 0;   // one pass: the longest dur x its repeat count (1 when indefinite)
  bool repeats = false;    // some animation repeats forever: the clip should loop
};

// Reads the clock of the document `text` (`name` names it in errors). Throws svgm::Error when
// it is not XML.
SmilClock smil_clock(std::string_view text, std::string_view name);

}  // namespace svgm
