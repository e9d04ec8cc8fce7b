// ranker `llm`: the paper's judge. Shows an OpenAI-compatible vision chat model a few frames of
// every candidate video, with the motion prompt and the pixel ranker's findings, and asks which
// candidate is best suited for fitting the original drawing to it. The pixel ranking is always
// computed first: it is what the model is told, and the choice whenever the model cannot give
// one (no url, connection, timeout, HTTP status, malformed or unknown answer), with one warning
// line naming the reason. ranking.json is the pixel ranking's, with "chosen" and "reason" from
// the judge and a "judge" object saying who chose and why.
//
// Options (stages.ranker.options): url (required), model, api_key_env, timeout_s (default 120),
// frames (per candidate, 1..16, default 4), size (frame width in px, 32..1024, default 256).
// Request: {"model", "temperature": 0, "messages": [system: JUDGING_INSTRUCTIONS, user: [text:
//   prompt, candidate names and pixel findings; then per candidate a text label and its frames
//   as image_url PNG data URLs]]}. Answer (choices[0].message.content, ```json fences allowed):
//   {"best": "<candidate name>", "reason": "<one sentence>"}
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "common/chat_client.h"
#include "common/plugin_glue.h"
#include "common/stage_files.h"
#include "fit/palette.h"
#include "fit/preview_video.h"
#include "pipeline/plugin_options.h"
#include "rank/pixel_ranker.h"
#include "svgmotion/error.h"
#include "svgmotion/png_io.h"
#include "svgmotion/target_video.h"

namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;
namespace chat = svgm::plugin::chat;

struct Settings : chat::Settings {
  int frames = 4;
  int size = 256;
};

// Option mistakes are the user's to fix: an error, before any work. A missing url, like the
// network, is a reason to fall back (chat::Failure from chat_settings).
Settings read_options(const json& opts) {
  const svgm::PluginOptions o(opts, "ranker llm", {"url", "model", "api_key_env", "timeout_s", "frames", "size"});
  Settings s;
  s.frames = o.whole("frames", 4, 1, 16);
  s.size = o.whole("size", 256, 32, 1024);
  return s;
}

void chat_settings(const json& opts, Settings& s) {
  json chat_opts = opts;
  if (!chat_opts.contains("timeout_s")) chat_opts["timeout_s"] = 120;
  static_cast<chat::Settings&>(s) = chat::read_settings(chat_opts, "ranker");
}

// The idea of the paper's judging prompt, in our words.
const char* const kInstructions =
    "You judge candidate videos that an image-to-video model made from one flat 2D drawing. The "
    "original vector drawing will be animated by fitting its own shapes to the chosen video, so "
    "choose the candidate that is easiest to fit faithfully: every shape and colour of the "
    "drawing kept (flat, solid colours, no shading or texture, no new objects, text or "
    "background), motion only in the picture plane (no 3D turning, no camera motion or zoom), "
    "continuous motion (no part appearing, vanishing or jumping), and the requested motion shown "
    "clearly rather than a still picture. Answer with JSON only, no other text, in exactly this "
    "form: {\"best\": \"<candidate name>\", \"reason\": \"<one sentence>\"}";

// `frames` frames of a candidate, `size` px wide, as PNG data URLs.
std::vector<std::string> frame_urls(const fs::path& video, int frames, int size) {
  const svgm::TargetInfo info = svgm::probe_target(video);
  const int w = std::min(size, info.width);
  const int h = std::max(1, static_cast<int>(std::lround(static_cast<double>(info.height) * w / info.width)));
  svgm::TargetOptions o;
  o.keyframes = std::min(frames, info.frames);
  const svgm::TargetFrames t = svgm::load_target(video, w, h, o);
  std::vector<std::string> urls;
  for (int k = 0; k < t.keyframes; ++k)
    urls.push_back("data:image/png;base64," +
                   chat::base64(svgm::encode_png(svgm::rgba8_image(&t.raw[static_cast<size_t>(k) * w * h * 4], w, h))));
  return urls;
}

