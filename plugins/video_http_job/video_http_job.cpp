// video `http-job`: any queue-style hosted image-to-video API (submit JSON, poll a status URL,
// download a result URL) with the request and reply fields mapped in the config, so Wan or LTX
// hosts need a YAML file, not code (examples/video_models/*_job.yaml). The API key comes only
// from the environment variable options.api_key_env, goes only into options.headers
// ("{api_key}") and only to the submit URL's origin, and is scrubbed from every message.
// Options: see README.md here and engine/src/generators/http_job_client.h.
#include <string>

#include "common/curl_http.h"
#include "common/generator_request.h"
#include "common/plugin_glue.h"
#include "svgmotion/error.h"
#include "generators/http_job_client.h"

namespace {

nlohmann::json run(const nlohmann::json& req, const svgm_host* host) {
  const nlohmann::json& config = req.at("config");
  const svgm::HttpJobOptions options =
      svgm::parse_http_job_options(config.contains("options") ? config.at("options") : nlohmann::json());
  const svgm::plugin::GeneratorRequest g = svgm::plugin::generator_request(req, host, "video http-job");
  const std::string key = svgm::plugin::api_key_from_env(options.api_key_env, "video http-job", "the API key");
  svgm::HostedHooks hooks;
  static_cast<svgm::GeneratorHooks&>(hooks) = g.hooks;
  svgm::plugin::CurlTransport http(svgm::plugin::share_cancel(hooks), "svgmotion-video-http-job/1", {},
                                   {options.submit_url, svgm::job_headers(options, key)});
  const auto files = svgm::generate_http_job_candidates(options, g.run_dir, g.prompt, g.seed,
                                                        {key, options.api_key_env}, http, hooks);
  return {{"message", std::to_string(files.size()) + " of " + std::to_string(options.candidates) +
                          " candidates from " + svgm::plugin::url_origin(options.submit_url)},
          {"candidates", files.size()}};
}

}  // namespace

SVGM_DEFINE_PLUGIN("video", "http-job", "1",
                   "a queue-style hosted image-to-video API, fields mapped in the config", run)
