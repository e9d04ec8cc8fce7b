// `svgmotion run`: the whole method in one command, each stage through its plugin, in a run
// directory that keeps every intermediate and skips what is up to date.
//
// Every setting is checked before the first stage (pipeline/config_check.h). Values given as
// options (--input, --prompt, -o, --device) are set as plain strings, never pasted into YAML,
// so quotes and backslashes in a prompt or path reach the stages as typed. Plugins' progress
// is drawn as a bar on a terminal and as a line every few seconds otherwise; Ctrl-C asks the
// running stage to stop (the fitter writes its state so far and resumes on the next run), then
// one line says what the run directory holds.
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "pipeline/config.h"
#include "pipeline/config_check.h"
#include "pipeline/pipeline.h"
#include "pipeline/plugin_host.h"
#include "pipeline/run_directory.h"
#include "report/rerun_command.h"
#include "svgmotion/error.h"
#include "svgmotion/log.h"
#include "svgmotion/utf8_text.h"

namespace svgm::cli {

namespace fs = std::filesystem;

namespace {

// The signal that stopped the run (SIGINT from Ctrl-C, SIGTERM from kill or a scheduler's
// time limit, SIGHUP from a closed terminal): each stops the running stage the same way.
volatile std::sig_atomic_t g_interrupted = 0;
extern "C" void on_run_signal(int sig) {
  g_interrupted = sig;
  std::signal(sig, SIG_DFL);  // a second one stops at once
}
constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGHUP};
void catch_stop_signals(bool on) {
  for (int sig : kStopSignals) std::signal(sig, on ? on_run_signal : SIG_DFL);
}
// "interrupted" after Ctrl-C, "interrupted (SIGTERM)" after the others.
const char* stopped_by(int sig) {
  return sig == SIGTERM ? "interrupted (SIGTERM)" : sig == SIGHUP ? "interrupted (SIGHUP)" : "interrupted";
}

bool looks_like_key(const std::string& s) {
  if (s.find('.') == std::string::npos || s.ends_with(".yaml") || s.ends_with(".yml")) return false;
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.')) return false;
  return true;
}

// Progress of the running stage: a bar redrawn in place on a terminal, a line every 5 s in a log.
class ProgressView {
 public:
  explicit ProgressView(bool quiet) : quiet_(quiet), tty_(::isatty(2) != 0) {}
  void stage(const std::string& name) {
    end_line();
    stage_ = name;
    last_ = std::chrono::steady_clock::now();
    log::info("run: %s ...", name.c_str());
  }
  void update(double f, const std::string& note) {
    if (quiet_) return;
    const auto now = std::chrono::steady_clock::now();
    f = std::clamp(f, 0.0, 1.0);
    if (tty_) {
      if (now - last_ < std::chrono::milliseconds(200) && f < 1) return;
      constexpr int kWidth = 24;
      const int filled = static_cast<int>(f * kWidth + 0.5);
      std::fprintf(stderr, "\r  [%.*s%*s] %3.0f%%  %-60.60s", filled, "########################",
                   kWidth - filled, "", 100 * f, note.c_str());
      drawn_ = true;
    } else {
      if (now - last_ < std::chrono::seconds(5)) return;
      log::info("run: %s %3.0f%%  %s", stage_.c_str(), 100 * f, note.c_str());
    }
    last_ = now;
  }
  // A stage's one-line report (what the procedural video moves): an info line.
  void info(const std::string& line) {
    if (!quiet_) end_line();
    log::info("  %s", line.c_str());
  }
  void end_line() {
    if (drawn_) std::fputc('\n', stderr);
    drawn_ = false;
  }

 private:
  bool quiet_, tty_, drawn_ = false;
  std::string stage_;
  std::chrono::steady_clock::time_point last_;
};

// What the run directory holds now, for the line after a stop.
std::string outputs_in(const fs::path& dir) {
  std::string list;
  for (const char* f : {"grouped.svg", "recolored.png", "candidates", "target.mp4", "layered.svg", "tracks.json",
                        "animation.svg", "animation.failed.svg", "preview.mp4", "fit.json", "checkpoint.bin"}) {
    std::error_code ec;
    if (fs::exists(dir / f, ec)) list += (list.empty() ? "" : ", ") + std::string(f);
  }
  return list.empty() ? "nothing yet" : list;
}

}  // namespace

