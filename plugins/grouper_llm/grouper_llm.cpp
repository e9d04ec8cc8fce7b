// grouper `llm`: asks an OpenAI-compatible chat-completions endpoint which paths move together.
//
// Settings (stages.grouper.options): url (required, e.g. http://127.0.0.1:8080/v1/chat/completions),
// model, api_key_env (name of the environment variable holding the key; sent as
// "Authorization: Bearer <key>" when that variable is set and not empty), timeout_s (default 60),
// max_groups (default: stages.grouper.max_groups, else 15).
//
// Request: {"model": ..., "temperature": 0, "messages": [{"role": "system", "content": INSTRUCTIONS},
//   {"role": "user", "content": [{"type": "text", "text": SVG source + path ids in paint order +
//   the motion prompt}, {"type": "image_url", "image_url": {"url": "data:image/png;base64,..."}}]}]}
// Expected answer (choices[0].message.content, optionally inside ```json fences):
//   {"groups": [{"name": "...", "paths": ["id1", ...]}, ...]}
// checked strictly: every path id in exactly one group, no unknown ids, 1..max_groups non-empty
// groups. On any failure (no url, connection, timeout, HTTP status, malformed JSON, invalid
// grouping, render failure) the structural grouper decides instead, with one warning line naming
// the reason. grouped.svg has the groups in paint order of their first path, each group's paths
// in paint order.

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/chat_client.h"
#include "common/plugin_glue.h"
#include "common/stage_files.h"
#include "group/grouped_svg.h"
#include "group/structural_grouper.h"
#include "svgmotion/error.h"
#include "svgmotion/png_io.h"
#include "svgmotion/svg_reader.h"

namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;
namespace chat = svgm::plugin::chat;
using chat::base64;
using chat::one_line;
using Fallback = chat::Failure;  // a reason to fall back to the structural grouper (one line)

constexpr size_t kMaxSvgChars = 256 * 1024;  // SVG source sent as text, at most
constexpr int kRenderWidth = 512;            // width of the PNG sent along

std::string read_file(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  if (!f) throw Fallback("cannot read " + p.string());
  return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}

struct Settings : chat::Settings {
  int max_groups = 15;
};

Settings read_settings(const json& config) {
  Settings s;
  if (config.contains("max_groups") && config["max_groups"].is_number_integer())
    s.max_groups = config["max_groups"].get<int>();
  const json opts = config.contains("options") && config["options"].is_object() ? config["options"] : json::object();
  if (opts.contains("max_groups")) {
    if (!opts["max_groups"].is_number_integer() || opts["max_groups"].get<int>() < 1)
      throw Fallback("options.max_groups must be a positive integer");
    s.max_groups = opts["max_groups"].get<int>();
  }
  static_cast<chat::Settings&>(s) = chat::read_settings(opts, "grouper");
  return s;
}

std::string instructions(int max_groups) {
  return "You split an SVG drawing into parts for animation. Each part is a set of paths that move "
         "together rigidly (for example a head, a forearm, a leg, a wheel), so that the requested "
         "motion can be made by moving each part on its own. Use every path id exactly once, use only "
         "the ids given, and make between 1 and " + std::to_string(max_groups) +
         " parts. Answer with JSON only, no other text, in exactly this form: "
         "{\"groups\": [{\"name\": \"part name\", \"paths\": [\"id1\", \"id2\"]}]}";
}

std::string user_text(const std::string& svg_source, const svgm::Scene& scene, const std::string& prompt) {
  std::ostringstream t;
  t << "SVG source";
  if (svg_source.size() > kMaxSvgChars) t << " (first " << kMaxSvgChars << " bytes)";
  t << ":\n```svg\n" << svg_source.substr(0, kMaxSvgChars) << "\n```\n\n";
  t << "Path ids in paint order (first is drawn first, at the bottom), " << scene.paths.size() << " paths:\n";
  for (const auto& p : scene.paths) {
    t << "- " << p.id << " (" << p.tag;
    if (p.has_fill) t << ", fill " << svgm::plugin::hex_color(p.fill);
    if (p.has_stroke) t << ", stroke " << svgm::plugin::hex_color(p.stroke.color);
    t << ")\n";
  }
  t << "\nMotion: " << (prompt.empty() ? std::string("(not described; group by natural moving parts)") : prompt)
    << "\n\nThe attached image is a render of the SVG.";
  return t.str();
}

