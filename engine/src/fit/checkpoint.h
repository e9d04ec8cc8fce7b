// Fit checkpoints: the whole FitState in one binary file, so `svgmotion fit --resume` goes on
// where a run stopped (or was interrupted).
#pragma once

#include <filesystem>
#include <string>

#include "fit/fitter.h"

namespace svgm {

// `key` identifies the problem (SVG, target, sizes, options): a checkpoint made for another
// problem is refused on load. Written to a temporary name and renamed.
void save_checkpoint(const std::filesystem::path& file, const std::string& key, const FitState& s);
// Throws svgm::Error "<file>: <problem>" for a missing, truncated or foreign checkpoint.
FitState load_checkpoint(const std::filesystem::path& file, const std::string& key);

}  // namespace svgm
