// Small file helpers shared by svgmotion's built-in plugins (see stage_files.h).
#include "common/stage_files.h"
#include "common/plugin_glue.h"
#include "svgmotion/atomic_file.h"
#include "svgmotion/temporary_name.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "opencl/runtime.h"
#include "raster/raster_cl.h"
#include "svgmotion/error.h"
#include "svgmotion/png_io.h"
#include "svgmotion/render_size.h"
#include "svgmotion/target_video.h"
#include "color/palette_json.h"
#include "media/preview_video.h"
#include "svgmotion/svg_reader.h"
#include "generators/candidates.h"
#include "svgmotion/utf8_text.h"

namespace svgm::plugin {

namespace fs = std::filesystem;

void copy_atomic(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  const bool folder = fs::is_directory(from, ec);
  // A file lands as write_file_atomic writes one (a device or FIFO at `to` is refused, a link
  // is written through); a folder replaces a folder or file of ours, never anything else.
  const fs::path dest = folder ? to : output_target(to);
  if (folder) {
    const fs::file_type t = fs::symlink_status(to, ec).type();
    if (!ec && t != fs::file_type::not_found && t != fs::file_type::directory &&
        t != fs::file_type::regular)
      throw Error(to.string() + ": not a directory");
  }
  const fs::path tmp = temporary_path(dest);
  fs::remove_all(tmp, ec);
  fs::copy(from, tmp, fs::copy_options::recursive, ec);
  if (ec) {
    fs::remove_all(tmp, ec);
    throw Error(from.string() + ": cannot copy: " + ec.message());
  }
  if (folder) fs::remove_all(dest, ec);
  fs::rename(tmp, dest, ec);
  if (ec) {
    const std::string why = ec.message();
    fs::remove_all(tmp, ec);
    throw Error(to.string() + ": cannot write: " + why);
  }
}

void write_json(const fs::path& file, const nlohmann::json& j) {
  write_file_atomic(file, json_text(j, 2) + "\n");
}

RgbaImage render_image(const Scene& scene, int width, const std::string& device) {
  const RenderSize size = render_size(scene, width);
  const RasterPlan plan = plan_raster(scene, size.view, size.width, size.height);
  ClRuntime rt(device);
  ClRaster r(rt, plan, 1);
  r.set_rest_pose();
  r.forward(ClRaster::Output::Rgba8, {1, 1, 1, 1});
  return RgbaImage{size.width, size.height, r.read_rgba8()};
}

void render_png(const Scene& scene, int width, const std::string& device, const fs::path& file) {
  write_png(file, render_image(scene, width, device));
}

std::string hex_color(const Rgba& c) {
  char b[8];
  auto v = [](float x) { return static_cast<int>(std::lround(std::clamp(x, 0.f, 1.f) * 255)); };
  std::snprintf(b, sizeof b, "#%02x%02x%02x", v(c.r), v(c.g), v(c.b));
  return b;
}

void write_target(const fs::path& chosen, const fs::path& target) { write_target_video(chosen, target); }

std::vector<Rgba> candidate_colours(const nlohmann::json& req, const std::string& who) {
  const nlohmann::json& stages = req.at("stages");
  const std::string colors = stages.at("fitter").value("colors", "auto");
  const bool user_video = stages.at("video").value("plugin", "") == "file";
  std::vector<Rgba> out;
  if (colors == "original" || (colors == "auto" && user_video)) {
    for (const Path& p : read_svg_file(file(req, "inputs", "svg")).paths) {
      if (p.has_fill) out.push_back(p.fill);
      if (p.has_stroke) out.push_back(p.stroke.color);
    }
    if (out.empty()) throw Error(who + ": the SVG has no coloured paths");
    return out;
  }
  for (const auto& [id, c] : read_palette(file(req, "inputs", "palette"))) out.push_back(c);
  if (out.empty()) throw Error(who + ": palette.json has no colours");
  return out;
}

std::map<std::string, int> candidate_keyframes(const nlohmann::json& req) {
  std::map<std::string, int> out;
  if (req.at("stages").at("video").value("plugin", "") != "procedural" || !req.contains("run_dir")) return out;
  std::ifstream in(std::filesystem::path(req.at("run_dir").get<std::string>()) / "motion.json");
  const nlohmann::json m = nlohmann::json::parse(in, nullptr, false);
  if (!m.is_object() || !m.contains("candidates") || !m.at("candidates").is_array()) return out;
  for (const auto& c : m.at("candidates"))
    if (c.is_object() && c.contains("name") && c.at("name").is_string() && c.contains("keyframes") && c.at("keyframes").is_number_integer())
      out[c.at("name").get<std::string>()] = c.at("keyframes").get<int>();
  return out;
}

int fitter_keyframes(const nlohmann::json& req, std::string* why) {
  const int asked = req.at("stages").at("fitter").value("keyframes", 15);
  const std::map<std::string, int> asks = candidate_keyframes(req);
  if (asks.empty()) return asked;
  // The ranker's choice, else the first candidate (the one motion.json describes).
  std::ifstream ranking(std::filesystem::path(req.at("run_dir").get<std::string>()) / "ranking.json");
  const nlohmann::json r = nlohmann::json::parse(ranking, nullptr, false);
  const std::string chosen = r.is_object() && r.contains("chosen") && r.at("chosen").is_string() ? r.at("chosen").get<std::string>() : "";
  const auto it = asks.count(chosen) ? asks.find(chosen) : asks.begin();
  const int need = std::min(it->second, 2 * (asked - 1) + 1);
  if (need <= asked) return asked;
  if (why)
    *why = std::to_string(need) + " keyframes instead of " + std::to_string(asked) + ": the procedural motion moves too far between " +
           std::to_string(asked) + " to follow";
  return need;
}

}  // namespace svgm::plugin
