// Listing candidate videos (see candidates.h).
#include "video/candidates.h"

#include <algorithm>
#include <string>

namespace svgm {

std::vector<std::filesystem::path> list_candidates(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> out;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    const std::string ext = e.path().extension().string();
    if (name.rfind('.', 0) == 0) continue;  // hidden, or a temporary being written
    if (ext == ".log" || ext == ".json" || ext == ".txt") continue;  // a provider's side files
    out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace svgm
