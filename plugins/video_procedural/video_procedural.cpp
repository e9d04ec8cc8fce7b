// video `procedural`: offline candidate videos of the recoloured SVG moving as the prompt says
// (engine/src/procedural): the parts get names and a rig (part_rig.h), the prompt's verbs, part
// nouns and modifiers become a motion plan (prompt_parse.h, motion_plan.h), or
// stages.video.options.motion gives the plan outright ("flap:wing*, bob:root"), or
// stages.video.options.planner: llm asks a vision chat model for one in that syntax
// (llm_planner.h; on any failure the offline planner, and one warning saying why). Each candidate
// is rendered as raster frames with a colour drift, blur and H.264 compression; candidate i uses
// seed + i, which varies the amplitudes and, where the prompt leaves a choice, the side.
// motion.json in the run directory reports the parts and the plan; one line says it on the
// terminal. Under the pixel ranker each candidate is scored as the ranker will score it, and
// one it would flag for continuity or chaotic motion is made again with smaller amplitudes.
#include <algorithm>
#include <chrono>
#include <filesystem>

#include "common/plugin_glue.h"
#include "common/stage_files.h"
#include "plugin/plugin_options.h"
#include "rank/pixel_ranker.h"
#include "svgmotion/atomic_file.h"
#include "svgmotion/error.h"
#include "svgmotion/svg_reader.h"
#include "procedural/eye_cue.h"
#include "procedural/gait_travel.h"
#include "procedural/motion_plan.h"
#include "procedural/procedural_video.h"
#include "svgmotion/utf8_text.h"
#include "llm_planner.h"

namespace {

// The fitter's keyframes when the request does not carry them (configs/default.yaml).
constexpr int kDefaultKeyframes = 15;
// A candidate the pixel ranker would flag is made again at 0.8 of its amplitudes, at most this
// many times (0.8^4: 41 %).
constexpr int kSelfCheckAttempts = 4;

// The plan on the terminal: its warnings and notes, each part a located part was found at and
// why, and one line of what moves.
void log_plan(const svgm_host* host, const svgm::MotionPlan& plan, const svgm::Rig& rig) {
  if (!host || !host->log) return;
  for (const auto& w : plan.warnings) host->log(host, 2, ("video procedural: " + w).c_str());
  for (const auto& w : plan.notes) host->log(host, 1, ("video procedural: " + w).c_str());
  std::string line;
  for (const auto& a : plan.actions) {
    std::string who = a.target == svgm::Target::Whole ? "whole figure" : a.target == svgm::Target::Repeated
                          ? std::to_string(rig.repeated.size()) + " repeated elements" : "";
    if (a.region != svgm::Region::None) who = "a region of ";
    // A part the rig had none for: where it was found, and why there (part_locator.h).
    if (a.region == svgm::Region::Located) host->log(host, 1, ("video procedural: " + a.why).c_str());
    for (int p : a.parts) who += (who.empty() || a.region != svgm::Region::None ? "" : "+") + rig.parts[p].name;
    line += (line.empty() ? "" : "; ") + a.verb + " " + who;
  }
  host->log(host, 1, ("video procedural: " + line + " (motion.json)").c_str());
}

// The bar's share as the share of the stage's time: the rig and the plan before the first
// candidate take seconds the candidates' count does not measure (at i / n of the count the CLI's
// ETA, time so far / share x share left, read three times the time left). After `made` of `n`
// candidates the rest is those left at the mean time of those made; never going back.
class StageShare {
 public:
  using Clock = std::chrono::steady_clock;
  explicit StageShare(Clock::time_point started) : started_(started), first_(Clock::now()) {}
  double shown() const { return share_; }
  double made(int made, int n) {
    const double so_far = seconds(started_), left = (n - made) * seconds(first_) / std::max(made, 1);
    share_ = std::max(share_, made >= n ? 1.0 : so_far / (so_far + left));
    return share_;
  }

