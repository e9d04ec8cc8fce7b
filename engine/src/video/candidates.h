// The candidate videos of a run: the entries of candidates/ that are videos or frame folders,
// in name order, without hidden entries and the providers' side files (logs, notes).
#pragma once

#include <filesystem>
#include <vector>

namespace svgm {

std::vector<std::filesystem::path> list_candidates(const std::filesystem::path& dir);

}  // namespace svgm
