// fitter `opencl`: the differentiable fitter (engine/src/fit) behind the plugin interface. Fits
// layered.svg (the working copy) to target.mp4 (in the palette's colours, or the SVG's own for a
// user's video, see stages.fitter.colors) and writes animation.svg into the user's own document
// (input.svg: every element, id, style, gradient, comment and root attribute kept, only `d`
// animated, the layers stage's paint order applied by moving just the elements it must), the
// same animation as Lottie (animation.json), preview.mp4, fit.json and checkpoint.bin. A fit the result gate rejects answers
// "rejected": 3 (svgm::Rejected) with animation.failed.svg written instead.
#include <fstream>

#include "common/plugin_glue.h"
#include "common/stage_files.h"
#include "fit/fit_job.h"

namespace {

nlohmann::json run(const nlohmann::json& req, const svgm_host* host) {
  namespace P = svgm::plugin;
  const nlohmann::json& c = req.at("config");
  svgm::FitJob job;
  job.svg = P::file(req, "inputs", "svg");
  job.export_into = P::file(req, "inputs", "original");
  job.export_name = req.value("input", "");
  job.target = P::file(req, "inputs", "target");
  // Colours to fit in: the palette's when the target video was made from the recoloured image
  // (generators), the SVG's own when it is the user's video (`video: file`), unless set.
  const std::string colors = c.value("colors", "auto");
  const bool user_video = req.at("stages").at("video").value("plugin", "") == "file";
  if (colors == "palette" || (colors == "auto" && !user_video)) job.palette = P::file(req, "inputs", "palette");
  else if (colors != "original" && colors != "auto")
    throw std::runtime_error("stages.fitter.colors must be auto, palette or original, not '" + colors + "'");
  job.tracks = P::file(req, "inputs", "tracks");
  // The procedural video's report says which paths its target moves (motion_groups.h). It is
  // the video stage's output beside the chosen candidate: its parts and travels are those of
  // the first candidate, and the candidates differ only in amplitudes and directions.
  // stages.fitter.motion_groups: false fits the grouper's groups as they are.
  if (!user_video && c.value("motion_groups", true) && req.at("stages").at("video").value("plugin", "") == "procedural") {
    const std::filesystem::path motion = std::filesystem::path(req.at("run_dir").get<std::string>()) / "motion.json";
    if (std::filesystem::exists(motion)) job.motion = motion;
    // The ranker's choice names the candidate whose known motion is the target's.
    std::ifstream ranking(std::filesystem::path(req.at("run_dir").get<std::string>()) / "ranking.json");
    const nlohmann::json r = nlohmann::json::parse(ranking, nullptr, false);
    if (!r.is_discarded() && r.is_object()) job.motion_candidate = r.value("chosen", "");
  }
  job.out = req.at("run_dir").get<std::string>();
  job.options.iterations = c.value("iterations", 2000);
  job.options.track = c.value("track", true);
  if (!c.value("stop_when_converged", true)) job.options.plateau_window = 0;
  // A procedural motion too fast to follow between that many keyframes asks for more.
  std::string more;
  job.keyframes = svgm::plugin::fitter_keyframes(req, &more);
  if (!more.empty() && host && host->log) host->log(host, 1, ("fitter: " + more).c_str());
  job.width = c.value("size", 256);
  // max_keyframes: auto (the default) or the most keyframes the fit may add up to (fit_job.h).
  if (c.contains("max_keyframes") && c.at("max_keyframes").is_number_integer()) job.max_keyframes = c.at("max_keyframes").get<int>();
  // start: auto (decided from the first frame), rest or free (keyframe 0; rest_start.h).
  const std::string start = c.value("start", "auto");
  if (start == "rest") job.start_at_rest = true;
  else if (start == "free") job.start_at_rest = false;
  else if (start != "auto") throw std::runtime_error("stages.fitter.start must be auto, rest or free, not '" + start + "'");
  job.mask_threshold = c.value("mask_threshold", 0.97);
  // refine_size: auto (the default), 0 (off) or a width in pixels.
  if (c.contains("refine_size")) job.refine_width = c.at("refine_size").is_number_integer() ? c.at("refine_size").get<int>() : -1;
  job.device = req.value("device", "auto");
  const std::string deform = c.value("deform", "field");
  if (deform == "free") job.options.use_free_offsets();
  else if (deform != "field") throw std::runtime_error("stages.fitter.deform must be field or free, not '" + deform + "'");
  job.loop = svgm::parse_loop_mode(c.value("loop", "loop"), "stages.fitter.loop");
  job.gate = c.value("gate", true);
  // stabilise: auto (the default: when the video shakes, fit/target/frame_scan.h), true or false.
  const nlohmann::json st = c.value("stabilise", nlohmann::json("auto"));
  if (st.is_boolean()) job.stabilise = st.get<bool>();
  else if (!st.is_string() || st.get<std::string>() != "auto")
    throw std::runtime_error("stages.fitter.stabilise must be auto, true or false, not '" + st.dump() + "'");
  job.denoise_radius = c.value("denoise", job.denoise_radius);
  // chroma_weight: auto (the default: calibrated only when the video's chroma is softer than
  // its luma, a codec's damage; a clean render keeps 1) or a number in (0, 1].
  const nlohmann::json cw = c.value("chroma_weight", nlohmann::json("auto"));
  job.chroma_weight_auto = cw.is_string();
  if (cw.is_string() && cw.get<std::string>() != "auto")
    throw std::runtime_error("stages.fitter.chroma_weight must be auto or a number in (0, 1], not '" + cw.get<std::string>() + "'");
  if (cw.is_number()) job.chroma_weight = cw.get<double>();
  // precision: auto (the fewest decimals that keep the compact export's tolerance) or 0..6.
  if (c.contains("precision") && c.at("precision").is_number_integer()) job.decimals = c.at("precision").get<int>();
  job.compact = c.value("compact", true);
  job.inbetweens = c.value("inbetweens", job.inbetweens);
  job.group_transforms = c.value("group_transforms", false);
  job.max_segment = c.value("max_segment", job.max_segment);
  job.quiet = true;
  job.resume_unfinished = true;  // after Ctrl-C, the next run goes on where this one stopped
  job.progress = [host](double f, const std::string& note) {
    if (host && host->progress) host->progress(host, f, note.c_str());
  };
  const int rc = svgm::run_fit_job(job, [host] { return host && host->cancelled && host->cancelled(host) != 0; });
  if (rc != 0) throw std::runtime_error("fit interrupted");
  return {{"message", "fitted"}};
}

}  // namespace

SVGM_DEFINE_PLUGIN("fitter", "opencl", "1", "differentiable fitting on OpenCL", run)
