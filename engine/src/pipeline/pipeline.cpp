// The pipeline runner (see pipeline.h).
#include "pipeline/pipeline.h"
#include "fit/output/animation_export.h"
#include "motion/wordnet_pages.h"
#include "pipeline/candidate_choice.h"
#include "pipeline/canvas_room.h"
#include "svgmotion/atomic_file.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "svgmotion/error.h"
#include "svgmotion/log.h"
#include "svgmotion/svg_reader.h"
#include "svgmotion/utf8_text.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

struct Hash {
  uint64_t h = 1469598103934665603ull;
  void add(std::string_view s) {
    for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
    h = (h ^ 0xff) * 1099511628211ull;  // separator, so ("ab","c") != ("a","bc")
  }
  void add_file(const fs::path& p) {
    std::error_code ec;
    if (fs::is_directory(p, ec)) {
      std::vector<fs::path> files;
      for (const auto& e : fs::recursive_directory_iterator(p, ec))
        if (e.is_regular_file()) files.push_back(e.path());
      std::sort(files.begin(), files.end());
      for (const auto& f : files) {
        add(fs::relative(f, p).string());
        add_file(f);
      }
      return;
    }
    std::ifstream in(p, std::ios::binary);
    if (!in) { add("<missing>"); return; }
    char buf[1 << 16];
    while (in.read(buf, sizeof buf) || in.gcount() > 0) add(std::string_view(buf, static_cast<size_t>(in.gcount())));
  }
  std::string hex() const {
    char b[17];
    std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(h));
    return b;
  }
};

void write_atomic(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  write_file_atomic(file, text);
}

// The ranker may flag every candidate (chaotic motion, invented content, ...): fitting one of
// them would hand the user a broken animation, so the run stops here with the reasons, unless
// stages.ranker.accept_flagged is set. Read from ranking.json each run (also when the ranker
// stage was up to date). A ranking without per-candidate "defects" lists flags nothing.
void stop_if_every_candidate_flagged(const fs::path& ranking, const nlohmann::json& config) {
  const nlohmann::json& ranker = config["stages"]["ranker"];
  if (ranker.is_object() && ranker.value("accept_flagged", false)) return;
  std::ifstream in(ranking);
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (!j.is_object() || !j.contains("candidates") || !j["candidates"].is_array() || j["candidates"].empty()) return;
  std::string why;
  for (const auto& c : j["candidates"]) {
    if (!c.is_object() || !c.contains("defects") || !c["defects"].is_array() || c["defects"].empty()) return;
    std::string d;
    for (const auto& x : c["defects"])
      if (x.is_string()) d += (d.empty() ? "" : ", ") + x.get<std::string>();
    why += (why.empty() ? "" : "; ") + c.value("name", std::string("?")) + ": " + d;
  }
  throw Rejected("every candidate video was flagged by the ranker (" + why + "; see " + ranking.string() +
                     "); stopped before fitting. Try another prompt or seed, or set "
                     "stages.ranker.accept_flagged=true to fit the best one anyway",
                 Rejected::kCandidatesFlagged);
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return in ? s.str() : std::string("<missing>");
}

// The input as the stages read it: the user's file, or, when stages.video.room asks for it
// (canvas_room.h), the same document with room around the figure, said once on the terminal.
std::string staged_input(const nlohmann::json& config, const std::string& input) {
  std::string text = read_text(input);
  const nlohmann::json& video = config["stages"]["video"];
  const nlohmann::json room = video.value("room", nlohmann::json("auto"));
  double share = 0;
  char why[160] = "";
  // Parsed only when room may be given (the grouper parses it anyway).
  const bool maybe = room.is_number() ? room.get<double>() > 0 : room == "auto" && video.value("plugin", "") == "procedural";
  if (!maybe) return text;
  const Scene scene = read_svg_string(text, shown_path(input));
  if (room.is_number()) {
    share = room.get<double>();
    std::snprintf(why, sizeof why, "stages.video.room is %g", share);
  } else {
    share = auto_room(scene, config.value("prompt", std::string()), why, sizeof why);
  }
  if (share <= 0) return text;
  log::info("%s: %s: its canvas grows by %.0f %% on each side so the motion stays in view "
            "(stages.video.room=0 keeps the canvas as it is)", shown_path(input).c_str(), why, 100 * share);
  return give_canvas_room(text, shown_path(input), scene, share);
}

}  // namespace

