// The part of a video stage request every generator plugin (command, comfyui) reads the same
// way: the run directory (checked to be where the pipeline wants candidates/), the prompt, the
// seed, and hooks that forward progress, log lines and cancellation to the host.
#pragma once

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "common/plugin_glue.h"
#include "svgmotion/error.h"
#include "generators/generator_hooks.h"

namespace svgm::plugin {

struct GeneratorRequest {
  std::filesystem::path run_dir;
  std::string prompt;
  int64_t seed = 0;
  GeneratorHooks hooks;
};

// `who` names the plugin in the error ("video command: the pipeline asked for ...").
inline GeneratorRequest generator_request(const json& req, const svgm_host* host, const std::string& who) {
  GeneratorRequest g;
  g.run_dir = req.at("run_dir").get<std::string>();
  // The generators write run_dir/candidates; say so if the pipeline's file names change.
  if (file(req, "outputs", "candidates") != g.run_dir / "candidates")
    throw Error(who + ": the pipeline asked for candidates at " + file(req, "outputs", "candidates").string() +
                "; this plugin writes run_dir/candidates");
  g.prompt = req.value("prompt", std::string());
  const json& seed = req.contains("seed") ? req.at("seed") : json(0);
  g.seed = seed.is_number() ? seed.get<int64_t>() : 0;
  if (host) {
    g.hooks.progress = [host](double f, const std::string& note) {
      if (host->progress) host->progress(host, f, note.c_str());
    };
    g.hooks.log = [host](const std::string& line) {
      if (host->log) host->log(host, 1, line.c_str());
    };
    g.hooks.warn = [host](const std::string& line) {
      if (host->log) host->log(host, 2, line.c_str());
    };
    g.hooks.cancelled = [host] { return host->cancelled && host->cancelled(host) != 0; };
  }
  return g;
}

// The API key held by the environment variable `env` ("" = none wanted: returns ""). Throws
// "<who>: $ENV is not set (<what>; options.api_key_env names the variable)" when it is empty.
inline std::string api_key_from_env(const std::string& env, const std::string& who, const std::string& what) {
  if (env.empty()) return "";
  const char* k = std::getenv(env.c_str());
  if (!k || !*k) throw Error(who + ": $" + env + " is not set (" + what + "; options.api_key_env names the variable)");
  return k;
}

// For generators with transfers on worker threads (candidate_pool.h): the host's cancel check
// may only be called from run()'s thread, so `hooks.cancelled` (which the pool calls there)
// now also raises a flag, and the returned check reads only that flag, from any thread (give it
// to the HTTP transport).
inline std::function<bool()> share_cancel(GeneratorHooks& hooks) {
  auto flag = std::make_shared<std::atomic<bool>>(false);
  hooks.cancelled = [host_check = hooks.cancelled, flag] {
    if (host_check && host_check()) *flag = true;
    return flag->load();
  };
  return [flag] { return flag->load(); };
}

}  // namespace svgm::plugin
