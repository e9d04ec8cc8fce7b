// The forward render of scenes with gradients, group opacity, clip paths and masks, on the CPU.
//
// The OpenCL rasteriser composites flat-coloured paths one by one, which is what the fitter
// differentiates; drawing what a browser draws needs more: a paint evaluated per pixel
// (gradient_paint.h) and a layer stack, where the content of an element with opacity,
// clip-path or mask is drawn into its own transparent layer and then composited into the one
// below it as a whole, times opacity × clip coverage × mask value. Coverage is the same exact
// area coverage of the same raster plan (area_coverage.h), so edges match the GPU render;
// everything is double or float arithmetic in a fixed order, so the output is deterministic.
// render_image uses this only for scenes that need it (Scene::needs_layers), so every other
// render stays the GPU's, bit for bit.
#pragma once

#include <vector>

#include "svgmotion/png_io.h"
#include "svgmotion/render_size.h"
#include "svgmotion/scene.h"

namespace svgm {

// Premultiplied RGBA floats (height * width * 4) of the scene over transparent; edges as a
// browser rasterises them under `browser_edges` (RasterPlan::browser_edges).
std::vector<float> composite_layers(const Scene& scene, const RenderSize& size,
                                    bool browser_edges = false);

// The same as 8-bit straight RGBA over white, or over nothing when `transparent` (rounded as
// kernels/raster.cl's to_rgba8_pixel rounds).
RgbaImage render_layers(const Scene& scene, const RenderSize& size, bool transparent,
                        bool browser_edges = false);

}  // namespace svgm
