// One still image of a scene through the OpenCL renderer: what `svgmotion render` writes, and
// every frame of a clip (export/clip_writer.h) so that a clip's frame at time T is exactly
// `render --time T`.
#pragma once

#include "opencl/runtime.h"
#include "svgmotion/png_io.h"
#include "svgmotion/scene.h"

namespace svgm {

// The scene rasterised `width` pixels wide (0: its own width; height by its aspect, see
// render_size.h), 8-bit straight RGBA over white, or over nothing when `transparent`. With
// `browser_edges` its edges are rasterised as a browser does (RasterPlan::browser_edges): what
// people are shown; without, the exact coverage the fitter differentiates.
RgbaImage render_image(ClRuntime& rt, const Scene& scene, int width, bool transparent,
                       bool browser_edges = false);

}  // namespace svgm
