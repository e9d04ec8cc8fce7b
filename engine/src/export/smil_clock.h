// How long an animated SVG plays and whether it repeats, for making a clip of it: the longest
// `dur` among its <animate> and <animateTransform> elements (a mirror written by the fitter is one forward-and-back
// pass), whether any of them repeats forever (repeatCount="indefinite"), and the frame rate the
// animation was fitted at, which svgmotion's writer states on the root element
// (data-svgmotion-fps="24"), so that a clip of it is made at that rate and not resampled.
#pragma once

#include <string>
#include <string_view>

namespace svgm {

struct SmilClock {
  int animations = 0;      // <animate>, <animateTransform> elements with a usable dur
  double duration_s = 0;   // one pass: the longest dur x its repeat count (1 when indefinite)
  bool repeats = false;    // some animation repeats forever: the clip should loop
  double fps = 0;          // the root's data-svgmotion-fps (0: none, or not a rate in (0, 240])
};

// The root attribute that states the frame rate.
constexpr const char* kFrameRateAttribute = "data-svgmotion-fps";

// Reads the clock of the document `text` (`name` names it in errors). Throws svgm::Error when
// it is not XML.
SmilClock smil_clock(std::string_view text, std::string_view name);

// `text` with data-svgmotion-fps="FPS" on its root element (replacing one there), every other
// byte as it was. Throws svgm::Error "<name>: ..." when it is not XML.
std::string with_frame_rate(std::string_view text, std::string_view name, double fps);

}  // namespace svgm
