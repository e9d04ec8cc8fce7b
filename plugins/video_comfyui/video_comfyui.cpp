// video `comfyui`: a ComfyUI server driven over its HTTP API, once per candidate: upload
// recolored.png, queue a workflow template (options.workflow, API format, with "{image}",
// "{prompt}", "{seed}", "{frames}" placeholders), poll its history, download the video to
// candidates/NN.<ext>. Options: url, workflow, candidates, frames, timeout_s, retries, poll_s,
// prompt_template; see README.md here and engine/src/generators/comfyui_client.h.
#include <filesystem>
#include <string>

#include "common/curl_http.h"
#include "common/generator_request.h"
#include "common/plugin_glue.h"
#include "svgmotion/error.h"
#include "generators/comfyui_client.h"

namespace {

nlohmann::json run(const nlohmann::json& req, const svgm_host* host) {
  const nlohmann::json& config = req.at("config");
  const svgm::ComfyuiOptions options = svgm::parse_comfyui_options(
      config.contains("options") ? config.at("options") : nlohmann::json());
  const svgm::plugin::GeneratorRequest g = svgm::plugin::generator_request(req, host, "video comfyui");
  svgm::ComfyuiHooks hooks;
  static_cast<svgm::GeneratorHooks&>(hooks) = g.hooks;
  svgm::plugin::CurlTransport http(hooks.cancelled, "svgmotion-video-comfyui/1");
  const auto files =
      svgm::generate_comfyui_candidates(options, g.run_dir, g.prompt, g.seed, http, hooks);
  return {{"message", std::to_string(files.size()) + " candidate" +
                          (files.size() == 1 ? "" : "s") + " from ComfyUI at " + options.url},
          {"candidates", files.size()}};
}

}  // namespace

SVGM_DEFINE_PLUGIN("video", "comfyui", "1",
                   "a ComfyUI server's image-to-video workflow over its HTTP API", run)
