// video `command`: any external image-to-video generator, run once per candidate from an argv
// template (never through a shell), each run writing candidates/NN.mp4. Settings come from
// stages.video.options (argv, candidates, frames, timeout_s, fps, prompt_template); see
// README.md here and engine/src/video/command_video.h.
#include <filesystem>
#include <string>

#include "common/plugin_glue.h"
#include "svgmotion/error.h"
#include "video/command_video.h"

namespace {

nlohmann::json run(const nlohmann::json& req, const svgm_host* host) {
  namespace fs = std::filesystem;
  const nlohmann::json& config = req.at("config");
  const svgm::CommandVideoOptions options =
      svgm::parse_command_video_options(config.contains("options") ? config.at("options")
                                                                   : nlohmann::json());
  const fs::path run_dir = req.at("run_dir").get<std::string>();
  // The pipeline's file names are the ones generate_candidates uses; say so if that changes.
  if (svgm::plugin::file(req, "outputs", "candidates") != run_dir / "candidates")
    throw svgm::Error("video command: the pipeline asked for candidates at " +
                      svgm::plugin::file(req, "outputs", "candidates").string() +
                      "; this plugin writes run_dir/candidates");
  const std::string prompt = req.value("prompt", std::string());
  const nlohmann::json& seed_json = req.contains("seed") ? req.at("seed") : nlohmann::json(0);
  const int64_t seed = seed_json.is_number() ? seed_json.get<int64_t>() : 0;

  svgm::CommandVideoHooks hooks;
  if (host) {
    hooks.progress = [host](double f, const std::string& note) {
      if (host->progress) host->progress(host, f, note.c_str());
    };
    hooks.log = [host](const std::string& line) {
      if (host->log) host->log(host, 1, line.c_str());
    };
    hooks.cancelled = [host] { return host->cancelled && host->cancelled(host) != 0; };
  }
  const auto files = svgm::generate_candidates(options, run_dir, prompt, seed, hooks);
  return {{"message", std::to_string(files.size()) + " candidate" +
                          (files.size() == 1 ? "" : "s") + " from " + options.argv[0]},
          {"candidates", files.size()}};
}

}  // namespace

SVGM_DEFINE_PLUGIN("video", "command", "1",
                   "any image-to-video generator run as a command, once per candidate", run)
