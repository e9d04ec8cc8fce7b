// Which pixels of a figure's mask belong together, for the deformation mesh (shape_mesh.h): the
// rule that keeps two shapes which merely touch (two discs meeting at a pixel, a hand resting
// on a hip by a 2-px contact) from being glued into one piece that must bend as one.
//
// The rule, erode-then-connect: the mask is eroded by one pixel (3x3 square), which removes
// every neck of width 1 or 2 px; the eroded mask's 4-connected components are the cores. Every
// mask pixel then joins the core it reaches first by a 4-connected walk inside the mask (a
// multi-source breadth-first search, so a neck is split at its middle, and a thin stroke
// hanging off a body, a 2-px whisker, joins that body). Mask pixels no core reaches (a figure
// drawn only in hairlines) are labelled by their own 4-connected components, after the cores.
// A neck 3 px or wider survives the erosion and keeps the two sides one piece.
// Labels are assigned in raster order of the cores' first pixels: the same mask, the same labels.
#pragma once

#include <opencv2/core.hpp>

namespace svgm {

// mask: CV_8U, non-zero inside the figure. Returns CV_32S of the same size: -1 outside the
// mask, else the piece label 0..pieces-1; `pieces` receives the number of labels.
cv::Mat shape_pieces(const cv::Mat& mask, int& pieces);

}  // namespace svgm
