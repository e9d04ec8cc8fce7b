// Config loading and validation (see config.h).
#include "pipeline/config.h"

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <set>

#include "opencl/kernel_sources.h"
#include "svg/utf8.h"
#include "svgmotion/error.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

// kMaxConfigValues and kMaxYamlDepth (config.h) bound what one config may expand to.

// Values left to produce, shared by one file and its overrides; `where` names the source
// ("file:line: 'key.path'") in the error.
struct ValueBudget {
  size_t left = kMaxConfigValues;
  void take(const std::string& where) {
    if (left == 0)
      throw Error(where + " expands to more than " + std::to_string(kMaxConfigValues) +
                  " values (YAML aliases of aliases?)");
    --left;
  }
};

// Text from a config as it may appear inside a one-line message: control characters (a key
// "a\nb" is legal YAML) are written as escapes, so the message stays one line.
std::string shown(std::string_view text) {
  std::string out;
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '\n') out += "\\n";
    else if (c == '\t') out += "\\t";
    else if (c < 0x20 || c == 0x7f) {
      char esc[8];
      std::snprintf(esc, sizeof esc, "\\x%02x", c);
      out += esc;
    } else {
      out += ch;
    }
  }
  return out;
}

// Config text reaches plugins as JSON, which holds UTF-8 only: anything else would fail deep
// inside a stage ("internal error: [json.exception.type_error.316]").
const std::string& checked_text(const std::string& text, const std::string& where) {
  if (!valid_utf8(text)) throw Error(where + " is not valid UTF-8 text");
  return text;
}

// A map key as text. YAML allows lists and maps as keys ("? [a, b]\n: 1"); a config does not.
std::string key_text(const YAML::Node& key, const std::string& where) {
  if (!key.IsScalar()) throw Error(where + ": a key must be a name, not a list or a map");
  return checked_text(key.Scalar(), where + ": a key");
}

// The nodes from the root of a value down to the one being converted. An alias inside its own
// anchor ("a: &a [*a]") makes yaml-cpp's node graph a cycle; converting it recursed until the
// stack overflowed (fuzz finding: config alias_cycle.yaml), before the value budget ran out.
using NodePath = std::vector<const YAML::Node*>;

nlohmann::json to_json(const YAML::Node& n, ValueBudget& budget, const std::string& where,
                       NodePath& path);

nlohmann::json child_to_json(const YAML::Node& n, ValueBudget& budget, const std::string& where,
                             NodePath& path) {
  if (path.size() >= static_cast<size_t>(kMaxYamlDepth)) {
    // Deep either way; a node that is its own ancestor says why (checked once, at the error).
    for (size_t i = 0; i < path.size(); ++i)
      for (size_t j = i + 1; j < path.size(); ++j)
        if (path[i]->is(*path[j])) throw Error(where + " contains itself (a YAML alias inside its own anchor)");
    throw Error(where + ": nested too deeply (more than " + std::to_string(kMaxYamlDepth) + " levels)");
  }
  return to_json(n, budget, where, path);
}

nlohmann::json to_json(const YAML::Node& n, ValueBudget& budget, const std::string& where,
                       NodePath& path) {
  budget.take(where);
  switch (n.Type()) {
    case YAML::NodeType::Map: {
      path.push_back(&n);
      nlohmann::json o = nlohmann::json::object();
      for (const auto& kv : n) o[key_text(kv.first, where)] = child_to_json(kv.second, budget, where, path);
      path.pop_back();
      return o;
    }
    case YAML::NodeType::Sequence: {
      path.push_back(&n);
      nlohmann::json a = nlohmann::json::array();
      for (const auto& v : n) a.push_back(child_to_json(v, budget, where, path));
      path.pop_back();
      return a;
    }
    case YAML::NodeType::Scalar: {
      const std::string& s = checked_text(n.Scalar(), where);
      if (n.Tag() == "!") return s;  // quoted: a string
      if (s == "true" || s == "false") return s == "true";
      if (s == "null" || s == "~") return nullptr;
      // std::stoll and std::stod as they were used here, without their exceptions: a config of
      // 100,000 words threw 200,000 of them, which under AddressSanitizer at a deep alias
      // nesting took over a minute (fuzz finding: config alias_words_slow.yaml).
      const char* begin = s.c_str();
      char* end = nullptr;
      errno = 0;
      const long long i = std::strtoll(begin, &end, 10);
      if (end != begin && errno != ERANGE && end == begin + s.size()) return i;
      errno = 0;
      const double d = std::strtod(begin, &end);
      if (end != begin && errno != ERANGE && end == begin + s.size()) return d;
      return s;
    }
    default:
      return nullptr;
  }
}

