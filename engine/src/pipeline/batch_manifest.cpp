// Reading batch manifests (see batch_manifest.h).
#include "pipeline/batch_manifest.h"

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "pipeline/config.h"
#include "svgmotion/error.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

// The largest manifest read: a 100,000-item CSV is about 15 MB. A manifest is read whole.
constexpr uintmax_t kMaxManifestBytes = 64u << 20;

// What a YAML manifest may expand to through aliases, over all its items: the text it yields
// (ids, paths, prompts, overrides) and the values it visits. An alias repeats its anchor's node
// wherever it is used, so a few hundred bytes of aliases of aliases name 10^9 overrides (the
// "billion laughs": 1.8 GB in 30 s before this cap). Without aliases the text is at most the
// file; ten values an item covers a million items. Each item's overrides are also held to the
// config loader's own cap (kMaxConfigValues), since the item's run loads them as a config.
constexpr size_t kMaxManifestText = 64u << 20;
constexpr size_t kMaxManifestValues = 10000000;

// An id longer than this would make run directory names some file systems refuse (255 bytes).
constexpr size_t kMaxIdLength = 200;

// What reading one YAML manifest has left to produce; `where` names the place in the error.
struct ManifestBudget {
  std::string file;
  size_t text = kMaxManifestText, values = kMaxManifestValues;
  size_t item_values = kMaxConfigValues;  // reset for each item's overrides
  void take_value() {
    if (values == 0)
      throw Error(file + ": expands to more than " + std::to_string(kMaxManifestValues) +
                  " values (YAML aliases of aliases?)");
    --values;
  }
  void take_override_value(const std::string& where) {
    take_value();
    if (item_values == 0)
      throw Error(where + ": overrides expand to more than " + std::to_string(kMaxConfigValues) +
                  " values (YAML aliases of aliases?)");
    --item_values;
  }
  const std::string& take_text(const std::string& s, const std::string& where) {
    if (s.size() > text)
      throw Error(where + ": the manifest expands to more than " + std::to_string(kMaxManifestText >> 20) +
                  " MB of text (YAML aliases?)");
    text -= s.size();
    return s;
  }
};

const std::vector<std::string>& known_fields() {
  static const std::vector<std::string> f = {"id", "input", "prompt", "target", "overrides"};
  return f;
}

bool is_id_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_' ||
         c == '-';
}

// One CSV record starting at `pos` (which it advances); quoted fields may span lines, and
// `line` counts the newlines consumed.
std::vector<std::string> csv_record(const std::string& text, size_t& pos, int& line, const std::string& where) {
  std::vector<std::string> fields(1);
  bool quoted = false, was_quoted = false;
  const int start_line = line;
  while (pos < text.size()) {
    const char c = text[pos++];
    if (quoted) {
      if (c == '"' && pos < text.size() && text[pos] == '"') fields.back() += '"', ++pos;
      else if (c == '"') quoted = false;
      else fields.back() += c, line += c == '\n';
    } else if (c == '"' && fields.back().empty() && !was_quoted) {
      quoted = was_quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
      was_quoted = false;
    } else if (c == '\n') {
      ++line;
      break;
    } else if (c != '\r') {
      if (was_quoted) throw Error(where + ":" + std::to_string(line) + ": text after a closing quote");
      fields.back() += c;
    }
  }
  if (quoted) throw Error(where + ":" + std::to_string(start_line) + ": a quoted field is not closed");
  return fields;
}

std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

// Checks each override once (a 100,000-item manifest repeats a few), naming the row on error.
class OverrideChecker {
 public:
  void check(const std::string& o, const std::string& where) {
    if (checked_.count(o)) return;
    try {
      check_batch_override(o);
    } catch (const Error& e) {
      throw Error(where + ": " + e.what());
    }
    checked_.insert(o);
  }

 private:
  std::set<std::string> checked_;
};

std::vector<std::string> split_overrides(const std::string& s, const std::string& where, OverrideChecker& checker) {
  std::vector<std::string> out;
  std::istringstream in(s);
  for (std::string w; in >> w;) {
    checker.check(w, where);
    out.push_back(w);
  }
  return out;
}

