// What counts as a drawing's backdrop (a sky, a hill, the wave under a surfer): a shape whose
// box covers much of the canvas, reaches two of its edges and is painted early. One rule for the
// structural grouper (a backdrop must not merge with the figure it contains) and the part rig
// (a backdrop stays still unless the prompt asks).
#pragma once

#include "svgmotion/scene.h"

namespace svgm {

// A box covering at least this share of the canvas may be a backdrop; chosen so that a figure
// filling a square icon's middle is not one (emoji figures cover 30-40 % of the canvas).
inline constexpr double kBackdropArea = 0.45;
// A box within this share of the canvas size of an edge touches it (Noto emoji keep a 4 px
// margin on their 128 px canvas: 3.1 %).
inline constexpr double kBackdropEdge = 0.04;
// Painted within the first this-share of the drawing's paths.
inline constexpr double kBackdropEarly = 0.35;

// Whether the box (x0, y0)-(x1, y1) on a width x height canvas, painted at `paint_position`
// (its paint index over the number of paths, 0..1), is a backdrop.
inline bool is_backdrop(double x0, double y0, double x1, double y1, double paint_position, double width,
                        double height) {
  if (!(width > 0 && height > 0) || x1 < x0 || y1 < y0) return false;
  const double tx = kBackdropEdge * width, ty = kBackdropEdge * height;
  const int edges = (x0 <= tx) + (y0 <= ty) + (x1 >= width - tx) + (y1 >= height - ty);
  return (x1 - x0) * (y1 - y0) >= kBackdropArea * width * height && edges >= 2 && paint_position < kBackdropEarly;
}

// The same on `scene`'s canvas, judged on the drawing's own canvas: a drawing given room to move
// (Scene::room) keeps its backdrop at the edges of the canvas it was drawn on, the room's
// middle, not at the larger canvas's.
inline bool is_backdrop(const Scene& scene, double x0, double y0, double x1, double y1, double paint_position) {
  const double f = 1 + 2 * scene.room, ox = scene.room * scene.width / f, oy = scene.room * scene.height / f;
  return is_backdrop(x0 - ox, y0 - oy, x1 - ox, y1 - oy, paint_position, scene.width / f, scene.height / f);
}

}  // namespace svgm
