// The GIF writer: decoded by a small independent GIF reader (below, written from the GIF89a
// specification), frames come back exactly when the clip has at most 256 colours and within a
// bounded error otherwise; delays add up to the clip's length; the loop extension is there only
// for a loop; the LZW dictionary resets (large noisy frames) decode correctly.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "export/gif_writer.h"
#include "temp_dir.h"

using namespace svgm;
using svgm::test::TempDir;

namespace {

struct Gif {
  int width = 0, height = 0;
  bool loops = false;
  std::vector<int> delays;
  std::vector<std::vector<uint32_t>> frames;  // 0xRRGGBB per pixel
};

// A minimal GIF reader: global palette, full-canvas frames, LZW (what our writer produces).
Gif decode(const std::string& b) {
  Gif g;
  size_t p = 0;
  auto u8 = [&]() { return static_cast<int>(static_cast<uint8_t>(b.at(p++))); };
  auto u16 = [&]() { const int lo = u8(); return lo | u8() << 8; };
  REQUIRE(b.substr(0, 6) == "GIF89a");
  p = 6;
  g.width = u16();
  g.height = u16();
  const int packed = u8();
  u8();
  u8();
  REQUIRE((packed & 0x80) != 0);
  std::vector<uint32_t> palette(static_cast<size_t>(1) << ((packed & 7) + 1));
  for (uint32_t& c : palette) c = static_cast<uint32_t>(u8() << 16 | u8() << 8 | u8());
  for (;;) {
    const int tag = u8();
    if (tag == 0x3B) break;
    if (tag == 0x21) {
      const int label = u8();
      std::string data;
      for (int n = u8(); n; n = u8()) data += b.substr((p += n) - n, static_cast<size_t>(n));
      if (label == 0xFF && data.rfind("NETSCAPE2.0", 0) == 0) g.loops = true;
      if (label == 0xF9) g.delays.push_back(static_cast<uint8_t>(data[1]) | static_cast<uint8_t>(data[2]) << 8);
      continue;
    }
    REQUIRE(tag == 0x2C);
    p += 8;  // position and size (the whole canvas)
    u8();
    const int min_size = u8();
    std::string data;
    for (int n = u8(); n; n = u8()) data += b.substr((p += n) - n, static_cast<size_t>(n));
    // LZW decoding.
    const int clear = 1 << min_size, eoi = clear + 1;
    std::vector<std::vector<uint8_t>> dict;
    int size = min_size + 1;
    auto reset = [&]() {
      dict.assign(static_cast<size_t>(eoi + 1), {});
      for (int i = 0; i < clear; ++i) dict[static_cast<size_t>(i)] = {static_cast<uint8_t>(i)};
      size = min_size + 1;
    };
    reset();
    std::vector<uint8_t> out;
    size_t bit = 0;
    int prev = -1;
    while (bit + static_cast<size_t>(size) <= data.size() * 8) {
      int code = 0;
      for (int k = 0; k < size; ++k, ++bit) code |= (static_cast<uint8_t>(data[bit / 8]) >> (bit % 8) & 1) << k;
      if (code == clear) {
        reset();
        prev = -1;
        continue;
      }
      if (code == eoi) break;
      std::vector<uint8_t> entry;
      if (code < static_cast<int>(dict.size())) entry = dict[static_cast<size_t>(code)];
      else {
        REQUIRE(prev >= 0);
        entry = dict[static_cast<size_t>(prev)];
        entry.push_back(entry[0]);
      }
      out.insert(out.end(), entry.begin(), entry.end());
      if (prev >= 0 && dict.size() < 4096) {
        std::vector<uint8_t> add = dict[static_cast<size_t>(prev)];
        add.push_back(entry[0]);
        dict.push_back(add);
      }
      if (static_cast<int>(dict.size()) == (1 << size) && size < 12) ++size;
      prev = code;
    }
    REQUIRE(out.size() == static_cast<size_t>(g.width) * g.height);
    std::vector<uint32_t> frame;
    for (uint8_t i : out) frame.push_back(palette[i]);
    g.frames.push_back(frame);
  }
  return g;
}

std::string read_all(const std::filesystem::path& f) {
  std::ifstream in(f, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Frame i: a colour per pixel from `colour(i, x, y)`, opaque.
RgbaImage make(int w, int h, int i, uint32_t (*colour)(int, int, int)) {
  RgbaImage img{w, h, std::vector<uint8_t>(static_cast<size_t>(w) * h * 4)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const uint32_t c = colour(i, x, y);
      uint8_t* px = &img.rgba[(static_cast<size_t>(y) * w + x) * 4];
      px[0] = static_cast<uint8_t>(c >> 16);
      px[1] = static_cast<uint8_t>(c >> 8);
      px[2] = static_cast<uint8_t>(c);
      px[3] = 255;
    }
  return img;
}

}  // namespace

TEST_SUITE("export") {

TEST_CASE("gif: few colours come back exactly, through LZW dictionary resets; delays sum to the clip") {
  TempDir dir("gif");
  // 200 colours scattered pseudo-randomly: the LZW dictionary fills (4096 codes) many times.
  auto colour = [](int i, int x, int y) -> uint32_t {
    const uint32_t k = static_cast<uint32_t>((x * 7919 + y * 104729 + i * 31) % 200);
    return k * 0x010203u & 0xffffff;
  };
  const int W = 160, H = 120, N = 7;
  write_gif(dir.path / "a.gif", N, 30, [&](int i) { return make(W, H, i, colour); }, true);
  const Gif g = decode(read_all(dir.path / "a.gif"));
  CHECK(g.width == W);
  CHECK(g.height == H);
  CHECK(g.loops);
  REQUIRE(g.frames.size() == static_cast<size_t>(N));
  int total = 0;
  for (int d : g.delays) total += d;
  CHECK(total == 23);  // round(700 / 30) hundredths
  for (int i = 0; i < N; ++i) {
    size_t wrong = 0;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) wrong += g.frames[static_cast<size_t>(i)][static_cast<size_t>(y * W + x)] != colour(i, x, y);
    CAPTURE(i);
    CHECK(wrong == 0);
  }
}

TEST_CASE("gif: more than 256 colours are approximated by a shared palette; once plays once") {
  TempDir dir("gif");
  // A smooth two-axis ramp: 4096 colours over a 64 x 64 frame.
  auto colour = [](int i, int x, int y) -> uint32_t {
    return static_cast<uint32_t>((x * 4) << 16 | (y * 4) << 8 | (i * 60));
  };
  write_gif(dir.path / "b.gif", 3, 10, [&](int i) { return make(64, 64, i, colour); }, false);
  const Gif g = decode(read_all(dir.path / "b.gif"));
  CHECK(!g.loops);
  REQUIRE(g.frames.size() == 3);
  CHECK(g.delays == std::vector<int>{10, 10, 10});
  double se = 0, worst = 0;
  for (int i = 0; i < 3; ++i)
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) {
        const uint32_t a = g.frames[static_cast<size_t>(i)][static_cast<size_t>(y * 64 + x)], b = colour(i, x, y);
        for (int k = 0; k < 3; ++k) {
          const double d = (static_cast<int>(a >> (8 * k) & 255) - static_cast<int>(b >> (8 * k) & 255)) / 255.0;
          se += d * d;
          worst = std::fmax(worst, std::fabs(d));
        }
      }
  const double psnr = 10 * std::log10(1 / (se / (3 * 64 * 64 * 3)));
  CAPTURE(psnr);
  CAPTURE(worst);
  // 256 boxes over 12,288 ramp colours: each box spans about 16 levels of a 256-level channel.
  CHECK(psnr > 30);
  CHECK(worst < 0.2);
}

}  // TEST_SUITE
