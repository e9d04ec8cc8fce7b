// Reading batch manifests (see batch_manifest.h).
#include "pipeline/batch_manifest.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

#include "svgmotion/error.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

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

std::vector<std::string> split_overrides(const std::string& s, const std::string& where) {
  std::vector<std::string> out;
  std::istringstream in(s);
  for (std::string w; in >> w;) {
    if (w.find('=') == std::string::npos || w.front() == '=')
      throw Error(where + ": override '" + w + "' is not key.path=value");
    out.push_back(w);
  }
  return out;
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
    item.id = item.input.stem().string();
    for (char& c : item.id)
      if (!is_id_char(c)) c = '_';
  }
  for (char c : item.id)
    if (!is_id_char(c))
      throw Error(where + ": id '" + item.id + "' may hold only letters, digits, '.', '_' and '-'");
  if (item.id == "." || item.id == ".." || item.id.front() == '.')
    throw Error(where + ": id '" + item.id + "' may not start with '.'");
  return item;
}

std::vector<BatchItem> read_csv(const fs::path& file, const std::string& text) {
  const std::string name = file.string();
  const fs::path base = file.parent_path();
  std::vector<BatchItem> items;
  std::vector<std::string> header;
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
    items.push_back(make_item(fields, split_overrides(fields["overrides"], where), base, where, at));
  }
  if (header.empty()) throw Error(name + ": no header row (columns: id, input, prompt, target, overrides)");
  return items;
}

// Nested maps become dotted keys: {stages: {fitter: {iterations: 50}}} -> stages.fitter.iterations=50.
void flatten(const YAML::Node& n, const std::string& prefix, std::vector<std::string>& out, const std::string& where) {
  if (n.IsMap()) {
    for (const auto& kv : n) flatten(kv.second, prefix.empty() ? kv.first.as<std::string>() : prefix + "." + kv.first.as<std::string>(), out, where);
  } else if (n.IsScalar()) {
    out.push_back(prefix + "=" + n.Scalar());
  } else {
    throw Error(where + ": override '" + prefix + "' must be a single value");
  }
}

std::vector<BatchItem> read_yaml(const fs::path& file) {
  const std::string name = file.string();
  YAML::Node root;
  try {
    root = YAML::LoadFile(name);
  } catch (const YAML::Exception& e) {
    throw Error(name + ":" + std::to_string(e.mark.line + 1) + ": " + e.msg);
  }
  YAML::Node list = root;
  if (root.IsMap()) {
    for (const auto& kv : root)
      if (kv.first.as<std::string>() != "items")
        throw Error(name + ":" + std::to_string(kv.first.Mark().line + 1) + ": unknown key '" +
                    kv.first.as<std::string>() + "' (a manifest holds `items:`)");
    list = root["items"];
  }
  if (!list || !list.IsSequence()) throw Error(name + ": expected a list of items (or `items:` with one)");
  std::vector<BatchItem> items;
  for (const auto& n : list) {
    const int line = n.Mark().line + 1;
    const std::string where = name + ":" + std::to_string(line);
    if (!n.IsMap()) throw Error(where + ": an item must be a map (input:, prompt:, ...)");
    std::map<std::string, std::string> fields;
    std::vector<std::string> overrides;
    for (const auto& kv : n) {
      const std::string k = kv.first.as<std::string>();
      const std::string kw = name + ":" + std::to_string(kv.first.Mark().line + 1);
      if (std::find(known_fields().begin(), known_fields().end(), k) == known_fields().end())
        throw Error(kw + ": unknown key '" + k + "' (keys: id, input, prompt, target, overrides)");
      if (k == "overrides") {
        if (kv.second.IsMap()) flatten(kv.second, "", overrides, kw);
        else if (kv.second.IsSequence())
          for (const auto& o : kv.second) {
            const auto more = split_overrides(o.IsScalar() ? o.Scalar() : "", kw);
            if (more.size() != 1) throw Error(kw + ": each override is one key.path=value");
            overrides.push_back(more[0]);
          }
        else if (!kv.second.IsNull()) throw Error(kw + ": overrides must be a map or a list of key=value");
      } else {
        if (!kv.second.IsScalar()) throw Error(kw + ": '" + k + "' must be a single value");
        fields[k] = kv.second.Scalar();
      }
    }
    items.push_back(make_item(fields, std::move(overrides), file.parent_path(), where, line));
  }
  return items;
}

}  // namespace

std::vector<BatchItem> read_batch_manifest(const fs::path& file) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) throw Error(file.string() + ": cannot open: No such file");
  const std::string ext = file.extension().string();
  std::vector<BatchItem> items;
  if (ext == ".yaml" || ext == ".yml") {
    items = read_yaml(file);
  } else if (ext == ".csv") {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    items = read_csv(file, ss.str());
  } else {
    throw Error(file.string() + ": a manifest is .csv, .yaml or .yml");
  }
  if (items.empty()) throw Error(file.string() + ": no items");
  std::map<std::string, int> seen;
  for (const BatchItem& it : items)
    if (const auto [pos, fresh] = seen.emplace(it.id, it.line); !fresh)
      throw Error(file.string() + ":" + std::to_string(it.line) + ": id '" + it.id + "' is already used on line " +
                  std::to_string(pos->second) + " (give the item an id)");
  return items;
}

}  // namespace svgm
