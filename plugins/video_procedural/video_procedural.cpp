// video `procedural`: offline candidate videos from a motion library driven by the prompt
// (engine/src/video): the recoloured SVG's parts move around pivots found from the geometry,
// rendered as raster frames with a colour drift, blur and H.264 compression. Candidate i uses
// seed + i, which varies amplitude, phase and which parts move.
#include <filesystem>

#include "common/plugin_glue.h"
#include "common/stage_files.h"
#include "svgmotion/error.h"
#include "svgmotion/svg_reader.h"
#include "video/procedural_video.h"

namespace {

nlohmann::json run(const nlohmann::json& req, const svgm_host* host) {
  namespace fs = std::filesystem;
  namespace P = svgm::plugin;
  const nlohmann::json& c = req.at("config");
  if (!c.value("path", std::string()).empty())
    throw svgm::Error("stages.video.path is set but the video plugin is 'procedural'; add "
                      "stages.video.plugin=file to fit your own video");
  const svgm::Scene scene = svgm::read_svg_file(P::file(req, "inputs", "svg"));
  std::string note;
  const std::string motion = svgm::motion_for_prompt(req.value("prompt", ""), &note);
  if (!note.empty() && host && host->log) host->log(host, 2, ("video procedural: " + note).c_str());
  svgm::ProceduralVideoOptions o;
  o.frames = c.value("frames", 49);
  o.fps = c.value("fps", 24.0);
  o.width = c.value("size", 512);
  o.device = req.value("device", "auto");
  o.side = svgm::side_for_prompt(req.value("prompt", ""));
  const int n = c.value("candidates", 4);
  const fs::path dir = P::file(req, "outputs", "candidates");
  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::create_directories(dir);
  nlohmann::json made = nlohmann::json::array();
  for (int i = 0; i < n; ++i) {
    char name[16];
    std::snprintf(name, sizeof name, "%02d", i);
    svgm::ProceduralMotion info;
    const uint32_t seed = static_cast<uint32_t>(req.value("seed", 0) + i);
    svgm::write_procedural_video(scene, motion, seed, o, dir / (std::string(name) + ".mp4"), &info);
    made.push_back({{"name", std::string(name) + ".mp4"}, {"motion", info.motion}, {"seed", seed},
                    {"moving_groups", info.parts.size()}});
    if (host && host->progress) host->progress(host, (i + 1.0) / n, name);
  }
  return {{"message", std::to_string(n) + " candidates (" + motion + ")"}, {"motion", motion},
          {"note", note}, {"candidates", made}};
}

}  // namespace

SVGM_DEFINE_PLUGIN("video", "procedural", "1", "offline motion library (no model needed)", run)