std::vector<std::vector<int>> parse_groups(const std::string& text, const svgm::Scene& scene, int max_groups,
                                           std::vector<std::string>& names) {
  json a;
  try {
    a = json::parse(chat::strip_fences(text));
  } catch (const json::exception& e) {
    throw Fallback("malformed JSON in the answer: " + one_line(e.what(), 200));
  }
  if (!a.is_object() || !a.contains("groups") || !a["groups"].is_array())
    throw Fallback("malformed JSON in the answer: no \"groups\" list");
  const json& gs = a["groups"];
  if (gs.empty() || gs.size() > static_cast<size_t>(max_groups))
    throw Fallback("invalid grouping: " + std::to_string(gs.size()) + " groups (expected 1.." +
                   std::to_string(max_groups) + ")");
  std::map<std::string, int> index;
  for (size_t i = 0; i < scene.paths.size(); ++i)
    if (!index.emplace(scene.paths[i].id, static_cast<int>(i)).second)
      throw Fallback("the SVG has two paths with id '" + scene.paths[i].id + "'");
  std::vector<int> owner(scene.paths.size(), -1);
  std::vector<std::vector<int>> groups;
  for (const auto& g : gs) {
    if (!g.is_object() || !g.contains("paths") || !g["paths"].is_array())
      throw Fallback("invalid grouping: a group without a \"paths\" list");
    if (g.contains("name") && !g["name"].is_string()) throw Fallback("invalid grouping: a group name is not a string");
    const std::string name = g.value("name", "group " + std::to_string(groups.size() + 1));
    if (g["paths"].empty()) throw Fallback("invalid grouping: group '" + one_line(name, 60) + "' is empty");
    std::vector<int> members;
    for (const auto& id : g["paths"]) {
      if (!id.is_string()) throw Fallback("invalid grouping: a path id is not a string");
      const auto it = index.find(id.get<std::string>());
      if (it == index.end()) throw Fallback("invalid grouping: unknown path id '" + one_line(id.get<std::string>(), 60) + "'");
      if (owner[it->second] != -1)
        throw Fallback("invalid grouping: path '" + it->first + "' appears more than once");
      owner[it->second] = static_cast<int>(groups.size());
      members.push_back(it->second);
    }
    groups.push_back(std::move(members));
    names.push_back(name);
  }
  for (size_t i = 0; i < owner.size(); ++i)
    if (owner[i] == -1) throw Fallback("invalid grouping: path '" + scene.paths[i].id + "' is in no group");
  // Paint order: paths within a group, then groups by their first path.
  for (auto& g : groups) std::sort(g.begin(), g.end());
  std::vector<size_t> order(groups.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t x, size_t y) { return groups[x].front() < groups[y].front(); });
  std::vector<std::vector<int>> sorted;
  std::vector<std::string> sorted_names;
  for (size_t i : order) {
    sorted.push_back(std::move(groups[i]));
    sorted_names.push_back(std::move(names[i]));
  }
  names = std::move(sorted_names);
  return sorted;
}

std::vector<std::vector<int>> ask(const json& req, const svgm::Scene& scene, const fs::path& svg,
                                  const Settings& s, const svgm_host* host, std::vector<std::string>& names) {
  if (scene.paths.empty()) throw Fallback("the SVG has no paths");
  auto progress = [&](double f, const char* note) {
    if (host && host->progress) host->progress(host, f, note);
  };
  progress(0.05, "rendering the SVG for the model");
  std::string png_bytes;
  try {
    png_bytes = svgm::encode_png(svgm::plugin::render_image(scene, kRenderWidth, req.value("device", "auto")));
  } catch (const std::exception& e) {
    throw Fallback(std::string("cannot render the SVG: ") + one_line(e.what(), 200));
  }

  const std::string prompt = req.contains("prompt") && req["prompt"].is_string() ? req["prompt"].get<std::string>() : "";
  const json body = {
      {"model", s.model},
      {"messages",
       json::array({{{"role", "system"}, {"content", instructions(s.max_groups)}},
                    {{"role", "user"},
                     {"content", json::array({{{"type", "text"}, {"text", user_text(read_file(svg), scene, prompt)}},
                                              {{"type", "image_url"},
                                               {"image_url", {{"url", "data:image/png;base64," + base64(png_bytes)}}}}})}}})},
      {"temperature", 0}};
  progress(0.2, "waiting for the model");
  const std::string reply = chat::post(s, body.dump(-1, ' ', false, json::error_handler_t::replace), host, "grouper llm");
  progress(0.9, "checking the answer");
  return parse_groups(chat::answer_text(reply), scene, s.max_groups, names);
}

json run(const json& req, const svgm_host* host) {
  namespace P = svgm::plugin;
  const auto in = P::file(req, "inputs", "svg");
  const svgm::Scene scene = svgm::read_svg_file(in);
  const json& config = req.at("config");
  std::vector<std::vector<int>> groups;
  std::vector<std::string> names;
  std::string source = "llm";
  int max_groups = config.value("max_groups", 15);
  try {
    const Settings s = read_settings(config);
    max_groups = s.max_groups;
    groups = ask(req, scene, in, s, host, names);
  } catch (const Fallback& f) {
    const std::string reason = one_line(f.what());
    if (host && host->log) host->log(host, 2, ("grouper llm: " + reason + "; using the structural grouper").c_str());
    svgm::GroupingOptions o;
    o.max_groups = std::max(1, max_groups);
    groups = svgm::group_paths(scene, o);
    names.clear();
    source = "structural (fallback: " + reason + ")";
  }
  svgm::write_grouped_svg(in, scene, groups, P::file(req, "outputs", "svg"), names);
  json r = {{"message", std::to_string(groups.size()) + " groups (" + (source == "llm" ? "llm" : "structural fallback") + ")"},
            {"source", source},
            {"groups", groups.size()}};
  if (!names.empty()) r["names"] = names;
  // A fallback depends on the network being down: let the next run ask again.
  if (source != "llm") r["cache"] = false;
  return r;
}

}  // namespace

SVGM_DEFINE_PLUGIN("grouper", "llm", "1", "groups from an OpenAI-compatible vision chat model (falls back to structural)", run)
