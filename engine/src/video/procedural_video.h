// The procedural video provider: renders one candidate target video of the recoloured SVG
// moving by the motion library (procedural_motion.h), as raster frames degraded like a real
// generated video (a slow colour drift, a slight blur, H.264 compression), so that fitting it
// is not trivially exact.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "video/procedural_motion.h"

namespace svgm {

struct ProceduralVideoOptions {
  int frames = 49;      // default 49 frames at 24 fps (about 2 s)
  double fps = 24;
  int width = 512;      // frame width; height by the SVG's aspect
  double drift = 0.03;  // largest colour drift by the last frame (fraction per channel)
  double blur_sigma = 0.6;  // pixels
  int side = 0;         // one-sided motions: side_for_prompt(prompt); 0 lets the seed choose
  std::string device = "auto";
};

// Writes `out` (an mp4); fills `info` with the motion used. Throws svgm::Error.
void write_procedural_video(const Scene& recoloured, const std::string& motion, uint32_t seed,
                            const ProceduralVideoOptions& options, const std::filesystem::path& out,
                            ProceduralMotion* info);

}  // namespace svgm
