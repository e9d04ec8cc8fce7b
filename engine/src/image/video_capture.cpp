// Opening a video file for reading: see video_capture.h.
#include "image/video_capture.h"

#include <opencv2/videoio/registry.hpp>

#include <cstring>
#include <fstream>
#include <string>
#include <string_view>

#include "svgmotion/error.h"

namespace svgm {

namespace {

// What `file` holds when it is an image rather than a video ("" otherwise): FFmpeg reads an SVG,
// PNG or JPEG as a one-frame clip, so such a file named .mp4 would be fitted as a still.
std::string image_content(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  char head[512] = {0};
  in.read(head, sizeof head);
  const size_t n = static_cast<size_t>(in.gcount());
  const std::string_view h(head, n);
  if (h.substr(0, 8) == std::string_view("\x89PNG\r\n\x1a\n", 8)) return "a PNG image";
  if (h.substr(0, 3) == "\xff\xd8\xff") return "a JPEG image";
  // Markup: an optional UTF-8 byte-order mark and white space, then "<" (XML, SVG, HTML).
  size_t i = h.substr(0, 3) == "\xef\xbb\xbf" ? 3 : 0;
  while (i < n && std::strchr(" \t\r\n", h[i]) && h[i] != '\0') ++i;
  if (i < n && h[i] == '<') return h.find("<svg") != std::string_view::npos ? "an SVG document" : "an XML or HTML document";
  return "";
}

}  // namespace

cv::VideoCapture open_video_capture(const std::filesystem::path& file) {
  // FFmpeg explicitly when available: CAP_ANY would let the image-sequence back end interpret
  // printf patterns in the name, and other back ends disagree on frame counts.
  const auto api = cv::videoio_registry::hasBackend(cv::CAP_FFMPEG) ? cv::CAP_FFMPEG : cv::CAP_ANY;
  if (const std::string what = image_content(file); !what.empty())
    throw Error(file.string() + ": not a readable video (it holds " + what + ")");
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
