// Plugin discovery, validation and calls (see plugin_host.h).
#include "pipeline/plugin_host.h"

#include <dlfcn.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "pipeline/module_check.h"
#include "svgmotion/error.h"
#include "svgmotion/log.h"
#include "svgmotion/utf8_text.h"

#ifndef SVGM_VERSION
#define SVGM_VERSION "0.0.0"
#endif

#ifndef SVGM_INSTALL_PLUGIN_DIR
#define SVGM_INSTALL_PLUGIN_DIR "/usr/local/lib/svgmotion/plugins"
#endif

namespace svgm {

namespace fs = std::filesystem;

const std::vector<std::string>& stage_names() {
  static const std::vector<std::string> names = {"grouper", "recolorer", "video", "ranker",
                                                 "layers",  "tracker",   "fitter"};
  return names;
}

namespace {

void host_log(const svgm_host* host, int level, const char* message) {
  const auto* hooks = static_cast<const HostHooks*>(host ? host->context : nullptr);
  // level: 0 debug, 1 info, 2 warning, 3 error (svgmotion/plugin.h), as the host logger's.
  if (level == 1 && hooks && hooks->info) hooks->info(message);
  else log::write(static_cast<log::Level>(std::clamp(level, 0, 3)), message ? message : "");
}
void host_progress(const svgm_host* host, double fraction, const char* note) {
  const auto* hooks = static_cast<const HostHooks*>(host->context);
  if (hooks && hooks->progress) hooks->progress(fraction, note ? note : "");
}
int host_cancelled(const svgm_host* host) {
  const auto* hooks = static_cast<const HostHooks*>(host->context);
  return hooks && hooks->cancelled && hooks->cancelled() ? 1 : 0;
}

}  // namespace

std::vector<fs::path> plugin_search_path(const std::vector<fs::path>& extra) {
  std::vector<fs::path> out;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) out.push_back(exe.parent_path() / "plugins");
  // The installed layout, wherever it was installed to (PREFIX/bin/svgmotion and
  // PREFIX/lib/svgmotion/plugins; `cmake --install --prefix` or DESTDIR need not be the prefix
  // the build was configured for).
  if (!ec) out.push_back(exe.parent_path().parent_path() / "lib" / "svgmotion" / "plugins");
  out.push_back(SVGM_INSTALL_PLUGIN_DIR);
  if (const char* env = std::getenv("SVGMOTION_PLUGIN_PATH"); env && *env) {
    std::string s = env;
    size_t start = 0;
    while (start <= s.size()) {
      const size_t colon = s.find(':', start);
      const std::string part = s.substr(start, colon == std::string::npos ? std::string::npos : colon - start);
      if (!part.empty()) out.push_back(part);
      if (colon == std::string::npos) break;
      start = colon + 1;
    }
  }
  out.insert(out.end(), extra.begin(), extra.end());
  return out;
}

PluginHost::PluginHost(const std::vector<fs::path>& search_path) {
  std::vector<fs::path> seen;  // one folder named twice (the installed layout is also the prefix's) loads once
  for (const fs::path& dir : search_path) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) continue;
    const fs::path canonical = fs::canonical(dir, ec);
    if (std::find(seen.begin(), seen.end(), canonical) != seen.end()) continue;
    seen.push_back(canonical);
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir, ec)) {
      const std::string n = e.path().filename().string();
      if (n.rfind("svgm_", 0) == 0 && e.path().extension() == ".so") files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    for (const fs::path& f : files) load(f);
  }
}

