// The files each stage of the pipeline reads and writes in the run directory, in pipeline
// order: what the stage runner hashes (pipeline.h), the names a run directory owns
// (run_directory.h) and the page's list of intermediates (report/report_page.h) read them here.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace svgm {

struct StageFiles {
  std::string stage;
  nlohmann::json inputs, outputs;  // name -> path relative to the run directory
};

// The files each stage reads and writes, in pipeline order.
const std::vector<StageFiles>& stage_files();

}  // namespace svgm
