// tracker `none`: no point tracks (the fitter still warm-starts keyframes from its own
// optical-flow tracking of each keyframe's render).
#include "common/plugin_glue.h"
#include "common/stage_files.h"

namespace {

nlohmann::json run(const nlohmann::json& req, const svgm_host*) {
  svgm::plugin::write_json(svgm::plugin::file(req, "outputs", "tracks"), {{"tracks", nlohmann::json::array()}});
  return {{"message", "no tracks"}};
}

}  // namespace

SVGM_DEFINE_PLUGIN("tracker", "none", "1", "no point tracks", run)
