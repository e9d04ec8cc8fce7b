// The fitter's target input (load_target, probe_target) and the preview video writer.
//
// Inputs are made at run time in a temporary folder: PNG frames with svgm::write_png (libpng,
// known RGBA byte order, so a BGR/RGB slip in the loader shows) and videos with the preview
// writer itself (one panel), whose colours are then checked through the already-checked
// loader. The tests need no OpenCV headers.
#include <doctest/doctest.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

#include "media/preview_video.h"
#include "svgmotion/error.h"
#include "svgmotion/png_io.h"
#include "svgmotion/target_video.h"

#include "temp_dir.h"

using namespace svgm;
namespace fs = std::filesystem;

namespace {

struct TempDir : test::TempDir {
  TempDir() : test::TempDir("svgm_fit_test") {}
};

struct Rgb {
  int r, g, b;
};

RgbaImage solid(int w, int h, Rgb c = {255, 255, 255}, int a = 255) {
  RgbaImage img;
  img.width = w;
  img.height = h;
  img.rgba.resize(static_cast<size_t>(w) * h * 4);
  for (size_t i = 0; i < img.rgba.size(); i += 4) {
    img.rgba[i] = static_cast<uint8_t>(c.r);
    img.rgba[i + 1] = static_cast<uint8_t>(c.g);
    img.rgba[i + 2] = static_cast<uint8_t>(c.b);
    img.rgba[i + 3] = static_cast<uint8_t>(a);
  }
  return img;
}

// Fills columns [x0, x1) x rows [y0, y1).
void fill(RgbaImage& img, int x0, int y0, int x1, int y1, Rgb c, int a = 255) {
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      uint8_t* p = img.rgba.data() + (static_cast<size_t>(y) * img.width + x) * 4;
      p[0] = static_cast<uint8_t>(c.r);
      p[1] = static_cast<uint8_t>(c.g);
      p[2] = static_cast<uint8_t>(c.b);
      p[3] = static_cast<uint8_t>(a);
    }
}

void write_video(const fs::path& file, const std::vector<RgbaImage>& frames, double fps = 24) {
  write_preview_video(file, std::vector<std::vector<RgbaImage>>{frames}, fps);
}

// Channel c of pixel (x, y) of keyframe k in a K*H*W*4 buffer.
float at(const TargetFrames& t, const std::vector<float>& buf, int k, int x, int y, int c) {
  return buf[((static_cast<size_t>(k) * t.height + y) * t.width + x) * 4 + c];
}
float sdf_at(const TargetFrames& t, int k, int x, int y) {
  return t.sdf[(static_cast<size_t>(k) * t.height + y) * t.width + x];
}
int mask_at(const TargetFrames& t, int k, int x, int y) {
  return t.mask[(static_cast<size_t>(k) * t.height + y) * t.width + x];
}

