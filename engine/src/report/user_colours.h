// Candidate videos in the user's colours for report.html. The video model is
// shown the drawing recoloured (every part its own distinct colour,
// palette.json), so its videos come back in those false colours; the page maps
// them back: each pixel is read as a mix of white (the background) and the
// nearest palette colour, and drawn as the same mix of white and that part's
// own colour in the drawing (grouped.svg). Edges between two parts, rarer than
// edges against the background, come out as one of the two.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "svgmotion/png_io.h"
#include "svgmotion/scene.h"

namespace svgm {

struct ColourMap {
  std::vector<Rgba> from, to; // palette colour -> the part's own colour
};

// From <run>/palette.json and <run>/grouped.svg; nothing (with the reason) when
// either is missing or they share no part.
std::optional<ColourMap> user_colour_map(const std::filesystem::path &run,
                                         std::string &why_not);

// `img` (straight RGBA over white) redrawn in the user's colours.
void to_user_colours(RgbaImage &img, const ColourMap &map);

} // namespace svgm
