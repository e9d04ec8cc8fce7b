// One fit from files to files: the body of `svgmotion fit` and of the opencl fitter plugin.
//
// Reads the SVG (and palette), loads the target, fits with progress on stderr and checkpoints,
// and writes animation.svg, preview.mp4, fit.json and checkpoint.bin into the output folder.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "fit/fitter.h"

namespace svgm {

struct FitJob {
  std::filesystem::path svg, target, out;
  std::optional<std::filesystem::path> palette;
  std::optional<std::filesystem::path> tracks;  // tracks.json of the tracker stage
  // The document the animation is written into (default: svg); the fitter plugin fits the
  // layered SVG and exports into it.
  std::optional<std::filesystem::path> export_into;
  FitOptions options;
  int keyframes = 15;
  int width = 256;
  double mask_threshold = 0.97;
  bool resume = false;
  bool quiet = false;
  std::string device = "auto";
};

// Runs the fit; returns 0 when done, 130 when `interrupted()` stopped it early (the outputs are
// written either way). Throws svgm::Error on bad input.
int run_fit_job(const FitJob& job, const std::function<bool()>& interrupted);

}  // namespace svgm