std::string load_error(const fs::path& source, int w, int h, const TargetOptions& o = {}) {
  try {
    load_target(source, w, h, o);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

// Frame i shows i's 6 bits as 8x8 black/white blocks: survives lossy compression exactly.
RgbaImage bit_frame(int i) {
  RgbaImage img = solid(64, 16);
  for (int b = 0; b < 6; ++b)
    if (i >> b & 1) fill(img, 8 * b + 4, 4, 8 * b + 12, 12, {0, 0, 0});
  return img;
}
int read_bits(const TargetFrames& t, int k) {
  int v = 0;
  for (int b = 0; b < 6; ++b)
    if (at(t, t.raw, k, 8 * b + 8, 8, 1) < 0.5f) v |= 1 << b;
  return v;
}

const std::vector<int> kIndices49x15 = {0, 3, 7, 10, 14, 17, 21, 24, 27, 31, 34, 38, 41, 45, 48};

}  // namespace

TEST_SUITE("fit") {

TEST_CASE("uniform keyframe sampling from a PNG folder") {
  TempDir dir;
  // Frame i carries its index in pixel (0, 0): 5i / 255, exact through PNG.
  for (int i = 0; i < 49; ++i) {
    RgbaImage img = solid(8, 8);
    fill(img, 0, 0, 1, 1, {5 * i, 5 * i, 5 * i});
    char name[16];
    std::snprintf(name, sizeof name, "%03d.png", i);
    write_png(dir.path / name, img);
  }
  const TargetFrames t = load_target(dir.path, 8, 8, TargetOptions{});
  CHECK(t.keyframes == 15);
  CHECK(t.source_frames == 49);
  CHECK(t.fps == 24);
  CHECK(t.source_index == kIndices49x15);
  for (int k = 0; k < 15; ++k)
    CHECK(at(t, t.raw, k, 0, 0, 0) ==
          doctest::Approx(5.0 * kIndices49x15[k] / 255.0).epsilon(1e-6));

  TargetOptions o;
  o.keyframes = 1;
  CHECK(load_target(dir.path, 8, 8, o).source_index == std::vector<int>{0});
  o.keyframes = 49;
  const TargetFrames all = load_target(dir.path, 8, 8, o);
  for (int k = 0; k < 49; ++k) CHECK(all.source_index[k] == k);

  // Halves round up: 4 frames, 3 keyframes -> 0, round(1.5) = 2, 3.
  TempDir four;
  for (int i = 0; i < 4; ++i) write_png(four.path / (std::to_string(i) + ".png"), solid(4, 4));
  o.keyframes = 3;
  CHECK(load_target(four.path, 4, 4, o).source_index == std::vector<int>{0, 2, 3});
}

TEST_CASE("uniform keyframe sampling from a video picks the right frames") {
  TempDir dir;
  std::vector<RgbaImage> frames;
  for (int i = 0; i < 49; ++i) frames.push_back(bit_frame(i));
  write_video(dir.path / "count.mp4", frames, 25);

  const TargetInfo info = probe_target(dir.path / "count.mp4");
  CHECK(info.frames == 49);
  CHECK(info.width == 64);
  CHECK(info.height == 16);
  CHECK(info.fps == doctest::Approx(25));

  const TargetFrames t = load_target(dir.path / "count.mp4", 64, 16);
  CHECK(t.source_frames == 49);
  CHECK(t.fps == doctest::Approx(25));
  CHECK(t.source_index == kIndices49x15);
  for (int k = 0; k < 15; ++k) CHECK(read_bits(t, k) == kIndices49x15[k]);
}

TEST_CASE("frame colours survive the round trip (exact for PNG, H.264 tolerance for video)") {
  // Red, green and blue squares, so a channel swap anywhere shows.
  RgbaImage img = solid(64, 48);
  fill(img, 4, 12, 20, 36, {220, 40, 30});
  fill(img, 24, 12, 40, 36, {30, 200, 60});
  fill(img, 44, 12, 60, 36, {40, 50, 210});
  const struct {
    int x;
    Rgb c;
  } squares[] = {{12, {220, 40, 30}}, {32, {30, 200, 60}}, {52, {40, 50, 210}}};

  TempDir dir;
  fs::create_directory(dir.path / "png");
  for (int i = 0; i < 3; ++i) write_png(dir.path / "png" / ("f" + std::to_string(i) + ".png"), img);
  TargetOptions o;
  o.keyframes = 3;
  const TargetFrames p = load_target(dir.path / "png", 64, 48, o);
  for (int k = 0; k < 3; ++k)
    for (const auto& s : squares) {
      const int want[3] = {s.c.r, s.c.g, s.c.b};
      for (int c = 0; c < 3; ++c) {
        CHECK(at(p, p.raw, k, s.x, 24, c) == doctest::Approx(want[c] / 255.0).epsilon(1e-6));
        CHECK(at(p, p.rgba, k, s.x, 24, c) == at(p, p.raw, k, s.x, 24, c));
      }
      CHECK(at(p, p.rgba, k, s.x, 24, 3) == 1.0f);
      CHECK(at(p, p.raw, k, s.x, 24, 3) == 1.0f);
    }
  // White background is exactly white.
  CHECK(at(p, p.raw, 0, 2, 2, 0) == 1.0f);

  write_video(dir.path / "colours.mp4", std::vector<RgbaImage>(5, img));
  const TargetFrames v = load_target(dir.path / "colours.mp4", 64, 48, o);
  CHECK(v.source_index == std::vector<int>{0, 2, 4});
  for (int k = 0; k < 3; ++k)
    for (const auto& s : squares) {
      const int want[3] = {s.c.r, s.c.g, s.c.b};
      for (int c = 0; c < 3; ++c)
        CHECK(std::abs(at(v, v.raw, k, s.x, 24, c) - want[c] / 255.0f) < 0.06f);
    }
}

TEST_CASE("PNG alpha is composited over white") {
  TempDir dir;
  RgbaImage img = solid(8, 8, {0, 0, 0}, 0);  // transparent black: must read as white
  fill(img, 2, 2, 4, 4, {0, 0, 0}, 255);
  fill(img, 5, 5, 6, 6, {0, 0, 0}, 128);
  write_png(dir.path / "0.png", img);
  TargetOptions o;
  o.keyframes = 1;
  const TargetFrames t = load_target(dir.path, 8, 8, o);
  CHECK(at(t, t.raw, 0, 0, 0, 0) == 1.0f);
  CHECK(at(t, t.raw, 0, 2, 2, 0) == 0.0f);
  CHECK(at(t, t.raw, 0, 5, 5, 1) == doctest::Approx(127.0 / 255.0).epsilon(1e-5));
}

TEST_CASE("foreground on an off-white, drifting background is the figure, not the frame") {
  TempDir dir;
  RgbaImage img = solid(40, 40);
  fill(img, 0, 0, 40, 40, {252, 254, 247});  // a generated video's off-white (blue 0.969 < 0.97)
  fill(img, 10, 10, 20, 20, {40, 40, 200});
  write_png(dir.path / "0.png", img);
  RgbaImage dark = solid(40, 40);
  fill(dark, 0, 0, 40, 40, {20, 30, 80});  // a scene's own night sky is figure, as before
  write_png(dir.path / "1.png", dark);
  TargetOptions o;
  o.keyframes = 2;
  o.dilate_px = 0;
  const TargetFrames t = load_target(dir.path, 40, 40, o);
  size_t fg0 = 0, fg1 = 0;
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 40; ++x) fg0 += mask_at(t, 0, x, y), fg1 += mask_at(t, 1, x, y);
  CHECK(fg0 == 100);  // exactly the 10x10 square
  CHECK(fg1 == 1600);
  CHECK(t.source_width == 40);
}

TEST_CASE("frames are resized to the requested size") {
  TempDir dir;
  RgbaImage img = solid(64, 48);
  fill(img, 0, 0, 32, 48, {0, 0, 0});  // left half black
  for (int i = 0; i < 2; ++i) write_png(dir.path / (std::to_string(i) + ".png"), img);
  TargetOptions o;
  o.keyframes = 2;
  for (const auto& size : {std::pair{32, 24}, std::pair{128, 96}, std::pair{50, 50}}) {
    const int w = size.first, h = size.second;  // copies: clang 14 cannot CAPTURE a binding
    CAPTURE(w);
    const TargetFrames t = load_target(dir.path, w, h, o);
    CHECK(t.width == w);
    CHECK(t.height == h);
    CHECK(t.raw.size() == size_t(2) * w * h * 4);
    CHECK(t.rgba.size() == size_t(2) * w * h * 4);
    CHECK(t.mask.size() == size_t(2) * w * h);
    CHECK(t.sdf.size() == size_t(2) * w * h);
    CHECK(at(t, t.raw, 1, 1, h / 2, 0) == doctest::Approx(0.0));
    CHECK(at(t, t.raw, 1, w - 2, h / 2, 2) == doctest::Approx(1.0));
    CHECK(mask_at(t, 1, w / 4, h / 2) == 1);
    CHECK(mask_at(t, 1, w - 2, h / 2) == 0);
  }
}

TEST_CASE("foreground mask: components filtered, dilated by a 1-px disc, the rest whitened") {
  TempDir dir;
  RgbaImage img = solid(64, 64);
  fill(img, 20, 20, 30, 30, {50, 50, 60});    // the figure: 100 px
  fill(img, 55, 5, 56, 6, {0, 0, 0});         // a 1-px speck far away: below 4 px
  fill(img, 5, 50, 8, 53, {0, 0, 0});         // a 3x3 blot: 9 px >= max(4, 0.02 * 100)
  fill(img, 40, 40, 44, 44, {240, 240, 240}); // light grey: not ink (0.94 >= 0.9)
  write_png(dir.path / "0.png", img);
  TargetOptions o;
  o.keyframes = 1;
  o.white_threshold = 0.9;
  const TargetFrames t = load_target(dir.path, 64, 64, o);

  auto in_rect = [](int x, int y, int x0, int y0, int x1, int y1) {
    return x >= x0 && x < x1 && y >= y0 && y < y1;
  };
  // A rectangle dilated by the 3x3 cross: grown by one pixel on each side, corners excluded.
  auto dilated = [&](int x, int y, int x0, int y0, int x1, int y1) {
    return in_rect(x, y, x0 - 1, y0, x1 + 1, y1) || in_rect(x, y, x0, y0 - 1, x1, y1 + 1);
  };
  int wrong = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const bool want = dilated(x, y, 20, 20, 30, 30) || dilated(x, y, 5, 50, 8, 53);
      if (mask_at(t, 0, x, y) != (want ? 1 : 0)) ++wrong;
      if (!want)
        for (int c = 0; c < 4; ++c)
          if (at(t, t.rgba, 0, x, y, c) != 1.0f) ++wrong;
    }
  CHECK(wrong == 0);
  CHECK(mask_at(t, 0, 19, 19) == 0);  // cross, not square
  CHECK(mask_at(t, 0, 55, 5) == 0);   // the speck is gone from the mask...
  CHECK(at(t, t.rgba, 0, 55, 5, 0) == 1.0f);  // ...and from the target
  CHECK(at(t, t.raw, 0, 55, 5, 0) == 0.0f);   // but not from the raw frame
  CHECK(at(t, t.raw, 0, 41, 41, 0) < 1.0f);
  CHECK(at(t, t.rgba, 0, 41, 41, 0) == 1.0f);
  CHECK(at(t, t.rgba, 0, 25, 25, 2) == doctest::Approx(60 / 255.0).epsilon(1e-6));

  // A larger fraction drops the blot too (9 < 0.1 * 100); no dilation keeps the square exact.
  o.min_component_fraction = 0.1;
  o.dilate_px = 0;
  const TargetFrames u = load_target(dir.path, 64, 64, o);
  int count = 0;
  for (uint8_t m : u.mask) count += m;
  CHECK(count == 100);
  CHECK(mask_at(u, 0, 6, 51) == 0);
  CHECK(at(u, u.rgba, 0, 6, 51, 0) == 1.0f);

  // A larger threshold makes the light grey ink.
  o.white_threshold = 0.95;
  CHECK(mask_at(load_target(dir.path, 64, 64, o), 0, 41, 41) == 1);
}

