// The video stage's `comfyui` plugin, minus the plugin boundary and minus HTTP: drives a ComfyUI
// server through its HTTP API once per candidate (upload the image, queue a filled workflow,
// poll its history, download the result to candidates/NN.<ext>). The HTTP transport is given by
// the caller (the plugin uses libcurl; the engine stays curl-free), so the logic is testable.
#pragma once

#include "net/http_transport.h"
#include "generators/hosted_session.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace svgm {

struct ComfyuiOptions {
  std::string url;                 // e.g. "http://127.0.0.1:8188" (no trailing slash kept)
  std::filesystem::path workflow;  // a JSON file in ComfyUI's API format
  int candidates = 4;              // 1..99
  int frames = 49;                 // the value of "{frames}"
  double timeout_s = 600;          // per candidate: upload + queue + poll + download
  int retries = 2;                 // per request, for connection errors and HTTP 5xx
  double poll_s = 1;               // between GET /history/<id>
  uint64_t max_video_bytes = uint64_t{2} << 30;  // options.max_video_mib (SessionLimits)
  std::string prompt_template;     // "{prompt}" = the user's prompt; default as `command`
};

// Reads request["config"]["options"]. url and workflow are required. Throws svgm::Error
// "video comfyui: options.<key> ..." for a wrong type or range, an unknown key or a missing
// url/workflow.
ComfyuiOptions parse_comfyui_options(const nlohmann::json& options);

// Reads and parses the workflow file; throws "video comfyui: the workflow file X is not valid
// JSON (...)" / "... cannot be read" / "... is not a JSON object" / "... has no "{image}"
// placeholder".
nlohmann::json load_comfyui_workflow(const std::filesystem::path& path);

// A copy of `workflow` where every string value exactly equal to "{image}" or "{prompt}"
// becomes that string and every one exactly "{seed}" or "{frames}" becomes that number.
nlohmann::json fill_comfyui_workflow(const nlohmann::json& workflow, const std::string& image,
                                     const std::string& prompt, int64_t seed, int frames);

struct ComfyuiFile {
  std::string filename, subfolder, type;
};

// The first output file of prompt `prompt_id` in a GET /history/<id> reply (node outputs'
// "gifs", then "videos", then "images" entries), or nothing while the prompt has not finished.
std::optional<ComfyuiFile> find_comfyui_output(const nlohmann::json& history,
                                               const std::string& prompt_id);

// Percent-encodes a query-string value (RFC 3986 unreserved characters stay).
std::string url_encode(const std::string& s);

using ComfyuiHooks = HostedHooks;

// For candidates 0..N-1 in order: uploads run_dir/recolored.png, queues the workflow filled with
// the uploaded name, the prompt (options.prompt_template), seed + i and options.frames, polls
// the history every poll_s until an output appears, and saves it as candidates/NN.<ext> (the
// returned filename's extension: mp4, webm, gif, ...), checked readable. candidates/ is emptied
// first; nothing outside it is written. Returns the files. Throws one-line svgm::Error, e.g.
//   "video comfyui: candidate 00: no result within 5 s (prompt 1234)"
//   "video comfyui: candidate 00: HTTP 500 from http://host/prompt: <body>"
//   "video comfyui: candidate 00: cannot connect to http://host/upload/image: <why>"
std::vector<std::filesystem::path> generate_comfyui_candidates(
    const ComfyuiOptions& options, const std::filesystem::path& run_dir, const std::string& prompt,
    int64_t seed, HttpTransport& http, const ComfyuiHooks& hooks = {});

}  // namespace svgm
