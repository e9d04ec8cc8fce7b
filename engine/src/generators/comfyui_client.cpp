#include "generators/comfyui_client.h"

#include "net/percent_encode.h"

#include <cctype>
#include <fstream>
#include <functional>
#include <iterator>

#include "svgmotion/error.h"
#include "svgmotion/target_video.h"
#include "plugin/plugin_options.h"
#include "generators/command_runner.h"
#include "generators/command_video.h"
#include "generators/hosted_session.h"
#include "svgmotion/utf8_text.h"

namespace svgm {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

[[noreturn]] void fail(const std::string& message) { throw Error("video comfyui: " + message); }

}  // namespace

ComfyuiOptions parse_comfyui_options(const json& options) {
  const PluginOptions opt(options, "video comfyui",
                          {"url", "workflow", "candidates", "frames", "timeout_s", "retries", "poll_s", "max_video_mib",
                           "prompt_template"});
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
  o.max_video_bytes = static_cast<uint64_t>(opt.whole("max_video_mib", static_cast<int>(o.max_video_bytes >> 20), 1, 65536)) << 20;
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

std::string url_encode(const std::string& s) { return percent_encode(s); }

namespace {

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

  const std::string full_prompt = video_prompt(options.prompt_template, prompt);

  const fs::path dir = reset_candidates_dir(run_dir, "video comfyui");
  const std::string upload_url = options.url + "/upload/image";
  const std::string prompt_url = options.url + "/prompt";
  std::vector<fs::path> outputs;
  const int n = options.candidates;
  SessionLimits limits{options.timeout_s, options.retries};
  limits.max_video_bytes = options.max_video_bytes;
  for (int i = 0; i < n; ++i) {
    const std::string nn = two_digits(i);
    const std::string label = "candidate " + nn + ": ";
    auto progress = [&](double within, const std::string& note) {
      if (hooks.progress) hooks.progress((i + within) / n, "candidate " + std::to_string(i + 1) +
                                                               " of " + std::to_string(n) + ": " +
                                                               note);
    };
    HostedSession s("video comfyui", label, limits, http, hooks);
    s.check_cancelled();

    progress(0, "uploading the image");
    const json up = s.parse(upload_url, s.post_file(upload_url, "image", image));
    if (!up.is_object() || !up.contains("name") || !up["name"].is_string())
      s.fail("no \"name\" in the reply from " + upload_url + ": " + s.excerpt(json_text(up), 120));
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
    const json queued = s.parse(prompt_url, s.post_json(prompt_url, json_text(body)));
    if (!queued.is_object() || !queued.contains("prompt_id") ||
        !(queued["prompt_id"].is_string() || queued["prompt_id"].is_number()))
      s.fail("no \"prompt_id\" in the reply from " + prompt_url + ": " +
             s.excerpt(json_text(queued), 120));
    const std::string prompt_id = queued["prompt_id"].is_string()
                                      ? queued["prompt_id"].get<std::string>()
                                      : json_text(queued["prompt_id"]);
    s.job = "prompt " + prompt_id;
    s.log("queued as prompt " + prompt_id + " (seed " + std::to_string(candidate_seed) + ")");

    progress(0.1, "waiting for ComfyUI");
    const std::string history_url = options.url + "/history/" + url_encode(prompt_id);
    std::optional<ComfyuiFile> result;
    for (;;) {
      const json h = s.parse(history_url, s.get(history_url));
      result = find_comfyui_output(h, prompt_id);
      if (result) break;
      if (h.is_object() && h.contains(prompt_id) && h[prompt_id].is_object()) {
        // ComfyUI lists a prompt in its history once it has finished, well or not.
        const json& entry = h[prompt_id];
        const json status = entry.value("status", json::object());
        if (status.is_object() && status.value("status_str", std::string()) == "error") {
          std::string detail;
          if (status.contains("messages") && status["messages"].is_array())
            for (const auto& m : status["messages"])
              if (m.is_array() && m.size() == 2 && m[0] == "execution_error" && m[1].is_object())
                detail = ": " + m[1].value("node_type", std::string("?")) + ": " +
                         m[1].value("exception_message", std::string());
          s.fail("ComfyUI failed on prompt " + prompt_id + s.excerpt(detail));
        }
        if (entry.contains("outputs"))
          s.fail("prompt " + prompt_id +
                 " finished without a video (no node output has gifs, videos or images with a "
                 "filename)");
      }
      if (s.left() <= 0) s.timeout(history_url);
      s.pause(options.poll_s);
    }

    const std::string ext = lowercase_extension(result->filename);
    if (!is_video_extension(ext))
      s.fail("prompt " + prompt_id + " produced " + result->filename +
             ", not a video file (mp4, webm, gif, ...)");
    progress(0.9, "downloading " + result->filename);
    const std::string view_url = options.url + "/view?filename=" + url_encode(result->filename) +
                                 "&subfolder=" + url_encode(result->subfolder) +
                                 "&type=" + url_encode(result->type);
    const std::string out_rel = "candidates/" + nn + "." + ext;
    const fs::path out = dir / (nn + "." + ext);
    download_candidate_video(s, view_url, out, out_rel);
    outputs.push_back(out);
  }
  if (hooks.progress) hooks.progress(1.0, "done");
  return outputs;
}

}  // namespace svgm
