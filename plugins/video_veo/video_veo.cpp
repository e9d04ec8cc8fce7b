// video `veo`: Google's Veo image-to-video models through the Gemini API (predictLongRunning,
// operation polling, download), several candidates at once. The API key comes only from the
// environment variable options.api_key_env (default GEMINI_API_KEY): it is sent as the
// x-goog-api-key header to the API's own origin and nowhere else, and never written to a log,
// a manifest or a message. Options: see README.md here and engine/src/generators/veo_client.h.
#include <string>

#include "common/curl_http.h"
#include "common/generator_request.h"
#include "common/plugin_glue.h"
#include "svgmotion/error.h"
#include "generators/veo_client.h"

namespace {

nlohmann::json run(const nlohmann::json& req, const svgm_host* host) {
  const nlohmann::json& config = req.at("config");
  const svgm::VeoOptions options =
      svgm::parse_veo_options(config.contains("options") ? config.at("options") : nlohmann::json());
  const svgm::plugin::GeneratorRequest g = svgm::plugin::generator_request(req, host, "video veo");
  const std::string key = svgm::plugin::api_key_from_env(options.api_key_env, "video veo", "the Gemini API key");
  svgm::HostedHooks hooks;
  static_cast<svgm::GeneratorHooks&>(hooks) = g.hooks;
  svgm::plugin::CurlTransport http(svgm::plugin::share_cancel(hooks), "svgmotion-video-veo/1", {},
                                   {options.base_url, {"x-goog-api-key: " + key}});
  const auto files = svgm::generate_veo_candidates(options, g.run_dir, g.prompt, g.seed,
                                                   {key, options.api_key_env}, http, hooks);
  return {{"message", std::to_string(files.size()) + " of " + std::to_string(options.candidates) +
                          " candidates from " + options.model},
          {"candidates", files.size()}};
}

}  // namespace

SVGM_DEFINE_PLUGIN("video", "veo", "1", "Google's Veo image-to-video through the Gemini API", run)
