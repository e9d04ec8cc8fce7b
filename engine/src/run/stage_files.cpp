// The stages' files in the run directory (see stage_files.h).
#include "run/stage_files.h"

namespace svgm {

const std::vector<StageFiles>& stage_files() {
  static const std::vector<StageFiles> s = {
      {"grouper", {{"svg", "input.svg"}}, {{"svg", "grouped.svg"}}},
      {"recolorer", {{"svg", "grouped.svg"}},
       {{"svg", "recolored.svg"}, {"png", "recolored.png"}, {"palette", "palette.json"}}},
      {"video", {{"image", "recolored.png"}, {"svg", "recolored.svg"}, {"original", "input.svg"}}, {{"candidates", "candidates"}}},
      {"ranker", {{"candidates", "candidates"}, {"palette", "palette.json"}, {"svg", "grouped.svg"}},
       {{"ranking", "ranking.json"}, {"target", "target.mp4"}}},
      {"layers",
       {{"svg", "grouped.svg"}, {"target", "target.mp4"}, {"palette", "palette.json"}, {"original", "input.svg"}},
       {{"svg", "layered.svg"}, {"layers", "layers.json"}}},
      {"tracker", {{"svg", "layered.svg"}, {"target", "target.mp4"}}, {{"tracks", "tracks.json"}}},
      {"fitter",
       {{"svg", "layered.svg"}, {"target", "target.mp4"}, {"palette", "palette.json"}, {"tracks", "tracks.json"},
        {"original", "input.svg"}},
       {{"animation", "animation.svg"}, {"lottie", "animation.json"}, {"preview", "preview.mp4"}, {"report", "fit.json"}}},
  };
  return s;
}

}  // namespace svgm
