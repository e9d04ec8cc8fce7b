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

void write_png(const fs::path& file, const RgbaImage& img) {
  if (img.width <= 0 || img.height <= 0 ||
      img.rgba.size() != static_cast<size_t>(img.width) * img.height * 4)
    throw Error(file.string() + ": internal: image buffer does not match its size");
  png_image pi;
  std::memset(&pi, 0, sizeof pi);
  pi.version = PNG_IMAGE_VERSION;
  pi.width = static_cast<png_uint_32>(img.width);
  pi.height = static_cast<png_uint_32>(img.height);
  pi.format = PNG_FORMAT_RGBA;
  png_alloc_size_t size = 0;
  if (!png_image_write_to_memory(&pi, nullptr, &size, 0, img.rgba.data(), 0, nullptr))
    throw Error(file.string() + ": cannot encode PNG: " + pi.message);
  std::vector<uint8_t> bytes(size);
  if (!png_image_write_to_memory(&pi, bytes.data(), &size, 0, img.rgba.data(), 0, nullptr))
    throw Error(file.string() + ": cannot encode PNG: " + pi.message);

  write_file_atomic(file, std::string_view(reinterpret_cast<const char*>(bytes.data()), size));
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