TEST_CASE("a small mark enclosed by the figure is its detail and kept; one outside is a speck") {
  // A ring (1200 px: 40x40 less its 20x20 hole) with a 2x2 grain in its hole and a 2x2 speck
  // outside it: both are under the size floor (0.02 * 1200 = 24 px); only the speck is whitened.
  TempDir dir;
  RgbaImage img = solid(64, 64);
  fill(img, 10, 10, 50, 50, {50, 50, 60});
  fill(img, 20, 20, 40, 40, {255, 255, 255});
  fill(img, 29, 29, 31, 31, {200, 190, 170});
  fill(img, 56, 56, 58, 58, {200, 190, 170});
  write_png(dir.path / "0.png", img);
  TargetOptions o;
  o.keyframes = 1;
  o.dilate_px = 0;
  const TargetFrames t = load_target(dir.path, 64, 64, o);
  CHECK(mask_at(t, 0, 29, 29) == 1);
  CHECK(mask_at(t, 0, 30, 30) == 1);
  CHECK(at(t, t.rgba, 0, 30, 30, 2) == doctest::Approx(170 / 255.0).epsilon(1e-6));
  CHECK(mask_at(t, 0, 56, 56) == 0);
  CHECK(at(t, t.rgba, 0, 56, 56, 2) == 1.0f);
  CHECK(mask_at(t, 0, 25, 25) == 0);  // the hole itself stays background
  int count = 0;
  for (uint8_t m : t.mask) count += m;
  CHECK(count == 1200 + 4);

  // A gap in the ring opens the hole to the outside: the grain is then a speck like the other.
  fill(img, 30, 40, 32, 50, {255, 255, 255});
  write_png(dir.path / "0.png", img);
  const TargetFrames open = load_target(dir.path, 64, 64, o);
  CHECK(mask_at(open, 0, 30, 30) == 0);
}

