// ranker `first`: picks the first candidate (the `file` video provider offers one). Writes
// ranking.json and the chosen video as target.mp4 (a folder of frames is encoded to mp4).
#include <algorithm>
#include <filesystem>
#include <vector>

#include "common/plugin_glue.h"
#include "common/stage_files.h"
#include "media/preview_video.h"
#include "svgmotion/error.h"
#include "svgmotion/target_video.h"
#include "generators/candidates.h"

namespace {

nlohmann::json run(const nlohmann::json& req, const svgm_host*) {
  namespace fs = std::filesystem;
  const fs::path dir = svgm::plugin::file(req, "inputs", "candidates");
  const std::vector<fs::path> c = svgm::list_candidates(dir);
  if (c.empty()) throw svgm::Error(dir.string() + ": no candidate videos");
  const fs::path chosen = c.front(), target = svgm::plugin::file(req, "outputs", "target");
  if (fs::is_directory(chosen) || chosen.extension() != ".mp4") {
    // Re-encode whatever OpenCV reads (frames folder, webm, ...) as the run's target.mp4.
    const svgm::TargetInfo info = svgm::probe_target(chosen);
    svgm::TargetOptions o;
    o.keyframes = info.frames;
    const svgm::TargetFrames t = svgm::load_target(chosen, info.width, info.height, o);
    svgm::write_preview_video(target, info.frames, 1, [&](int k, int) {
      return svgm::rgba8_image(&t.raw[static_cast<size_t>(k) * info.width * info.height * 4], info.width, info.height);
    }, info.fps);
  } else {
    svgm::plugin::copy_atomic(chosen, target);
  }
  svgm::plugin::write_json(svgm::plugin::file(req, "outputs", "ranking"),
                           {{"chosen", chosen.filename().string()},
                            {"reason", "ranker 'first' takes the first candidate"},
                            {"candidates", {{{"name", chosen.filename().string()}, {"score", 1.0}}}}});
  return {{"message", "chose " + chosen.filename().string()}};
}

}  // namespace

SVGM_DEFINE_PLUGIN("ranker", "first", "1", "picks the first candidate", run)