// An id names a folder in OUT_DIR beside the batch's own files, so it may not climb out
// ('/', ".."), hide (a leading '.': the batch's locks are dot-files) or be one of those files
// or their temporaries (summary.csv.part<pid>); compared without case, for file systems that
// ignore it.
void check_id(const std::string& id, const std::string& where) {
  for (char c : id)
    if (!is_id_char(c)) throw Error(where + ": id '" + id + "' may hold only letters, digits, '.', '_' and '-'");
  if (id.front() == '.') throw Error(where + ": id '" + id + "' may not start with '.'");
  if (id.find("..") != std::string::npos) throw Error(where + ": id '" + id + "' may not contain '..'");
  if (id.size() > kMaxIdLength)
    throw Error(where + ": id '" + id.substr(0, 20) + "...' is longer than " + std::to_string(kMaxIdLength) +
                " characters");
  std::string lower = id;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* own : {"summary.csv", "summary.json"})
    if (lower.rfind(own, 0) == 0)
      throw Error(where + ": id '" + id + "' is taken by the batch's own " + own + " (give the item another id)");
}

// Fills in defaults and resolves paths; `fields` maps known field names to their text.
BatchItem make_item(const std::map<std::string, std::string>& fields, std::vector<std::string> overrides,
                    const fs::path& base, const std::string& where, int line) {
  BatchItem item;
  item.line = line;
  auto get = [&](const char* k) {
    const auto it = fields.find(k);
    return it == fields.end() ? std::string() : it->second;
  };
  const std::string input = get("input");
  if (input.empty()) throw Error(where + ": the item has no input");
  item.input = fs::path(input).is_absolute() ? fs::path(input) : base / input;
  item.input = item.input.lexically_normal();
  if (const std::string t = get("target"); !t.empty())
    item.target = (fs::path(t).is_absolute() ? fs::path(t) : base / t).lexically_normal();
  item.prompt = get("prompt");
  item.overrides = std::move(overrides);
  item.id = get("id");
  if (item.id.empty()) {
    // The input's file name without its extension, made an id: other characters become '_'
    // and leading dots go (".hidden.svg" is "hidden"; a dot-file would be a hidden folder).
    std::string name = item.input.filename().string();
    if (const size_t dot = name.rfind('.'); dot != std::string::npos && dot > 0) name.erase(dot);
    name.erase(0, name.find_first_not_of('.'));
    for (char& c : name)
      if (!is_id_char(c)) c = '_';
    if (name.empty())
      throw Error(where + ": no id can be made from the input's name '" + input + "' (give the item an id)");
    item.id = name;
  }
  check_id(item.id, where);
  return item;
}

std::vector<BatchItem> read_csv(const fs::path& file, const std::string& text) {
  const std::string name = file.string();
  const fs::path base = file.parent_path();
  std::vector<BatchItem> items;
  std::vector<std::string> header;
  OverrideChecker checker;
  size_t pos = 0;
  int line = 1;
  while (pos < text.size()) {
    const int at = line;
    std::vector<std::string> rec = csv_record(text, pos, line, name);
    if (rec.size() == 1 && (trim(rec[0]).empty() || trim(rec[0]).front() == '#')) continue;
    const std::string where = name + ":" + std::to_string(at);
    if (header.empty()) {
      for (std::string& h : rec) {
        h = trim(h);
        if (std::find(known_fields().begin(), known_fields().end(), h) == known_fields().end())
          throw Error(where + ": unknown column '" + h + "' (columns: id, input, prompt, target, overrides)");
        if (std::count(rec.begin(), rec.end(), h) > 1) throw Error(where + ": column '" + h + "' appears twice");
      }
      if (std::find(rec.begin(), rec.end(), "input") == rec.end()) throw Error(where + ": no 'input' column");
      header = rec;
      continue;
    }
    if (rec.size() != header.size())
      throw Error(where + ": " + std::to_string(rec.size()) + " fields, the header has " +
                  std::to_string(header.size()));
    std::map<std::string, std::string> fields;
    for (size_t i = 0; i < rec.size(); ++i) fields[header[i]] = header[i] == "prompt" ? rec[i] : trim(rec[i]);
    items.push_back(make_item(fields, split_overrides(fields["overrides"], where, checker), base, where, at));
  }
  if (header.empty()) throw Error(name + ": no header row (columns: id, input, prompt, target, overrides)");
  return items;
}