TEST_CASE("a detached part as large as the drawing's smallest is kept however large the figure") {
  // A 40x40 figure (1600 px) and a 5x5 loose part (25 px): the fraction alone (0.02 * 1600 =
  // 32 > 25) whitens the part; keep_part_share at half the drawing's smallest part keeps it.
  TempDir dir;
  RgbaImage img = solid(64, 64);
  fill(img, 4, 4, 44, 44, {50, 50, 60});
  fill(img, 54, 54, 59, 59, {200, 150, 0});
  write_png(dir.path / "0.png", img);
  // The drawing at rest: the same figure and a 6x6 loose part (36 px), plus a 1-px and a
  // 3-px mark, too small to count as parts (under 4 px).
  RgbaImage rest = solid(64, 64);
  fill(rest, 4, 4, 44, 44, {50, 50, 60});
  fill(rest, 53, 53, 59, 59, {200, 150, 0});
  fill(rest, 60, 2, 61, 3, {0, 0, 0});
  fill(rest, 50, 2, 53, 3, {0, 0, 0});
  const double share = smallest_part_share(rest.rgba, 64, 64, 0.97);
  CHECK(share == 36.0 / (64 * 64));
  CHECK(smallest_part_share(solid(64, 64).rgba, 64, 64, 0.97) == 0.0);

  TargetOptions o;
  o.keyframes = 1;
  const TargetFrames before = load_target(dir.path, 64, 64, o);
  CHECK(mask_at(before, 0, 56, 56) == 0);
  CHECK(at(before, before.rgba, 0, 56, 56, 2) == 1.0f);  // whitened
  o.keep_part_share = 0.5 * share;  // 18 px
  const TargetFrames after = load_target(dir.path, 64, 64, o);
  CHECK(mask_at(after, 0, 56, 56) == 1);
  CHECK(at(after, after.rgba, 0, 56, 56, 0) == doctest::Approx(200 / 255.0).epsilon(1e-6));
  // A part under the share is still a speck: 25 px against a share of 26 px.
  o.keep_part_share = 26.0 / (64 * 64);
  CHECK(mask_at(load_target(dir.path, 64, 64, o), 0, 56, 56) == 0);
  o.keep_part_share = 1.5;
  CHECK_THROWS_WITH(load_target(dir.path, 64, 64, o), doctest::Contains("kept part share must be in [0, 1]"));
}

