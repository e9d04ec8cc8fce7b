// video `comfyui`: a ComfyUI server driven over its HTTP API, once per candidate: upload
// recolored.png, queue a workflow template (options.workflow, API format, with "{image}",
// "{prompt}", "{seed}", "{frames}" placeholders), poll its history, download the video to
// candidates/NN.<ext>. Options: url, workflow, candidates, frames, timeout_s, retries, poll_s,
// prompt_template; see README.md here and engine/src/video/comfyui_client.h.
#include <filesystem>
#include <string>

#include "common/plugin_glue.h"
#include "svgmotion/error.h"
#include "video/comfyui_client.h"
#include "video_comfyui/comfyui_http.h"

namespace {

nlohmann::json run(const nlohmann::json& req, const svgm_host* host) {
  namespace fs = std::filesystem;
  const nlohmann::json& config = req.at("config");
  const svgm::ComfyuiOptions options = svgm::parse_comfyui_options(
      config.contains("options") ? config.at("options") : nlohmann::json());
  const fs::path run_dir = req.at("run_dir").get<std::string>();
  if (svgm::plugin::file(req, "outputs", "candidates") != run_dir / "candidates")
    throw svgm::Error("video comfyui: the pipeline asked for candidates at " +
                      svgm::plugin::file(req, "outputs", "candidates").string() +
                      "; this plugin writes run_dir/candidates");
  const std::string prompt = req.value("prompt", std::string());
  const nlohmann::json& seed_json = req.contains("seed") ? req.at("seed") : nlohmann::json(0);
  const int64_t seed = seed_json.is_number() ? seed_json.get<int64_t>() : 0;

  svgm::ComfyuiHooks hooks;
  if (host) {
    hooks.progress = [host](double f, const std::string& note) {
      if (host->progress) host->progress(host, f, note.c_str());
    };
    hooks.log = [host](const std::string& line) {
      if (host->log) host->log(host, 1, line.c_str());
    };
    hooks.cancelled = [host] { return host->cancelled && host->cancelled(host) != 0; };
  }
  svgm::comfyui::CurlTransport http(hooks.cancelled);
  const auto files =
      svgm::generate_comfyui_candidates(options, run_dir, prompt, seed, http, hooks);
  return {{"message", std::to_string(files.size()) + " candidate" +
                          (files.size() == 1 ? "" : "s") + " from ComfyUI at " + options.url},
          {"candidates", files.size()}};
}

}  // namespace

SVGM_DEFINE_PLUGIN("video", "comfyui", "1",
                   "a ComfyUI server's image-to-video workflow over its HTTP API", run)