// A map key as text: YAML allows lists and maps as keys ("? [a, b]\n: 1"), a manifest does not
// (yaml-cpp's own conversion said only "bad conversion").
std::string key_text(const YAML::Node& key, const std::string& where) {
  if (!key.IsScalar()) throw Error(where + ": a key must be a name, not a list or a map");
  return key.Scalar();
}

const char* kind(const YAML::Node& n) {
  return n.IsSequence() ? "a list" : n.IsMap() ? "a map" : "empty";
}

// Nested maps become dotted keys: {stages: {fitter: {iterations: 50}}} -> stages.fitter.iterations=50.
// Every value visited counts against the budget, and the depth is bounded: an alias inside its
// own anchor ("o: &o {a: *o}") is a cycle in yaml-cpp's node graph.
void flatten(const YAML::Node& n, const std::string& prefix, std::vector<std::string>& out, const std::string& where,
             ManifestBudget& budget, std::vector<const YAML::Node*>& path) {
  budget.take_override_value(where);
  if (n.IsMap()) {
    if (path.size() >= static_cast<size_t>(kMaxYamlDepth)) {
      for (size_t i = 0; i < path.size(); ++i)
        for (size_t j = i + 1; j < path.size(); ++j)
          if (path[i]->is(*path[j]))
            throw Error(where + ": overrides contain themselves (a YAML alias inside its own anchor)");
      throw Error(where + ": overrides nested too deeply (more than " + std::to_string(kMaxYamlDepth) + " levels)");
    }
    path.push_back(&n);
    for (const auto& kv : n) {
      const std::string key = key_text(kv.first, where + ": overrides" + (prefix.empty() ? "" : " '" + prefix + "'"));
      flatten(kv.second, prefix.empty() ? key : prefix + "." + key, out, where, budget, path);
    }
    path.pop_back();
  } else if (n.IsScalar()) {
    out.push_back(budget.take_text(prefix + "=" + n.Scalar(), where));
  } else {
    throw Error(where + ": override '" + prefix + "' must be a single value");
  }
}

std::vector<BatchItem> read_yaml(const fs::path& file, const std::string& text) {
  const std::string name = file.string();
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::DeepRecursion& e) {
    // yaml-cpp reports its nesting limit with the message "bad file".
    throw Error(name + ":" + std::to_string(e.mark.line + 1) + ": nested too deeply (more than " +
                std::to_string(kMaxYamlDepth) + " levels)");
  } catch (const YAML::Exception& e) {
    throw Error(name + ":" + std::to_string(e.mark.line + 1) + ": " + e.msg);
  }
  YAML::Node list = root;
  if (root.IsMap()) {
    for (const auto& kv : root) {
      const std::string at = name + ":" + std::to_string(kv.first.Mark().line + 1);
      if (const std::string k = key_text(kv.first, at); k != "items")
        throw Error(at + ": unknown key '" + k + "' (a manifest holds `items:`)");
    }
    list = root["items"];
  }
  if (!list || !list.IsSequence()) throw Error(name + ": expected a list of items (or `items:` with one)");
  ManifestBudget budget{name};
  OverrideChecker checker;
  std::vector<BatchItem> items;
  int number = 0;
  for (const auto& n : list) {
    const int line = n.Mark().line + 1;
    const std::string where = name + ":" + std::to_string(line);
    const std::string item = "item " + std::to_string(++number);
    budget.take_value();
    if (!n.IsMap()) throw Error(where + ": an item must be a map (input:, prompt:, ...)");
    std::map<std::string, std::string> fields;
    std::vector<std::string> overrides;
    budget.item_values = kMaxConfigValues;
    for (const auto& kv : n) {
      const std::string kw = name + ":" + std::to_string(kv.first.Mark().line + 1);
      budget.take_value();
      const std::string k = key_text(kv.first, kw + ": " + item);
      if (std::find(known_fields().begin(), known_fields().end(), k) == known_fields().end())
        throw Error(kw + ": unknown key '" + k + "' (keys: id, input, prompt, target, overrides)");
      if (k == "overrides") {
        std::vector<const YAML::Node*> path;
        if (kv.second.IsMap()) flatten(kv.second, "", overrides, kw + ": " + item, budget, path);
        else if (kv.second.IsSequence())
          for (const auto& o : kv.second) {
            budget.take_override_value(kw);
            if (!o.IsScalar()) throw Error(kw + ": " + item + ": each override is one key.path=value, not " + kind(o));
            const auto more = split_overrides(budget.take_text(o.Scalar(), kw), kw, checker);
            if (more.size() != 1) throw Error(kw + ": each override is one key.path=value");
            overrides.push_back(more[0]);
          }
        else if (!kv.second.IsNull()) throw Error(kw + ": overrides must be a map or a list of key=value");
      } else {
        if (!kv.second.IsScalar())
          throw Error(kw + ": " + item + ": '" + k + "' must be a single value, not " + kind(kv.second));
        fields[k] = budget.take_text(kv.second.Scalar(), kw);
      }
    }
    for (const std::string& o : overrides) checker.check(o, where);
    items.push_back(make_item(fields, std::move(overrides), file.parent_path(), where, line));
  }
  return items;
}

