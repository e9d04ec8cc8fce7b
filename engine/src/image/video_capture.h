// Opening a video file for reading, one way everywhere (the fitter's target, the report's
// frames): OpenCV's FFmpeg back end when it has one, and one error line naming the file.
#pragma once

#include <filesystem>

#include <opencv2/videoio.hpp>

namespace svgm {

// An opened capture of `file`. Throws svgm::Error "<file>: not a readable video".
cv::VideoCapture open_video_capture(const std::filesystem::path& file);

}  // namespace svgm
