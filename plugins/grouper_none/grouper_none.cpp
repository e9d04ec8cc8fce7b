// grouper `none`: keeps the document as it is (its own top-level groups, one group per loose
// path): grouped.svg is a copy of the input.
#include "common/plugin_glue.h"
#include "common/stage_files.h"

namespace {

nlohmann::json run(const nlohmann::json& req, const svgm_host*) {
  svgm::plugin::copy_atomic(svgm::plugin::file(req, "inputs", "svg"), svgm::plugin::file(req, "outputs", "svg"));
  return {{"message", "kept the document's own groups"}};
}

}  // namespace

SVGM_DEFINE_PLUGIN("grouper", "none", "1", "keeps the SVG's own groups", run)
