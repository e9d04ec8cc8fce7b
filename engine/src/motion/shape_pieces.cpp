// The erode-then-connect labelling of a figure's mask: see shape_pieces.h for the rule and why.
#include "motion/shape_pieces.h"

#include <deque>

#include <opencv2/imgproc.hpp>

#include "svgmotion/error.h"

namespace svgm {

namespace {

const int kStep[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};  // 4-connected neighbours

// Labels the 4-connected components of `on` (CV_8U) into `labels` (CV_32S, -1 where unset),
// starting at `first`, numbered in raster order of each component's first pixel; returns how
// many. Our own flood fill rather than cv::connectedComponents, whose parallel variant does not
// promise this numbering.
int label_components(const cv::Mat& on, cv::Mat& labels, int first) {
  int count = 0;
  std::deque<cv::Point> queue;
  for (int y0 = 0; y0 < on.rows; ++y0)
    for (int x0 = 0; x0 < on.cols; ++x0) {
      if (!on.at<uint8_t>(y0, x0) || labels.at<int>(y0, x0) >= 0) continue;
      const int label = first + count++;
      labels.at<int>(y0, x0) = label;
      queue.emplace_back(x0, y0);
      while (!queue.empty()) {
        const cv::Point p = queue.front();
        queue.pop_front();
        for (const auto& s : kStep) {
          const int x = p.x + s[0], y = p.y + s[1];
          if (x < 0 || y < 0 || x >= on.cols || y >= on.rows) continue;
          if (!on.at<uint8_t>(y, x) || labels.at<int>(y, x) >= 0) continue;
          labels.at<int>(y, x) = label;
          queue.emplace_back(x, y);
        }
      }
    }
  return count;
}

}  // namespace

cv::Mat shape_pieces(const cv::Mat& mask, int& pieces) {
  if (mask.type() != CV_8U) throw Error("shape_pieces: the mask must be CV_8U");
  const cv::Mat inside = mask > 0;
  // Erosion by a 3x3 square: a pixel survives only when all 8 neighbours are inside, so a neck
  // 1 or 2 px across disappears. Outside the image counts as outside (a figure cut by the edge
  // erodes there too, which only shrinks its core).
  cv::Mat core;
  cv::erode(inside, core, cv::Mat::ones(3, 3, CV_8U), cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
  cv::Mat labels(mask.size(), CV_32S, cv::Scalar(-1));
  const int cores = label_components(core, labels, 0);
  std::deque<cv::Point> queue;
  for (int y = 0; y < mask.rows; ++y)
    for (int x = 0; x < mask.cols; ++x)
      if (labels.at<int>(y, x) >= 0) queue.emplace_back(x, y);
  // Breadth-first from every core at once: a pixel takes the label of the first core to reach
  // it (ties go to the core whose front was queued first, which is fixed by the raster order).
  while (!queue.empty()) {
    const cv::Point p = queue.front();
    queue.pop_front();
    const int label = labels.at<int>(p.y, p.x);
    for (const auto& s : kStep) {
      const int x = p.x + s[0], y = p.y + s[1];
      if (x < 0 || y < 0 || x >= mask.cols || y >= mask.rows) continue;
      if (!inside.at<uint8_t>(y, x) || labels.at<int>(y, x) >= 0) continue;
      labels.at<int>(y, x) = label;
      queue.emplace_back(x, y);
    }
  }
  // Hairline parts no core reached: their own 4-connected components (labelled pixels are
  // skipped by label_components, so only the unreached ones are numbered).
  pieces = cores + label_components(inside, labels, cores);
  return labels;
}

}  // namespace svgm
