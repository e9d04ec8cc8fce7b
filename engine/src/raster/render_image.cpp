// A still image of a scene (see render_image.h): plan, one-frame raster, 8-bit read-back; or
// the CPU layer compositor for scenes with gradients, group opacity, clips or masks.
#include "raster/render_image.h"

#include <array>

#include "raster/browser_stroke.h"
#include "raster/layer_compositor.h"
#include "raster/raster_cl.h"
#include "raster/raster_plan.h"
#include "svgmotion/render_size.h"

namespace svgm {

namespace {

RgbaImage draw(ClRuntime& rt, const Scene& scene, const RenderSize& size, bool transparent,
               bool browser_edges) {
  // Gradients and layers (group opacity, clips, masks) are drawn by the CPU compositor; the
  // GPU rasteriser composites flat paths one by one (and stays the fitter's forward pass).
  if (scene.needs_layers()) return render_layers(scene, size, transparent, browser_edges);
  // Hairlines (raster/browser_stroke.h) are drawn by the CPU compositor too.
  if (browser_edges)
    for (const Path& p : scene.paths)
      if (browser_hairline(p, size.view)) return render_layers(scene, size, transparent, true);
  RasterPlan plan = plan_raster(scene, size.view, size.width, size.height);
  plan.browser_edges = browser_edges;
  ClRaster raster(rt, plan, 1);
  raster.set_rest_pose();
  const std::array<float, 4> white{1, 1, 1, 1}, clear{0, 0, 0, 0};
  raster.forward(ClRaster::Output::Rgba8, transparent ? clear : white);
  return RgbaImage{size.width, size.height, raster.read_rgba8()};
}

}  // namespace

RgbaImage render_image(ClRuntime& rt, const Scene& scene, int width, bool transparent,
                       bool browser_edges) {
  const RenderSize size = render_size(scene, width);
  // Browser edges also draw strokes as the browser outlines them (raster/browser_stroke.h).
  if (browser_edges) return draw(rt, with_browser_strokes(scene, size.view), size, transparent, true);
  return draw(rt, scene, size, transparent, false);
}

}  // namespace svgm