 private:
  static double seconds(Clock::time_point from) { return std::chrono::duration<double>(Clock::now() - from).count(); }
  Clock::time_point started_, first_;
  double share_ = 0;
};

// Draws candidate `name` into `file` and, with `ranker` (the pixel ranker's options; null: no
// self check), has the ranker look at it: a candidate it would flag is made again, its turn
// round left out or its amplitudes smaller (kSelfCheckAttempts). Returns its points.
std::vector<svgm::Vec2> checked_candidate(const svgm::Scene& scene, const svgm::Rig& rig, svgm::MotionPlan& plan,
                                          const svgm::ProceduralVideoOptions& o, const std::filesystem::path& file, uint32_t seed,
                                          const char* name, const std::vector<svgm::Rgba>& palette, const svgm::PixelRankOptions* ranker) {
  std::vector<svgm::Vec2> pts;
  for (int attempt = 0;; ++attempt) {
    pts = svgm::animate_plan(scene, rig, plan, o.frames);
    svgm::write_procedural_video(scene, pts, seed, o, file);
    if (!ranker || palette.empty()) break;
    svgm::PixelRankOptions check = *ranker;
    check.keyframes = svgm::frames_to_rank(*ranker, plan.keyframes);
    const svgm::CandidateScore sc = svgm::score_candidate_file(file, palette, check);
    // What a smaller motion cures: parts whose visible area jumps between the ranker's
    // frames (continuity), and chaotic motion. 'No motion' is not cured by less of it.
    std::string why;
    if (sc.continuity.value >= check.defect_threshold) why = "continuity: " + sc.continuity.reason;
    else if (sc.motion.value >= check.defect_threshold && sc.motion.reason.find("chaotic") != std::string::npos)
      why = "chaotic motion: " + sc.motion.reason;
    if (why.empty()) break;
    char line[400];
    // A figure turning round (gait_travel.h) goes edge on: a thin patch of colour (a line
    // drawing's door or window, a few pixels wide) falls to nothing there, and smaller
    // amplitudes do not make a turn wider (an openmoji bus was flagged at 41 %). The turn is left
    // out first: the figure goes the told way facing its own way, as it did before it turned.
    if (why.rfind("continuity", 0) == 0 && svgm::leave_out_turns(plan)) {
      std::snprintf(line, sizeof line, "candidate %s: turning round left out: the pixel ranker saw %s", name, why.c_str());
      plan.notes.push_back(line);
      continue;
    }
    if (attempt == kSelfCheckAttempts) {
      std::snprintf(line, sizeof line, "candidate %s: the pixel ranker still flags it at %.0f %% of its amplitudes (%s)", name,
                    plan.scale * 100, why.c_str());
      plan.warnings.push_back(line);
      break;
    }
    // Whole turns are never scaled: when smaller amplitudes move nothing differently, the
    // candidate made again would be the same one (a spinning dancer was made five times).
    svgm::MotionPlan smaller = plan;
    smaller.scale *= 0.8;
    if (svgm::animate_plan(scene, rig, smaller, o.frames) == pts) {
      std::snprintf(line, sizeof line, "candidate %s: the pixel ranker flags it and smaller amplitudes would not change it (%s)", name,
                    why.c_str());
      plan.warnings.push_back(line);
      break;
    }
    plan.scale *= 0.8;
    std::snprintf(line, sizeof line, "candidate %s: amplitudes scaled to %.0f %%: the pixel ranker saw %s", name, plan.scale * 100,
                  why.c_str());
    plan.notes.push_back(line);
  }
  return pts;
}

nlohmann::json run(const nlohmann::json& req, const svgm_host* host) {
  namespace fs = std::filesystem;
  namespace P = svgm::plugin;
  const nlohmann::json& c = req.at("config");
  if (!c.value("path", std::string()).empty())
    throw svgm::Error("stages.video.path is set but the video plugin is 'procedural'; add "
                      "stages.video.plugin=file to fit your own video");
  const nlohmann::json options = c.contains("options") ? c.at("options") : nlohmann::json();
  const svgm::PluginOptions opt(options, "video procedural", {"motion", "planner", "url", "model", "api_key_env", "timeout_s"});
  const std::string explicit_plan = opt.string("motion", "");
  const std::string planner = opt.string("planner", "offline");
  if (planner != "offline" && planner != "llm") opt.fail("options.planner must be offline or llm, not '" + planner + "'");
  if (planner == "llm" && !explicit_plan.empty())
    opt.fail("options.motion gives the plan and options.planner: llm would ask a model for one; set only one");
  const auto started = std::chrono::steady_clock::now();
  const svgm::Scene scene = svgm::read_svg_file(P::file(req, "inputs", "svg"));
  const nlohmann::json& inputs = req.at("inputs");
  const svgm::SourceNames names =
      inputs.contains("original") ? svgm::read_source_names(P::file(req, "inputs", "original").string()) : svgm::SourceNames{};
  // The grouper's part names where it gave some (grouper llm: "left wing"), from data-name.
  std::vector<std::string> group_names;
  for (const auto& g : scene.groups) group_names.push_back(g.name);
  svgm::Rig rig = svgm::build_rig(scene, names, group_names);
  // A drawn eye shows an animal's head end (eye_cue.h), in the original's colours (not recoloured).
  svgm::apply_eye_cue(rig, scene, inputs.contains("original") ? svgm::read_svg_file(P::file(req, "inputs", "original").string()) : scene);
  const std::string prompt = req.value("prompt", "");
  auto steps = explicit_plan.empty() ? std::vector<svgm::ExplicitStep>{} : svgm::parse_explicit_plan(explicit_plan);
  const svgm::ParsedPrompt parsed = svgm::parse_prompt(prompt);
  // The llm planner's plan stands in for an explicit one; its failure leaves the prompt's.
  svgm::plugin::PlannerOutcome asked;
  if (planner == "llm") {
    if (host && host->progress) host->progress(host, 0, "asking the planner model");
    asked = svgm::plugin::run_llm_planner(options, scene, rig, prompt, static_cast<uint32_t>(req.value("seed", 0)),
                                          req.value("device", "auto"), host);
    if (asked.from_llm) steps = asked.steps;
  }
  int keyframes = kDefaultKeyframes;
  if (req.contains("stages") && req.at("stages").contains("fitter") && req.at("stages").at("fitter").contains("keyframes") &&
      req.at("stages").at("fitter").at("keyframes").is_number_integer())
    keyframes = req.at("stages").at("fitter").at("keyframes").get<int>();

  svgm::ProceduralVideoOptions o;
  o.frames = c.value("frames", 49);
  o.fps = c.value("fps", 24.0);
  o.width = c.value("size", 512);
  o.device = req.value("device", "auto");
  const int n = c.value("candidates", 4);
  const fs::path dir = P::file(req, "outputs", "candidates");
  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::create_directories(dir);
  nlohmann::json made = nlohmann::json::array();
  nlohmann::json report;
  std::string summary;
  // The pixel ranker's view of a candidate (stages.ranker: its analysis size and frames, at
  // least as many as the fitter's keyframes the plan asks for), in the recoloured drawing's
  // colours: generator and ranker agree, or the candidate is made again, smaller.
  const nlohmann::json& stages = req.contains("stages") ? req.at("stages") : nlohmann::json::object();
  const bool self_check = stages.contains("ranker") && stages.at("ranker").value("plugin", "") == "pixel";
  svgm::PixelRankOptions ro;
  if (self_check && stages.at("ranker").contains("options") && stages.at("ranker").at("options").is_object()) {
    const nlohmann::json& ropt = stages.at("ranker").at("options");
    if (ropt.contains("size") && ropt.at("size").is_number_integer()) ro.analysis_width = ropt.at("size").get<int>();
    if (ropt.contains("keyframes") && ropt.at("keyframes").is_number_integer()) ro.keyframes = ropt.at("keyframes").get<int>();
  }
  std::vector<svgm::Rgba> palette;
  for (const svgm::Path& p : scene.paths) {
    if (p.has_fill) palette.push_back(p.fill);
    if (p.has_stroke) palette.push_back(p.stroke.color);
  }
  StageShare share(started);
  for (int i = 0; i < n; ++i) {
    char name[16];
    std::snprintf(name, sizeof name, "%02d", i);
    const uint32_t seed = static_cast<uint32_t>(req.value("seed", 0) + i);
    svgm::MotionPlan plan = steps.empty() ? svgm::plan_from_prompt(parsed, rig, seed) : svgm::plan_from_steps(steps, rig, seed);
    if (asked.from_llm) plan.source = "llm";
    svgm::fit_plan(scene, rig, plan, o.frames, keyframes);
    // Named before it is made: a candidate takes seconds (the first one, 11 s on a loaded
    // machine, was "starting" on the bar until then).
    if (host && host->progress)
      host->progress(host, share.shown(), ("making candidate " + std::string(name)).c_str());
    const std::vector<svgm::Vec2> pts =
        checked_candidate(scene, rig, plan, o, dir / (std::string(name) + ".mp4"), seed, name, palette, self_check ? &ro : nullptr);
    if (i == 0) {
      report = svgm::motion_report(scene, rig, plan);
      report["prompt"] = prompt;
      if (!explicit_plan.empty()) report["explicit_plan"] = explicit_plan;
      if (!asked.record.is_null()) report["planner"] = asked.record;
      summary = plan.summary();
      log_plan(host, plan, rig);
    }
    // Each candidate's rigid bodies and their maps (the fitter warm-starts from the chosen
    // one's: the candidates differ in amplitudes and directions); the paths' travels are the
    // first candidate's.
    std::vector<std::vector<svgm::Affine>> maps;
    const std::vector<svgm::PathMotion> motion = svgm::path_motion(scene, pts, o.frames, &maps);
    nlohmann::json path_body = nlohmann::json::array();
    for (const auto& m : motion) path_body.push_back(m.body);
    if (i == 0) {
      report["canvas"] = {scene.width, scene.height};
      report["paths"] = svgm::path_motion_json(scene, motion);
      report["bodies"] = svgm::body_maps_json(maps);
    }
    made.push_back({{"name", std::string(name) + ".mp4"}, {"seed", seed}, {"amplitude_scale", plan.scale}, {"keyframes", plan.keyframes},
                    {"plan", plan.summary()}, {"path_body", path_body}, {"bodies", svgm::body_maps_json(maps)}});
    if (host && host->progress) host->progress(host, share.made(i + 1, n), name);
  }
  report["candidates"] = made;
  svgm::write_file_atomic(fs::path(req.at("run_dir").get<std::string>()) / "motion.json", svgm::json_text(report, 2) + "\n");
  nlohmann::json r = {{"message", std::to_string(n) + " candidates (" + summary + ")"}, {"candidates", made}};
  // A fallback depends on the network: let the next run ask the model again.
  if (planner == "llm" && !asked.from_llm) r["cache"] = false;
  return r;
}

}  // namespace

SVGM_DEFINE_PLUGIN("video", "procedural", "1", "offline motion from the prompt's words (no model needed)", run)
