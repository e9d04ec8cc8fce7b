// ranker `llm`: the paper's two-stage judge on an OpenAI-compatible vision chat model. The pixel
// ranking is computed first: it is what the model is told, and the choice whenever the model
// cannot give one (no url, connection, timeout, HTTP status, malformed or unknown answer), with
// one warning line naming the reason.
//
// Stage 1 (options.two_stage, default true) shows the model each readable candidate alone (a few
// frames, the prompt, the pixel findings) and asks for the four constraints of a fittable video
// (no 3D rotation, no new elements, constant flat colours, continuity: Yes / Partial / No each)
// and whether it is viable at all (rank/judge_scores.h). Stage 2 shows the best top_k viable
// ones together and asks which is best. One viable candidate is chosen without stage 2; none
// viable: every candidate is flagged "not viable" in ranking.json (the pipeline then stops,
// exit 4, unless stages.ranker.accept_flagged) and the one with the most points is named.
// ranking.json is the pixel ranking's, with "chosen" and "reason" from the judge and a "judge"
// object holding every answer the model gave (stage 1 per candidate, stage 2) and who chose.
//
// Options (stages.ranker.options): url (required), model, api_key_env, timeout_s (default 120,
// per request), frames (per candidate, 1..16, default 4), size (frame width in px, 32..1024,
// default 256), two_stage (default true), top_k (candidates compared in stage 2, 2..20, default 4).
// Stage 1 request: {"model", "temperature": 0, "messages": [system: kScoreInstructions, user:
//   [text: prompt and pixel findings; text "Candidate NAME:"; its frames as PNG data URLs]]}
//   answer: {"no_3d_rotation", "no_new_elements", "flat_colours", "continuity": "Yes|Partial|No",
//            "viable": true|false, "reason": "<one sentence>"}
// Stage 2 request: as stage 1 but with kCompareInstructions and every finalist's label and
//   frames; answer: {"best": "<candidate name>", "reason": "<one sentence>"}
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <tuple>
#include <sstream>
#include <string>
#include <vector>

#include "common/chat_client.h"
#include "common/plugin_glue.h"
#include "common/stage_files.h"
#include "color/palette_json.h"
#include "media/preview_video.h"
#include "plugin/plugin_options.h"
#include "rank/judge_scores.h"
#include "rank/pixel_ranker.h"
#include "svgmotion/error.h"
#include "svgmotion/png_io.h"
#include "svgmotion/target_video.h"
#include "svgmotion/utf8_text.h"

namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;
namespace chat = svgm::plugin::chat;

struct Settings : chat::Settings {
  int frames = 4;
  int size = 256;
  bool two_stage = true;
  int top_k = 4;  // the paper compares its best few in stage 2
};

// Option mistakes are the user's to fix: an error, before any work. A missing url, like the
// network, is a reason to fall back (chat::Failure from chat_settings).
Settings read_options(const json& opts) {
  const svgm::PluginOptions o(opts, "ranker llm",
                              {"url", "model", "api_key_env", "timeout_s", "frames", "size", "two_stage", "top_k"});
  Settings s;
  s.frames = o.whole("frames", 4, 1, 16);
  s.size = o.whole("size", 256, 32, 1024);
  s.two_stage = o.flag("two_stage", s.two_stage);
  s.top_k = o.whole("top_k", s.top_k, 2, 20);
  return s;
}

void chat_settings(const json& opts, Settings& s) {
  json chat_opts = opts;
  if (!chat_opts.contains("timeout_s")) chat_opts["timeout_s"] = 120;
  static_cast<chat::Settings&>(s) = chat::read_settings(chat_opts, "ranker");
}

