// recolorer `none`: keeps the original colours. recolored.svg is a copy of grouped.svg,
// recolored.png its render, palette.json each path's own fill (or stroke) colour.
#include "common/plugin_glue.h"
#include "common/stage_files.h"
#include "svgmotion/svg_reader.h"

namespace {

nlohmann::json run(const nlohmann::json& req, const svgm_host*) {
  namespace P = svgm::plugin;
  const auto svg = P::file(req, "inputs", "svg");
  const svgm::Scene scene = svgm::read_svg_file(svg);
  P::copy_atomic(svg, P::file(req, "outputs", "svg"));
  P::render_png(scene, 512, req.value("device", "auto"), P::file(req, "outputs", "png"));
  nlohmann::json colors = nlohmann::json::object();
  for (const auto& p : scene.paths) colors[p.id] = P::hex_color(p.has_fill ? p.fill : p.stroke.color);
  P::write_json(P::file(req, "outputs", "palette"), {{"colors", colors}});
  return {{"message", "original colours kept"}};
}

}  // namespace

SVGM_DEFINE_PLUGIN("recolorer", "none", "1", "keeps the original colours", run)