nlohmann::json to_json(const YAML::Node& n, ValueBudget& budget, const std::string& where) {
  NodePath path;
  return to_json(n, budget, where, path);
}

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t prev = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t cur = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, prev + (a[i - 1] == b[j - 1] ? 0 : 1)});
      prev = cur;
    }
  }
  return row[b.size()];
}

std::string suggestion(const std::string& key, const nlohmann::json& schema) {
  std::string best;
  size_t best_d = 3;  // suggest only close matches
  for (const auto& [k, v] : schema.items()) {
    (void)v;
    const size_t d = edit_distance(key, k);
    if (d < best_d) { best_d = d; best = k; }
  }
  return best;
}

bool free_form(const std::string& path) {
  return path.rfind("stages.", 0) == 0 && path.find(".options") != std::string::npos;
}

// Merges `user` into `into`, checking every key against `schema`.
void merge(const YAML::Node& user, nlohmann::json& into, const nlohmann::json& schema,
           const std::string& path, const std::string& file, ValueBudget& budget, ConfigOrigins* origins) {
  std::set<std::string> seen;  // YAML maps may not repeat a key; yaml-cpp would keep both
  for (const auto& kv : user) {
    // "file:line" for files; overrides come as "command line 'k=v'" with no line to point at.
    const auto line = file.rfind("command line", 0) == 0 ? std::string() : ":" + std::to_string(kv.first.Mark().line + 1);
    const std::string key = key_text(kv.first, file + line);
    const std::string full = shown(path.empty() ? key : path + "." + key);
    if (!seen.insert(key).second) throw Error(file + line + ": duplicate key '" + full + "'");
    if (!schema.is_object() || !schema.contains(key)) {
      const std::string near = schema.is_object() ? suggestion(key, schema) : "";
      throw Error(file + line + ": unknown key '" + full + "'" +
                  (near.empty() ? "" : " (did you mean '" + (path.empty() ? near : path + "." + near) + "'?)"));
    }
    const nlohmann::json& s = schema[key];
    if (s.is_object() && !free_form(full)) {
      if (!kv.second.IsMap()) throw Error(file + line + ": '" + full + "' must be a section of keys");
      merge(kv.second, into[key], s, full, file, budget, origins);
    } else if (s.is_object()) {
      // Free-form sections merge key by key, so options.x=1 keeps the other options.
      const nlohmann::json v = to_json(kv.second, budget, file + line + ": '" + full + "'");
      if (into[key].is_object() && v.is_object()) into[key].update(v, true);
      else into[key] = v;
      if (origins) (*origins)[full] = file + line;
    } else {
      const nlohmann::json v = to_json(kv.second, budget, file + line + ": '" + full + "'");
      if (s.is_number() && !v.is_number())
        throw Error(file + line + ": '" + full + "' must be a number");
      if (s.is_boolean() && !v.is_boolean())
        throw Error(file + line + ": '" + full + "' must be true or false");
      if (s.is_array() && !v.is_array()) throw Error(file + line + ": '" + full + "' must be a list");
      into[key] = v;
      if (origins) (*origins)[full] = file + line;
    }
  }
}

}  // namespace

std::optional<std::string_view> builtin_config(const std::string& name) {
  if (name.find('/') != std::string::npos) return std::nullopt;
  for (const auto& c : embedded_configs())
    if (name == c.name || name + ".yaml" == c.name) return std::string_view(c.text);
  return std::nullopt;
}

