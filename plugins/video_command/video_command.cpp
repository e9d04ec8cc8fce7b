// video `command`: any external image-to-video generator, run once per candidate from an argv
// template (never through a shell), each run writing candidates/NN.mp4. Settings come from
// stages.video.options (argv, candidates, frames, timeout_s, fps, prompt_template); see
// README.md here and engine/src/generators/command_video.h.
#include <filesystem>
#include <string>

#include "common/generator_request.h"
#include "common/plugin_glue.h"
#include "svgmotion/error.h"
#include "generators/command_video.h"

namespace {

nlohmann::json run(const nlohmann::json& req, const svgm_host* host) {
  const nlohmann::json& config = req.at("config");
  const svgm::CommandVideoOptions options =
      svgm::parse_command_video_options(config.contains("options") ? config.at("options")
                                                                   : nlohmann::json());
  const svgm::plugin::GeneratorRequest g = svgm::plugin::generator_request(req, host, "video command");
  const auto files = svgm::generate_candidates(options, g.run_dir, g.prompt, g.seed, g.hooks);
  return {{"message", std::to_string(files.size()) + " candidate" +
                          (files.size() == 1 ? "" : "s") + " from " + options.argv[0]},
          {"candidates", files.size()}};
}

}  // namespace

SVGM_DEFINE_PLUGIN("video", "command", "1",
                   "any image-to-video generator run as a command, once per candidate", run)
