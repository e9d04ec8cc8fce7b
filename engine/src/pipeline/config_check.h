// Every setting of a run checked before the first stage runs.
//
// The config reader (config.h) checks keys and types against the schema; this checks values:
// ranges (a fitting size below 32 px or 1e12 iterations are refused), whole numbers, the
// enumerations (fitter colors and loop), the device (resolved against the OpenCL devices), the
// plugins named for each stage (found on the search path), the input SVG (exists and reads:
// a malformed one is reported with the user's path, not the run directory's copy), a video
// path for `video: file`, the output folder, and that the prompt is UTF-8. Each problem is one
// svgm::Error naming the key: "stages.fitter.size: must be a whole number from 32 to 4096, not 1.5".
#pragma once

#include <nlohmann/json.hpp>

#include "pipeline/plugin_host.h"

namespace svgm {

void check_config(const nlohmann::json& config, const PluginHost& host);

}  // namespace svgm
