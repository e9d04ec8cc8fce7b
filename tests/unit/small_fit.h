// A fit job on a folder of frames at test size (64 px, no refinement, no denoising, no gate,
// quiet), for tests that assert what fit.json records: the keyframes chosen, the frame scan.
#pragma once

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "fit/fit_job.h"

namespace svgm::test {

// Fits `svg` to dir/frames into dir/out and returns dir/out/fit.json.
inline nlohmann::json fit_frames(const std::filesystem::path& dir, const std::filesystem::path& svg, int keyframes,
                                 int iterations, int max_keyframes = -1) {
  FitJob job;
  job.svg = svg;
  job.target = dir / "frames";
  job.out = dir / "out";
  job.keyframes = keyframes;
  job.max_keyframes = max_keyframes;
  job.width = 64;
  job.refine_width = 0;
  job.denoise_radius = 0;
  job.options.iterations = iterations;
  job.gate = false;
  job.quiet = true;
  REQUIRE(run_fit_job(job, [] { return false; }) == 0);
  std::ifstream in(dir / "out" / "fit.json");
  return nlohmann::json::parse(in);
}

}  // namespace svgm::test
