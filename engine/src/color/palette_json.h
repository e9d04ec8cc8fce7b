// palette.json: the colour each path has in the target video (written by the recolouring
// stage), so the fit compares like with like; the export keeps the original colours.
#pragma once

#include <filesystem>
#include <map>
#include <string>

#include "svgmotion/scene.h"

namespace svgm {

// Reads {"colors": {"path-id": "#rrggbb", ...}} (or the inner object alone). Throws
// svgm::Error "<file>: <problem>" for unreadable JSON, a non-string value or a bad colour.
std::map<std::string, Rgba> read_palette(const std::filesystem::path& file);

// A copy of `scene` whose paths' fills and strokes take their palette colour (alpha kept).
// Throws svgm::Error naming the file and the first path id the palette lacks, or an id it has
// that the scene does not.
Scene apply_palette(const Scene& scene, const std::map<std::string, Rgba>& palette,
                    const std::string& palette_name);

}  // namespace svgm
