// Running an external program without a shell: an argv template filled in from named values,
// and one run with its output captured to a log file and a time limit.
//
// The program is started with posix_spawnp (PATH search for argv[0], no shell, so no word
// splitting, globbing, quoting or `;`: every template element is exactly one argument), in a
// process group of its own, with stdin from /dev/null and stdout + stderr appended to the log.
// When the time limit passes (or the caller cancels) the whole group gets SIGTERM and, 2 s
// later, SIGKILL, so a generator's own children (workers, ffmpeg) go too. Since the group is not
// the terminal's, Ctrl-C would not reach it: while the program runs, SIGINT, SIGTERM and SIGHUP
// (unless ignored) are caught, stop the group like a cancel, and are raised again once the
// host's own handlers are back (so the default action still ends the host afterwards).
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace svgm {

struct CommandResult {
  int status = -1;          // exit status when the program exited by itself, else -1
  bool timed_out = false;   // stopped because the time limit passed
  bool cancelled = false;   // stopped because the caller asked to (or on SIGINT/SIGTERM/SIGHUP)
  bool signalled = false;   // ended by a signal (also set when timed out or cancelled)
  int signal = 0;           // that signal
  std::string spawn_error;  // non-empty when the program could not be started at all
  double seconds = 0;       // wall time from start to reaping
  long peak_rss_kb = 0;     // the program's peak resident memory (with its waited-for children)

  // Exited by itself with status 0.
  bool ok() const { return spawn_error.empty() && !signalled && !timed_out && !cancelled && status == 0; }
};

// Runs argv (argv[0] searched in PATH) with stdout and stderr going to `log` (created or
// truncated; it starts with one "# svgmotion: ..." line naming the command and ends with one
// saying how it ended). `timeout_s` <= 0 means no limit. `cancelled`, when given, is polled
// about every 20 ms; once it returns true the group is stopped as on a timeout. Throws
// svgm::Error only when argv is empty or the log cannot be opened; everything about the program
// itself is in the result.
CommandResult run_command(const std::vector<std::string>& argv, const std::filesystem::path& log,
                          double timeout_s, const std::function<bool()>& cancelled = {});

// Fills in a template: every "{name}" whose name is a key of `values` is replaced by the value,
// in one pass (a value that itself contains "{out}" stays as it is). Elements are never split or
// joined. A "{name}" (a letter or '_', then letters, digits, '_') that is not a key throws
// svgm::Error "unknown placeholder {name} in argv[i] (known: {a}, {b}, ...)"; other braces
// (JSON, "{1}") are literal.
std::vector<std::string> expand_argv(const std::vector<std::string>& argv_template,
                                     const std::map<std::string, std::string>& values);

// Replaces every "{key}" in `text` by `value` (one pass), for templates like the prompt's.
std::string replace_placeholder(const std::string& text, const std::string& key,
                                const std::string& value);

// The status of a finished run in words: "exited with status 3", "was killed by signal 9
// (Killed)", "timed out after 5 s", "was cancelled", "could not be started: <reason>".
std::string describe(const CommandResult& result, double timeout_s);

// A number as a short decimal: 24 -> "24", 0.5 -> "0.5", 23.976 -> "23.976".
std::string short_number(double value);

}  // namespace svgm
