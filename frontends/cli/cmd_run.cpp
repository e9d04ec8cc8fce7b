// `svgmotion run`: the whole method in one command, each stage through its plugin, in a run
// directory that keeps every intermediate and skips what is up to date.
//
// Every setting is checked before the first stage (pipeline/config_check.h). Values given as
// options (--input, --prompt, -o, --device) are set as plain strings, never pasted into YAML,
// so quotes and backslashes in a prompt or path reach the stages as typed. Plugins' progress
// is drawn as a bar on a terminal and as a line every few seconds otherwise; Ctrl-C asks the
// running stage to stop (the fitter writes its state so far and resumes on the next run), then
// one line says what the run directory holds.
#include <sys/ioctl.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "pipeline/config.h"
#include "pipeline/config_check.h"
#include "pipeline/config_keys.h"
#include "pipeline/pipeline.h"
#include "pipeline/plugin_host.h"
#include "run/run_directory.h"
#include "report/rerun_command.h"
#include "svgmotion/atomic_file.h"
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

// Whether a positional of `run` is the SVG to animate: by its extension, else (a file without
// .yaml/.yml) by its content, whose first character past spaces and a BOM is '<'.
bool is_svg_argument(const std::string& p) {
  std::string ext = fs::path(p).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".svg") return true;
  if (ext == ".yaml" || ext == ".yml") return false;
  std::error_code ec;
  if (!fs::is_regular_file(p, ec)) return false;
  std::FILE* f = std::fopen(p.c_str(), "rb");
  if (!f) return false;
  char head[64] = {};
  const size_t n = std::fread(head, 1, sizeof head, f);
  std::fclose(f);
  std::string_view h(head, n);
  if (h.starts_with("\xEF\xBB\xBF")) h.remove_prefix(3);
  while (!h.empty() && std::isspace(static_cast<unsigned char>(h.front()))) h.remove_prefix(1);
  return !h.empty() && h.front() == '<';
}

bool looks_like_key(const std::string& s) {
  if (s.find('.') == std::string::npos || s.ends_with(".yaml") || s.ends_with(".yml")) return false;
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.')) return false;
  return true;
}

