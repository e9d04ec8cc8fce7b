// SMIL calcMode="spline" timing: the keySplines easing of one keyTimes interval, for
// `render --time T` of animations written with easing (the compact export, smil_writer.h).
#pragma once

#include <pugixml.hpp>

namespace svgm::svg {

// The eased fraction of interval `interval` at its linear fraction `u` (0..1): u itself unless
// `anim` has calcMode="spline" and a keySplines entry for that interval ("x1 y1 x2 y2", the
// cubic Bezier from (0,0) to (1,1) whose x is time and y progress, SMIL 3.0 / SVG 1.1 19.2.9).
double spline_fraction(pugi::xml_node anim, size_t interval, double u);

}  // namespace svgm::svg
