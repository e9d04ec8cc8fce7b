// A small command-line parser for the svgmotion subcommands: positionals, --flag, --key value
// and --key=value, with an error for unknown options that names the subcommand.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace svgm::cli {

struct Args {
  std::vector<std::string> positional;
  std::map<std::string, std::string> options;  // "--size" -> "256"; flags map to ""

  bool has(const std::string& key) const { return options.count(key) != 0; }
  std::optional<std::string> get(const std::string& key) const;
  // The integer value of an option, `fallback` when absent; Error if not an integer in range.
  int get_int(const std::string& key, int fallback, int lo, int hi) const;
  double get_double(const std::string& key, double fallback) const;
};

// `valued` options take a value, `flags` take none; anything else is an error.
Args parse_args(const std::string& command, const std::vector<std::string>& argv,
                const std::set<std::string>& valued, const std::set<std::string>& flags);

}  // namespace svgm::cli
