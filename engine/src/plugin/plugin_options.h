// A plugin's free-form `options` section, read strictly: a map (or absent), only known keys,
// numbers finite and whole where they must be. Every mistake is one svgm::Error prefixed with
// the plugin's name ("video command: options.frames must be a whole number in 1..100000, not
// 2.5"), so a config typo never silently falls back to a default.
#pragma once

#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace svgm {

class PluginOptions {
 public:
  // `who` prefixes every message ("video command"). Throws for a non-map or an unknown key
  // (naming the known ones).
  PluginOptions(const nlohmann::json& options, std::string who, std::initializer_list<const char*> known);

  bool has(const char* key) const { return o_.contains(key); }
  const nlohmann::json& at(const char* key) const { return o_.at(key); }
  double number(const char* key, double fallback) const;
  int whole(const char* key, int fallback, int lo, int hi) const;
  std::string string(const char* key, const std::string& fallback) const;
  bool flag(const char* key, bool fallback) const;  // true or false, nothing else

  [[noreturn]] void fail(const std::string& message) const;

 private:
  nlohmann::json o_;
  std::string who_;
};

}  // namespace svgm
