#include "video/comfyui_client.h"

#include <algorithm>
#include <chrono>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iterator>
#include <thread>

#include "svgmotion/error.h"
#include "svgmotion/target_video.h"
#include "pipeline/plugin_options.h"
#include "video/command_runner.h"
#include "video/command_video.h"

namespace svgm {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

const char* const kVideoExtensions[] = {"mp4", "webm", "gif", "mov", "mkv", "avi", "m4v", "webp"};

[[noreturn]] void fail(const std::string& message) { throw Error("video comfyui: " + message); }

std::string one_line(std::string s, size_t max_chars = 200) {
  for (char& c : s)
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  if (s.size() > max_chars) s = s.substr(0, max_chars) + "...";
  return s;
}

std::string two_digits(int i) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%02d", i);
  return buf;
}

using Clock = std::chrono::steady_clock;

}  // namespace

ComfyuiOptions parse_comfyui_options(const json& options) {
  const PluginOptions opt(options, "video comfyui",
                          {"url", "workflow", "candidates", "frames", "timeout_s", "retries", "poll_s", "prompt_template"});
  ComfyuiOptions o;
  o.url = opt.string("url", o.url);
  o.workflow = opt.string("workflow", o.workflow.string());
  o.candidates = opt.whole("candidates", o.candidates, 1, 99);
  o.frames = opt.whole("frames", o.frames, 1, 100000);
  o.timeout_s = opt.number("timeout_s", o.timeout_s);
  if (o.timeout_s <= 0) opt.fail("options.timeout_s must be > 0 seconds");
  o.retries = opt.whole("retries", o.retries, 0, 10);
  o.poll_s = opt.number("poll_s", o.poll_s);
  if (o.poll_s <= 0 || o.poll_s > 60) opt.fail("options.poll_s must be in (0, 60] seconds");
  o.prompt_template = opt.string("prompt_template", kDefaultVideoPromptTemplate);
  while (!o.url.empty() && o.url.back() == '/') o.url.pop_back();
  if (o.url.empty())
    fail("options.url is not set (the ComfyUI server, e.g. http://127.0.0.1:8188)");
  if (o.url.rfind("http://", 0) != 0 && o.url.rfind("https://", 0) != 0)
    fail("options.url must start with http:// or https://, not " + o.url);
  if (o.workflow.empty())
    fail("options.workflow is not set (a workflow JSON file in ComfyUI's API format)");
  return o;
}

json load_comfyui_workflow(const fs::path& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) fail("the workflow file " + path.string() + " cannot be read");
  const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  json w;
  try {
    w = json::parse(text);
  } catch (const json::exception& e) {
    fail("the workflow file " + path.string() + " is not valid JSON (" + one_line(e.what()) +
         ")");
  }
  if (!w.is_object() || w.empty())
    fail("the workflow file " + path.string() +
         " is not a JSON object of nodes (export it with \"Save (API Format)\")");
  bool has_image = false;
  std::function<void(const json&)> scan = [&](const json& v) {
    if (v.is_string() && v.get<std::string>() == "{image}") has_image = true;
    if (v.is_structured())
      for (const auto& e : v) scan(e);
  };
  scan(w);
  if (!has_image)
    fail("the workflow file " + path.string() +
         " has no \"{image}\" placeholder (the uploaded image's name)");
  return w;
}

json fill_comfyui_workflow(const json& workflow, const std::string& image,
                           const std::string& prompt, int64_t seed, int frames) {
  if (workflow.is_string()) {
    const std::string& s = workflow.get_ref<const std::string&>();
    if (s == "{image}") return image;
    if (s == "{prompt}") return prompt;
    if (s == "{seed}") return seed;
    if (s == "{frames}") return frames;
    return workflow;
  }
  if (workflow.is_object()) {
    json out = json::object();
    for (const auto& [k, v] : workflow.items())
      out[k] = fill_comfyui_workflow(v, image, prompt, seed, frames);
    return out;
  }
  if (workflow.is_array()) {
    json out = json::array();
    for (const auto& v : workflow) out.push_back(fill_comfyui_workflow(v, image, prompt, seed, frames));
    return out;
  }
  return workflow;
}

std::optional<ComfyuiFile> find_comfyui_output(const json& history, const std::string& prompt_id) {
  if (!history.is_object() || !history.contains(prompt_id)) return std::nullopt;
  const json& entry = history[prompt_id];
  if (!entry.is_object() || !entry.contains("outputs") || !entry["outputs"].is_object())
    return std::nullopt;
  for (const char* kind : {"gifs", "videos", "images"}) {
    for (const auto& [node, out] : entry["outputs"].items()) {
      if (!out.is_object() || !out.contains(kind) || !out[kind].is_array()) continue;
      for (const auto& f : out[kind]) {
        if (!f.is_object() || !f.contains("filename") || !f["filename"].is_string()) continue;
        ComfyuiFile file;
        file.filename = f["filename"].get<std::string>();
        if (file.filename.empty()) continue;
        file.subfolder = f.value("subfolder", std::string());
        file.type = f.value("type", std::string("output"));
        return file;
      }
    }
  }
  return std::nullopt;
}

