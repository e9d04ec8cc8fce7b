// A drawing with its parts marked for a vision model (the procedural video's `llm` planner):
// each part's outline traced in a colour of its own and its number on a white label at the
// centre of its box, so the model can tie the numbered list it reads to what it sees. Drawn
// with OpenCV onto an image the engine's renderer made; the caller maps the parts to pixels.
#pragma once

#include <vector>

#include "svgmotion/affine.h"
#include "svgmotion/png_io.h"

namespace svgm {

struct NumberedPart {
  int number = 0;
  std::vector<std::vector<Vec2>> outlines;  // closed or open polylines, in image pixels
  Vec2 box_min, box_max;                    // its box, in image pixels (the label's place)
};

// Draws every part's outlines (2 px), then every label (so no outline crosses a number).
// Parts cycle through kNumberedPartColours distinct colours in number order.
void draw_numbered_parts(RgbaImage& image, const std::vector<NumberedPart>& parts);

constexpr int kNumberedPartColours = 10;

}  // namespace svgm