// The idea of the paper's stage-1 prompt, in our words.
const char* const kScoreInstructions =
    "You check one candidate video that an image-to-video model made from a flat 2D drawing. The "
    "original vector drawing will be animated by fitting its own shapes to this video, so it must "
    "meet four constraints. no_3d_rotation: parts move only in the picture plane (no turning in "
    "depth, no camera motion or zoom). no_new_elements: no object, text, shadow or background "
    "appears that the drawing does not have. flat_colours: every shape keeps its flat, solid "
    "colour (no shading, gradients, texture or colour drift). continuity: no part appears, "
    "vanishes or jumps between frames. Judge each as Yes (met), Partial (mostly met) or No, then "
    "say whether the video is viable for fitting at all. Answer with JSON only, no other text, in "
    "exactly this form: {\"no_3d_rotation\": \"Yes|Partial|No\", \"no_new_elements\": "
    "\"Yes|Partial|No\", \"flat_colours\": \"Yes|Partial|No\", \"continuity\": \"Yes|Partial|No\", "
    "\"viable\": true, \"reason\": \"<one sentence>\"}";

// The idea of the paper's comparative (stage-2) prompt, in our words.
const char* const kCompareInstructions =
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

// One chat request (temperature 0, a system and a user message); the answer without fences.
std::string ask(const Settings& s, const char* instructions, const json& content, const svgm_host* host) {
  const json body = {{"model", s.model},
                     {"messages", json::array({{{"role", "system"}, {"content", instructions}},
                                               {{"role", "user"}, {"content", content}}})},
                     {"temperature", 0}};
  return chat::strip_fences(chat::answer_text(chat::post(s, svgm::json_text(body), host, "ranker llm")));
}

std::string findings(const svgm::CandidateScore& c) {
  std::string t;
  for (const auto& d : c.defects) t += (t.empty() ? "" : ", ") + d;
  return t.empty() ? "no defects" : t;
}

// The judge's conversation with the model over the readable candidates.
class Judge {
 public:
  Judge(const json& req, const svgm::Ranking& pixel, const fs::path& dir, const Settings& s, const svgm_host* host)
      : pixel_(pixel), dir_(dir), s_(s), host_(host) {
    prompt_ = req.contains("prompt") && req["prompt"].is_string() ? req["prompt"].get<std::string>() : "";
    if (prompt_.empty()) prompt_ = "(not described)";
    for (const auto& c : pixel.candidates)
      if (c.error.empty()) order_.push_back(c.name);  // the pixel ranking's order
  }

  // Stage 1 for every candidate; the answers go to `record`.
  std::vector<svgm::JudgeScore> score_all(json& record) {
    std::vector<svgm::JudgeScore> scores;
    record = json::array();
    const std::vector<std::string> names = in_name_order(order_);
    for (size_t i = 0; i < names.size(); ++i) {
      progress(0.3 + 0.4 * static_cast<double>(i) / names.size(), "scoring " + names[i]);
      const svgm::CandidateScore& c = *find(names[i]);
      json content = json::array({{{"type", "text"},
                                   {"text", "Motion asked for: " + prompt_ + "\nAutomatic pixel checks of this candidate found: " +
                                                findings(c) + "\nThe candidate, as " + std::to_string(s_.frames) +
                                                " frames in time order:"}}});
      add_frames(content, names[i]);
      const std::string answer = ask(s_, kScoreInstructions, content, host_);
      try {
        scores.push_back(svgm::read_judge_score(names[i], answer));
      } catch (const svgm::Error& e) {
        throw chat::Failure(chat::one_line(e.what(), 300));
      }
      record.push_back(scores.back().to_json());
    }
    return scores;
  }

  // Stage 2 over `names`; returns {best, reason, answer}.
  std::tuple<std::string, std::string, std::string> compare(const std::vector<std::string>& names_in) {
    // In name order, not the pixel ranking's: the listing order should not suggest an answer.
    const std::vector<std::string> names = in_name_order(names_in);
    std::ostringstream text;
    text << "Motion asked for: " << prompt_ << "\n\nCandidates";
    text << " (each shown below as " << s_.frames << " frames in time order), with what automatic pixel checks found:\n";
    for (const auto& n : names) text << "- " << n << ": " << findings(*find(n)) << "\n";
    json content = json::array({{{"type", "text"}, {"text", text.str()}}});
    for (size_t i = 0; i < names.size(); ++i) {
      progress(0.7 + 0.1 * static_cast<double>(i) / names.size(), "frames of " + names[i]);
      add_frames(content, names[i]);
    }
    progress(0.8, "waiting for the model");
    const std::string answer = ask(s_, kCompareInstructions, content, host_);
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
      throw chat::Failure("the answer names '" + chat::one_line(best, 60) + "', which is not a " +
                          (find(best) ? "finalist" : "readable candidate"));
    const std::string reason = a.contains("reason") && a["reason"].is_string() ? a["reason"].get<std::string>() : "";
    return {best, chat::one_line(reason, 500), answer};
  }

