// The plugin host: finds stage plugins on the search path, checks their descriptors, and runs
// them with a JSON request (see svgmotion/plugin.h for the ABI and the contract).
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "svgmotion/plugin.h"

namespace svgm {

struct PluginInfo {
  std::string stage, name, version, description;
  std::filesystem::path path;
  const svgm_plugin* descriptor = nullptr;
};

// The known stage kinds, in pipeline order.
const std::vector<std::string>& stage_names();

// What a running plugin's progress and cancel callbacks reach (svgm_host::progress, cancelled).
struct HostHooks {
  std::function<void(double fraction, const std::string& note)> progress;
  std::function<bool()> cancelled;
  std::function<void(const std::string& line)> info;  // a plugin's info line (log level 1)
};

class PluginHost {
 public:
  // Scans `search_path` in order for modules named svgm_*.so. The first module providing a
  // (stage, name) wins; later ones with the same pair are refused as duplicates. Modules that
  // cannot be loaded or speak another ABI are refused too; problems() says why.
  explicit PluginHost(const std::vector<std::filesystem::path>& search_path);

  const std::vector<PluginInfo>& plugins() const { return plugins_; }
  const std::vector<std::string>& problems() const { return problems_; }
  const PluginInfo* find(const std::string& stage, const std::string& name) const;

  // Runs plugin (stage, name) on `request`; returns its response. Throws svgm::Error
  // "<stage> plugin '<name>': <problem>" when it is missing, fails, or answers garbage.
  // A response with "rejected": 3 or 4 (and ok false) throws svgm::Rejected with that status.
  nlohmann::json run(const std::string& stage, const std::string& name,
                     const nlohmann::json& request) const;

  // Where plugins' progress reports go and how they learn the user asked to stop.
  void set_hooks(HostHooks hooks) { hooks_ = std::move(hooks); }

 private:
  void load(const std::filesystem::path& file);
  std::vector<PluginInfo> plugins_;
  std::vector<std::string> problems_;
  HostHooks hooks_;
};

// The default search path: next to the binary (<exe dir>/plugins), the install's plugin
// directory, $SVGMOTION_PLUGIN_PATH (colon-separated), then `extra` (the config's plugin_paths).
std::vector<std::filesystem::path> plugin_search_path(const std::vector<std::filesystem::path>& extra);

}  // namespace svgm