int cmd_run(const std::vector<std::string>& argv) {
  const Args a = parse_args("run", argv, {"--input", "--prompt", "-o", "--output", "--from", "--device"},
                            {"--force"});
  // Positionals: an optional CONFIG.yaml first, then key.path=value overrides.
  std::optional<fs::path> file;
  std::vector<std::string> overrides;
  for (const std::string& p : a.positional) {
    if (p.find('=') != std::string::npos) {
      overrides.push_back(p);
    } else if (!file) {
      std::error_code ec;
      if (!fs::exists(p, ec) && looks_like_key(p))
        throw Error("run: '" + p + "' is not a config file; a setting needs a value: " + p + "=VALUE");
      if (fs::is_directory(p, ec)) throw Error(p + ": is a folder, not a config file");
      file = p;
    } else {
      throw UsageError("run: unexpected argument '" + p + "' (one config file, then key.path=value)");
    }
  }
  ConfigOrigins origins;
  nlohmann::json config = load_config(file, overrides, &origins);
  // The options win over the file and overrides; their values name themselves in any error.
  const auto option = [&](const char* key, std::optional<std::string> v) {
    if (!v) return;
    config[key] = *v;
    origins.erase(key);
  };
  option("input", a.get("--input"));
  option("prompt", a.get("--prompt"));
  option("output", a.get("-o") ? a.get("-o") : a.get("--output"));
  option("device", a.get("--device"));
  if (const auto from = a.get("--from")) {
    const auto& st = stage_names();
    if (std::find(st.begin(), st.end(), *from) == st.end())
      throw Error("--from " + *from + ": no such stage (stages: grouper, recolorer, video, ranker, layers, tracker, fitter)");
  }
  std::vector<fs::path> extra;
  if (config.contains("plugin_paths") && !config["plugin_paths"].is_null()) {
    const nlohmann::json& paths = config["plugin_paths"];
    const auto wrong = [&](const std::string& what) {
      const std::string origin = origin_of_message(origins, "plugin_paths: ");
      throw Error((origin.empty() ? std::string() : origin + ": ") + "plugin_paths: " + what);
    };
    if (!paths.is_array()) wrong("must be a list of folders (strings), not " + json_text(paths));
    for (const auto& p : paths) {
      if (!p.is_string()) wrong("must be a list of folders (strings); " + json_text(p) + " is not a string");
      extra.push_back(p.get<std::string>());
    }
  }
  PluginHost host(plugin_search_path(extra));
  try {
    check_config(config, host);
  } catch (const Error& e) {
    // "stages.fitter.iterations: must be ..." becomes "my.yaml:4: stages.fitter.iterations: ...".
    const std::string origin = origin_of_message(origins, e.what());
    if (origin.empty()) throw;
    throw Error(origin + ": " + e.what());
  }

  ProgressView view(log::quiet());
  host.set_hooks({[&view](double f, const std::string& note) { view.update(f, note); },
                  [] { return g_interrupted != 0; },
                  [&view](const std::string& line) { view.info(line); }});
  const fs::path dir = fs::absolute(config.value("output", "run"));
  // A folder of the user's is never taken over (run_directory.h); one run at a time.
  const RunLock lock(dir, a.has("--force"), run_output_names());
  // Every message of this run at debug level, appended to RUN_DIR/log.txt (svgmotion/log.h).
  log::open_file(dir / "log.txt");
  g_interrupted = 0;
  catch_stop_signals(true);
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<StageReport> reports;
  // The command (for report.html's "use this one") and the page, after a finished run and
  // after one stopped for a reason the page shows (a rejected fit, flagged candidates).
  bool report_written = false;
  auto report = [&] {
    try {
      record_run_command(dir, argv, config.value("prompt", ""));
    } catch (const Error& e) {
      std::fprintf(stderr, "svgmotion: warning: %s\n", e.what());
    }
    report_written = write_run_report(dir, config.value("device", "auto"), true);
  };
  try {
    reports = run_pipeline(config, host, a.get("--from"), [&](const std::string& stage) { view.stage(stage); });
    view.end_line();
  } catch (const Rejected&) {
    view.end_line();
    catch_stop_signals(false);
    report();
    throw;
  } catch (const Error&) {
    view.end_line();
    catch_stop_signals(false);
    if (g_interrupted) {
      log::error("%s; %s holds %s (run the same command again to continue)", stopped_by(g_interrupted),
                 dir.c_str(), outputs_in(dir).c_str());
      return 130;
    }
    throw;
  }
  // The handler stays while the page is written (a few seconds): a Ctrl-C then says what the
  // run holds, as one during the stages does, instead of killing the process without a word.
  report();
  catch_stop_signals(false);
  if (g_interrupted) {
    log::error("%s; %s holds %s (run the same command again to continue)", stopped_by(g_interrupted),
               dir.c_str(), outputs_in(dir).c_str());
    return 130;
  }
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  bool all_skipped = true;
  for (const auto& r : reports) {
    all_skipped = all_skipped && r.skipped;
    if (r.skipped) std::printf("  %-9s %-12s up to date\n", r.stage.c_str(), r.plugin.c_str());
    else std::printf("  %-9s %-12s %6.1f s\n", r.stage.c_str(), r.plugin.c_str(), r.seconds);
    log::debug("run: %s (%s) %s", r.stage.c_str(), r.plugin.c_str(),
               r.skipped ? "up to date" : (std::to_string(r.seconds) + " s").c_str());
  }
  if (all_skipped) std::printf("every stage is up to date\n");
  std::printf("outputs in %s: animation.svg, preview.mp4, fit.json%s (total %.1f s)\n", shown_path(dir).c_str(),
              report_written ? ", report.html" : "", total);
  return 0;
}

int cmd_plugins(const std::vector<std::string>& argv) {
  parse_args("plugins", argv, {}, {});
  const PluginHost host(plugin_search_path({}));
  for (const std::string& stage : stage_names())
    for (const PluginInfo& p : host.plugins())
      if (p.stage == stage)
        std::printf("%-9s %-12s %-6s %s\n", p.stage.c_str(), p.name.c_str(), p.version.c_str(), p.path.c_str());
  for (const std::string& problem : host.problems()) std::printf("refused: %s\n", problem.c_str());
  return 0;
}

}  // namespace svgm::cli
