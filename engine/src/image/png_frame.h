// Reading a PNG as it is stored, for a target given as a folder of frames: grey, grey+alpha, RGB
// or RGBA at 8 or 16 bits per channel, as a cv::Mat in OpenCV's channel order (BGR, BGRA), so
// that the target loader's conversion sees every bit the file holds. Palette and 1/2/4-bit images
// are expanded to 8 bits; a tRNS colour key becomes an alpha channel. No gamma or colour-profile
// processing: a frame's values are taken as written, as video frames are.
#pragma once

#include <filesystem>

#include <opencv2/core.hpp>

namespace svgm {

// The image in `file`, or an empty Mat when it is not a PNG libpng can read (the caller names
// the file in its own error line).
cv::Mat read_png_frame(const std::filesystem::path& file);

}  // namespace svgm