void PluginHost::load(const fs::path& file) {
  // A truncated or garbage file would kill the process inside dlopen (SIGBUS): look first.
  if (const auto problem = module_problem(file)) {
    problems_.push_back(file.string() + ": not a loadable module (" + *problem + ")");
    return;
  }
  // RTLD_LOCAL: plugins do not see each other's symbols; the handle stays open for the
  // process's life (descriptors point into the module).
  void* h = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!h) {
    problems_.push_back(file.string() + ": cannot load: " + dlerror());
    return;
  }
  auto entry = reinterpret_cast<svgm_plugin_entry_fn>(dlsym(h, "svgm_plugin_entry"));
  if (!entry) {
    problems_.push_back(file.string() + ": not an svgmotion plugin (no svgm_plugin_entry)");
    dlclose(h);
    return;
  }
  const svgm_plugin* d = entry();
  if (!d) {
    problems_.push_back(file.string() + ": svgm_plugin_entry returned nothing");
    return;
  }
  if (d->abi != SVGM_PLUGIN_ABI) {
    problems_.push_back(file.string() + ": built against plugin ABI " + std::to_string(d->abi) +
                        ", this svgmotion speaks ABI " + std::to_string(SVGM_PLUGIN_ABI) + "; rebuild it");
    return;
  }
  if (d->size < sizeof(svgm_plugin) || !d->stage || !d->name || !d->run || !d->free_string) {
    problems_.push_back(file.string() + ": malformed plugin descriptor");
    return;
  }
  const auto& stages = stage_names();
  if (std::find(stages.begin(), stages.end(), d->stage) == stages.end()) {
    problems_.push_back(file.string() + ": unknown stage '" + d->stage + "'");
    return;
  }
  if (const PluginInfo* other = find(d->stage, d->name)) {
    problems_.push_back(file.string() + ": duplicate " + d->stage + " plugin '" + d->name +
                        "' (using " + other->path.string() + ")");
    return;
  }
  plugins_.push_back({d->stage, d->name, d->version ? d->version : "", d->description ? d->description : "",
                      file, d});
}

const PluginInfo* PluginHost::find(const std::string& stage, const std::string& name) const {
  for (const PluginInfo& p : plugins_)
    if (p.stage == stage && p.name == name) return &p;
  return nullptr;
}

nlohmann::json PluginHost::run(const std::string& stage, const std::string& name,
                               const nlohmann::json& request) const {
  const std::string who = stage + " plugin '" + name + "'";
  const PluginInfo* p = find(stage, name);
  if (!p) {
    std::string why;
    for (const std::string& pr : problems_)
      if (pr.find("_" + stage + "_" + name) != std::string::npos || pr.find("'" + name + "'") != std::string::npos)
        why = " (" + pr + ")";
    std::string have;
    for (const PluginInfo& q : plugins_)
      if (q.stage == stage) have += (have.empty() ? "" : ", ") + q.name;
    throw Error(who + " not found" + why + "; available " + stage + " plugins: " +
                (have.empty() ? "none" : have));
  }
  // A path that is not UTF-8 travels as its shown form plus its bytes (svgmotion/utf8_text.h).
  nlohmann::json packed = request;
  if (packed.is_object()) pack_raw_strings(packed);
  const std::string text = json_text(packed);
  char* response = nullptr;
  const svgm_host host = {SVGM_PLUGIN_ABI, sizeof(svgm_host), SVGM_VERSION, const_cast<HostHooks*>(&hooks_),
                          host_log, host_progress, host_cancelled};
  const int rc = p->descriptor->run(&host, text.c_str(), &response);
  std::string body = response ? response : "";
  if (response) p->descriptor->free_string(response);
  nlohmann::json r;
  try {
    r = nlohmann::json::parse(body);
  } catch (const nlohmann::json::exception&) {
    throw Error(who + " returned a response that is not JSON (exit status " + std::to_string(rc) + ")");
  }
  if (!r.is_object()) throw Error(who + " returned a response that is not a JSON object");
  if (rc != 0 || !r.value("ok", false)) {
    std::string err = r.contains("error") && r["error"].is_string() ? r["error"].get<std::string>() : "failed";
    std::replace(err.begin(), err.end(), '\n', ' ');
    // A plugin may say its result was produced but must not be trusted (see svgm::Rejected).
    if (r.contains("rejected") && r["rejected"].is_number_integer()) {
      const int status = r["rejected"].get<int>();
      if (status == Rejected::kFitRejected || status == Rejected::kCandidatesFlagged)
        throw Rejected(who + ": " + err, status);
    }
    throw Error(who + ": " + err);
  }
  return r;
}

}  // namespace svgm
