// The colour correction's palette (see correction_palette.h).
#include "fit/target/correction_palette.h"

#include <algorithm>

#include "raster/render_image.h"

namespace svgm {

namespace {

bool any_gradient(const Scene& scene) {
  return std::any_of(scene.paths.begin(), scene.paths.end(),
                     [](const Path& p) { return p.fill_gradient >= 0 || p.stroke_gradient >= 0; });
}

// The share of the canvas gradient paint shows at rest: the scene rendered with every gradient
// paint black and every flat paint white (alphas, opacities, layers and paint order kept, so a
// gradient hidden under a flat path does not count), darkness averaged over the canvas.
double gradient_share(ClRuntime& rt, const Scene& scene, int width) {
  Scene probe = scene;
  auto paint = [](Rgba& c, int& gradient) {
    const float v = gradient >= 0 ? 0.f : 1.f;
    c = {v, v, v, c.a};
    gradient = -1;
  };
  for (Path& p : probe.paths) {
    paint(p.fill, p.fill_gradient);
    paint(p.stroke.color, p.stroke_gradient);
  }
  // A gradient's alpha lives in its stops (and Gradient::opacity); the flat colour's alpha is
  // the path's own, which for a gradient-painted path is the mean stop alpha: close enough to
  // count its area.
  const RgbaImage img = render_image(rt, probe, width, false);
  double dark = 0;
  const size_t px = static_cast<size_t>(img.width) * img.height;
  for (size_t i = 0; i < px; ++i) dark += 1.0 - img.rgba[i * 4] / 255.0;
  return px ? dark / static_cast<double>(px) : 0;
}

}  // namespace

CorrectionPalette correction_palette(ClRuntime& rt, const Scene& scene, int width) {
  CorrectionPalette out;
  for (const Path& p : scene.paths) {
    if (p.opacity < 0.99f) continue;
    if (p.has_fill && p.fill_gradient < 0 && p.fill.a >= 0.99f) out.colours.push_back({p.fill.r, p.fill.g, p.fill.b});
    if (p.has_stroke && p.stroke_gradient < 0 && p.stroke.color.a >= 0.99f)
      out.colours.push_back({p.stroke.color.r, p.stroke.color.g, p.stroke.color.b});
  }
  if (any_gradient(scene)) {
    out.gradient_share = gradient_share(rt, scene, width);
    out.usable = out.gradient_share <= kMaxGradientShare;
  }
  return out;
}

}  // namespace svgm