  const std::vector<std::string>& order() const { return order_; }

 private:
  void progress(double f, const std::string& note) const {
    if (host_ && host_->progress) host_->progress(host_, f, note.c_str());
  }
  const svgm::CandidateScore* find(const std::string& name) const {
    for (const auto& c : pixel_.candidates)
      if (c.name == name && c.error.empty()) return &c;
    return nullptr;
  }
  static std::vector<std::string> in_name_order(std::vector<std::string> v) {
    std::sort(v.begin(), v.end());
    return v;
  }
  // "Candidate NAME:" and its frames (read once per candidate).
  void add_frames(json& content, const std::string& name) {
    auto it = frames_.find(name);
    if (it == frames_.end()) {
      try {
        it = frames_.emplace(name, frame_urls(dir_ / name, s_.frames, s_.size)).first;
      } catch (const std::exception& e) {
        throw chat::Failure("cannot read the frames of " + name + ": " + chat::one_line(e.what(), 200));
      }
    }
    content.push_back({{"type", "text"}, {"text", "Candidate " + name + ":"}});
    for (const auto& u : it->second) content.push_back({{"type", "image_url"}, {"image_url", {{"url", u}}}});
  }

  const svgm::Ranking& pixel_;
  fs::path dir_;
  const Settings& s_;
  const svgm_host* host_;
  std::string prompt_;
  std::vector<std::string> order_;
  std::map<std::string, std::vector<std::string>> frames_;
};

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
    Judge judge(req, pixel, dir, s, host);
    json record = {{"source", "llm"}, {"model", s.model}, {"pixel_choice", pixel.chosen}};
    std::string reason;
    if (!s.two_stage) {
      const auto [best, why, answer] = judge.compare(judge.order());
      chosen = best;
      reason = "the model's choice" + (why.empty() ? std::string() : ": " + why);
      record["comparison"] = {{"candidates", judge.order()}, {"answer", answer}};
    } else {
      const std::vector<svgm::JudgeScore> scores = judge.score_all(record["scores"]);
      const std::vector<std::string> finalists = svgm::judge_finalists(scores, judge.order(), s.top_k);
      if (finalists.size() > 1) {
        const auto [best, why, answer] = judge.compare(finalists);
        chosen = best;
        reason = "the model's choice among " + std::to_string(finalists.size()) + " viable candidates" +
                 (why.empty() ? std::string() : ": " + why);
        record["comparison"] = {{"candidates", finalists}, {"answer", answer}};
      } else if (finalists.size() == 1) {
        chosen = finalists[0];
        reason = "the only candidate the model found viable";
      } else {
        chosen = svgm::judge_best_of_rest(scores, judge.order());
        reason = "the model found no candidate viable; this one met most constraints";
      }
      // A candidate the judge found not viable is flagged like a pixel defect, so that a run
      // whose candidates are all unusable stops before fitting (pipeline, exit 4).
      for (const auto& sc : scores)
        if (!sc.viable)
          for (auto& c : ranking["candidates"])
            if (c.value("name", "") == sc.candidate)
              c["defects"].push_back("not viable for the judge" + (sc.reason.empty() ? std::string() : ": " + chat::one_line(sc.reason, 200)));
      for (const auto& sc : scores)
        if (sc.candidate == chosen && !sc.reason.empty() && finalists.size() <= 1) reason += ": " + chat::one_line(sc.reason, 300);
    }
    judged = true;
    ranking["chosen"] = chosen;
    ranking["reason"] = reason;
    ranking["judge"] = record;
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