TEST_CASE("distance field: 0 inside, Euclidean distance to the nearest foreground outside") {
  TempDir dir;
  RgbaImage img = solid(64, 64);
  fill(img, 20, 20, 30, 30, {0, 0, 0});
  write_png(dir.path / "0.png", img);
  write_png(dir.path / "1.png", solid(64, 64));  // nothing drawn
  TargetOptions o;
  o.keyframes = 2;
  o.dilate_px = 0;
  const TargetFrames t = load_target(dir.path, 64, 64, o);
  for (int y = 20; y < 30; ++y)
    for (int x = 20; x < 30; ++x) CHECK(sdf_at(t, 0, x, y) == 0.0f);
  for (int d = 1; d <= 20; ++d) {
    CAPTURE(d);
    CHECK(sdf_at(t, 0, 29 + d, 25) == doctest::Approx(d).epsilon(1e-3));
    CHECK(sdf_at(t, 0, 25, 20 - d) == doctest::Approx(d).epsilon(1e-3));
  }
  CHECK(sdf_at(t, 0, 29 + 3, 29 + 4) == doctest::Approx(5.0).epsilon(1e-3));  // off the corner
  // An empty keyframe: no foreground, distances of width + height, a white target.
  for (int y = 0; y < 64; y += 7)
    for (int x = 0; x < 64; x += 7) {
      CHECK(sdf_at(t, 1, x, y) == 128.0f);
      CHECK(mask_at(t, 1, x, y) == 0);
    }

  // With dilation the distance is to the dilated mask.
  o.dilate_px = 2;
  const TargetFrames u = load_target(dir.path, 64, 64, o);
  CHECK(sdf_at(u, 0, 31, 25) == 0.0f);
  CHECK(mask_at(u, 0, 31, 25) == 1);
  CHECK(sdf_at(u, 0, 35, 25) == doctest::Approx(4.0).epsilon(1e-3));  // mask edge at 31
}

