// The table of config keys and the YAML text of a config (see config_keys.h).
#include "pipeline/config_keys.h"

#include <yaml-cpp/yaml.h>

#include <string_view>

#include "opencl/kernel_sources.h"
#include "svgmotion/error.h"
#include "svgmotion/utf8_text.h"

namespace svgm {

namespace {

// The comment of one line of YAML: the text after the first '#' that starts a
// comment (at the line's start or after a space, outside quotes), trimmed; ""
// when there is none.
std::string line_comment(std::string_view line) {
  char quote = 0;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quote) {
      if (c == quote)
        quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '#' &&
               (i == 0 || line[i - 1] == ' ' || line[i - 1] == '\t')) {
      std::string_view t = line.substr(i + 1);
      while (!t.empty() && (t.front() == ' ' || t.front() == '\t'))
        t.remove_prefix(1);
      while (!t.empty() && (t.back() == ' ' || t.back() == '\r'))
        t.remove_suffix(1);
      return std::string(t);
    }
  }
  return "";
}

std::string type_of(const nlohmann::json &v, bool free_form) {
  if (free_form)
    return "section";
  if (v.is_boolean())
    return "boolean";
  if (v.is_number_integer())
    return "integer";
  if (v.is_number())
    return "number";
  if (v.is_array())
    return "list";
  return "string";
}

void collect(const YAML::Node &map, const nlohmann::json &defaults,
             const std::string &prefix,
             const std::vector<std::string_view> &lines,
             std::vector<ConfigKey> &out) {
  for (const auto &kv : map) {
    const std::string key = kv.first.Scalar();
    const std::string path = prefix.empty() ? key : prefix + "." + key;
    // stages.<stage>.options: free-form, set as a whole (config.cpp's
    // free_form()).
    const bool free_form =
        path.rfind("stages.", 0) == 0 && path.ends_with(".options");
    if (kv.second.IsMap() && !free_form) {
      collect(kv.second, defaults[key], path, lines, out);
      continue;
    }
    const size_t line = kv.first.Mark().line;
    out.push_back(
        {path, defaults[key], type_of(defaults[key], free_form),
         line < lines.size() ? line_comment(lines[line]) : std::string()});
  }
}

bool is_block_map(const nlohmann::json &v) {
  return v.is_object() && !v.empty();
}

void emit(const nlohmann::json &map, const std::string &prefix, int indent,
          const ConfigOrigins &origins, std::string &out) {
  for (const auto &[key, v] : map.items()) {
    const std::string path = prefix.empty() ? key : prefix + "." + key;
    // A key that is not a plain name (free-form options may hold anything) is
    // written quoted.
    const bool plain =
        !key.empty() &&
        key.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUV"
                              "WXYZ0123456789_-") == std::string::npos;
    out += std::string(static_cast<size_t>(indent), ' ') +
           (plain ? key : json_text(key)) + ":";
    const auto origin = origins.find(path);
    std::string note = origin == origins.end() ? "" : "  # " + origin->second;
    for (char &c : note)
      if (c == '\n' || c == '\r')
        c = ' '; // a comment ends at the line's end
    if (is_block_map(v) &&
        !(path.rfind("stages.", 0) == 0 && path.ends_with(".options") &&
          origin != origins.end())) {
      out += note + "\n";
      emit(v, path, indent + 2, origins, out);
    } else {
      out += " " + json_text(v) + note + "\n";
    }
  }
}

} // namespace

const std::vector<ConfigKey> &config_keys() {
  static const std::vector<ConfigKey> keys = [] {
    std::string_view text;
    for (const auto &c : embedded_configs())
      if (std::string_view(c.name) == "default.yaml")
        text = c.text;
    std::vector<std::string_view> lines;
    for (size_t from = 0; from <= text.size();) {
      const size_t nl = text.find('\n', from);
      lines.push_back(text.substr(from, nl == std::string_view::npos
                                            ? std::string_view::npos
                                            : nl - from));
      if (nl == std::string_view::npos)
        break;
      from = nl + 1;
    }
    std::vector<ConfigKey> out;
    collect(YAML::Load(std::string(text)), default_config(), "", lines, out);
    return out;
  }();
  return keys;
}

std::string config_yaml(const nlohmann::json &config,
                        const ConfigOrigins &origins) {
  std::string out;
  emit(config, "", 0, origins, out);
  return out;
}

} // namespace svgm
