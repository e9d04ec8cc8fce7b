// Test-only masks for the deformation mesh (motion/shape_mesh.h): rectangles and discs set
// pixel by pixel, so a test states exactly which pixels are inside (a disc's extreme column is
// one pixel, which cv::circle does not promise).
#pragma once

#include <opencv2/core.hpp>

namespace svgm::test {

// Pixels x0 <= x < x1, y0 <= y < y1.
inline void fill_rect(cv::Mat& mask, int x0, int y0, int x1, int y1) {
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) mask.at<uint8_t>(y, x) = 255;
}

// Pixels with (x - cx)^2 + (y - cy)^2 <= r^2.
inline void fill_disc(cv::Mat& mask, int cx, int cy, int r) {
  for (int y = cy - r; y <= cy + r; ++y)
    for (int x = cx - r; x <= cx + r; ++x)
      if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r) mask.at<uint8_t>(y, x) = 255;
}

// The 200x40 bar of the tests: pixels 20 <= x < 220, 20 <= y < 60 of a 240x80 mask.
inline cv::Mat bar_mask() {
  cv::Mat m(80, 240, CV_8U, cv::Scalar(0));
  fill_rect(m, 20, 20, 220, 60);
  return m;
}

}  // namespace svgm::test
