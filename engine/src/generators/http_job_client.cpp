// http_job_client.h: queue-style hosted video APIs, mapped by configuration.
#include "generators/http_job_client.h"

#include <algorithm>
#include <cctype>

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

const char* const kWho = "video http-job";

std::vector<std::string> string_list(const PluginOptions& opt, const char* key) {
  std::vector<std::string> out;
  if (!opt.has(key)) return out;
  const json& v = opt.at(key);
  if (v.is_string()) return {v.get<std::string>()};
  if (!v.is_array()) opt.fail(std::string("options.") + key + " must be a list of strings, not " + json_text(v));
  for (const auto& e : v) {
    if (!e.is_string()) opt.fail(std::string("options.") + key + " must be a list of strings, not " + json_text(v));
    out.push_back(e.get<std::string>());
  }
  return out;
}

bool mentions_key(const json& j) {
  if (j.is_string()) return j.get<std::string>().find("{api_key}") != std::string::npos;
  if (j.is_structured())
    for (const auto& e : j)
      if (mentions_key(e)) return true;
  return false;
}

// The extension of a URL's path when it is a video's, else mp4.
std::string video_extension(const std::string& url) {
  std::string path = url.substr(0, url.find_first_of("?#"));
  const size_t slash = path.rfind('/'), dot = path.rfind('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "mp4";
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return is_video_extension(ext) ? ext : "mp4";
}

std::string as_text(const json& v) { return v.is_string() ? v.get<std::string>() : json_text(v); }

}  // namespace

HttpJobOptions parse_http_job_options(const json& options) {
  const PluginOptions opt(options, kWho,
                          {"submit_url", "body", "headers", "api_key_env", "id_field", "status_url",
                           "status_field", "done_values", "failed_values", "error_field", "result_url",
                           "video_url_field", "candidates", "concurrency", "frames", "fps", "timeout_s",
                           "retries", "poll_s", "poll_max_s", "max_video_mib", "prompt_template"});
  HttpJobOptions o;
  o.submit_url = opt.string("submit_url", "");
  if (!is_http_url(o.submit_url)) opt.fail("options.submit_url must be an http:// or https:// URL, not '" + o.submit_url + "'");
  if (!opt.has("body") || !opt.at("body").is_object())
    opt.fail("options.body must be the request's JSON object (a template with {prompt}, {image_data_url}, ...)");
  o.body = opt.at("body");
  if (opt.has("headers")) {
    const json& h = opt.at("headers");
    if (!h.is_object()) opt.fail("options.headers must be a map of header name to value, not " + json_text(h));
    for (const auto& [k, v] : h.items()) {
      if (!v.is_string()) opt.fail("options.headers." + k + " must be a string");
      o.headers.emplace_back(k, v.get<std::string>());
    }
  }
  o.api_key_env = opt.string("api_key_env", "");
  o.id_field = opt.string("id_field", "");
  o.status_url = opt.string("status_url", "");
  if (o.status_url.empty()) opt.fail("options.status_url is not set (a URL template such as {submit.status_url})");
  o.status_field = opt.string("status_field", o.status_field);
  o.done_values = string_list(opt, "done_values");
  if (o.done_values.empty()) opt.fail("options.done_values is not set (the status values of a finished job)");
  o.failed_values = string_list(opt, "failed_values");
  o.error_field = opt.string("error_field", o.error_field);
  o.result_url = opt.string("result_url", "");
  o.video_url_field = opt.string("video_url_field", "");
  if (o.video_url_field.empty()) opt.fail("options.video_url_field is not set (where the result names the video's URL)");
  o.candidates = opt.whole("candidates", o.candidates, 1, 99);
  o.concurrency = opt.whole("concurrency", o.concurrency, 1, 16);
  o.frames = opt.whole("frames", o.frames, 1, 100000);
  o.fps = opt.number("fps", o.fps);
  if (o.fps <= 0 || o.fps > 240) opt.fail("options.fps must be in (0, 240]");
  o.limits = read_session_limits(opt, o.limits);
  o.prompt_template = opt.string("prompt_template", kDefaultVideoPromptTemplate);
  // The key goes in a header only: a URL or body would put it in server logs and our messages.
  if (mentions_key(o.body) || o.submit_url.find("{api_key}") != std::string::npos ||
      o.status_url.find("{api_key}") != std::string::npos || o.result_url.find("{api_key}") != std::string::npos)
    opt.fail("{api_key} may only appear in options.headers");
  bool header_key = false;
  for (const auto& [k, v] : o.headers) header_key = header_key || v.find("{api_key}") != std::string::npos;
  if (header_key && o.api_key_env.empty()) opt.fail("options.headers use {api_key} but options.api_key_env is not set");
  return o;
}

json field_at(const json& j, const std::string& path) {
  const json* at = &j;
  size_t start = 0;
  while (start <= path.size()) {
    const size_t dot = path.find('.', start);
    const std::string part = path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (at->is_object() && at->contains(part)) {
      at = &(*at)[part];
    } else if (at->is_array() && !part.empty() &&
               std::all_of(part.begin(), part.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }) &&
               std::stoul(part) < at->size()) {
      at = &(*at)[std::stoul(part)];
    } else {
      return nullptr;
    }
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return *at;
}

