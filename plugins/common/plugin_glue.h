// Glue for svgmotion's own C++ stage plugins: turns a C++ function taking and returning JSON
// into the C descriptor of svgmotion/plugin.h, with exceptions caught at the boundary (they
// become {"ok": false, "error": "..."}). Third-party plugins may copy the idea; they only need
// svgmotion/plugin.h.
#pragma once

#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "svgmotion/error.h"
#include "svgmotion/log.h"
#include "svgmotion/plugin.h"
#include "svgmotion/utf8_text.h"

namespace svgm::plugin {

using json = nlohmann::json;
using StageFn = json (*)(const json& request, const svgm_host* host);

inline char* copy_string(const std::string& s) {
  char* p = static_cast<char*>(std::malloc(s.size() + 1));
  if (p) std::memcpy(p, s.c_str(), s.size() + 1);
  return p;
}

inline int call(StageFn fn, const svgm_host* host, const char* request, char** response) {
  // This module's copy of the engine logs through the host (svgmotion/log.h), so its warnings
  // and debug lines reach the host's console level and run's log.txt.
  if (host && host->log)
    svgm::log::set_forward([host](svgm::log::Level level, const std::string& m) {
      host->log(host, static_cast<int>(level), m.c_str());
    });
  try {
    // Paths that are not UTF-8 (file names are bytes) come back as they are on disk.
    json req = json::parse(request);
    svgm::unpack_raw_strings(req);
    json r = fn(req, host);
    r["ok"] = true;
    *response = copy_string(svgm::json_text(r));
    return 0;
  } catch (const svgm::Rejected& e) {  // a result that must not be trusted (svgmotion/error.h)
    *response = copy_string(svgm::json_text(json{{"ok", false}, {"error", e.what()}, {"rejected", e.exit_status()}}));
  } catch (const std::exception& e) {
    *response = copy_string(svgm::json_text(json{{"ok", false}, {"error", e.what()}}));
  } catch (...) {
    *response = copy_string(R"({"ok": false, "error": "unknown failure"})");
  }
  return 1;
}

inline void free_string(char* s) { std::free(s); }

// run_dir / request["inputs"|"outputs"][key]
inline std::filesystem::path file(const json& request, const char* kind, const char* key) {
  return std::filesystem::path(request.at("run_dir").get<std::string>()) /
         request.at(kind).at(key).get<std::string>();
}

}  // namespace svgm::plugin

#define SVGM_DEFINE_PLUGIN(STAGE, NAME, VERSION, DESCRIPTION, FN)                              \
  static int svgm_plugin_run(const svgm_host* host, const char* request, char** response) {   \
    return svgm::plugin::call(FN, host, request, response);                                    \
  }                                                                                            \
  extern "C" SVGM_PLUGIN_EXPORT const svgm_plugin* svgm_plugin_entry(void) {                   \
    static const svgm_plugin descriptor = {SVGM_PLUGIN_ABI, sizeof(svgm_plugin), STAGE, NAME,  \
                                           VERSION, DESCRIPTION, svgm_plugin_run,             \
                                           svgm::plugin::free_string};                         \
    return &descriptor;                                                                        \
  }