std::vector<StageReport> run_pipeline(const nlohmann::json& config, const PluginHost& host,
                                      const std::optional<std::string>& from,
                                      const std::function<void(const std::string&)>& on_stage) {
  const std::string input = config.value("input", "");
  if (input.empty()) throw Error("no input SVG (set input: in the config or pass --input)");
  if (!fs::is_regular_file(input)) throw Error(input + ": cannot open: No such file or directory");
  if (from) {
    const auto& st = stage_names();
    if (std::find(st.begin(), st.end(), *from) == st.end())
      throw Error("--from " + *from + ": no such stage (stages: grouper, recolorer, video, ranker, layers, tracker, fitter)");
  }
  const fs::path run = fs::absolute(config.value("output", "run"));
  std::error_code ec;
  // The input is copied into the run directory, so the run is self-contained (given room to
  // move when it fills its canvas: canvas_room.h); the copy only changes (and invalidates later
  // stages) when its content does.
  {
    const std::string staged = staged_input(config, input);
    Hash a, b;
    a.add(staged);
    b.add(read_text(run / "input.svg"));
    if (a.h != b.h) write_file_atomic(run / "input.svg", staged);
  }
  bool forced = false;
  std::vector<StageReport> reports;
  for (const StageFiles& sf : stage_files()) {
    const nlohmann::json& section = config["stages"][sf.stage];
    const std::string plugin = section.value("plugin", "");
    if (from && *from == sf.stage) forced = true;
    const PluginInfo* info = host.find(sf.stage, plugin);
    Hash h;
    h.add(plugin);
    h.add(info ? info->version : "?");
    if (info) {  // a rebuilt or upgraded plugin module runs again
      std::error_code fe;
      h.add(std::to_string(fs::file_size(info->path, fe)));
      h.add(std::to_string(fs::last_write_time(info->path, fe).time_since_epoch().count()));
    }
    // A hand-chosen candidate is applied by the pipeline after the ranker (candidate_choice.h),
    // so choosing another one does not ask the ranker again.
    nlohmann::json hashed = section;
    if (sf.stage == "ranker" && hashed.is_object()) hashed.erase("choose");
    // The fitter's export settings change how the fit is written, not the fit: a change is
    // re-exported from its checkpoint (fit/output/animation_export.h) instead of refitting.
    nlohmann::json export_keys = nlohmann::json::object();
    if (sf.stage == "fitter" && hashed.is_object())
      for (const char* k : {"precision", "inbetweens", "compact"})
        if (hashed.contains(k)) {
          export_keys[k] = hashed[k];
          hashed.erase(k);
        }
    h.add(json_text(hashed));
    h.add(config.value("prompt", ""));
    h.add(std::to_string(config.value("seed", 0)));
    for (const auto& [k, v] : sf.inputs.items()) {
      h.add(k);
      h.add_file(run / v.get<std::string>());
    }
    const fs::path manifest = run / ".svgmotion" / (sf.stage + ".json");
    bool up_to_date = !forced && fs::exists(manifest);
    if (up_to_date) {
      std::ifstream m(manifest);
      nlohmann::json mj = nlohmann::json::parse(m, nullptr, false);
      up_to_date = mj.is_object() && mj.value("hash", "") == h.hex();
      for (const auto& [k, v] : sf.outputs.items()) up_to_date = up_to_date && fs::exists(run / v.get<std::string>());
    }
    if (up_to_date && sf.stage == "fitter") {
      std::ifstream m(manifest);
      const nlohmann::json mj = nlohmann::json::parse(m, nullptr, false);
      if (mj.is_object() && mj.value("export", nlohmann::json()) != export_keys) {
        ExportSettings es;
        es.compact = section.value("compact", true);
        if (section.contains("precision") && section["precision"].is_number_integer()) es.decimals = section["precision"].get<int>();
        es.inbetweens = section.value("inbetweens", es.inbetweens);
        try {
          export_fit_directory(run, run, es, /*lock=*/false);
          nlohmann::json updated = mj;
          updated["export"] = export_keys;
          write_atomic(manifest, json_text(updated, 2) + "\n");
          log::info("fitter: export settings changed; re-exported from checkpoint.bin without fitting");
        } catch (const Error& e) {
          log::debug("fitter: re-export failed (%s); fitting again", e.what());
          up_to_date = false;
        }
      }
    }
    StageReport r{sf.stage, plugin, up_to_date, 0};
    log::debug("%s: plugin %s (%s), inputs %s, key %s: %s", sf.stage.c_str(), plugin.c_str(),
               info ? info->path.c_str() : "not found", json_text(sf.inputs).c_str(), h.hex().c_str(),
               up_to_date ? "up to date" : forced ? "forced by --from" : "runs");
    if (!up_to_date) {
      if (on_stage) on_stage(sf.stage + " (" + plugin + ")");
      const auto t0 = std::chrono::steady_clock::now();
      nlohmann::json req = {{"abi", SVGM_PLUGIN_ABI}, {"stage", sf.stage},       {"run_dir", run.string()},
                            {"inputs", sf.inputs},    {"outputs", sf.outputs},   {"config", section},
                            {"prompt", config.value("prompt", "")}, {"seed", config.value("seed", 0)},
                            {"device", config.value("device", "auto")}, {"input", input},
                            {"stages", config["stages"]}};  // every stage's settings, read-only
      // The fitter reads no words: WordNet's pages, mapped by the prompt's stages, leave the
      // resident set before its peak (issue 38; a later lookup reads them again).
      if (sf.stage == "fitter") wordnet::release_shared_pages();
      const nlohmann::json response = host.run(sf.stage, plugin, req);
      for (const auto& [k, v] : sf.outputs.items())
        if (!fs::exists(run / v.get<std::string>()))
          throw Error(sf.stage + " plugin '" + plugin + "' did not write its output " + v.get<std::string>());
      r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      log::debug("%s: done in %.2f s, wrote %s; the plugin answered %s", sf.stage.c_str(), r.seconds,
                 json_text(sf.outputs).c_str(), json_text(response).c_str());
      // A plugin answering "cache": false (say, a network fallback) is asked again next run.
      if (response.value("cache", true))
        write_atomic(manifest, json_text(nlohmann::json{{"stage", sf.stage}, {"plugin", plugin}, {"hash", h.hex()},
                                                        {"seconds", r.seconds}, {"export", export_keys}}, 2) + "\n");
      else
        fs::remove(manifest, ec);
    }
    reports.push_back(r);
    if (sf.stage == "ranker") {
      // A candidate chosen by hand is fitted even when the ranker flagged it: the user saw it.
      const std::string choose = section.is_object() && section.contains("choose") && section["choose"].is_string()
                                     ? section["choose"].get<std::string>()
                                     : "";
      apply_candidate_choice(run, choose);
      if (choose.empty()) stop_if_every_candidate_flagged(run / "ranking.json", config);
    }
  }
  return reports;
}

}  // namespace svgm
