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
#include <string_view>
#include <vector>

namespace svgm {

// The most values (maps, lists and scalars) one config may expand to. A YAML alias repeats its
// anchor's whole node wherever it is used, so aliases of aliases let a file of a few hundred
// bytes name 10^9 values (the "billion laughs"); yaml-cpp shares them, but JSON copies each.
// default.yaml holds about 60 values and an inline ComfyUI workflow a few thousand. Batch
// manifests hold each item's overrides to the same cap (batch_manifest.h).
inline constexpr size_t kMaxConfigValues = 100000;

// yaml-cpp 0.7's own nesting limit (DepthGuard<500> in its single-document parser); deeper
// documents throw YAML::DeepRecursion, whose message reads "bad file".
inline constexpr int kMaxYamlDepth = 500;

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

// A built-in config (configs/*.yaml, embedded at build time) by its name, with or without
// ".yaml" ("fast", "fast.yaml"); nothing for a name with a folder in it. load_config takes one
// when no file of that name exists, so `svgmotion run fast` works from any folder.
std::optional<std::string_view> builtin_config(const std::string& name);
// How errors name it: "fast.yaml (built in)".
std::string builtin_config_label(const std::string& name);

// The built-in defaults (configs/default.yaml).
nlohmann::json default_config();

}  // namespace svgm
