// `svgmotion run`: the whole method in one command, each stage through its plugin, in a run
// directory that keeps every intermediate and skips what is up to date.
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "pipeline/config.h"
#include "pipeline/pipeline.h"
#include "pipeline/plugin_host.h"
#include "svgmotion/error.h"

namespace svgm::cli {

int cmd_run(const std::vector<std::string>& argv) {
  const Args a = parse_args("run", argv, {"--input", "--prompt", "-o", "--output", "--from", "--device"},
                            {"--quiet"});
  // Positionals: an optional CONFIG.yaml first, then key.path=value overrides.
  std::optional<std::filesystem::path> file;
  std::vector<std::string> overrides;
  for (const std::string& p : a.positional) {
    if (p.find('=') != std::string::npos) overrides.push_back(p);
    else if (!file) file = p;
    else throw Error("run: unexpected argument '" + p + "' (one config file, then key.path=value)");
  }
  if (const auto v = a.get("--input")) overrides.push_back("input=\"" + *v + "\"");
  if (const auto v = a.get("--prompt")) overrides.push_back("prompt=\"" + *v + "\"");
  if (const auto v = a.get("-o") ? a.get("-o") : a.get("--output")) overrides.push_back("output=\"" + *v + "\"");
  if (const auto v = a.get("--device")) overrides.push_back("device=\"" + *v + "\"");
  const nlohmann::json config = load_config(file, overrides);
  std::vector<std::filesystem::path> extra;
  for (const auto& p : config["plugin_paths"]) extra.push_back(p.get<std::string>());
  const PluginHost host(plugin_search_path(extra));
  const auto t0 = std::chrono::steady_clock::now();
  const auto reports = run_pipeline(config, host, a.get("--from"), [&](const std::string& stage) {
    if (!a.has("--quiet")) std::fprintf(stderr, "run: %s ...\n", stage.c_str());
  });
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::filesystem::path dir = std::filesystem::absolute(config.value("output", "run"));
  bool all_skipped = true;
  for (const auto& r : reports) {
    all_skipped = all_skipped && r.skipped;
    if (r.skipped) std::printf("  %-9s %-12s up to date\n", r.stage.c_str(), r.plugin.c_str());
    else std::printf("  %-9s %-12s %6.1f s\n", r.stage.c_str(), r.plugin.c_str(), r.seconds);
  }
  if (all_skipped) std::printf("every stage is up to date\n");
  std::printf("outputs in %s: animation.svg, preview.mp4, fit.json (total %.1f s)\n", dir.c_str(), total);
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
