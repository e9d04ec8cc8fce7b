// What counts as a drawing's backdrop (a sky, a hill, the wave under a surfer, a rock face): a
// shape whose box covers much of the canvas, reaches two of its edges and is painted early. One
// rule for the structural grouper (a backdrop must not merge with the figure it contains) and the
// part rig (a backdrop stays still unless the prompt asks).
//
// On a scene (a drawing read with its paths) the box is not enough: an emoji's figure often fills
// its canvas (a fairy's wings, a mermaid's tail, painted first and reaching three edges), and
// taken for a backdrop it stopped moving. What tells scenery from such a figure is the frame: the
// frame cuts scenery (a sky, the ground, a rock face go on beyond the picture, so their outline
// runs along its edges), while a figure touches the edges at its tips. So a scene's backdrop must
// also run along one edge of the drawing's own canvas for kBackdropCut of it (frame_cut).
#pragma once

#include <vector>

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
// The frame cuts a backdrop along at least this share of one side of the canvas: a rock face
// 0.93 (twemoji 1f9d7), a sky or a ground band a whole side; the part holding a fairy's two
// wings that fill her canvas 0.32 (twemoji 1f9da), a mermaid's tail 0.24 (1f9dc), as
// backdrop_probe measured them on the pipeline's grouped drawings. A sum over the sides took
// the wings' part (0.89) for a backdrop. A bust cut by the bottom edge reaches 0.72 (the
// fairy's shoulders): only the area rule keeps it from being one.
inline constexpr double kBackdropCut = 0.6;

// Whether the box (x0, y0)-(x1, y1) on a width x height canvas, painted at `paint_position`
// (its paint index over the number of paths, 0..1), is a backdrop.
inline bool is_backdrop(double x0, double y0, double x1, double y1, double paint_position, double width,
                        double height) {
  if (!(width > 0 && height > 0) || x1 < x0 || y1 < y0) return false;
  const double tx = kBackdropEdge * width, ty = kBackdropEdge * height;
  const int edges = (x0 <= tx) + (y0 <= ty) + (x1 >= width - tx) + (y1 >= height - ty);
  return (x1 - x0) * (y1 - y0) >= kBackdropArea * width * height && edges >= 2 && paint_position < kBackdropEarly;
}

// How far the outlines of `scene`'s paths `paths` run along the edges of the drawing's own
// canvas (Scene::room: a drawing given room to move keeps its backdrop at the edges of the
// canvas it was drawn on, the room's middle), within kBackdropEdge of them: per side the length
// of the union of the stretches (the outlines sampled along their curves, a filled subpath
// closed), over that side's length; the longest of the four sides (0..1).
double frame_cut(const Scene& scene, const std::vector<int>& paths);

// Whether `scene`'s paths `paths`, with the box (x0, y0)-(x1, y1) and painted at
// `paint_position`, are a backdrop: the box rule on the drawing's own canvas, and the frame cuts
// them for kBackdropCut of a side.
bool is_backdrop(const Scene& scene, const std::vector<int>& paths, double x0, double y0, double x1, double y1,
                 double paint_position);

}  // namespace svgm
