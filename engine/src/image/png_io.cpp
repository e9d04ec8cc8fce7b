// PNG reading and atomic writing through libpng's simplified API.
#include "svgmotion/png_io.h"
#include "svgmotion/atomic_file.h"

#include <png.h>

#include <cstring>
#include <fstream>
#include <system_error>


#include "svgmotion/error.h"

namespace svgm {

namespace fs = std::filesystem;

std::string encode_png(const RgbaImage& img) {
  if (img.width <= 0 || img.height <= 0 ||
      img.rgba.size() != static_cast<size_t>(img.width) * img.height * 4)
    throw Error("internal: image buffer does not match its size");
  png_image pi;
  std::memset(&pi, 0, sizeof pi);
  pi.version = PNG_IMAGE_VERSION;
  pi.width = static_cast<png_uint_32>(img.width);
  pi.height = static_cast<png_uint_32>(img.height);
  pi.format = PNG_FORMAT_RGBA;
  png_alloc_size_t size = 0;
  if (!png_image_write_to_memory(&pi, nullptr, &size, 0, img.rgba.data(), 0, nullptr))
    throw Error(std::string("cannot encode PNG: ") + pi.message);
  std::string bytes(size, '\0');
  if (!png_image_write_to_memory(&pi, bytes.data(), &size, 0, img.rgba.data(), 0, nullptr))
    throw Error(std::string("cannot encode PNG: ") + pi.message);
  bytes.resize(size);
  return bytes;
}

void write_png(const fs::path& file, const RgbaImage& img) {
  std::string bytes;
  try {
    bytes = encode_png(img);
  } catch (const Error& e) {
    throw Error(file.string() + ": " + e.what());
  }
  write_file_atomic(file, bytes);
}

RgbaImage read_png(const fs::path& file) {
  png_image pi;
  std::memset(&pi, 0, sizeof pi);
  pi.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&pi, file.c_str()))
    throw Error(file.string() + ": cannot read PNG: " + pi.message);
  pi.format = PNG_FORMAT_RGBA;
  RgbaImage img;
  img.width = static_cast<int>(pi.width);
  img.height = static_cast<int>(pi.height);
  img.rgba.resize(PNG_IMAGE_SIZE(pi));
  if (!png_image_finish_read(&pi, nullptr, img.rgba.data(), 0, nullptr)) {
    png_image_free(&pi);
    throw Error(file.string() + ": cannot read PNG: " + pi.message);
  }
  return img;
}

}  // namespace svgm
