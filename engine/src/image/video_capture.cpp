// Opening a video file for reading: see video_capture.h.
#include "image/video_capture.h"

#include <opencv2/videoio/registry.hpp>

#include "svgmotion/error.h"

namespace svgm {

cv::VideoCapture open_video_capture(const std::filesystem::path& file) {
  // FFmpeg explicitly when available: CAP_ANY would let the image-sequence back end interpret
  // printf patterns in the name, and other back ends disagree on frame counts.
  const auto api = cv::videoio_registry::hasBackend(cv::CAP_FFMPEG) ? cv::CAP_FFMPEG : cv::CAP_ANY;
  cv::VideoCapture cap;
  try {
    cap.open(file.string(), api);
  } catch (const cv::Exception&) {
    cap.release();
  }
  if (!cap.isOpened()) throw Error(file.string() + ": not a readable video");
  return cap;
}

}  // namespace svgm
