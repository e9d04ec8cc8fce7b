// The GIF writer: decoded by a small independent GIF reader (below, written from the GIF89a
// specification: sub-rectangles, the transparent index, disposal 1 and 2), frames come back
// exactly when the clip has at most 256 colours and within a bounded error otherwise; delays
// add up to the clip's length; the loop extension is there only for a loop; the LZW dictionary
// resets (large noisy frames) decode correctly; frames after the first draw only what changed;
// a transparent GIF's alpha comes back at every frame, including pixels that turn transparent.
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

constexpr uint32_t kClear = 0xFF000000u;  // a transparent pixel in a decoded frame

struct Gif {
  int width = 0, height = 0;
  bool loops = false;
  std::vector<int> delays;
  std::vector<std::vector<uint32_t>> frames;  // 0xRRGGBB per pixel, kClear where transparent
  std::vector<int> areas;                     // pixels each image descriptor covers
};

// A minimal GIF reader: global palette, LZW, frames drawn on a canvas as a browser does (what
// our writer produces).
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
  std::vector<uint32_t> canvas(static_cast<size_t>(g.width) * g.height, kClear);
  int transparent = -1, disposal = 0;
  for (;;) {
    const int tag = u8();
    if (tag == 0x3B) break;
    if (tag == 0x21) {
      const int label = u8();
      std::string data;
      for (int n = u8(); n; n = u8()) data += b.substr((p += n) - n, static_cast<size_t>(n));
      if (label == 0xFF && data.rfind("NETSCAPE2.0", 0) == 0) g.loops = true;
      if (label == 0xF9) {
        g.delays.push_back(static_cast<uint8_t>(data[1]) | static_cast<uint8_t>(data[2]) << 8);
        disposal = data[0] >> 2 & 7;
        transparent = (data[0] & 1) ? static_cast<uint8_t>(data[3]) : -1;
      }
      continue;
    }
    REQUIRE(tag == 0x2C);
    const int x0 = u16(), y0 = u16(), w = u16(), h = u16();
    REQUIRE(x0 + w <= g.width);
    REQUIRE(y0 + h <= g.height);
    g.areas.push_back(w * h);
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
    REQUIRE(out.size() == static_cast<size_t>(w) * h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const int i = out[static_cast<size_t>(y * w + x)];
        if (i != transparent) canvas[static_cast<size_t>((y0 + y) * g.width + x0 + x)] = palette[static_cast<size_t>(i)];
      }
    g.frames.push_back(canvas);
    if (disposal == 2)
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) canvas[static_cast<size_t>((y0 + y) * g.width + x0 + x)] = kClear;
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
  // 255 boxes over 12,288 ramp colours: each box spans about 16 levels of a 256-level channel;
  // error diffusion trades a little PSNR (28 dB here; 30 nearest-colour) for no banding.
  CHECK(psnr > 27);
  CHECK(worst < 0.2);
}

TEST_CASE("gif: frames after the first draw only the rectangle that changed; a still frame is not written") {
  TempDir dir("gif");
  // A 6 x 6 square moving 2 px right per frame over a two-colour 64 x 48 background, still at
  // frames 3 and 4.
  static const int kX[] = {4, 6, 8, 10, 10, 12};
  auto colour = [](int i, int x, int y) -> uint32_t {
    if (x >= kX[i] && x < kX[i] + 6 && y >= 20 && y < 26) return 0xd33682;
    return y < 24 ? 0xfdf6e3 : 0x268bd2;
  };
  write_gif(dir.path / "d.gif", 6, 10, [&](int i) { return make(64, 48, i, colour); }, true);
  const std::string bytes = read_all(dir.path / "d.gif");
  const Gif g = decode(bytes);
  REQUIRE(g.frames.size() == 5);  // frame 4 repeats frame 3: shown twice as long instead
  CHECK(g.delays == std::vector<int>{10, 10, 10, 20, 10});
  CHECK(g.areas[0] == 64 * 48);
  // The square's old and new place: 8 x 6 pixels.
  for (size_t k = 1; k < g.areas.size(); ++k) CHECK(g.areas[k] == 8 * 6);
  static const int kShown[] = {0, 1, 2, 3, 5};
  for (size_t k = 0; k < g.frames.size(); ++k) {
    size_t wrong = 0;
    for (int y = 0; y < 48; ++y)
      for (int x = 0; x < 64; ++x) wrong += g.frames[k][static_cast<size_t>(y * 64 + x)] != colour(kShown[k], x, y);
    CAPTURE(k);
    CHECK(wrong == 0);
  }
  // Five frames cost little more than one: a GIF of frame 0 alone.
  write_gif(dir.path / "one.gif", 1, 10, [&](int) { return make(64, 48, 0, colour); }, true);
  CHECK(bytes.size() < read_all(dir.path / "one.gif").size() + 4 * 60);
}

TEST_CASE("gif: transparent: alpha below 128 is transparent at every frame, also where a shape leaves") {
  TempDir dir("gif");
  // A 10 x 10 square crossing an empty 40 x 20 canvas, half-transparent at its left column
  // (alpha 100: transparent in a GIF), and a still 4 x 4 square at the right.
  auto frame = [](int i) {
    RgbaImage img{40, 20, std::vector<uint8_t>(40 * 20 * 4, 0)};
    auto put = [&](int x, int y, uint32_t c, int a) {
      uint8_t* px = &img.rgba[static_cast<size_t>(y * 40 + x) * 4];
      px[0] = static_cast<uint8_t>(c >> 16), px[1] = static_cast<uint8_t>(c >> 8), px[2] = static_cast<uint8_t>(c);
      px[3] = static_cast<uint8_t>(a);
    };
    for (int y = 5; y < 15; ++y)
      for (int x = 3 * i; x < 3 * i + 10; ++x) put(x, y, 0x36c, x == 3 * i ? 100 : 255);
    for (int y = 0; y < 4; ++y)
      for (int x = 36; x < 40; ++x) put(x, y, 0xc33, 200);
    return img;
  };
  write_gif(dir.path / "t.gif", 5, 10, frame, true, true);
  const Gif g = decode(read_all(dir.path / "t.gif"));
  REQUIRE(g.frames.size() == 5);
  for (int i = 0; i < 5; ++i) {
    const RgbaImage want = frame(i);
    size_t wrong = 0;
    for (int p = 0; p < 40 * 20; ++p) {
      const uint8_t* px = &want.rgba[static_cast<size_t>(p) * 4];
      const uint32_t expect = px[3] < 128 ? kClear : static_cast<uint32_t>(px[0] << 16 | px[1] << 8 | px[2]);
      wrong += g.frames[static_cast<size_t>(i)][static_cast<size_t>(p)] != expect;
    }
    CAPTURE(i);
    CHECK(wrong == 0);
  }
}

}  // TEST_SUITE
