// A SMIL <animateTransform attributeName="transform"> at a given time, for `render --time T`
// of exports written with group transforms (fit --group-transforms, export/group_transform.h).
//
// Supported: `values` with optional `keyTimes` (uniform when absent), calcMode linear or
// discrete or spline (keySplines), `dur`, repeatCount (a number or indefinite), fill="freeze", additive sum or
// replace, types translate, scale, rotate (with an optional centre), skewX and skewY. Several
// animations on one element apply in document order: a sum post-multiplies onto what came
// before (the transform attribute first), a replace starts afresh (SVG 1.1, 19.2.14). `from`,
// `to`, `by` and begin offsets are not read (an element using them keeps the
// value built so far).
#pragma once

#include <pugixml.hpp>
#include <string_view>

#include "svgmotion/affine.h"

namespace svgm::svg {

// The element's transform at `seconds`: `base` (its transform attribute) with its
// animateTransform children applied. `attribute`: the animated attribute (a gradient's is
// gradientTransform; the SMIL export moves gradients with their paths, export/smil_writer.h).
Affine animated_transform(pugi::xml_node element, double seconds, const Affine& base,
                          std::string_view attribute = "transform");

}  // namespace svgm::svg
