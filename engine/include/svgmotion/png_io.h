// PNG files: writing images atomically, reading them back (tests, targets).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace svgm {

struct RgbaImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;  // straight alpha, row-major, 4 bytes per pixel
};

// `image` as the bytes of an 8-bit RGBA PNG file. Throws svgm::Error.
std::string encode_png(const RgbaImage& image);

// Writes `image` as an 8-bit RGBA PNG to a temporary name beside `file`, then renames it, so a
// failure never leaves a half-written file. Throws svgm::Error naming the file.
void write_png(const std::filesystem::path& file, const RgbaImage& image);

// Reads any PNG as 8-bit straight RGBA. Throws svgm::Error naming the file.
RgbaImage read_png(const std::filesystem::path& file);

}  // namespace svgm
