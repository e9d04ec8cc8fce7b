// Pipeline configs: YAML, one section per stage, merged over the built-in defaults
// (configs/default.yaml, embedded at build time, is also the schema), then key.path=value
// overrides from the command line. Unknown keys are errors naming the file, the line and the
// nearest known key; stages.<stage>.options is free-form for third-party plugins.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace svgm {

// The merged config as JSON (what plugins receive, section by section).
nlohmann::json load_config(const std::optional<std::filesystem::path>& file,
                           const std::vector<std::string>& overrides);

// The built-in defaults (configs/default.yaml).
nlohmann::json default_config();

}  // namespace svgm
