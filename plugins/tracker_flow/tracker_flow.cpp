// tracker `flow` (default): dense optical flow (OpenCV Farnebäck) between consecutive target
// keyframes, with forward-backward consistency as the certainty, sampled on a grid and written
// to tracks.json (engine/src/fit/optimise/flow_tracks.h). The fitter warm-starts each newly activated
// keyframe by moving the previous keyframe's fitted points along it.
#include "common/plugin_glue.h"
#include "common/stage_files.h"
#include "fit/optimise/flow_tracks.h"
#include "svgmotion/render_size.h"
#include "svgmotion/svg_reader.h"
#include "svgmotion/target_video.h"

namespace {

nlohmann::json run(const nlohmann::json& req, const svgm_host*) {
  namespace P = svgm::plugin;
  // The fitter's sampling, so that flow k is exactly the step into the fitter's keyframe k.
  const nlohmann::json& fitter = req.at("stages").at("fitter");
  const svgm::Scene scene = svgm::read_svg_file(P::file(req, "inputs", "svg"));
  const svgm::RenderSize size = svgm::render_size(scene, fitter.value("size", 256));
  svgm::TargetOptions o;
  o.keyframes = P::fitter_keyframes(req);
  o.white_threshold = fitter.value("mask_threshold", 0.97);
  const svgm::TargetFrames t = svgm::load_target(P::file(req, "inputs", "target"), size.width, size.height, o);
  const auto flows = svgm::compute_flows(t, req.at("config").value("grid", 32));
  svgm::write_tracks(P::file(req, "outputs", "tracks"), flows);
  return {{"message", std::to_string(flows.size() - 1) + " keyframe flows"}};
}

}  // namespace

SVGM_DEFINE_PLUGIN("tracker", "flow", "1", "optical flow between keyframes (Farneback, FB-checked)", run)
