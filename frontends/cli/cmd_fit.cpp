// `svgmotion fit`: fit a static SVG to a target video the user brings and write the animation.
//
// Parses the options and runs engine/src/fit/fit_job.h; Ctrl-C stops the fit early and still
// writes the result so far (exit status 130). A drawing with very many path segments is fitted
// all the same, after a warning that it will be slow.
#include <csignal>
#include <cstdio>
#include <filesystem>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "fit/fit_job.h"
#include "svgmotion/error.h"
#include "svgmotion/log.h"
#include "svgmotion/svg_reader.h"

namespace svgm::cli {

namespace {

// Ctrl-C, SIGTERM and SIGHUP all stop the fit early, which then writes its result so far.
volatile std::sig_atomic_t g_interrupted = 0;
extern "C" void on_stop_signal(int) { g_interrupted = 1; }
void catch_stop_signals(bool on) {
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, on ? on_stop_signal : SIG_DFL);
}

// Above this many path segments a fit is slow enough to deserve a warning: every iteration draws
// and differentiates every segment of every keyframe. Issue 12 measured 3 s per iteration for a
// 100,000-segment path (time about linear in segments), so 20,000 segments make the default
// 2,000 iterations take over 20 minutes; render draws such files in seconds.
constexpr size_t kSlowFitSegments = 20000;

// The warning, before any work: the drawing is read here once more (a malformed one fails with
// the same line the fit would print).
void warn_if_slow(const std::string& svg) {
  const size_t segments = read_svg_file(svg).segment_count();
  if (segments > kSlowFitSegments)
    log::warning("%s: %zu path segments (over %zu): every fitting iteration draws them "
                 "all, so this fit will be slow; fewer nodes (a simplified drawing) fit faster",
                 svg.c_str(), segments, kSlowFitSegments);
}

}  // namespace

int cmd_fit(const std::vector<std::string>& argv) {
  const Args a = parse_args("fit", argv,
                            {"--target", "-o", "--output", "--iterations", "--keyframes", "--size",
                             "--palette", "--device", "--mask-threshold", "--loop", "--deform", "--refine-size",
                             "--precision", "--inbetweens", "--max-segment", "--chroma-weight", "--denoise",
                             "--max-keyframes", "--start"},
                            {"--resume", "--no-track", "--no-gate", "--no-colour-correction", "--no-blur-matching", "--stabilise",
                             "--no-stabilise",
                             "--group-transforms", "--all-iterations", "--force", "--full"});
  if (a.positional.size() != 1)
    throw UsageError("fit: expected one input SVG (svgmotion fit IN.svg --target VIDEO -o OUT_DIR)");
  FitJob job;
  job.svg = a.positional[0];
  const auto target = a.get("--target");
  if (!target) throw UsageError("fit: missing --target VIDEO|FRAMES_DIR");
  job.target = *target;
  const auto out = a.get("-o") ? a.get("-o") : a.get("--output");
  if (!out) throw UsageError("fit: missing -o OUT_DIR");
  job.out = *out;
  job.options.iterations = a.get_int("--iterations", 2000, 1, 10000000);
  job.options.track = !a.has("--no-track");
  if (a.has("--all-iterations")) job.options.plateau_window = 0;
  job.keyframes = a.get_int("--keyframes", 15, 2, 1000);
  // Keyframes added where the spline misses frames, up to this many (auto: fit_job.h).
  if (const auto m = a.get("--max-keyframes"); m && *m != "auto")
    job.max_keyframes = a.get_int("--max-keyframes", -1, 0, 10000);
  // Keyframe 0: the rest pose, fitted freely, or decided from the first frame (rest_start.h).
  if (const auto st = a.get("--start")) {
    if (*st == "rest") job.start_at_rest = true;
    else if (*st == "free") job.start_at_rest = false;
    else if (*st != "auto") throw Error("fit: --start must be auto, rest or free, not '" + *st + "'");
  }
  job.width = a.get_int("--size", 256, 32, 4096);
  if (const auto r = a.get("--refine-size"))
    job.refine_width = *r == "auto" ? -1 : a.get_int("--refine-size", 0, 0, 4096);
  job.loop = parse_loop_mode(a.get("--loop").value_or("loop"), "--loop");
  const std::string deform = a.get("--deform").value_or("field");
  if (deform == "free") job.options.use_free_offsets();
  else if (deform != "field") throw Error("fit: --deform must be field or free, not '" + deform + "'");
  job.gate = !a.has("--no-gate");
  job.colour_correction = !a.has("--no-colour-correction");
  job.blur_matching = !a.has("--no-blur-matching");
  // The chroma weight: auto (fit/target/chroma_calibration.h) unless a number is given.
  job.chroma_weight_auto = true;
  if (const auto w = a.get("--chroma-weight")) {
    job.chroma_weight_auto = *w == "auto";
    if (!job.chroma_weight_auto) {
      // One line for anything else than auto or a number in (0, 1] ("2", "abc", "nan").
      double v = 0;
      try {
        v = a.get_double("--chroma-weight", 1);
      } catch (const Error&) {
        v = 0;
      }
      if (!(v > 0 && v <= 1)) throw Error("fit: --chroma-weight must be auto or a number in (0, 1], not '" + *w + "'");
      job.chroma_weight = v;
    }
  }
  if (a.has("--stabilise") && a.has("--no-stabilise")) throw UsageError("fit: --stabilise and --no-stabilise contradict each other");
  if (a.has("--stabilise")) job.stabilise = true;
  if (a.has("--no-stabilise")) job.stabilise = false;
  job.denoise_radius = a.get_int("--denoise", job.denoise_radius, 0, kMaxDenoiseRadius);
  job.decimals = a.get_int("--precision", -1, 0, kMaxDecimals);  // -1: measured
  job.compact = !a.has("--full");
  job.inbetweens = a.get_int("--inbetweens", job.inbetweens, 0, kMaxInbetweens);
  job.group_transforms = a.has("--group-transforms");
  job.max_segment = a.get_double("--max-segment", job.max_segment);
  if (const auto p = a.get("--palette")) job.palette = *p;
  job.mask_threshold = a.get_double("--mask-threshold", job.mask_threshold);
  job.resume = a.has("--resume");
  // The output folder becomes a run directory of its own (a user's folder is not taken over),
  // and a `run` working in it is not overwritten (run/run_directory.h).
  job.claim_out = true;
  job.force = a.has("--force");
  job.quiet = log::quiet();
  job.device = a.get("--device").value_or("auto");
  warn_if_slow(job.svg);
  g_interrupted = 0;
  catch_stop_signals(true);
  // Fitting into a run directory (say with another target.mp4) refreshes its report.html.
  std::error_code ec;
  const bool run_dir = std::filesystem::is_directory(job.out / ".svgmotion", ec) &&
                       std::filesystem::is_regular_file(job.out / "input.svg", ec);
  int rc = 0;
  try {
    rc = run_fit_job(job, [] { return g_interrupted != 0; });
  } catch (const Rejected&) {
    catch_stop_signals(false);
    if (run_dir) write_run_report(job.out, job.device, job.quiet);
    throw;
  }
  catch_stop_signals(false);
  if (run_dir && rc == 0) write_run_report(job.out, job.device, job.quiet);
  return rc;
}

}  // namespace svgm::cli
