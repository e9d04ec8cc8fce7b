// Round parts of a figure's mask that can be wheels: the evidence figure_class.h weighs for a
// wheeled figure.
//
// Three kinds, all in mask pixel coordinates: a hole that is nearly a circle (a tyre drawn as a
// ring, a bicycle's wheel), a component that is nearly a disc or a ring (a wheel drawn apart
// from the body), and a circular arc bulging out of the figure's bottom outline (a car's wheel
// drawn over its body's lower edge: the mask's lowest pixel per column traces the wheel's lower
// arc; a least-squares circle through it is a wheel when it fits to about a pixel and spans a
// good part of a half circle and the disc it bounds is filled). A leg's foot is flat-bottomed
// and its sides are straight, so its circle fit fails; a rounded paw's arc fits a circle wider
// than the leg, whose disc is not filled.
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "svgmotion/affine.h"

namespace svgm::motion {

struct Circle {
  Vec2 centre;
  double radius = 0;
  std::string source;  // "hole", "component" or "bottom arc"
};

// `mask`: CV_8U, non-zero inside. Circles smaller than `min_radius` px are ignored (0: a
// fortieth of the mask's larger side).
std::vector<Circle> find_circles(const cv::Mat& mask, double min_radius = 0);

}  // namespace svgm::motion
