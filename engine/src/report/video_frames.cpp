// Still frames of a video (see video_frames.h). The video is read once, front to back, keeping
// only the frames asked for: seeking is inexact for some codecs.
#include "report/video_frames.h"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <map>

#include "media/video_decoder.h"
#include "svgmotion/error.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

RgbaImage thumbnail(const cv::Mat& bgr, int width) {
  cv::Mat img = bgr;
  if (width > 0 && img.cols > width) {
    const int h = std::max(1, static_cast<int>(static_cast<double>(img.rows) * width / img.cols + 0.5));
    cv::resize(bgr, img, cv::Size(width, h), 0, 0, cv::INTER_AREA);
  }
  cv::Mat rgba;
  cv::cvtColor(img, rgba, img.channels() == 1 ? cv::COLOR_GRAY2RGBA : cv::COLOR_BGR2RGBA);
  RgbaImage out{rgba.cols, rgba.rows, {}};
  out.rgba.resize(static_cast<size_t>(rgba.cols) * rgba.rows * 4);
  for (int y = 0; y < rgba.rows; ++y)
    std::copy_n(rgba.ptr<uint8_t>(y), static_cast<size_t>(rgba.cols) * 4, &out.rgba[static_cast<size_t>(y) * rgba.cols * 4]);
  return out;
}

}  // namespace

std::vector<RgbaImage> video_frames(const fs::path& file, const std::vector<int>& indices, int width) {
  VideoDecoder cap(file);
  std::map<int, RgbaImage> wanted;
  for (int i : indices) wanted[std::max(0, i)];
  const int last_wanted = wanted.empty() ? -1 : wanted.rbegin()->first;
  RgbaImage last;
  cv::Mat frame;
  try {
    for (int i = 0; i <= last_wanted && cap.read(frame) && !frame.empty(); ++i) {
      last = thumbnail(frame, width);
      if (wanted.count(i)) wanted[i] = last;
    }
  } catch (const cv::Exception&) {
    throw Error(file.string() + ": not a readable video");
  }
  if (last.rgba.empty() && !indices.empty()) throw Error(file.string() + ": not a readable video");
  std::vector<RgbaImage> out;
  for (int i : indices) {
    const RgbaImage& img = wanted[std::max(0, i)];
    out.push_back(img.rgba.empty() ? last : img);
  }
  return out;
}

int video_frame_count(const fs::path& file) {
  VideoDecoder cap(file);
  int n = 0;
  while (cap.grab()) ++n;
  if (n == 0) throw Error(file.string() + ": not a readable video");
  return n;
}

}  // namespace svgm
