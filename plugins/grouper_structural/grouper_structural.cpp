// grouper `structural` (default): keeps meaningful existing groups, otherwise clusters paths
// that move together (containment, overlap, adjacency, colour), and writes grouped.svg with
// flat <g> elements in paint order (engine/src/group).
#include "common/plugin_glue.h"
#include "group/grouped_svg.h"
#include "group/structural_grouper.h"
#include "svgmotion/svg_reader.h"

namespace {

nlohmann::json run(const nlohmann::json& req, const svgm_host*) {
  namespace P = svgm::plugin;
  const auto in = P::file(req, "inputs", "svg");
  const svgm::Scene scene = svgm::read_svg_file(in);
  svgm::GroupingOptions o;
  o.max_groups = req.at("config").value("max_groups", 15);
  std::string note;
  const auto groups = svgm::group_paths(scene, o, &note);
  svgm::write_grouped_svg(in, scene, groups, P::file(req, "outputs", "svg"));
  std::string message = std::to_string(groups.size()) + " groups";
  if (!note.empty()) message += " (" + note + ")";
  return {{"message", message}, {"groups", groups.size()}};
}

}  // namespace

SVGM_DEFINE_PLUGIN("grouper", "structural", "1", "groups from structure: containment, overlap, adjacency", run)
