// fitter `opencl`: the differentiable fitter (engine/src/fit) behind the plugin interface. Fits
// layered.svg to target.mp4 (in the palette's colours, or the SVG's own for a user's video, see
// stages.fitter.colors) and writes animation.svg (the layered document in its original
// colours), preview.mp4, fit.json and checkpoint.bin.
#include "common/plugin_glue.h"
#include "fit/fit_job.h"

namespace {

nlohmann::json run(const nlohmann::json& req, const svgm_host* host) {
  namespace P = svgm::plugin;
  const nlohmann::json& c = req.at("config");
  svgm::FitJob job;
  job.svg = P::file(req, "inputs", "svg");
  job.export_into = job.svg;
  job.target = P::file(req, "inputs", "target");
  // Colours to fit in: the palette's when the target video was made from the recoloured image
  // (generators), the SVG's own when it is the user's video (`video: file`), unless set.
  const std::string colors = c.value("colors", "auto");
  const bool user_video = req.at("stages").at("video").value("plugin", "") == "file";
  if (colors == "palette" || (colors == "auto" && !user_video)) job.palette = P::file(req, "inputs", "palette");
  else if (colors != "original" && colors != "auto")
    throw std::runtime_error("stages.fitter.colors must be auto, palette or original, not '" + colors + "'");
  job.tracks = P::file(req, "inputs", "tracks");
  job.out = req.at("run_dir").get<std::string>();
  job.options.iterations = c.value("iterations", 2000);
  job.options.track = c.value("track", true);
  job.keyframes = c.value("keyframes", 15);
  job.width = c.value("size", 256);
  job.mask_threshold = c.value("mask_threshold", 0.97);
  job.device = req.value("device", "auto");
  job.quiet = true;
  const int rc = svgm::run_fit_job(job, [host] { return host->cancelled(host) != 0; });
  if (rc != 0) throw std::runtime_error("fit interrupted");
  return {{"message", "fitted"}};
}

}  // namespace

SVGM_DEFINE_PLUGIN("fitter", "opencl", "1", "differentiable fitting on OpenCL", run)