// Asks the model; returns {best, reason}. chat::Failure on anything unusable.
std::pair<std::string, std::string> ask(const json& req, const svgm::Ranking& pixel, const fs::path& dir,
                                        const Settings& s, const svgm_host* host) {
  auto progress = [&](double f, const char* note) {
    if (host && host->progress) host->progress(host, f, note);
  };
  const std::string prompt = req.contains("prompt") && req["prompt"].is_string() ? req["prompt"].get<std::string>() : "";
  std::vector<std::string> names;
  std::ostringstream text;
  text << "Motion asked for: " << (prompt.empty() ? std::string("(not described)") : prompt) << "\n\nCandidates";
  text << " (each shown below as " << s.frames << " frames in time order), with what automatic pixel checks found:\n";
  // In name order, not the pixel ranking's: the listing order should not suggest an answer.
  std::vector<const svgm::CandidateScore*> readable;
  for (const auto& c : pixel.candidates)
    if (c.error.empty()) readable.push_back(&c);
  std::sort(readable.begin(), readable.end(), [](auto* a, auto* b) { return a->name < b->name; });
  for (const svgm::CandidateScore* cp : readable) {
    const svgm::CandidateScore& c = *cp;
    names.push_back(c.name);
    text << "- " << c.name << ": ";
    if (c.defects.empty()) text << "no defects";
    for (const auto& d : c.defects) text << (&d == &c.defects.front() ? "" : ", ") << d;
    text << "\n";
  }
  json content = json::array({{{"type", "text"}, {"text", text.str()}}});
  for (size_t i = 0; i < names.size(); ++i) {
    progress(0.3 + 0.3 * static_cast<double>(i) / names.size(), ("frames of " + names[i]).c_str());
    std::vector<std::string> urls;
    try {
      urls = frame_urls(dir / names[i], s.frames, s.size);
    } catch (const chat::Failure&) {
      throw;
    } catch (const std::exception& e) {
      throw chat::Failure("cannot read the frames of " + names[i] + ": " + chat::one_line(e.what(), 200));
    }
    content.push_back({{"type", "text"}, {"text", "Candidate " + names[i] + ":"}});
    for (const auto& u : urls) content.push_back({{"type", "image_url"}, {"image_url", {{"url", u}}}});
  }
  const json body = {{"model", s.model},
                     {"messages", json::array({{{"role", "system"}, {"content", kInstructions}},
                                               {{"role", "user"}, {"content", content}}})},
                     {"temperature", 0}};
  progress(0.6, "waiting for the model");
  const std::string answer = chat::strip_fences(chat::answer_text(chat::post(s, body.dump(), host, "ranker llm")));
  json a;
  try {
    a = json::parse(answer);
  } catch (const json::exception& e) {
    throw chat::Failure("malformed JSON in the answer: " + chat::one_line(e.what(), 200));
  }
  if (!a.is_object() || !a.contains("best") || !a["best"].is_string())
    throw chat::Failure("malformed answer: no \"best\" candidate name");
  const std::string best = a["best"].get<std::string>();
  if (std::find(names.begin(), names.end(), best) == names.end())
    throw chat::Failure("the answer names '" + chat::one_line(best, 60) + "', which is not a readable candidate");
  const std::string reason = a.contains("reason") && a["reason"].is_string() ? a["reason"].get<std::string>() : "";
  return {best, chat::one_line(reason, 500)};
}

json run(const json& req, const svgm_host* host) {
  namespace P = svgm::plugin;
  const json& config = req.at("config");
  const json opts = config.contains("options") ? config["options"] : json::object();
  Settings s = read_options(opts);
  const fs::path dir = P::file(req, "inputs", "candidates");
  // The colours the candidates are drawn in: the palette's, or the SVG's own for a user's video.
  const std::vector<svgm::Rgba> palette = svgm::plugin::candidate_colours(req, "ranker llm");
  const svgm::Ranking pixel = svgm::rank_directory(dir, palette, {}, [&](double f, const std::string& note) {
    if (host && host->progress) host->progress(host, 0.3 * f, note.c_str());
    return !(host && host->cancelled && host->cancelled(host));
  });

  json ranking = pixel.to_json();
  std::string chosen = pixel.chosen;
  bool judged = false;
  try {
    chat_settings(opts, s);
    const auto [best, reason] = ask(req, pixel, dir, s, host);
    chosen = best;
    judged = true;
    ranking["chosen"] = best;
    ranking["reason"] = "the model's choice" + (reason.empty() ? std::string() : ": " + reason);
    ranking["judge"] = {{"source", "llm"}, {"model", s.model}, {"pixel_choice", pixel.chosen}};
  } catch (const chat::Failure& f) {
    const std::string why = chat::one_line(f.what());
    if (host && host->log) host->log(host, 2, ("ranker llm: " + why + "; using the pixel ranking").c_str());
    ranking["judge"] = {{"source", "pixel"}, {"fallback", why}};
  }
  if (host && host->progress) host->progress(host, 0.9, "writing target.mp4");
  P::write_target(dir / chosen, P::file(req, "outputs", "target"));
  P::write_json(P::file(req, "outputs", "ranking"), ranking);
  json r = {{"message", "chose " + chosen + (judged ? " (llm)" : " (pixel fallback)")}};
  // A fallback depends on the network: let the next run ask again.
  if (!judged) r["cache"] = false;
  return r;
}

}  // namespace

SVGM_DEFINE_PLUGIN("ranker", "llm", "1", "the paper's judge on an OpenAI-compatible vision chat model (falls back to pixel)", run)
