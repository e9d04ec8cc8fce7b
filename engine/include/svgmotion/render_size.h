// Choosing the pixel size of a render and the canvas -> pixel transform.
#pragma once

#include "svgmotion/affine.h"
#include "svgmotion/scene.h"

namespace svgm {

struct RenderSize {
  int width = 0, height = 0;
  Affine view;  // canvas space -> pixel space
};

// `width` pixels wide (0: the scene's own width), height by the scene's aspect ratio (at least 1
// pixel). Throws svgm::Error when the result is outside 1..16384 pixels.
RenderSize render_size(const Scene& scene, int width);

}  // namespace svgm