TEST_CASE("folder frames are ordered by the number in their names") {
  TempDir dir;
  for (int n : {10, 2, 1}) {
    RgbaImage img = solid(4, 4);
    fill(img, 0, 0, 1, 1, {10 * n, 0, 0});
    write_png(dir.path / ("frame_" + std::to_string(n) + ".png"), img);
  }
  write_png(dir.path / "._frame_7.png", solid(4, 4));  // hidden: ignored
  std::ofstream(dir.path / "notes.txt") << "not a frame\n";
  TargetOptions o;
  o.keyframes = 3;
  const TargetFrames t = load_target(dir.path, 4, 4, o);
  CHECK(t.source_frames == 3);
  CHECK(at(t, t.raw, 0, 0, 0, 0) == doctest::Approx(10 / 255.0).epsilon(1e-6));
  CHECK(at(t, t.raw, 1, 0, 0, 0) == doctest::Approx(20 / 255.0).epsilon(1e-6));
  CHECK(at(t, t.raw, 2, 0, 0, 0) == doctest::Approx(100 / 255.0).epsilon(1e-6));

  const TargetInfo info = probe_target(dir.path);
  CHECK(info.frames == 3);
  CHECK(info.width == 4);
  CHECK(info.height == 4);
  CHECK(info.fps == 24);
}

