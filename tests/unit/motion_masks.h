// Figures drawn as masks for the motion tests (skeleton, limbs, figure class): each a few
// cv::line / cv::circle / cv::ellipse calls whose geometry the tests know.
#pragma once

#include <cmath>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace motion_masks {

// A stick figure 160x160: head disc at (80, 30) r 14, body (80, 40)-(80, 95), arms from the
// shoulders (80, 55) to (50, 80) and (110, 80), legs from the hips (80, 95) to (60, 145) and
// (100, 145); lines 8 px thick.
inline cv::Mat stick_figure() {
  cv::Mat m(160, 160, CV_8U, cv::Scalar(0));
  cv::circle(m, {80, 30}, 14, 255, cv::FILLED);
  cv::line(m, {80, 40}, {80, 95}, 255, 8);
  cv::line(m, {80, 55}, {50, 80}, 255, 8);
  cv::line(m, {80, 55}, {110, 80}, 255, 8);
  cv::line(m, {80, 95}, {60, 145}, 255, 8);
  cv::line(m, {80, 95}, {100, 145}, 255, 8);
  return m;
}

// A quadruped 220x160 facing right: body ellipse at (110, 70) 55x22, four legs down to y 140 at
// x 70, 85, 135, 150, a neck up to a head ellipse at (188, 25), a thin tail to (25, 45).
inline cv::Mat quadruped() {
  cv::Mat m(160, 220, CV_8U, cv::Scalar(0));
  cv::ellipse(m, {110, 70}, {55, 22}, 0, 0, 360, 255, cv::FILLED);
  for (int x : {70, 85, 135, 150}) cv::line(m, {x, 80}, {x, 140}, 255, 8);
  cv::line(m, {155, 60}, {180, 30}, 255, 10);
  cv::ellipse(m, {188, 25}, {16, 10}, 0, 0, 360, 255, cv::FILLED);
  cv::line(m, {58, 65}, {25, 45}, 255, 5);
  return m;
}

// A long sinuous thick curve 260x160: y = 80 + 35 sin(x / 30), 14 px thick.
inline cv::Mat snake() {
  cv::Mat m(160, 260, CV_8U, cv::Scalar(0));
  std::vector<cv::Point> pts;
  for (int x = 20; x <= 240; x += 2) pts.push_back({x, static_cast<int>(80 + 35 * std::sin(x / 30.0))});
  cv::polylines(m, pts, false, 255, 14);
  return m;
}

// Two wheels (r 22 at (65, 110) and (155, 110)) under a box (30..190 x 40..100).
inline cv::Mat car() {
  cv::Mat m(160, 220, CV_8U, cv::Scalar(0));
  cv::rectangle(m, cv::Rect(30, 40, 160, 60), 255, cv::FILLED);
  cv::circle(m, {65, 110}, 22, 255, cv::FILLED);
  cv::circle(m, {155, 110}, 22, 255, cv::FILLED);
  return m;
}

}  // namespace motion_masks
