// A PNG read with libpng's progressive-free "read whole image" API (see png_frame.h): set the
// expansions, read every row into the Mat, swap RGB to BGR. libpng reports errors by longjmp,
// so nothing with a destructor lives between setjmp and the reads.
#include "image/png_frame.h"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <memory>
#include <vector>

namespace svgm {

namespace {

struct FileCloser {
  void operator()(FILE* f) const {
    if (f) std::fclose(f);
  }
};

}  // namespace

cv::Mat read_png_frame(const std::filesystem::path& file) {
  std::unique_ptr<FILE, FileCloser> fp(std::fopen(file.c_str(), "rb"));
  if (!fp) return {};
  png_byte sig[8];
  if (std::fread(sig, 1, 8, fp.get()) != 8 || png_sig_cmp(sig, 0, 8) != 0) return {};
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (!png) return {};
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    return {};
  }
  // Declared before setjmp: a longjmp back here must find them initialised.
  cv::Mat img;
  std::vector<png_bytep> rows;
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return {};
  }
  png_init_io(png, fp.get());
  png_set_sig_bytes(png, 8);
  png_read_info(png, info);
  const int color = png_get_color_type(png, info);
  const int depth = png_get_bit_depth(png, info);
  if (color == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (color == PNG_COLOR_TYPE_GRAY && depth < 8) png_set_expand_gray_1_2_4_to_8(png);
  if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png);
  if (depth == 16) png_set_swap(png);  // PNG is big-endian; the Mat holds native 16-bit values
  png_set_bgr(png);
  png_read_update_info(png, info);
  const int channels = png_get_channels(png, info);
  const int out_depth = png_get_bit_depth(png, info);
  const png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
  if (channels < 1 || channels > 4 || (out_depth != 8 && out_depth != 16) || w == 0 || h == 0) {
    png_destroy_read_struct(&png, &info, nullptr);
    return {};
  }
  img.create(static_cast<int>(h), static_cast<int>(w), CV_MAKETYPE(out_depth == 16 ? CV_16U : CV_8U, channels));
  rows.resize(h);
  for (png_uint_32 y = 0; y < h; ++y) rows[y] = img.ptr<png_byte>(static_cast<int>(y));
  png_read_image(png, rows.data());
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return img;
}

}  // namespace svgm
