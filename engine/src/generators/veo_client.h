// The video stage's `veo` plugin, minus the plugin boundary and minus HTTP: Google's Veo
// image-to-video models through the Gemini API's long-running operation. Per candidate:
//
//   POST {base_url}/models/{model}:predictLongRunning        (header x-goog-api-key)
//     {"instances": [{"prompt": P, "image": {"bytesBase64Encoded": PNG, "mimeType": "image/png"}}],
//      "parameters": {"aspectRatio", "durationSeconds", "resolution", "negativePrompt", "seed"}}
//     -> {"name": "models/{model}/operations/{id}"}
//   GET  {base_url}/{name}   until "done": true, the pause growing from poll_s to poll_max_s
//     -> {"done": true, "response": {"generateVideoResponse": {"generatedSamples":
//          [{"video": {"uri": U}}]}}}   or   {"done": true, "error": {"code", "message"}}
//   GET  U (the key goes only to the API's own origin; redirects are followed)
//
// The shapes are those of Google's documentation (third_party_notes.md), not tested against the
// live service. The key is never in this code's options: the plugin reads it from the
// environment variable options.api_key_env and gives it to the transport.
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "net/http_transport.h"
#include "generators/hosted_session.h"

namespace svgm {

struct VeoOptions {
  std::string base_url = "https://generativelanguage.googleapis.com/v1beta";
  std::string model = "veo-3.1-generate-preview";  // Gemini API model id of Veo 3.1
  std::string api_key_env = "GEMINI_API_KEY";
  int candidates = 4;        // 1..99; the paper draws 10-20
  int concurrency = 2;       // candidates in flight at once
  std::string aspect_ratio = "16:9";  // "" = not sent (Veo 3.1 takes 16:9 or 9:16)
  int duration_s = 8;        // durationSeconds; 0 = not sent (Veo 3.1 takes 4, 6 or 8)
  std::string resolution = "720p";  // "" = not sent
  std::string negative_prompt;      // "" = not sent
  bool send_seed = true;     // parameters.seed = run seed + candidate index
  // timeout_s per candidate (submit, polls, download), retries per request (connection
  // errors, 5xx, 429), the first pause between polls of the operation and its ceiling.
  SessionLimits limits{900, 3, 0.5, 5, 30};
  std::string prompt_template;  // "{prompt}" = the user's prompt; default as `command`
};

// Reads request["config"]["options"]; throws svgm::Error "video veo: options.<key> ..." for a
// wrong type or range or an unknown key.
VeoOptions parse_veo_options(const nlohmann::json& options);

// The predictLongRunning body for one candidate.
nlohmann::json veo_request(const VeoOptions& o, const std::string& png, const std::string& prompt,
                           int64_t seed);

// What a GET of the operation says.
struct VeoOperation {
  bool done = false;
  std::string video_uri;  // when done and successful
  std::string error;      // when done and failed: "<message> (code N)", or why no video came
};
VeoOperation read_veo_operation(const nlohmann::json& operation);

// Makes options.candidates videos of run_dir/recolored.png, at most options.concurrency at a
// time, each saved as candidates/NN.mp4 and checked readable. candidates/ is emptied first
// (after the image is read); nothing outside it is written. A failed candidate is a warning
// while another succeeds (candidate_pool.h). One-line errors, e.g.
//   "video veo: candidate 00: the API key in $GEMINI_API_KEY was refused: HTTP 400 from URL: ..."
//   "video veo: candidate 02: operation models/m/operations/x failed: <message> (code 13)"
//   "video veo: candidate 01: no result within 900 s (operation models/m/operations/x)"
// `key` is scrubbed from every message.
std::vector<std::filesystem::path> generate_veo_candidates(
    const VeoOptions& options, const std::filesystem::path& run_dir, const std::string& prompt,
    int64_t seed, const SessionSecret& key, HttpTransport& http, const HostedHooks& hooks = {});

}  // namespace svgm
