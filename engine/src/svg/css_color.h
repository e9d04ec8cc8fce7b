// CSS colours as SVG paints use them: #rgb, #rgba, #rrggbb, #rrggbbaa, rgb()/rgba() with
// numbers or percentages, hsl()/hsla(), the 147 named colours, transparent.
#pragma once

#include <optional>
#include <string_view>

#include "svgmotion/scene.h"

namespace svgm::svg {

// The colour, straight alpha in Rgba::a; nothing if `s` is not a colour (none, currentColor,
// url(...) and inherit are the caller's business).
std::optional<Rgba> parse_color(std::string_view s);

}  // namespace svgm::svg
