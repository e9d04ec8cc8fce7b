// Writing a finished fit's animation files (animation.svg and animation.json) from what the fit
// found, separately from fitting: `svgmotion fit` writes them at the end of a fit, and
// `svgmotion export` writes them again from the fit's checkpoint.bin with other export settings
// (precision, in-betweens, compact or full) without running the optimiser.
//
// The fit's result (FitResult) is the keyframes' control points in canvas space and their
// timing, plus the names of the documents they came from and were written into; it is stored
// in checkpoint.bin after the fit's own state (checkpoint.h), as JSON and raw doubles.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "export/compact_motion.h"
#include "export/group_transform.h"
#include "export/smil_writer.h"
#include "svgmotion/scene.h"

namespace svgm {

// How the animation is written; none of it changes what is fitted (the fit's checkpoint key
// leaves it out).
struct ExportSettings {
  bool compact = true;  // compact (smil_writer.h write_compact_animation_svg) or per-frame full
  int decimals = -1;    // coordinates' decimal places; -1: measured (compact) or kDefaultDecimals (full)
  int inbetweens = 3;   // smooth in-betweens per keyframe interval (inbetween.h)
  // The compact export's tolerance in pixels of a 1024-px rendering (compact_motion.h); 0: the
  // largest that keeps the render within 45 dB of the full export, measured (tolerance_choice.h).
  double tolerance_1024 = 0;
  bool svg = true, lottie = true;
};

struct FitResult {
  std::string svg;          // the SVG fitted
  std::string export_into;  // the document written into (empty: svg)
  std::string export_name;  // how messages name export_into
  double max_segment = 0;   // the fit's segment split (segment_split.h)
  bool rejected = false;    // by the result gate: written as animation.failed.svg
  AnimationTiming timing;   // keyframes, key times, duration, loop, closed loop
  double fps = 30;          // the target's
  int source_frames = 2;    // the target's frame count (the in-betweens' candidate times)
  int n_cp = 0;
  std::vector<double> points;  // timing.keyframes * n_cp (x, y) canvas pairs
};
std::string fit_result_json(const FitResult& r);  // without the points
// Throws svgm::Error("<what>: <problem>") on a record that does not read.
FitResult fit_result_from_json(const std::string& text, const std::string& what);

// The document written into and what the written animation is made of, read from the files a
// FitResult names: the fitted SVG split as the fit split it, and the export map when the
// animation goes into another document.
struct ExportDocument {
  Scene scene;                 // the document written into, split as fitted
  std::optional<ExportMap> map;
  std::filesystem::path into;  // its file
};
// `as_read`: the fitted SVG as read; `split`: the fit's segment split of it. Throws svgm::Error
// when export_into's paths do not match the fitted ones.
ExportDocument export_document(const Scene& as_read, const std::vector<std::vector<std::vector<int>>>& split,
                               const std::string& fitted_name, const std::string& export_into);

// Writes `anim` (animation.svg or animation.failed.svg) and the Lottie beside it (.json), per
// `settings`. `plan` is the fitted scene's raster plan (its control-point layout); `motion`
// (full export with group transforms only) is made by `group_motion` from the written times.
// Returns the warnings, each a line.
struct ExportOutcome {
  std::vector<std::string> warnings;
  CompactStats stats;
  int values_written = 0;
  double fps = 30;            // the target's frame rate (a clip's default)
  double tolerance_1024 = 0;  // compact: the tolerance written with (given or measured)
  double tolerance_db = 0;    // measured: the worst PSNR of the compact SVG against the full one
  double residual_scale = 1;  // measured: the residual shapes' tolerance, a multiple of it (kResidualScales)
  bool full_fallback = false; // measured, and no tolerance held the target: written in full
  // animation.json measured on its own in a Lottie player (tolerance_choice.h: lottie_drawer):
  bool lottie_measured = false;
  double lottie_tolerance_1024 = 0, lottie_residual_scale = 1;
  double lottie_db = 0;  // the worst PSNR of the compact JSON against the full one (below the floor: written in full)
  std::filesystem::path svg;  // the animation written (animation.svg or animation.failed.svg)
};
// "tolerance 1.5 px at 1024 (worst 46.2 dB of the full export)", or "(given)" when it was.
std::string tolerance_text(const ExportOutcome& outcome);
ExportOutcome write_animation_files(const FitResult& result, const ExportSettings& settings, const ExportDocument& doc,
                                    const RasterPlan& plan, const std::filesystem::path& anim,
                                    const std::function<std::optional<PathMotion>(const std::vector<double>& written_times,
                                                                                  const std::vector<double>& frame_times)>&
                                        group_motion = {});

// `svgmotion export`: reads DIR/checkpoint.bin (a fit directory, or a run directory holding
// one) and writes the animation files into `out` (default DIR) per `settings`, without fitting.
// Throws svgm::Error "<path>: <problem>" for a folder that is not a fit or run directory, a
// missing checkpoint or one without a finished fit.
// `lock`: hold `out`'s run lock meanwhile (false: the caller, a run, holds it).
ExportOutcome export_fit_directory(const std::filesystem::path& dir, const std::filesystem::path& out,
                                   const ExportSettings& settings, bool lock = true);

}  // namespace svgm