std::string builtin_config_label(const std::string& name) {
  return (name.ends_with(".yaml") ? name : name + ".yaml") + " (built in)";
}

nlohmann::json default_config() {
  // Parsed once per process: the config fuzz target loads a config per input.
  static const nlohmann::json defaults = [] {
    for (const auto& c : embedded_configs())
      if (std::string_view(c.name) == "default.yaml") {
        ValueBudget budget;
        return to_json(YAML::Load(c.text), budget, "default.yaml");
      }
    throw Error("internal: no embedded default.yaml");
  }();
  return defaults;
}

nlohmann::json load_config(const std::optional<std::filesystem::path>& file,
                           const std::vector<std::string>& overrides, ConfigOrigins* origins) {
  const nlohmann::json schema = default_config();
  nlohmann::json cfg = schema;
  ValueBudget budget;
  if (file) {
    YAML::Node root;
    // A file of that name wins; else a built-in config by name, from any folder.
    std::error_code ec;
    const std::optional<std::string_view> builtin = fs::exists(*file, ec) ? std::nullopt : builtin_config(file->string());
    const std::string label = builtin ? builtin_config_label(file->string()) : file->string();
    try {
      root = builtin ? YAML::Load(std::string(*builtin)) : YAML::LoadFile(file->string());
    } catch (const YAML::BadFile&) {
      std::string names;
      for (const auto& c : embedded_configs()) names += (names.empty() ? "" : ", ") + std::string(c.name);
      throw Error(file->string() + ": cannot open (built-in configs: " + names + ")");
    } catch (const YAML::DeepRecursion& e) {
      // yaml-cpp reports its nesting limit with the message "bad file".
      throw Error(label + ":" + std::to_string(e.mark.line + 1) +
                  ": nested too deeply (more than " + std::to_string(kMaxYamlDepth) + " levels)");
    } catch (const YAML::Exception& e) {
      // yaml-cpp quotes the offending character raw ("unknown escape character: " + '\n').
      throw Error(label + ":" + std::to_string(e.mark.line + 1) + ": " + shown(e.msg));
    }
    if (!root.IsNull()) {
      if (!root.IsMap()) throw Error(label + ": a config is a YAML map of keys");
      merge(root, cfg, schema, "", label, budget, origins);
    }
  }
  for (const std::string& o : overrides) {
    const size_t eq = o.find('=');
    if (eq == std::string::npos || eq == 0) throw Error("override '" + shown(o) + "': expected key.path=value");
    const std::string path = o.substr(0, eq);
    YAML::Node value;
    try {
      value = YAML::Load(o.substr(eq + 1));
    } catch (const YAML::DeepRecursion&) {
      throw Error("override '" + shown(o) + "': nested too deeply (more than " +
                  std::to_string(kMaxYamlDepth) + " levels)");
    } catch (const YAML::Exception& e) {
      throw Error("override '" + shown(o) + "': " + shown(e.msg));
    }
    // Build {a: {b: value}} and merge it like a file, so the same checks apply.
    YAML::Node tree = value;
    for (size_t end = path.size(); ;) {
      const size_t dot = path.rfind('.', end - 1);
      const std::string key = path.substr(dot == std::string::npos ? 0 : dot + 1,
                                          end - (dot == std::string::npos ? 0 : dot + 1));
      YAML::Node m(YAML::NodeType::Map);
      m[key] = tree;
      tree = m;
      if (dot == std::string::npos) break;
      end = dot;
    }
    merge(tree, cfg, schema, "", "command line '" + shown(o) + "'", budget, origins);
  }
  return cfg;
}

std::string origin_of_message(const ConfigOrigins& origins, const std::string& message) {
  const std::string key = message.substr(0, message.find(": "));
  // The setting itself, or the free-form section it lies in (stages.video.options.motion).
  for (std::string k = key;; k.erase(k.rfind('.'))) {
    if (const auto it = origins.find(k); it != origins.end()) return it->second;
    if (k.find('.') == std::string::npos) return "";
  }
}

}  // namespace svgm
