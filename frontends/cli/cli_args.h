// A small command-line parser for the svgmotion subcommands: positionals, --flag, --key value
// and --key=value, with an error for unknown options that names the subcommand.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "svgmotion/error.h"

namespace svgm::cli {

// A usage mistake on the command line (an unknown option, an option without its value, a
// missing argument): main() exits with status 2 for it (README "Exit statuses"), not 1.
class UsageError : public Error {
 public:
  explicit UsageError(const std::string& message) : Error(message) {}
};

struct Args {
  std::vector<std::string> positional;
  std::map<std::string, std::string> options;  // "--size" -> "256"; flags map to ""

  bool has(const std::string& key) const { return options.count(key) != 0; }
  std::optional<std::string> get(const std::string& key) const;
  // The integer value of an option, `fallback` when absent; Error if not an integer in range.
  int get_int(const std::string& key, int fallback, int lo, int hi) const;
  double get_double(const std::string& key, double fallback) const;
};

// `valued` options take a value, `flags` take none; anything else is an error (UsageError).
// The global message levels (--quiet/-q, -qq, --verbose/-v) are taken wherever they stand as
// options of their own, never as another option's value (`--prompt -q` is a prompt).
Args parse_args(const std::string& command, const std::vector<std::string>& argv,
                const std::set<std::string>& valued, const std::set<std::string>& flags);

// Adds --quiet / --verbose counts (from before the command, or from parse_args) and sets the
// console level (svgmotion/log.h); both at once is a UsageError.
void add_log_flags(int quiet, int verbose);
// Whether `arg` is one of those flags; adds its counts to `quiet` and `verbose`.
bool is_log_flag(const std::string& arg, int& quiet, int& verbose);

}  // namespace svgm::cli
