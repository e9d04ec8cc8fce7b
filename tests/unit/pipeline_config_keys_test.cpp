// The config key table of `svgmotion config` (pipeline/config_keys.h): every
// key of default.yaml is in it with a meaning, the types and defaults are the
// schema's, and the YAML of a merged config (config --show, a run's
// resolved.yaml) loads back to the same config. Built-in configs load by name
// (config.h builtin_config).
#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "pipeline/config.h"
#include "pipeline/config_keys.h"
#include "svgmotion/error.h"

using namespace svgm;
namespace fs = std::filesystem;

TEST_SUITE("pipeline") {

  TEST_CASE("config keys: every key of default.yaml, each with its default, "
            "type and meaning") {
    const std::vector<ConfigKey> &keys = config_keys();
    REQUIRE(keys.size() > 40);
    for (const ConfigKey &k : keys) {
      INFO(k.path);
      CHECK(!k.meaning
                 .empty()); // a key added without its comment in default.yaml
    }
    auto find = [&](const std::string &p) -> const ConfigKey * {
      for (const ConfigKey &k : keys)
        if (k.path == p)
          return &k;
      return nullptr;
    };
    REQUIRE(find("stages.fitter.iterations"));
    CHECK(find("stages.fitter.iterations")->value == 2000);
    CHECK(find("stages.fitter.iterations")->type == "integer");
    CHECK(find("stages.fitter.mask_threshold")->type == "number");
    CHECK(find("stages.fitter.gate")->type == "boolean");
    CHECK(find("plugin_paths")->type == "list");
    CHECK(find("stages.video.options")->type == "section");
    CHECK(find("device")->meaning ==
          "OpenCL device: auto, cpu, gpu, or part of a name");
    CHECK(!find("stages")); // a section of keys is not a key
    CHECK(!find("stages.fitter"));
    // Each key once, and every leaf of the defaults is one of them.
    size_t leaves = 0;
    std::function<void(const nlohmann::json &, const std::string &)> count =
        [&](const nlohmann::json &j, const std::string &p) {
          for (const auto &[k, v] : j.items()) {
            const std::string path = p.empty() ? k : p + "." + k;
            if (v.is_object() && !path.ends_with(".options"))
              count(v, path);
            else
              ++leaves;
          }
        };
    count(default_config(), "");
    CHECK(leaves == keys.size());
  }

  TEST_CASE("config yaml: a merged config written as YAML loads back to the "
            "same config") {
    const fs::path file =
        fs::temp_directory_path() /
        ("svgm_config_keys_test_" + std::to_string(::getpid()) + ".yaml");
    ConfigOrigins origins;
    const nlohmann::json merged =
        load_config(std::nullopt,
                    {"prompt=it's a \"quoted\" # prompt: with colons",
                     "stages.fitter.iterations=7", "stages.video.fps=12.5",
                     "stages.video.options={motion: 'flap:wing*', n: [1, 2]}",
                     "plugin_paths=[/a b, c]"},
                    &origins);
    const std::string text = config_yaml(merged, origins);
    CHECK(text.find(
              "iterations: 7  # command line 'stages.fitter.iterations=7'") !=
          std::string::npos);
    std::ofstream(file) << text;
    const nlohmann::json again = load_config(file, {});
    fs::remove(file);
    CHECK(again == merged);
  }

  TEST_CASE("built-in configs load by name from any folder; a file of that "
            "name wins") {
    CHECK(builtin_config("fast"));
    CHECK(builtin_config("fast.yaml"));
    CHECK(!builtin_config("./fast.yaml")); // a path is a file, never a built-in
    CHECK(!builtin_config("nonesuch"));
    const fs::path old = fs::current_path();
    const fs::path dir = fs::temp_directory_path() /
                         ("svgm_builtin_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    fs::current_path(dir);
    CHECK(load_config(fs::path("fast"), {})["stages"]["fitter"]["iterations"] ==
          400);
    CHECK(load_config(fs::path("fast.yaml"),
                      {})["stages"]["fitter"]["keyframes"] == 8);
    std::ofstream("fast.yaml") << "stages:\n  fitter:\n    iterations: 9\n";
    CHECK(load_config(fs::path("fast.yaml"),
                      {})["stages"]["fitter"]["iterations"] == 9);
    CHECK_THROWS_WITH(load_config(fs::path("fastt.yaml"), {}),
                      "fastt.yaml: cannot open (built-in configs: "
                      "default.yaml, fast.yaml, paper.yaml)");
    fs::current_path(old);
    fs::remove_all(dir);
  }

} // TEST_SUITE
