// Pipeline configs: YAML, one section per stage, merged over the built-in defaults
// (configs/default.yaml, embedded at build time, is also the schema), then key.path=value
// overrides from the command line. Unknown keys are errors naming the file, the line and the
// nearest known key; stages.<stage>.options is free-form for third-party plugins.
#pragma once

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace svgm {

// Where each setting the user gave came from, by key path ("stages.fitter.iterations"; a
// free-form options section by its own path): "FILE:LINE" or "command line 'k=v'" (an override
// replaces the file's entry). Defaults are not listed.
using ConfigOrigins = std::map<std::string, std::string>;

// The merged config as JSON (what plugins receive, section by section); `origins`, when given,
// receives where each user setting came from.
nlohmann::json load_config(const std::optional<std::filesystem::path>& file,
                           const std::vector<std::string>& overrides, ConfigOrigins* origins = nullptr);

// The origin of the setting a value check's message names ("key.path: must be ..."), or "" if
// the message names no setting the user gave. Values are checked after merging
// (config_check.h), so this is how their errors point at the file and line.
std::string origin_of_message(const ConfigOrigins& origins, const std::string& message);

// The built-in defaults (configs/default.yaml).
nlohmann::json default_config();

}  // namespace svgm