// Where the first NUL byte of `text` is (1-based line), or 0: a manifest is text, and a NUL
// would cut a path or prompt short where it reaches the C API.
int nul_line(const std::string& text) {
  const size_t at = text.find('\0');
  return at == std::string::npos ? 0 : 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

}  // namespace

void check_batch_override(const std::string& o) {
  // `svgmotion run` reads an argument starting with '-' as an option: "-o=DIR" in a manifest
  // ran the item elsewhere while the summary said done.
  if (!o.empty() && o.front() == '-')
    throw Error("override '" + o + "' is a command-line option, not a setting (overrides are key.path=value)");
  const size_t eq = o.find('=');
  if (eq == std::string::npos || eq == 0) throw Error("override '" + o + "' is not key.path=value");
  // The item's run takes these from the batch (its --input, --prompt and -o win over
  // overrides): an override of them would be ignored without a word.
  const std::string key = o.substr(0, eq);
  if (key == "input" || key == "prompt")
    throw Error("override '" + o + "': an item's " + key + " is its manifest field '" + key + "', not an override");
  if (key == "output") throw Error("override '" + o + "': an item's run directory is OUT_DIR/<id>, not an override");
  // The config reader's own check of the key path and the value's type (config.h).
  try {
    load_config(std::nullopt, {o});
  } catch (const Error& e) {
    const std::string m = e.what();
    const std::string cl = "command line ";
    throw Error(m.rfind(cl, 0) == 0 ? "override " + m.substr(cl.size()) : "override '" + o + "': " + m);
  }
}

std::vector<BatchItem> read_batch_manifest(const fs::path& file) {
  const std::string name = file.string();
  std::error_code ec;
  const fs::file_status st = fs::status(file, ec);
  if (fs::is_directory(st)) throw Error(name + ": is a directory, not a manifest");
  if (!fs::exists(st)) throw Error(name + ": cannot open: No such file");
  if (!fs::is_regular_file(st)) throw Error(name + ": not a regular file");
  std::string ext = file.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const bool yaml = ext == ".yaml" || ext == ".yml";
  if (!yaml && ext != ".csv") throw Error(name + ": a manifest is .csv, .yaml or .yml");
  if (const uintmax_t size = fs::file_size(file, ec); !ec && size > kMaxManifestBytes)
    throw Error(name + ": larger than " + std::to_string(kMaxManifestBytes >> 20) +
                " MB (split it into several manifests)");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(name + ": cannot open");
  std::ostringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  if (const int line = nul_line(text))
    throw Error(name + ":" + std::to_string(line) + ": a NUL byte (a manifest is text)");
  // A byte order mark (spreadsheets write one) would be part of the first column's name.
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
  std::vector<BatchItem> items = yaml ? read_yaml(file, text) : read_csv(file, text);
  if (items.empty()) throw Error(file.string() + ": no items");
  std::map<std::string, int> seen;
  for (const BatchItem& it : items)
    if (const auto [pos, fresh] = seen.emplace(it.id, it.line); !fresh)
      throw Error(file.string() + ":" + std::to_string(it.line) + ": id '" + it.id + "' is already used on line " +
                  std::to_string(pos->second) + " (give the item an id)");
  return items;
}

}  // namespace svgm
