// The candidate videos of a run: the entries of candidates/ that are videos or frame folders,
// in name order, without hidden entries and the providers' side files (logs, notes); and the
// chosen one written as the run's target.mp4.
#pragma once

#include <filesystem>
#include <vector>

namespace svgm {

std::vector<std::filesystem::path> list_candidates(const std::filesystem::path& dir);

// The chosen candidate becomes the run's target.mp4: an mp4 copied atomically; a frames
// folder, webm, ... re-encoded as mp4 at its own size and rate. Throws svgm::Error.
void write_target_video(const std::filesystem::path& chosen, const std::filesystem::path& target);

}  // namespace svgm
