// The pipeline: runs the stages in order in a run directory, each through its plugin, skipping
// stages whose inputs and config are unchanged since they last ran.
//
// Every stage reads and writes files in the run directory (stage_files() lists them), and
// leaves a manifest in <run>/.svgmotion/<stage>.json with a hash of its plugin, config
// section, prompt, seed and input files' contents. A re-run with equal hashes and existing
// outputs is skipped; replacing an intermediate by hand (say target.mp4) changes the hash of
// the stages that read it, so they run again. `from` forces a stage and all after it.
#pragma once

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/plugin_host.h"
#include "run/stage_files.h"

namespace svgm {

struct StageReport {
  std::string stage, plugin;
  bool skipped = false;
  double seconds = 0;
};

// `on_stage` is told when a stage starts (for progress). Throws svgm::Error on any failure;
// what earlier stages wrote stays in the run directory. The caller holds a RunLock on the run
// directory (config "output"; run_directory.h), which also made sure it is one.
std::vector<StageReport> run_pipeline(const nlohmann::json& config, const PluginHost& host,
                                      const std::optional<std::string>& from,
                                      const std::function<void(const std::string&)>& on_stage = {});

}  // namespace svgm
