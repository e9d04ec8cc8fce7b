// Reading and applying palette.json (see palette.h).
#include "color/palette_json.h"

#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "svgmotion/error.h"

namespace svgm {

namespace {

bool parse_hex(const std::string& s, Rgba* out) {
  auto hex = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
  };
  if (s.size() != 7 || s[0] != '#') return false;
  int v[6];
  for (int i = 0; i < 6; ++i)
    if ((v[i] = hex(s[1 + i])) < 0) return false;
  *out = {(v[0] * 16 + v[1]) / 255.f, (v[2] * 16 + v[3]) / 255.f, (v[4] * 16 + v[5]) / 255.f, 1.f};
  return true;
}

}  // namespace

std::map<std::string, Rgba> read_palette(const std::filesystem::path& file) {
  std::ifstream f(file);
  if (!f) throw Error(file.string() + ": cannot open: " + std::strerror(errno));
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(f);
  } catch (const nlohmann::json::exception& e) {
    throw Error(file.string() + ": not valid JSON: " + e.what());
  }
  const nlohmann::json& colors = j.is_object() && j.contains("colors") ? j["colors"] : j;
  if (!colors.is_object()) throw Error(file.string() + ": expected an object of path id -> \"#rrggbb\"");
  std::map<std::string, Rgba> out;
  for (const auto& [id, v] : colors.items()) {
    Rgba c;
    if (!v.is_string() || !parse_hex(v.get<std::string>(), &c))
      throw Error(file.string() + ": colour of '" + id + "' is not \"#rrggbb\"");
    out[id] = c;
  }
  return out;
}

Scene apply_palette(const Scene& scene, const std::map<std::string, Rgba>& palette,
                    const std::string& name) {
  Scene s = scene;
  std::set<std::string> used;
  for (Path& p : s.paths) {
    const auto it = palette.find(p.id);
    if (it == palette.end()) throw Error(name + ": no colour for path '" + p.id + "'");
    used.insert(p.id);
    const Rgba c = it->second;
    p.fill = {c.r, c.g, c.b, p.fill.a};
    p.stroke.color = {c.r, c.g, c.b, p.stroke.color.a};
  }
  for (const auto& [id, c] : palette)
    if (!used.count(id)) throw Error(name + ": path '" + id + "' is not in the SVG");
  return s;
}

}  // namespace svgm
