// Reading SVG documents into the scene model.
//
// read_svg_file/read_svg_string parse an SVG (pugixml), resolve styles, inheritance, use/defs,
// transforms and the viewBox, and return every visible shape as cubic Bézier paths in canvas
// space. Unsupported content (text, gradients, filters, masks, clip paths, images) adds one
// warning line to Scene::warnings naming the element and what was done. Malformed input
// (broken XML, NaN/inf numbers, absurd sizes, too-deep nesting, use cycles, oversized files)
// throws svgm::Error whose message is "<name>: <problem>" on one line.
#pragma once

#include <filesystem>
#include <string_view>

#include "svgmotion/scene.h"

namespace svgm {

struct SvgReadLimits {
  size_t max_file_bytes = 64u << 20;  // 64 MiB: larger inputs are refused before parsing
  int max_depth = 256;                // element nesting (including through <use>)
  double max_canvas_px = 1 << 15;     // width/height above this are "absurd sizes"
  size_t max_segments = 4u << 20;     // cubic segments over the whole document
  // Canvas-space coordinates (and stroke widths) beyond this are refused: the renderer works in
  // float, where a product of two coordinates must stay below FLT_MAX (sqrt = 1.8e19) even
  // after the up to 16384x scale to the render size.
  double max_coordinate = 1e15;
  // When >= 0: paths with an <animate attributeName="d"> take their animated shape at this
  // time in seconds (SMIL: values, keyTimes, dur, repeatCount, calcMode linear, discrete or
  // spline with keySplines).
  double animation_time = -1;
};

Scene read_svg_file(const std::filesystem::path& file, const SvgReadLimits& limits = {});

// `name` is used in error and warning messages (normally the file name).
Scene read_svg_string(std::string_view text, std::string_view name,
                      const SvgReadLimits& limits = {});

}  // namespace svgm
