// veo_client.h: Veo through the Gemini API's long-running operations.
#include "generators/veo_client.h"

#include <algorithm>

#include "net/base64.h"
#include "plugin/plugin_options.h"
#include "svgmotion/error.h"
#include "generators/candidate_pool.h"
#include "generators/command_runner.h"
#include "generators/command_video.h"
#include "svgmotion/utf8_text.h"

namespace svgm {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

const char* const kWho = "video veo";

}  // namespace

VeoOptions parse_veo_options(const json& options) {
  const PluginOptions opt(options, kWho,
                          {"base_url", "model", "api_key_env", "candidates", "concurrency", "aspect_ratio",
                           "duration_s", "resolution", "negative_prompt", "seed", "timeout_s", "retries",
                           "poll_s", "poll_max_s", "max_video_mib", "prompt_template"});
  VeoOptions o;
  o.base_url = opt.string("base_url", o.base_url);
  while (!o.base_url.empty() && o.base_url.back() == '/') o.base_url.pop_back();
  if (!is_http_url(o.base_url)) opt.fail("options.base_url must start with http:// or https://, not " + o.base_url);
  o.model = opt.string("model", o.model);
  if (o.model.empty() || o.model.find_first_of("/?# ") != std::string::npos)
    opt.fail("options.model must be a model id such as veo-3.1-generate-preview, not '" + o.model + "'");
  o.api_key_env = opt.string("api_key_env", o.api_key_env);
  if (o.api_key_env.empty()) opt.fail("options.api_key_env must name an environment variable");
  o.candidates = opt.whole("candidates", o.candidates, 1, 99);
  o.concurrency = opt.whole("concurrency", o.concurrency, 1, 16);
  o.aspect_ratio = opt.string("aspect_ratio", o.aspect_ratio);
  o.duration_s = opt.whole("duration_s", o.duration_s, 0, 60);
  o.resolution = opt.string("resolution", o.resolution);
  o.negative_prompt = opt.string("negative_prompt", o.negative_prompt);
  o.send_seed = opt.flag("seed", o.send_seed);
  o.limits = read_session_limits(opt, o.limits);
  o.prompt_template = opt.string("prompt_template", kDefaultVideoPromptTemplate);
  return o;
}

json veo_request(const VeoOptions& o, const std::string& png, const std::string& prompt, int64_t seed) {
  json parameters = json::object();
  if (!o.aspect_ratio.empty()) parameters["aspectRatio"] = o.aspect_ratio;
  if (o.duration_s > 0) parameters["durationSeconds"] = o.duration_s;
  if (!o.resolution.empty()) parameters["resolution"] = o.resolution;
  if (!o.negative_prompt.empty()) parameters["negativePrompt"] = o.negative_prompt;
  if (o.send_seed) parameters["seed"] = seed;
  return {{"instances", json::array({{{"prompt", prompt},
                                      {"image", {{"bytesBase64Encoded", base64(png)},
                                                 {"mimeType", "image/png"}}}}})},
          {"parameters", parameters}};
}

VeoOperation read_veo_operation(const json& op) {
  VeoOperation r;
  if (!op.is_object() || !op.value("done", false)) return r;
  r.done = true;
  if (op.contains("error") && op["error"].is_object()) {
    const json& e = op["error"];
    r.error = one_line(e.value("message", std::string("no message"))) +
              (e.contains("code") ? " (code " + json_text(e["code"]) + ")" : "");
    return r;
  }
  const json response = op.value("response", json::object());
  const json gvr = response.is_object() ? response.value("generateVideoResponse", json::object()) : json();
  if (gvr.is_object() && gvr.contains("generatedSamples") && gvr["generatedSamples"].is_array())
    for (const auto& s : gvr["generatedSamples"])
      if (s.is_object() && s.contains("video") && s["video"].is_object() && s["video"].contains("uri") &&
          s["video"]["uri"].is_string() && !s["video"]["uri"].get<std::string>().empty()) {
        r.video_uri = s["video"]["uri"].get<std::string>();
        return r;
      }
  // No sample: Veo's safety filters say why in raiMediaFilteredReasons.
  std::string reasons;
  if (gvr.is_object() && gvr.contains("raiMediaFilteredReasons") && gvr["raiMediaFilteredReasons"].is_array())
    for (const auto& x : gvr["raiMediaFilteredReasons"])
      if (x.is_string()) reasons += (reasons.empty() ? "" : "; ") + x.get<std::string>();
  r.error = reasons.empty() ? "finished without a video (no generatedSamples[].video.uri)"
                            : "the video was filtered: " + one_line(reasons);
  return r;
}

std::vector<fs::path> generate_veo_candidates(const VeoOptions& o, const fs::path& run_dir_in,
                                              const std::string& prompt, int64_t seed,
                                              const SessionSecret& key, HttpTransport& http,
                                              const HostedHooks& hooks) {
  const fs::path run_dir = fs::absolute(run_dir_in).lexically_normal();
  const std::string png = read_recolored_png(run_dir, kWho);
  const std::string full_prompt = video_prompt(o.prompt_template, prompt);
  const fs::path dir = reset_candidates_dir(run_dir, kWho);
  const std::string submit_url = o.base_url + "/models/" + o.model + ":predictLongRunning";

  return make_candidates(kWho, o.candidates, o.concurrency, hooks, [&](int i, const HostedHooks& h) {
    const std::string nn = two_digits(i);
    HostedSession s(kWho, "candidate " + nn + ": ", o.limits, http, h, key);
    if (h.progress) h.progress(0, "submitting");
    const json body = veo_request(o, png, full_prompt, seed + i);
    const json submitted = s.parse(submit_url, s.post_json(submit_url, json_text(body)));
    if (!submitted.is_object() || !submitted.contains("name") || !submitted["name"].is_string() ||
        submitted["name"].get<std::string>().empty())
      s.fail("no operation \"name\" in the reply from " + submit_url + ": " + s.excerpt(json_text(submitted), 120));
    const std::string name = submitted["name"].get<std::string>();
    s.job = "operation " + name;
    s.log("submitted as operation " + name + (o.send_seed ? " (seed " + std::to_string(seed + i) + ")" : ""));

    const std::string poll_url = o.base_url + "/" + name;
    VeoOperation op = read_veo_operation(submitted);
    while (!op.done) {
      if (h.progress) h.progress(0.1, "waiting for Veo");
      s.wait_to_poll(poll_url);
      op = read_veo_operation(s.parse(poll_url, s.get(poll_url)));
    }
    if (!op.error.empty()) s.fail(s.job + " failed: " + op.error);
    if (!is_http_url(op.video_uri))
      s.fail(s.job + " gave a video uri that is " + scheme_for_message(op.video_uri) + ", not http(s)");

    if (h.progress) h.progress(0.9, "downloading");
    const std::string out_rel = "candidates/" + nn + ".mp4";
    const fs::path out = dir / (nn + ".mp4");
    download_candidate_video(s, op.video_uri, out, out_rel);
    return out;
  });
}

}  // namespace svgm
