// Render size from a requested width and the scene's aspect ratio.
#include "svgmotion/render_size.h"

#include <cmath>
#include <string>

#include "svgmotion/error.h"

namespace svgm {

RenderSize render_size(const Scene& scene, int width) {
  if (!(scene.width > 0) || !(scene.height > 0))
    throw Error("the SVG has no size (width/height/viewBox all missing or zero)");
  RenderSize r;
  const double w = width > 0 ? width : std::round(scene.width);
  const double h = std::max(1.0, std::round(w * scene.height / scene.width));
  if (w < 1 || w > 16384 || h > 16384)
    throw Error("render size " + std::to_string(static_cast<long long>(w)) + "x" +
                std::to_string(static_cast<long long>(h)) + " is outside 1..16384 pixels");
  r.width = static_cast<int>(w);
  r.height = static_cast<int>(h);
  r.view = Affine::scale(w / scene.width, h / scene.height);
  return r;
}

}  // namespace svgm
