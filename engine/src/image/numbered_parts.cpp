// numbered_parts.h: outlines and number labels drawn with OpenCV.
#include "image/numbered_parts.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <string>

namespace svgm {

namespace {

// Distinct, saturated colours (RGBA) that read on white and on the palette's flat colours.
const cv::Scalar kColours[kNumberedPartColours] = {
    {230, 25, 75, 255},  {60, 180, 75, 255},  {0, 130, 200, 255}, {245, 130, 48, 255}, {145, 30, 180, 255},
    {0, 160, 160, 255},  {240, 50, 230, 255}, {128, 128, 0, 255}, {170, 110, 40, 255}, {0, 0, 128, 255}};

cv::Point pixel(Vec2 p) { return {static_cast<int>(std::lround(p.x)), static_cast<int>(std::lround(p.y))}; }

}  // namespace

void draw_numbered_parts(RgbaImage& image, const std::vector<NumberedPart>& parts) {
  if (image.width <= 0 || image.height <= 0) return;
  cv::Mat m(image.height, image.width, CV_8UC4, image.rgba.data());
  for (size_t i = 0; i < parts.size(); ++i)
    for (const auto& line : parts[i].outlines) {
      std::vector<cv::Point> pts;
      for (const Vec2& p : line) pts.push_back(pixel(p));
      if (pts.size() >= 2) cv::polylines(m, pts, false, kColours[i % kNumberedPartColours], 2, cv::LINE_AA);
    }
  // Labels: the number in black on white, framed in the part's colour, at its box's centre;
  // a label that would cover one already placed moves down (then up) until it is free.
  const int font = cv::FONT_HERSHEY_SIMPLEX;
  const double scale = 0.5;
  std::vector<cv::Rect> placed;
  for (size_t i = 0; i < parts.size(); ++i) {
    const std::string text = std::to_string(parts[i].number);
    int baseline = 0;
    const cv::Size ts = cv::getTextSize(text, font, scale, 1, &baseline);
    const int w = ts.width + 6, h = ts.height + baseline + 4;
    const Vec2 c = 0.5 * (parts[i].box_min + parts[i].box_max);
    auto at = [&](int dy) {
      const int x = std::clamp(static_cast<int>(std::lround(c.x)) - w / 2, 0, std::max(0, image.width - w));
      const int y = std::clamp(static_cast<int>(std::lround(c.y)) - h / 2 + dy, 0, std::max(0, image.height - h));
      return cv::Rect(x, y, w, h);
    };
    cv::Rect r = at(0);
    for (int k = 1; k < 12; ++k) {
      const bool free = std::none_of(placed.begin(), placed.end(), [&](const cv::Rect& o) { return (o & r).area() > 0; });
      if (free) break;
      r = at((k % 2 ? 1 : -1) * ((k + 1) / 2) * (h + 1));
    }
    placed.push_back(r);
    cv::rectangle(m, r, cv::Scalar(255, 255, 255, 255), cv::FILLED);
    cv::rectangle(m, r, kColours[i % kNumberedPartColours], 1);
    cv::putText(m, text, {r.x + 3, r.y + 2 + ts.height}, font, scale, cv::Scalar(0, 0, 0, 255), 1, cv::LINE_AA);
  }
}

}  // namespace svgm
