// video `file`: the user's own video (or folder of PNG frames), named by stages.video.path, is
// the only candidate: candidates/00.<ext> (or candidates/00/ for a folder).
#include <filesystem>

#include "common/plugin_glue.h"
#include "common/stage_files.h"
#include "svgmotion/error.h"
#include "svgmotion/target_video.h"

namespace {

nlohmann::json run(const nlohmann::json& req, const svgm_host*) {
  namespace fs = std::filesystem;
  const std::string path = req.at("config").value("path", "");
  if (path.empty()) throw svgm::Error("stages.video.path is not set (the video to fit)");
  svgm::probe_target(path);  // a clear error now for an unreadable video or folder
  const fs::path dir = svgm::plugin::file(req, "outputs", "candidates");
  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::create_directories(dir);
  const fs::path src(path);
  svgm::plugin::copy_atomic(src, dir / (fs::is_directory(src) ? fs::path("00") : fs::path("00" + src.extension().string())));
  return {{"message", "candidate 00 is " + path}, {"candidates", 1}};
}

}  // namespace

SVGM_DEFINE_PLUGIN("video", "file", "1", "the user's own video or PNG frames", run)