std::string url_encode(const std::string& s) {
  static const char* hex = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : s) {
    if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~') {
      out += static_cast<char>(c);
    } else {
      out += '%';
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  return out;
}

namespace {

// One candidate's exchanges with the server, under one deadline.
class Session {
 public:
  Session(const ComfyuiOptions& o, HttpTransport& http, const ComfyuiHooks& hooks,
          std::string label)
      : o_(o), http_(http), hooks_(hooks), label_(std::move(label)),
        end_(Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                std::chrono::duration<double>(o.timeout_s))) {}

  std::string prompt_id;  // once queued, named in a timeout

  double left() const { return std::chrono::duration<double>(end_ - Clock::now()).count(); }

  [[noreturn]] void timeout(const std::string& url) const {
    fail(label_ + "no result within " + short_number(o_.timeout_s) + " s (" +
         (prompt_id.empty() ? "waiting for " + url : "prompt " + prompt_id) + ")");
  }

  void check_cancelled() const {
    if (hooks_.cancelled && hooks_.cancelled()) fail(label_ + "cancelled");
  }

  // Sleeps up to `seconds` (never past the deadline), waking for a cancel.
  void pause(double seconds) const {
    const auto until = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                          std::chrono::duration<double>(std::min(seconds, left())));
    while (Clock::now() < until) {
      check_cancelled();
      const double rest = std::chrono::duration<double>(until - Clock::now()).count();
      const double step = std::min(rest, 0.1);
      if (step <= 0) break;
      if (hooks_.sleep) hooks_.sleep(step);
      else std::this_thread::sleep_for(std::chrono::duration<double>(step));
    }
  }

  // Runs one request with retries for connection errors and 5xx; returns a 2xx reply's body.
  template <class Fn>
  std::string request(const std::string& url, Fn&& send) {
    for (int attempt = 0;; ++attempt) {
      check_cancelled();
      const double budget = left();
      if (budget <= 0) timeout(url);
      const HttpReply r = send(budget);
      check_cancelled();
      if (r.timed_out) timeout(url);
      if (r.connected && r.status >= 200 && r.status < 300) return r.body;
      const std::string why =
          r.connected ? "HTTP " + std::to_string(r.status) + " from " + url +
                            (one_line(r.body).empty() ? "" : ": " + one_line(r.body))
                      : "cannot connect to " + url + ": " + one_line(r.error);
      const bool retryable = !r.connected || r.status >= 500;
      if (!retryable || attempt >= o_.retries) fail(label_ + why);
      const double backoff = 0.5 * (attempt + 1);
      if (hooks_.log)
        hooks_.log("video comfyui: " + label_ + why + "; retrying in " + short_number(backoff) +
                   " s");
      if (left() <= backoff) timeout(url);
      pause(backoff);
    }
  }

  json request_json(const std::string& url, const std::string& body_text) {
    try {
      return json::parse(body_text);
    } catch (const json::exception&) {
      fail(label_ + "malformed JSON from " + url + ": " + one_line(body_text, 120));
    }
  }

 private:
  const ComfyuiOptions& o_;
  HttpTransport& http_;
  const ComfyuiHooks& hooks_;
  std::string label_;
  Clock::time_point end_;
};

