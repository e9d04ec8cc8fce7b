// layers `masks`: reorders the SVG's top-level groups from occlusion evidence in the target
// video (where two groups' rest-pose shapes overlap, which group's palette colour the video
// shows there); see engine/src/group/layer_order.h for the method. Writes layered.svg (a byte
// copy of grouped.svg when the order does not change) and layers.json (order back to front,
// the per-pair evidence, and the fallback taken for cyclic evidence, if any).
//
// Config (stages.layers, or stages.layers.options): keyframes (15), size (256, analysis width
// in pixels), color_threshold (0.15), min_pixels (30), min_score (0.3), min_evidence_share (0.1),
// max_hidden_share (0.5).
#include <string>

#include "common/plugin_glue.h"
#include "common/stage_files.h"
#include "group/layer_order.h"

namespace {

template <typename T>
T setting(const nlohmann::json& config, const char* key, T fallback) {
  if (config.contains("options") && config["options"].is_object() && config["options"].contains(key))
    return config["options"][key].get<T>();
  if (config.contains(key)) return config[key].get<T>();
  return fallback;
}

nlohmann::json run(const nlohmann::json& req, const svgm_host* host) {
  using svgm::plugin::file;
  const nlohmann::json config = req.value("config", nlohmann::json::object());
  svgm::LayerOptions o;
  o.keyframes = setting(config, "keyframes", o.keyframes);
  o.width = setting(config, "size", o.width);
  o.color_threshold = setting(config, "color_threshold", o.color_threshold);
  o.min_pixels = setting(config, "min_pixels", o.min_pixels);
  o.min_score = setting(config, "min_score", o.min_score);
  o.min_evidence_share = setting(config, "min_evidence_share", o.min_evidence_share);
  o.max_hidden_share = setting(config, "max_hidden_share", o.max_hidden_share);
  std::optional<std::filesystem::path> original;
  if (req.at("inputs").contains("original")) original = file(req, "inputs", "original");
  if (host && host->progress) host->progress(host, 0.0, "reading the target");
  const svgm::LayerResult r =
      svgm::run_layers(file(req, "inputs", "svg"), file(req, "inputs", "target"),
                       file(req, "inputs", "palette"), file(req, "outputs", "svg"),
                       file(req, "outputs", "layers"), o, original);
  if (host && host->progress) host->progress(host, 1.0, "done");
  int used = 0;
  for (const svgm::LayerPair& p : r.pairs) used += p.used ? 1 : 0;
  std::string msg = r.changed ? "paint order changed" : "paint order kept";
  msg += " (" + std::to_string(r.pairs.size()) + " overlapping pairs, " + std::to_string(used) +
         " used)";
  if (r.fallback) {
    msg += "; " + *r.fallback;
    if (host && host->log) host->log(host, 2, r.fallback->c_str());
  }
  return {{"message", msg}, {"changed", r.changed}};
}

}  // namespace

SVGM_DEFINE_PLUGIN("layers", "masks", "1",
                   "orders the groups by occlusion evidence in the target video", run)
