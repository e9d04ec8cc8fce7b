// Fuzz target: the YAML config reader (pipeline/config.cpp): the file merged over the
// built-in schema, and one key.path=value override. The input's first line, when it holds a
// '=', is the override; the rest is the file. Properties checked on every input:
//  - load_config returns a config or throws svgm::Error, nothing else (a yaml-cpp or JSON
//    exception escaping would end `svgmotion run` as an "internal error");
//  - the error is one line;
//  - a config that loads can be written as JSON (plugins receive it that way), and keeps the
//    schema's sections.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_check.h"
#include "pipeline/config.h"
#include "svgmotion/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> overrides;
  if (const size_t nl = text.find('\n'); nl != std::string_view::npos &&
                                         text.substr(0, nl).find('=') != std::string_view::npos) {
    overrides.emplace_back(text.substr(0, nl));
    text.remove_prefix(nl + 1);
  }
  // One file per process, rewritten for every input (load_config reads a path).
  static const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("svgm_config_fuzz_" + std::to_string(::getpid()) + ".yaml");
  {
    std::ofstream f(file, std::ios::binary | std::ios::trunc);
    f.write(text.data(), static_cast<std::streamsize>(text.size()));
  }
  try {
    const nlohmann::json cfg = svgm::load_config(file, overrides);
    FUZZ_REQUIRE(cfg.is_object() && cfg.contains("stages") && cfg["stages"].is_object(),
                 "a loaded config keeps the schema's sections");
    (void)cfg.dump();  // throws (and so fails) on text a plugin could not receive as JSON
  } catch (const svgm::Error& e) {
    FUZZ_REQUIRE(svgm::fuzz::one_line(e.what()), "an error is one line");
  }
  return 0;
}
