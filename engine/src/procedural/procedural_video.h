// The procedural video provider: renders one candidate target video of the recoloured SVG
// moving by a motion plan (motion_plan.h: the control points of every frame), as raster frames
// degraded like a real generated video (a slow colour drift, a slight blur, H.264
// compression), so that fitting it is not trivially exact.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include <vector>

#include "svgmotion/scene.h"

namespace svgm {

struct ProceduralVideoOptions {
  int frames = 49;      // default 49 frames at 24 fps (about 2 s)
  double fps = 24;
  int width = 512;      // frame width; height by the SVG's aspect
  double drift = 0.03;  // largest colour drift by the last frame (fraction per channel)
  double blur_sigma = 0.6;  // pixels
  std::string device = "auto";
};

// Writes `out` (an mp4) from `points`: options.frames frames of every control point of the
// scene in scene order (animate_plan). `seed` picks the colour drift. Throws svgm::Error.
void write_procedural_video(const Scene& recoloured, const std::vector<Vec2>& points, uint32_t seed,
                            const ProceduralVideoOptions& options, const std::filesystem::path& out);

}  // namespace svgm