TEST_CASE("load_target errors name the source and the problem") {
  TempDir dir;
  const fs::path missing = dir.path / "nope.mp4";
  CHECK(load_error(missing, 8, 8) == missing.string() + ": cannot open: No such file or directory");
  CHECK(load_error(dir.path / "nodir", 8, 8) ==
        (dir.path / "nodir").string() + ": cannot open: No such file or directory");
  CHECK_THROWS_WITH_AS(probe_target(missing),
                       (missing.string() + ": cannot open: No such file or directory").c_str(),
                       Error);

  const fs::path text = dir.path / "text.mp4";
  std::ofstream(text) << "this is not a video\n";
  CHECK(load_error(text, 8, 8) == text.string() + ": not a readable video");
  const fs::path empty = dir.path / "empty.mp4";
  std::ofstream(empty).flush();
  CHECK(load_error(empty, 8, 8) == empty.string() + ": not a readable video");

  // A truncated mp4: the index (moov) is written last, so half a file is unreadable.
  const fs::path whole = dir.path / "whole.mp4";
  std::vector<RgbaImage> frames;
  for (int i = 0; i < 20; ++i) frames.push_back(bit_frame(i));
  write_video(whole, frames);
  const fs::path cut = dir.path / "cut.mp4";
  {
    std::ifstream in(whole, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  }
  CHECK(load_error(cut, 8, 8) == cut.string() + ": not a readable video");

  // Too few frames, from a video and from a folder.
  const fs::path ten = dir.path / "ten.mp4";
  write_video(ten, std::vector<RgbaImage>(frames.begin(), frames.begin() + 10));
  CHECK(load_error(ten, 8, 8) ==
        ten.string() + ": has 10 frames, fewer than the 15 keyframes asked for");
  const fs::path folder10 = dir.path / "ten";
  fs::create_directory(folder10);
  for (int i = 0; i < 10; ++i) write_png(folder10 / (std::to_string(i) + ".png"), solid(8, 8));
  CHECK(load_error(folder10, 8, 8) ==
        folder10.string() + ": has 10 frames, fewer than the 15 keyframes asked for");
  TargetOptions two;
  two.keyframes = 2;
  const fs::path one = dir.path / "one";
  fs::create_directory(one);
  write_png(one / "0.png", solid(8, 8));
  CHECK(load_error(one, 8, 8, two) ==
        one.string() + ": has 1 frame, fewer than the 2 keyframes asked for");

  // A folder without PNGs.
  const fs::path nopng = dir.path / "nopng";
  fs::create_directory(nopng);
  std::ofstream(nopng / "readme.txt") << "x\n";
  CHECK(load_error(nopng, 8, 8) == nopng.string() + ": no PNG frames");

  // Unreadable PNGs: not a PNG at all, and a valid header with the data cut off.
  const fs::path bad = dir.path / "bad";
  fs::create_directory(bad);
  for (int i = 0; i < 3; ++i) write_png(bad / (std::to_string(i) + ".png"), solid(8, 8));
  std::ofstream(bad / "1.png") << "not a png\n";
  CHECK(load_error(bad, 8, 8, two) == (bad / "1.png").string() + ": not a readable PNG");
  {
    std::ifstream in(bad / "0.png", std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(bad / "1.png", std::ios::binary | std::ios::trunc) << bytes.substr(0, 40);
  }
  TargetOptions three;
  three.keyframes = 3;
  CHECK(load_error(bad, 8, 8, three) == (bad / "1.png").string() + ": not a readable PNG");

  // Frames of different sizes.
  const fs::path sizes = dir.path / "sizes";
  fs::create_directory(sizes);
  write_png(sizes / "000.png", solid(8, 8));
  write_png(sizes / "001.png", solid(10, 8));
  CHECK(load_error(sizes, 8, 8, two) == sizes.string() + ": 001.png is 10x8, but 000.png is 8x8");

  // Names that give no order.
  const fs::path unnumbered = dir.path / "unnumbered";
  fs::create_directory(unnumbered);
  write_png(unnumbered / "0.png", solid(8, 8));
  write_png(unnumbered / "frame.png", solid(8, 8));
  CHECK(load_error(unnumbered, 8, 8, two) ==
        unnumbered.string() + ": cannot order frame.png: no number in its name");
  const fs::path same = dir.path / "same";
  fs::create_directory(same);
  write_png(same / "1.png", solid(8, 8));
  write_png(same / "01.png", solid(8, 8));
  CHECK(load_error(same, 8, 8, two) ==
        same.string() + ": frames 01.png and 1.png have the same number");

  // Options.
  TargetOptions zero;
  zero.keyframes = 0;
  CHECK(load_error(folder10, 8, 8, zero) ==
        folder10.string() + ": keyframes must be at least 1 (got 0)");
  CHECK(load_error(folder10, 0, 8, two) ==
        folder10.string() + ": target size 0x8 is out of range (each side 1..16384)");
  CHECK(load_error(folder10, 8, 16385, two) ==
        folder10.string() + ": target size 8x16385 is out of range (each side 1..16384)");
  CHECK(load_error(folder10, 8, -1, two) ==
        folder10.string() + ": target size 8x-1 is out of range (each side 1..16384)");
  TargetOptions neg = two;
  neg.dilate_px = -1;
  CHECK(load_error(folder10, 8, 8, neg) ==
        folder10.string() + ": dilation must be 0..16384 pixels (got -1)");
  CHECK_NOTHROW(load_target(folder10, 16384, 1, two));
}

TEST_CASE("preview video: panels side by side, padded to even, readable with the right frames") {
  TempDir dir;
  const int frames = 7;
  std::vector<RgbaImage> left, right;
  for (int k = 0; k < frames; ++k) {
    left.push_back(solid(30, 20, {200, 30, 30}));
    RgbaImage r = solid(21, 20, {30, 30, 200});
    fill(r, 11, 0, 21, 20, {0, 0, 0}, 0);  // transparent: white in the video
    right.push_back(r);
  }
  const fs::path out = dir.path / "preview.mp4";
  write_preview_video(out, {left, right}, 12);
  REQUIRE(fs::exists(out));
  const TargetInfo info = probe_target(out);
  CHECK(info.frames == frames);
  CHECK(info.width == 52);  // 30 + 21, padded to even
  CHECK(info.height == 20);
  CHECK(info.fps == doctest::Approx(12));

  TargetOptions o;
  o.keyframes = frames;
  const TargetFrames t = load_target(out, 52, 20, o);
  for (int k = 0; k < frames; ++k) {
    CHECK(std::abs(at(t, t.raw, k, 15, 10, 0) - 200 / 255.0f) < 0.06f);
    CHECK(std::abs(at(t, t.raw, k, 15, 10, 2) - 30 / 255.0f) < 0.06f);
    CHECK(std::abs(at(t, t.raw, k, 35, 10, 2) - 200 / 255.0f) < 0.06f);
    CHECK(at(t, t.raw, k, 46, 10, 1) > 0.94f);
  }
  // Only the video is left behind: the temporary file was renamed.
  int files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.path)) ++files;
  CHECK(files == 1);

  // Float frames convert with rgba8_image.
  std::vector<float> px = {0.0f, 0.5f, 1.0f, 1.0f, -1.0f, 2.0f, 0.25f, 1.0f};
  const RgbaImage img = rgba8_image(px.data(), 2, 1);
  CHECK(img.rgba == std::vector<uint8_t>{0, 128, 255, 255, 0, 255, 64, 255});

  // The callback form pulls one frame at a time.
  const fs::path cb = dir.path / "callback.mp4";
  int calls = 0;
  write_preview_video(
      cb, 3, 2,
      [&](int, int p) {
        ++calls;
        return solid(p == 0 ? 16 : 8, 8);
      },
      24);
  CHECK(calls == 6);
  CHECK(probe_target(cb).width == 24);
  CHECK(probe_target(cb).frames == 3);
}