std::string lowercase_extension(const std::string& filename) {
  const fs::path p(filename);
  std::string ext = p.extension().string();
  if (!ext.empty() && ext[0] == '.') ext.erase(0, 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace

std::vector<fs::path> generate_comfyui_candidates(const ComfyuiOptions& options,
                                                  const fs::path& run_dir_in,
                                                  const std::string& prompt, int64_t seed,
                                                  HttpTransport& http, const ComfyuiHooks& hooks) {
  const fs::path run_dir = fs::absolute(run_dir_in).lexically_normal();
  const fs::path image = run_dir / "recolored.png";
  if (!fs::is_regular_file(image)) fail(image.string() + ": no such file (the recoloured image)");
  const json workflow = load_comfyui_workflow(options.workflow);  // before anything is deleted

  std::string full_prompt = replace_placeholder(options.prompt_template, "prompt", prompt);
  while (!full_prompt.empty() && (full_prompt.back() == ' ' || full_prompt.back() == '\n'))
    full_prompt.pop_back();

  const fs::path dir = run_dir / "candidates";
  std::error_code ec;
  fs::remove_all(dir, ec);
  if (ec) fail(dir.string() + ": cannot empty: " + ec.message());
  fs::create_directories(dir, ec);
  if (ec) fail(dir.string() + ": cannot create: " + ec.message());

  const std::string upload_url = options.url + "/upload/image";
  const std::string prompt_url = options.url + "/prompt";
  std::vector<fs::path> outputs;
  const int n = options.candidates;
  for (int i = 0; i < n; ++i) {
    const std::string nn = two_digits(i);
    const std::string label = "candidate " + nn + ": ";
    auto progress = [&](double within, const std::string& note) {
      if (hooks.progress) hooks.progress((i + within) / n, "candidate " + std::to_string(i + 1) +
                                                               " of " + std::to_string(n) + ": " +
                                                               note);
    };
    Session s(options, http, hooks, label);
    s.check_cancelled();

    progress(0, "uploading the image");
    const json up = s.request_json(upload_url, s.request(upload_url, [&](double t) {
      return http.post_file(upload_url, "image", image, t);
    }));
    if (!up.is_object() || !up.contains("name") || !up["name"].is_string())
      fail(label + "no \"name\" in the reply from " + upload_url + ": " + one_line(up.dump(), 120));
    std::string uploaded = up["name"].get<std::string>();
    if (up.contains("subfolder") && up["subfolder"].is_string() &&
        !up["subfolder"].get<std::string>().empty())
      uploaded = up["subfolder"].get<std::string>() + "/" + uploaded;

    progress(0.05, "queueing the workflow");
    const int64_t candidate_seed = seed + i;
    const json body = {
        {"prompt", fill_comfyui_workflow(workflow, uploaded, full_prompt, candidate_seed,
                                         options.frames)},
        {"client_id", "svgmotion"}};
    const json queued = s.request_json(prompt_url, s.request(prompt_url, [&](double t) {
      return http.post_json(prompt_url, body.dump(), t);
    }));
    if (!queued.is_object() || !queued.contains("prompt_id") ||
        !(queued["prompt_id"].is_string() || queued["prompt_id"].is_number()))
      fail(label + "no \"prompt_id\" in the reply from " + prompt_url + ": " +
           one_line(queued.dump(), 120));
    s.prompt_id = queued["prompt_id"].is_string() ? queued["prompt_id"].get<std::string>()
                                                  : queued["prompt_id"].dump();
    if (hooks.log)
      hooks.log("video comfyui: " + label + "queued as prompt " + s.prompt_id + " (seed " +
                std::to_string(candidate_seed) + ")");

    progress(0.1, "waiting for ComfyUI");
    const std::string history_url = options.url + "/history/" + url_encode(s.prompt_id);
    std::optional<ComfyuiFile> result;
    for (;;) {
      const json h = s.request_json(history_url, s.request(history_url, [&](double t) {
        return http.get(history_url, t);
      }));
      result = find_comfyui_output(h, s.prompt_id);
      if (result) break;
      if (h.is_object() && h.contains(s.prompt_id) && h[s.prompt_id].is_object()) {
        // ComfyUI lists a prompt in its history once it has finished, well or not.
        const json& entry = h[s.prompt_id];
        const json status = entry.value("status", json::object());
        if (status.is_object() && status.value("status_str", std::string()) == "error") {
          std::string detail;
          if (status.contains("messages") && status["messages"].is_array())
            for (const auto& m : status["messages"])
              if (m.is_array() && m.size() == 2 && m[0] == "execution_error" && m[1].is_object())
                detail = ": " + m[1].value("node_type", std::string("?")) + ": " +
                         m[1].value("exception_message", std::string());
          fail(label + "ComfyUI failed on prompt " + s.prompt_id + one_line(detail));
        }
        if (entry.contains("outputs"))
          fail(label + "prompt " + s.prompt_id +
               " finished without a video (no node output has gifs, videos or images with a "
               "filename)");
      }
      if (s.left() <= 0) s.timeout(history_url);
      s.pause(options.poll_s);
    }

    const std::string ext = lowercase_extension(result->filename);
    bool video = false;
    for (const char* e : kVideoExtensions) video = video || ext == e;
    if (!video)
      fail(label + "prompt " + s.prompt_id + " produced " + result->filename +
           ", not a video file (mp4, webm, gif, ...)");
    progress(0.9, "downloading " + result->filename);
    const std::string view_url = options.url + "/view?filename=" + url_encode(result->filename) +
                                 "&subfolder=" + url_encode(result->subfolder) +
                                 "&type=" + url_encode(result->type);
    const std::string bytes =
        s.request(view_url, [&](double t) { return http.get(view_url, t); });
    const std::string out_rel = "candidates/" + nn + "." + ext;
    const fs::path out = dir / (nn + "." + ext);
    {
      std::ofstream f(out, std::ios::binary);
      f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
      if (!f) fail(label + "cannot write " + out.string());
    }
    std::string why;
    try {
      const TargetInfo info = probe_target(out);
      if (info.frames < 1) why = "it has no frames";
      else if (hooks.log)
        hooks.log("video comfyui: " + label + out_rel + ": " + std::to_string(info.frames) +
                  " frames of " + std::to_string(info.width) + "x" + std::to_string(info.height) +
                  " at " + short_number(info.fps) + " fps");
    } catch (const Error& e) {
      why = e.what();
      const std::string prefix = out.string() + ": ";
      if (why.rfind(prefix, 0) == 0) why = why.substr(prefix.size());
    }
    if (!why.empty())
      fail(label + "the result of prompt " + s.prompt_id + " (" + out_rel +
           ") is not a readable video: " + one_line(why));
    outputs.push_back(out);
  }
  if (hooks.progress) hooks.progress(1.0, "done");
  return outputs;
}

}  // namespace svgm
