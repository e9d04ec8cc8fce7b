// Command-line parsing for the subcommands (see cli_args.h).
#include "cli/cli_args.h"

#include <charconv>

#include "svgmotion/error.h"
#include "svgmotion/log.h"

namespace svgm::cli {

std::optional<std::string> Args::get(const std::string& key) const {
  auto it = options.find(key);
  if (it == options.end()) return std::nullopt;
  return it->second;
}

int Args::get_int(const std::string& key, int fallback, int lo, int hi) const {
  auto v = get(key);
  if (!v) return fallback;
  int out = 0;
  auto [p, ec] = std::from_chars(v->data(), v->data() + v->size(), out);
  if (ec != std::errc() || p != v->data() + v->size() || out < lo || out > hi)
    throw Error(key + " wants an integer in " + std::to_string(lo) + ".." + std::to_string(hi) +
                ", got '" + *v + "'");
  return out;
}

double Args::get_double(const std::string& key, double fallback) const {
  auto v = get(key);
  if (!v) return fallback;
  double out = 0;
  auto [p, ec] = std::from_chars(v->data(), v->data() + v->size(), out);
  if (ec != std::errc() || p != v->data() + v->size())
    throw Error(key + " wants a number, got '" + *v + "'");
  return out;
}

bool is_log_flag(const std::string& arg, int& quiet, int& verbose) {
  if (arg == "--quiet" || arg == "-q") ++quiet;
  else if (arg == "-qq") quiet += 2;
  else if (arg == "--verbose" || arg == "-v") ++verbose;
  else return false;
  return true;
}

void add_log_flags(int quiet, int verbose) {
  static int q = 0, v = 0;
  q += quiet;
  v += verbose;
  if (q && v) throw UsageError("--quiet and --verbose contradict each other");
  log::set_console_level(v ? log::Level::Debug : q >= 2 ? log::Level::Error : q ? log::Level::Warning : log::Level::Info);
}

Args parse_args(const std::string& command, const std::vector<std::string>& argv,
                const std::set<std::string>& valued, const std::set<std::string>& flags) {
  Args a;
  int quiet = 0, verbose = 0;
  for (size_t i = 0; i < argv.size(); ++i) {
    std::string s = argv[i];
    if (is_log_flag(s, quiet, verbose)) continue;
    if (s.size() > 1 && s[0] == '-' && s != "-") {
      std::string key = s, value;
      bool has_value = false;
      if (auto eq = s.find('='); eq != std::string::npos) {
        key = s.substr(0, eq);
        value = s.substr(eq + 1);
        has_value = true;
      }
      if (valued.count(key)) {
        if (!has_value) {
          if (i + 1 >= argv.size()) throw UsageError(command + ": " + key + " needs a value");
          value = argv[++i];
        }
        a.options[key] = value;
      } else if (flags.count(key) && !has_value) {
        a.options[key] = "";
      } else {
        throw UsageError(command + ": unknown option " + key + " (see svgmotion help)");
      }
    } else {
      a.positional.push_back(s);
    }
  }
  if (quiet || verbose) add_log_flags(quiet, verbose);
  return a;
}

}  // namespace svgm::cli