TEST_CASE("preview video errors") {
  TempDir dir;
  const fs::path nodir = dir.path / "missing" / "p.mp4";
  CHECK_THROWS_WITH_AS(write_preview_video(nodir, {{solid(8, 8)}}, 24),
                       (nodir.string() + ": cannot write: No such file or directory").c_str(),
                       Error);
  const fs::path out = dir.path / "p.mp4";
  CHECK_THROWS_WITH_AS(write_preview_video(out, {{solid(8, 8)}, {solid(8, 6)}}, 24),
                       (out.string() + ": panel 1 is 6 pixels high, but panel 0 is 8").c_str(),
                       Error);
  CHECK_THROWS_WITH_AS(write_preview_video(out, {{solid(8, 8), solid(8, 10)}}, 24),
                       (out.string() + ": panel 0 of frame 1 is 8x10, but in frame 0 it is 8x8")
                           .c_str(),
                       Error);
  CHECK_THROWS_WITH_AS(write_preview_video(out, {{solid(8, 8)}, {}}, 24),
                       (out.string() + ": panel 1 has 0 frames, but panel 0 has 1").c_str(), Error);
  CHECK_THROWS_WITH_AS(write_preview_video(out, {{solid(8, 8)}}, 0),
                       (out.string() + ": frame rate must be positive").c_str(), Error);
  CHECK_THROWS_WITH_AS(write_preview_video(out, {std::vector<RgbaImage>{}}, 24),
                       (out.string() + ": a preview needs at least one frame").c_str(), Error);
  // Failures leave nothing behind (the frame-1 failure happened after the writer opened).
  CHECK(fs::is_empty(dir.path));
}

TEST_CASE("preview video: a FIFO at the path is refused, a symlink is written through") {
  TempDir dir;
  const fs::path fifo = dir.path / "p.mp4";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  CHECK_THROWS_WITH_AS(write_preview_video(fifo, {{solid(8, 8)}}, 24),
                       (fifo.string() + ": not a regular file").c_str(), Error);
  CHECK(fs::is_fifo(fifo));
  fs::create_directory(dir.path / "real");
  const fs::path link = dir.path / "link.mp4";
  fs::create_symlink("real/v.mp4", link);
  write_preview_video(link, {{solid(8, 8), solid(8, 8)}}, 24);
  CHECK(fs::is_symlink(link));
  CHECK(probe_target(dir.path / "real" / "v.mp4").frames == 2);
  // Only the FIFO, the link and the folder with the one video: no temporary left anywhere.
  size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::recursive_directory_iterator(dir.path)) ++n;
  CHECK(n == 4);
}

}  // TEST_SUITE