json fill_job_body(const json& body, const std::string& prompt, const std::string& png, int64_t seed, int frames,
                   double fps) {
  if (body.is_string()) {
    const std::string& s = body.get_ref<const std::string&>();
    if (s == "{seed}") return seed;
    if (s == "{frames}") return frames;
    if (s == "{fps}") return fps;
    std::string out = s;
    if (out.find('{') == std::string::npos) return out;
    const std::string b64 = out.find("{image_") != std::string::npos ? base64(png) : std::string();
    out = replace_placeholder(out, "image_data_url", "data:image/png;base64," + b64);
    out = replace_placeholder(out, "image_base64", b64);
    out = replace_placeholder(out, "prompt", prompt);
    return out;
  }
  if (body.is_object()) {
    json out = json::object();
    for (const auto& [k, v] : body.items()) out[k] = fill_job_body(v, prompt, png, seed, frames, fps);
    return out;
  }
  if (body.is_array()) {
    json out = json::array();
    for (const auto& v : body) out.push_back(fill_job_body(v, prompt, png, seed, frames, fps));
    return out;
  }
  return body;
}

std::string fill_job_url(const std::string& url, const json& reply, const std::string& id_field) {
  std::string out;
  size_t i = 0;
  while (i < url.size()) {
    const size_t open = url.find('{', i);
    if (open == std::string::npos) break;
    const size_t close = url.find('}', open);
    if (close == std::string::npos) break;
    out += url.substr(i, open - i);
    const std::string name = url.substr(open + 1, close - open - 1);
    std::string path;
    if (name == "id") {
      if (id_field.empty()) throw Error(std::string(kWho) + ": " + url + " uses {id} but options.id_field is not set");
      path = id_field;
    } else if (name.rfind("submit.", 0) == 0) {
      path = name.substr(7);
    } else {
      out += url.substr(open, close - open + 1);  // not ours: kept as written
      i = close + 1;
      continue;
    }
    const json v = field_at(reply, path);
    if (!(v.is_string() || v.is_number()) || as_text(v).empty())
      throw Error(std::string(kWho) + ": the submit reply has no field " + path + " for {" + name + "}: " +
                  one_line(json_text(reply), 120));
    out += as_text(v);
    i = close + 1;
  }
  return out + url.substr(std::min(i, url.size()));
}

std::vector<std::string> job_headers(const HttpJobOptions& o, const std::string& key) {
  std::vector<std::string> out;
  for (const auto& [name, value] : o.headers) out.push_back(name + ": " + replace_placeholder(value, "api_key", key));
  return out;
}

std::vector<fs::path> generate_http_job_candidates(const HttpJobOptions& o, const fs::path& run_dir_in,
                                                   const std::string& prompt, int64_t seed, const SessionSecret& key,
                                                   HttpTransport& http, const HostedHooks& hooks) {
  const fs::path run_dir = fs::absolute(run_dir_in).lexically_normal();
  const std::string png = read_recolored_png(run_dir, kWho);
  const std::string full_prompt = video_prompt(o.prompt_template, prompt);
  const fs::path dir = reset_candidates_dir(run_dir, kWho);
  auto status_of = [&](const json& reply) { return as_text(field_at(reply, o.status_field)); };
  auto in = [](const std::vector<std::string>& list, const std::string& v) {
    return std::find(list.begin(), list.end(), v) != list.end();
  };

  return make_candidates(kWho, o.candidates, o.concurrency, hooks, [&](int i, const HostedHooks& h) {
    const std::string nn = two_digits(i);
    HostedSession s(kWho, "candidate " + nn + ": ", o.limits, http, h, key);
    if (h.progress) h.progress(0, "submitting");
    const json body = fill_job_body(o.body, full_prompt, png, seed + i, o.frames, o.fps);
    const json submitted = s.parse(o.submit_url, s.post_json(o.submit_url, json_text(body)));
    std::string status_url, result_url;
    try {
      status_url = fill_job_url(o.status_url, submitted, o.id_field);
      if (!o.result_url.empty()) result_url = fill_job_url(o.result_url, submitted, o.id_field);
    } catch (const Error& e) {
      s.fail(std::string(e.what()).substr(std::string(kWho).size() + 2));
    }
    s.job = "job " + (o.id_field.empty() ? status_url : as_text(field_at(submitted, o.id_field)));
    s.log("submitted as " + s.job + " (seed " + std::to_string(seed + i) + ")");

    json reply = submitted;
    for (;;) {
      const std::string status = status_of(reply);
      if (in(o.done_values, status)) break;
      if (in(o.failed_values, status)) {
        const json why = field_at(reply, o.error_field);
        s.fail(s.job + " failed (" + o.status_field + " " + status + ")" +
               (why.is_null() ? "" : ": " + s.excerpt(as_text(why))));
      }
      if (h.progress) h.progress(0.1, "waiting (" + one_line(status, 40) + ")");
      s.wait_to_poll(status_url);
      reply = s.parse(status_url, s.get(status_url));
    }
    if (!result_url.empty()) reply = s.parse(result_url, s.get(result_url));
    json video = field_at(reply, o.video_url_field);
    if (video.is_array() && !video.empty()) video = video[0];
    if (!video.is_string()) s.fail(s.job + " finished without a video URL at " + o.video_url_field + ": " + s.excerpt(json_text(reply), 120));
    if (!is_http_url(video.get<std::string>()))
      s.fail(s.job + " finished with a video URL that is " + scheme_for_message(video.get<std::string>()) + ", not http(s)");
    const std::string url = video.get<std::string>();

    if (h.progress) h.progress(0.9, "downloading");
    const std::string ext = video_extension(url);
    const std::string out_rel = "candidates/" + nn + "." + ext;
    const fs::path out = dir / (nn + "." + ext);
    download_candidate_video(s, url, out, out_rel);
    return out;
  });
}

}  // namespace svgm
