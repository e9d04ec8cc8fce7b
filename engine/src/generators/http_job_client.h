// The video stage's `http-job` plugin, minus the plugin boundary and minus HTTP: one client for
// queue-style hosted image-to-video APIs (fal.ai's queue, Replicate's predictions, a self-hosted
// Wan or LTX server behind a job queue), with every request and reply field named in the
// config, so a new host needs a YAML file rather than code. Per candidate:
//
//   POST submit_url, JSON `body` (a template, below), `headers` (the API key's only place)
//   GET  status_url (a template) until reply[status_field] is in done_values (or in
//        failed_values: the job failed, reply[error_field] says why); the pause grows from
//        poll_s to poll_max_s. A submit reply that is already done is not polled.
//   GET  result_url (a template; "" = the last status reply holds the result)
//   GET  reply[video_url_field] (a string, or a list whose first string is taken)
//
// Templates. In `body`, a string exactly "{seed}", "{frames}" or "{fps}" becomes that number;
// "{prompt}", "{image_base64}" (the recoloured PNG) and "{image_data_url}" ("data:image/png;
// base64,...") are replaced inside any string. In status_url and result_url, "{id}" is
// reply[id_field] of the submit reply and "{submit.PATH}" any string field of it
// ("{submit.urls.get}"). In a header's value, "{api_key}" is the key from $api_key_env; the key
// may appear nowhere else. Field paths are dot-separated; a number picks an array element
// ("output.0").
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "net/http_transport.h"
#include "generators/hosted_session.h"

namespace svgm {

struct HttpJobOptions {
  std::string submit_url;
  nlohmann::json body;  // the request template (an object)
  std::vector<std::pair<std::string, std::string>> headers;  // name, value template
  std::string api_key_env;  // "" = no key
  std::string id_field;     // "" = no {id}
  std::string status_url;   // required
  std::string status_field = "status";
  std::vector<std::string> done_values, failed_values;  // done_values required
  std::string error_field = "error";
  std::string result_url;
  std::string video_url_field;  // required
  int candidates = 4, concurrency = 2, frames = 49;
  double fps = 24;
  SessionLimits limits{900, 3, 0.5, 2, 20};  // per candidate, per request, polls
  std::string prompt_template;
};

// Reads request["config"]["options"]; throws svgm::Error "video http-job: options.<key> ..."
// for a wrong type, range, a missing required key, an unknown key, or "{api_key}" outside a
// header.
HttpJobOptions parse_http_job_options(const nlohmann::json& options);

// The field at a dot path ("video.url", "output.0"), or null.
nlohmann::json field_at(const nlohmann::json& j, const std::string& path);

// `body` with the placeholders filled (see above).
nlohmann::json fill_job_body(const nlohmann::json& body, const std::string& prompt, const std::string& png,
                             int64_t seed, int frames, double fps);

// A status_url / result_url template filled from the submit reply; throws svgm::Error naming
// the missing field ("the submit reply has no string field urls.get for {submit.urls.get}").
std::string fill_job_url(const std::string& url, const nlohmann::json& submit_reply, const std::string& id_field);

// The header lines ("Name: value") with "{api_key}" replaced by `key`.
std::vector<std::string> job_headers(const HttpJobOptions& o, const std::string& key);

// As generate_veo_candidates (veo_client.h), through this API: candidates/NN.<ext> (the video
// URL's extension when it is a video's, else mp4), at most options.concurrency at a time.
std::vector<std::filesystem::path> generate_http_job_candidates(
    const HttpJobOptions& options, const std::filesystem::path& run_dir, const std::string& prompt,
    int64_t seed, const SessionSecret& key, HttpTransport& http, const HostedHooks& hooks = {});

}  // namespace svgm
