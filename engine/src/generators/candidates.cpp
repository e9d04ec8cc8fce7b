// Listing candidate videos, writing the chosen one as the target (see candidates.h).
#include "generators/candidates.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <string>

#include "media/preview_video.h"
#include "svgmotion/atomic_file.h"
#include "svgmotion/error.h"
#include "svgmotion/target_video.h"

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

void write_target_video(const std::filesystem::path& chosen, const std::filesystem::path& target) {
  std::error_code ec;
  if (std::filesystem::is_directory(chosen, ec) || chosen.extension() != ".mp4") {
    const TargetInfo info = probe_target(chosen);
    TargetOptions to;
    to.keyframes = info.frames;
    const TargetFrames t = load_target(chosen, info.width, info.height, to);
    write_preview_video(target, info.frames, 1, [&](int k, int) {
      return rgba8_image(&t.raw[static_cast<size_t>(k) * info.width * info.height * 4], info.width, info.height);
    }, info.fps);
    return;
  }
  std::ifstream in(chosen, std::ios::binary);
  if (!in) throw Error(chosen.string() + ": cannot open");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw Error(chosen.string() + ": cannot read");
  write_file_atomic(target, bytes);
}

}  // namespace svgm
