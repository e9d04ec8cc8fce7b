// ranker `pixel`: scores every candidate video from its pixels against the palette of the
// recoloured image (colour drift, invented content, continuity of each colour's area,
// out-of-plane motion, amount of motion; see engine/src/rank/pixel_ranker.h for the signals,
// thresholds and weights), writes ranking.json and the best candidate as target.mp4.
//
// Options (stages.ranker.options): size (analysis width in px, default 128), keyframes
// (frames sampled per candidate, default 16).
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "common/plugin_glue.h"
#include "common/stage_files.h"
#include "color/palette_json.h"
#include "plugin/plugin_options.h"
#include "rank/pixel_ranker.h"
#include "svgmotion/error.h"

namespace {

svgm::PixelRankOptions options_of(const nlohmann::json& req) {
  const nlohmann::json& config = req.at("config");
  const svgm::PluginOptions opt(config.contains("options") ? config.at("options") : nlohmann::json(),
                                "ranker pixel", {"size", "keyframes"});
  svgm::PixelRankOptions o;
  o.analysis_width = opt.whole("size", o.analysis_width, 1, 4096);
  o.keyframes = opt.whole("keyframes", o.keyframes, 1, 4096);
  return o;
}

nlohmann::json run(const nlohmann::json& req, const svgm_host* host) {
  namespace fs = std::filesystem;
  const svgm::PixelRankOptions o = options_of(req);
  const fs::path dir = svgm::plugin::file(req, "inputs", "candidates");
  // The colours the candidates are drawn in: the palette's, or the SVG's own for a user's video.
  const std::vector<svgm::Rgba> palette = svgm::plugin::candidate_colours(req, "ranker pixel");

  // A procedural candidate whose motion asks the fitter for more keyframes (motion.json,
  // fit_plan) is judged at that many frames + 1: its parts' areas change between the frames the
  // fitter will see. The procedural video scored it the same way before handing it over
  // (generator and ranker agree).
  const std::map<std::string, int> keyframes = svgm::plugin::candidate_keyframes(req);
  const svgm::Ranking r = svgm::rank_directory(
      dir, palette, o,
      [&](double f, const std::string& note) {
        if (host && host->progress) host->progress(host, 0.9 * f, note.c_str());
        return !(host && host->cancelled && host->cancelled(host));
      },
      [&](const std::string& name) {
        const auto it = keyframes.find(name);
        return it == keyframes.end() ? 0 : svgm::frames_to_rank(o, it->second);
      });
  if (host && host->log)
    for (const auto& c : r.candidates) {
      std::string line = c.name + ": " + (c.error.empty() ? "score " + std::to_string(c.score) : c.error);
      for (const auto& d : c.defects) line += (&d == &c.defects.front() ? " (" : ", ") + d;
      if (!c.defects.empty()) line += ")";
      host->log(host, c.error.empty() ? 1 : 2, line.c_str());
    }

  const fs::path chosen = dir / r.chosen, target = svgm::plugin::file(req, "outputs", "target");
  if (host && host->progress) host->progress(host, 0.9, ("writing " + target.filename().string()).c_str());
  svgm::plugin::write_target(chosen, target);
  svgm::plugin::write_json(svgm::plugin::file(req, "outputs", "ranking"), r.to_json());
  return {{"message", "chose " + r.chosen + ": " + r.reason}};
}

}  // namespace

SVGM_DEFINE_PLUGIN("ranker", "pixel", "1", "ranks candidate videos by their pixels against the palette", run)
