// `svgmotion config`: every config key with its default, type and meaning (the
// table comes from configs/default.yaml through pipeline/config_keys.h, the
// schema itself), and with
// --show the merged result of a config file or a built-in config and overrides.
#include <algorithm>
#include <cstdio>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "pipeline/config.h"
#include "pipeline/config_keys.h"
#include "svgmotion/utf8_text.h"

namespace svgm::cli {

int cmd_config(const std::vector<std::string> &argv) {
  const Args a = parse_args("config", argv, {"--show"}, {});
  std::vector<std::string> overrides;
  for (const std::string &p : a.positional) {
    if (p.find('=') == std::string::npos)
      throw UsageError(
          "config: unexpected argument '" + p +
          "' (svgmotion config [--show CONFIG] [key.path=value ...])");
    overrides.push_back(p);
  }
  if (a.has("--show") || !overrides.empty()) {
    ConfigOrigins origins;
    const auto file = a.get("--show");
    const nlohmann::json config = load_config(
        file && !file->empty() ? std::optional<std::filesystem::path>(*file)
                               : std::nullopt,
        overrides, &origins);
    std::fputs(config_yaml(config, origins).c_str(), stdout);
    return 0;
  }
  const std::vector<ConfigKey> &keys = config_keys();
  size_t wk = 3, wv = 7;
  std::vector<std::string> values;
  for (const ConfigKey &k : keys) {
    values.push_back(json_text(k.value));
    wk = std::max(wk, k.path.size());
    wv = std::min<size_t>(std::max(wv, values.back().size()), 12);
  }
  std::printf("%-*s  %-*s  %-7s  %s\n", static_cast<int>(wk), "key",
              static_cast<int>(wv), "default", "type", "meaning");
  for (size_t i = 0; i < keys.size(); ++i)
    std::printf("%-*s  %-*s  %-7s  %s\n", static_cast<int>(wk),
                keys[i].path.c_str(), static_cast<int>(wv), values[i].c_str(),
                keys[i].type.c_str(), keys[i].meaning.c_str());
  return 0;
}

} // namespace svgm::cli