// Progress of the running stage: a bar redrawn in place on a terminal, a line every 5 s in a
// log. One bar per stage, which only moves forward (a plugin's fraction below one it reported
// is held) and shows 100 % when the stage has ended; the ETA is the bar's own pace since the
// stage started: a plugin's fraction is a share of the stage's time, its setup included (the
// fitter's is, fit_progress.h; a pace counted from the bar's first move read the fitter's 30 s
// of setup as progress it never made, issue 37). On a terminal the
// line is cut to its width (TIOCGWINSZ, else $COLUMNS, else 80): a line longer than the
// terminal wraps, and "\r" then returns to the wrapped part, so each redraw scrolled a new line.
class ProgressView {
 public:
  explicit ProgressView(bool quiet) : quiet_(quiet), tty_(::isatty(2) != 0) {}
  void stage(const std::string& name) {
    finish();
    stage_ = name;
    running_ = true;
    shown_ = 0;
    note_.clear();
    drawn_note_.clear();
    start_ = last_ = std::chrono::steady_clock::now();
    log::info("run: %s ...", name.c_str());
    if (!quiet_ && tty_) {  // the bar from the start: a stage's setup may take a while before it reports
      note_ = "starting";
      draw("");
    }
  }
  void update(double f, const std::string& note) {
    if (quiet_ || !running_) return;
    const auto now = std::chrono::steady_clock::now();
    f = std::clamp(std::isfinite(f) ? f : 0.0, 0.0, 1.0);
    if (f < shown_) f = shown_;  // never back
    shown_ = f;
    note_ = note;
    const bool due = now - last_ >= (tty_ ? std::chrono::milliseconds(200) : std::chrono::milliseconds(5000));
    // On a terminal a new activity ("judging the frames between keyframes" after "fit iteration
    // ...") is drawn at once: it may be the last word for tens of seconds.
    const bool new_activity = tty_ && activity(note) != activity(drawn_note_);
    if (!due && !new_activity && (f < 1 || !tty_)) return;  // in a log, the stage's end says 100 % (finish)
    draw(eta(now));
    drawn_note_ = note;
    last_ = now;
  }
  // The stage ended well: its bar at 100 % with the seconds it took.
  void finish() {
    if (!running_) return;
    running_ = false;
    if (!quiet_) {
      shown_ = 1;
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
      note_ = "done in " + seconds_text(s);
      draw("");
    }
    end_line();
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
  static std::string seconds_text(double s) {
    char buf[32];
    if (s < 90) std::snprintf(buf, sizeof buf, "%.0f s", s);
    else if (s < 5400) std::snprintf(buf, sizeof buf, "%.0f min", s / 60);
    else std::snprintf(buf, sizeof buf, "%.1f h", s / 3600);
    return buf;
  }
  // "ETA 40 s" once the stage has run for 2 s and its bar has moved by 1 %; "" before.
  std::string eta(std::chrono::steady_clock::time_point now) const {
    if (shown_ >= 1) return "";
    const double t = std::chrono::duration<double>(now - start_).count();
    if (t < 2 || shown_ < 0.01) return "";
    return "ETA " + seconds_text(t / shown_ * (1 - shown_));
  }
  // What a note says the stage is doing: its words before the first number ("fit iteration").
  static std::string activity(const std::string& note) {
    const size_t n = note.find_first_of("0123456789");
    return note.substr(0, n == std::string::npos ? note.size() : n);
  }
  static int columns() {
    winsize ws{};
    if (::ioctl(2, TIOCGWINSZ, &ws) == 0 && ws.ws_col > 0) return ws.ws_col;
    if (const char* c = std::getenv("COLUMNS"); c && std::atoi(c) > 0) return std::atoi(c);
    return 80;
  }
  void draw(const std::string& eta) {
    constexpr int kWidth = 20;
    const int filled = static_cast<int>(shown_ * kWidth);
    const std::string pct = std::to_string(static_cast<int>(100 * shown_)) + "%";  // 99.7 % is not 100 %
    if (!tty_) {
      log::info("run: %s %s%s%s  %s", stage_.c_str(), pct.c_str(), eta.empty() ? "" : "  ", eta.c_str(), note_.c_str());
      return;
    }
    std::string line = "  [" + std::string(static_cast<size_t>(filled), '#') + std::string(static_cast<size_t>(kWidth - filled), ' ') +
                       "] " + std::string(4 - std::min<size_t>(4, pct.size()), ' ') + pct + "  " + (eta.empty() ? "" : eta + "  ") + note_;
    // Cut to the terminal's width less one column (writing the last column wraps on some
    // terminals), counting UTF-8 characters, never splitting one; control characters go.
    const size_t max = static_cast<size_t>(std::max(10, columns() - 1));
    std::string cut;
    size_t chars = 0;
    for (size_t i = 0; i < line.size(); ++i) {
      const auto c = static_cast<unsigned char>(line[i]);
      if ((c & 0xC0) == 0x80) {  // a continuation byte belongs to the character before
        if (chars <= max) cut += line[i];
        continue;
      }
      if (c < 0x20 || c == 0x7f) continue;
      if (++chars > max) break;
      cut += line[i];
    }
    std::fprintf(stderr, "\r%s\x1b[K", cut.c_str());  // ESC[K: clear what the longer line before left
    std::fflush(stderr);
    drawn_ = true;
  }

  bool quiet_, tty_, drawn_ = false, running_ = false;
  double shown_ = 0;
  std::string stage_, note_, drawn_note_;
  std::chrono::steady_clock::time_point start_, last_;
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
  // Positionals: an SVG and its prompt, a CONFIG.yaml (or a built-in config's name), and
  // key.path=value overrides.
  std::optional<fs::path> file;
  std::optional<std::string> svg, prompt;
  std::vector<std::string> overrides;
  for (const std::string& p : a.positional) {
    // Right after a positional SVG, a word that is not a setting or a file is its prompt.
    const std::string lhs = p.substr(0, p.find('='));
    const bool setting = p.find('=') != std::string::npos && !lhs.empty() &&
                         std::all_of(lhs.begin(), lhs.end(), [](unsigned char c) { return std::isalnum(c) || c == '_' || c == '.'; });
    std::error_code ec;
    if (svg && !prompt && !setting && !fs::exists(p, ec) && !p.ends_with(".yaml") && !p.ends_with(".yml") &&
        !builtin_config(p)) {
      prompt = p;
    } else if (p.find('=') != std::string::npos) {
      overrides.push_back(p);
    } else if (!svg && is_svg_argument(p)) {
      svg = p;
    } else if (!file) {
      if (!fs::exists(p, ec) && looks_like_key(p) && !builtin_config(p))
        throw Error("run: '" + p + "' is not a config file; a setting needs a value: " + p + "=VALUE");
      if (fs::is_directory(p, ec)) throw Error(p + ": is a folder, not a config file");
      file = p;
    } else {
      throw UsageError("run: unexpected argument '" + p + "' (X.svg \"PROMPT\", one config file, then key.path=value)");
    }
  }
  if (svg && a.get("--input")) throw UsageError("run: the SVG is given twice (" + *svg + " and --input)");
  if (prompt && a.get("--prompt")) throw UsageError("run: the prompt is given twice (\"" + *prompt + "\" and --prompt)");
  ConfigOrigins origins;
  nlohmann::json config = load_config(file, overrides, &origins);
  // The options win over the file and overrides; their values name themselves in any error.
  const auto option = [&](const char* key, std::optional<std::string> v) {
    if (!v) return;
    config[key] = *v;
    origins.erase(key);
  };
  option("input", svg ? svg : a.get("--input"));
  option("prompt", prompt ? prompt : a.get("--prompt"));
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
  // The config the stages run with, every key, as YAML `run` takes back (`svgmotion run
  // RUN/resolved.yaml`); a setting that is not a default names its origin.
  write_file_atomic(dir / "resolved.yaml",
                    "# The merged config of this run (svgmotion " SVGM_VERSION "): defaults, config file, overrides, options.\n" +
                        config_yaml(config, origins));
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
    view.finish();
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
