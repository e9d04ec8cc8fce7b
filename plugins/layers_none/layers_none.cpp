// layers `none`: keeps the paint order; layered.svg is a copy of grouped.svg.
#include "common/plugin_glue.h"
#include "common/stage_files.h"

namespace {

nlohmann::json run(const nlohmann::json& req, const svgm_host*) {
  svgm::plugin::copy_atomic(svgm::plugin::file(req, "inputs", "svg"), svgm::plugin::file(req, "outputs", "svg"));
  svgm::plugin::write_json(svgm::plugin::file(req, "outputs", "layers"),
                           {{"order", "unchanged"}, {"reason", "layers plugin 'none'"}});
  return {{"message", "paint order kept"}};
}

}  // namespace

SVGM_DEFINE_PLUGIN("layers", "none", "1", "keeps the paint order", run)
