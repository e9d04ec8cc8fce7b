// Reading a video file frame by frame through FFmpeg's libavformat/libavcodec/libswscale, one
// way everywhere (the fitter's target, the report's frames, the check that a written clip reads
// back), with one error line naming the file.
//
// Why not OpenCV's VideoCapture: its module (videoio) pulls in imgcodecs and through them GDAL,
// GDCM, Poppler and ~180 other shared libraries, loaded by every run of the CLI (~30 MB resident
// and most of a second of start-up on this project's machines) for nothing we use; and it
// converts every clip to RGB with BT.601's matrix whatever the stream says, while our own clips
// are BT.709-tagged (media/video_encoder.h). Here the stream's own colour matrix and range pick
// the conversion (untagged: BT.601, as FFmpeg's tools assume), and a rotation the container
// asks for (phones) is applied, as players do.
#pragma once

#include <filesystem>
#include <memory>

#include <opencv2/core.hpp>

namespace svgm {

class VideoDecoder {
 public:
  // Opens `file`'s first video stream. Throws svgm::Error "<file>: not a readable video" (or
  // "... (it holds a PNG image)" and the like, for an image FFmpeg would read as a one-frame clip).
  explicit VideoDecoder(const std::filesystem::path& file);
  ~VideoDecoder();
  VideoDecoder(const VideoDecoder&) = delete;
  VideoDecoder& operator=(const VideoDecoder&) = delete;

  // The stream's frame size as its parameters give it, after the container's rotation (0 when
  // the container does not say), and its frame rate (average, else the stream's base rate; 0 when
  // neither is known).
  int width() const;
  int height() const;
  double fps() const;

  // Decodes the next frame; false at the end of the stream or when it cannot be decoded any
  // further. Damaged packets in between are skipped, as players do.
  bool grab();
  // The frame grab() decoded, as 8-bit BGR (OpenCV's channel order); false before any grab.
  bool retrieve(cv::Mat& bgr);
  bool read(cv::Mat& bgr) { return grab() && retrieve(bgr); }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace svgm
