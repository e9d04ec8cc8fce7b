// plugin_options.h: strict reading of a plugin's options section.
#include "plugin/plugin_options.h"

#include <cmath>

#include "svgmotion/error.h"
#include "svgmotion/utf8_text.h"

namespace svgm {

PluginOptions::PluginOptions(const nlohmann::json& options, std::string who,
                             std::initializer_list<const char*> known)
    : o_(options.is_null() ? nlohmann::json::object() : options), who_(std::move(who)) {
  std::string list;
  for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
  if (!o_.is_object()) fail("options must be a map (" + list + "), not " + json_text(options));
  for (const auto& [key, value] : o_.items()) {
    bool ok = false;
    for (const char* k : known) ok = ok || key == k;
    if (!ok) fail("unknown option '" + key + "' (options: " + list + ")");
  }
}

double PluginOptions::number(const char* key, double fallback) const {
  if (!has(key)) return fallback;
  const nlohmann::json& v = o_.at(key);
  if (!v.is_number()) fail(std::string("options.") + key + " must be a number, not " + json_text(v));
  const double d = v.get<double>();
  if (!std::isfinite(d)) fail(std::string("options.") + key + " must be a finite number");
  return d;
}

int PluginOptions::whole(const char* key, int fallback, int lo, int hi) const {
  if (!has(key)) return fallback;
  const double d = number(key, 0);
  if (d != std::round(d) || d < lo || d > hi)
    fail(std::string("options.") + key + " must be a whole number in " + std::to_string(lo) + ".." +
         std::to_string(hi) + ", not " + json_text(o_.at(key)));
  return static_cast<int>(d);
}

std::string PluginOptions::string(const char* key, const std::string& fallback) const {
  if (!has(key)) return fallback;
  const nlohmann::json& v = o_.at(key);
  if (!v.is_string()) fail(std::string("options.") + key + " must be a string, not " + json_text(v));
  return v.get<std::string>();
}

bool PluginOptions::flag(const char* key, bool fallback) const {
  if (!has(key)) return fallback;
  const nlohmann::json& v = o_.at(key);
  if (!v.is_boolean()) fail(std::string("options.") + key + " must be true or false, not " + json_text(v));
  return v.get<bool>();
}

void PluginOptions::fail(const std::string& message) const { throw Error(who_ + ": " + message); }

}  // namespace svgm
