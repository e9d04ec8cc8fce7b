// The table of config keys for `svgmotion config`: every key of
// configs/default.yaml with its default, its type and its meaning, read from
// that one file (the embedded copy), so the table can never disagree with the
// schema load_config checks against (config.h). The meaning is the comment on
// the key's own line in default.yaml; a key without one is a test failure
// (config_keys_test.cpp), not a blank in the table.
//
// Also the YAML text of a merged config (`config --show`, a run's
// resolved.yaml): block maps, every other value in JSON's flow syntax (YAML 1.2
// reads JSON), so the text loads back as the same config.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pipeline/config.h"

namespace svgm {

struct ConfigKey {
  std::string path;     // "stages.fitter.iterations"
  nlohmann::json value; // the default
  std::string type;     // string, integer, number, boolean, list, or section
                        // (free-form options)
  std::string meaning;  // the comment on its line in default.yaml
};

// Every settable key of default.yaml in file order (sections themselves are not
// keys, except the free-form stages.<stage>.options, which a config sets as a
// whole).
const std::vector<ConfigKey> &config_keys();

// `config` as YAML that loads back to the same config; a key the user set gets
// its origin
// ("# fast.yaml:4", "# command line 'k=v'") as a trailing comment.
std::string config_yaml(const nlohmann::json &config,
                        const ConfigOrigins &origins = {});

} // namespace svgm
