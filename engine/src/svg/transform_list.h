// The SVG transform attribute: matrix, translate, scale, rotate (with centre), skewX, skewY.
#pragma once

#include <optional>
#include <string_view>

#include "svgmotion/affine.h"

namespace svgm::svg {

// The product of the list (the first item outermost). Nothing when the list is malformed
// (resvg and browsers then ignore the attribute); *out_of_range is set for nan/inf numbers.
std::optional<Affine> parse_transform(std::string_view s, bool* out_of_range = nullptr);

}  // namespace svgm::svg
