// Evaluating a gradient paint server (svgmotion/scene.h) at a point, for the layer compositor.
//
// Linear: the position t is the projection onto the gradient vector. Radial: the two-point
// conical gradient of SVG 2 (focal circle fx, fy, fr to end circle cx, cy, r): t is the largest
// value whose interpolated circle passes through the point with a non-negative radius. Outside
// [0, 1], t is padded, reflected or repeated; colours are interpolated between stops in straight
// (not premultiplied) sRGB, as resvg and browsers do.
#pragma once

#include <optional>

#include "svgmotion/scene.h"

namespace svgm {

// The straight colour of `g` at gradient position t (before the spread method).
Rgba gradient_color_at(const Gradient& g, double t);

// The straight colour of `g` at canvas point p; nothing where a radial gradient whose focal
// circle is outside its end circle leaves the point unpainted.
std::optional<Rgba> gradient_color(const Gradient& g, const Affine& canvas_to_gradient, Vec2 p);

}  // namespace svgm
