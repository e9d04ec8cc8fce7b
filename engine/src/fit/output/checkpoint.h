// Fit checkpoints: the whole FitState in one binary file, so `svgmotion fit --resume` goes on
// where a run stopped (or was interrupted).
#pragma once

#include <filesystem>
#include <string>

#include "fit/output/animation_export.h"
#include "fit/optimise/fitter.h"

namespace svgm {

// `key` identifies the problem (SVG, target, sizes, options): a checkpoint made for another
// problem is refused on load. Written to a temporary name and renamed.
// `result` (a finished fit's written keyframes, animation_export.h) follows the state, for
// `svgmotion export`; the resume reads only the state.
void save_checkpoint(const std::filesystem::path& file, const std::string& key, const FitState& s,
                     const FitResult* result = nullptr);
// Throws svgm::Error "<file>: <problem>" for a missing, truncated or foreign checkpoint.
FitState load_checkpoint(const std::filesystem::path& file, const std::string& key);
// The finished fit's result stored after the state. Throws svgm::Error "<file>: <problem>" for a
// missing or damaged file, or one without a result (an unfinished fit, an older svgmotion).
FitResult load_fit_result(const std::filesystem::path& file);

}  // namespace svgm
