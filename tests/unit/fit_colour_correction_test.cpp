// Per-frame colour correction (fit/target/colour_correction.h) and the held-frame timing of
// load_target: a tinted, off-white, shaded frame comes back in the drawing's exact colours; a
// clean frame is left alone; colours the drawing does not have are not invented; a clip at a
// third of its container's frame rate has its keyframes timed at the first frame of each run.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "fit/target/colour_correction.h"
#include "media/preview_video.h"
#include "svgmotion/target_video.h"

#include "temp_dir.h"

using namespace svgm;

namespace {

constexpr int kW = 64, kH = 48;
using Colour = std::array<float, 3>;

// White frame with a red block (x 8..27) and a blue block (x 36..55), rows 10..37.
std::vector<float> two_blocks(Colour red, Colour blue, Colour paper) {
  std::vector<float> f(static_cast<size_t>(kW) * kH * 4, 1.f);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const Colour& c = (y >= 10 && y < 38 && x >= 8 && x < 28) ? red : (y >= 10 && y < 38 && x >= 36 && x < 56) ? blue : paper;
      for (int j = 0; j < 3; ++j) f[(static_cast<size_t>(y) * kW + x) * 4 + j] = c[static_cast<size_t>(j)];
    }
  return f;
}

const float* px(const std::vector<float>& f, int x, int y) { return &f[(static_cast<size_t>(y) * kW + x) * 4]; }

// The largest change of any channel between two frames.
double max_change(const std::vector<float>& a, const std::vector<float>& b) {
  double worst = 0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, static_cast<double>(std::fabs(a[i] - b[i])));
  return worst;
}

}  // namespace

TEST_SUITE("fit") {

TEST_CASE("colour correction: an 8% tint on an off-white background comes back exactly") {
  const Colour red{0.8f, 0.1f, 0.1f}, blue{0.1f, 0.2f, 0.9f};
  // The video's version: a growing tint (R x1.08, B x0.92) and a 0.95 grey paper.
  auto tint = [](Colour c) { return Colour{std::min(1.f, c[0] * 1.08f), c[1], c[2] * 0.92f}; };
  std::vector<float> f = two_blocks(tint(red), tint(blue), {0.95f, 0.95f, 0.95f});
  const ColourCorrection cc = correct_colours(f.data(), kW, kH, {red, blue});
  CHECK(cc.applied);
  CHECK(cc.colours_matched == 3);  // red, blue, white
  // Interiors and paper are the drawing's colours exactly.
  for (int j = 0; j < 3; ++j) {
    CHECK(px(f, 15, 20)[j] == red[static_cast<size_t>(j)]);
    CHECK(px(f, 45, 20)[j] == blue[static_cast<size_t>(j)]);
    CHECK(px(f, 2, 2)[j] == 1.f);
  }
}

TEST_CASE("colour correction: an edge pixel gets only the map's change of luma, the same in every channel") {
  const Colour red{0.8f, 0.1f, 0.1f}, blue{0.1f, 0.2f, 0.9f};
  auto tint = [](Colour c) { return Colour{std::min(1.f, c[0] * 1.08f), c[1], c[2] * 0.92f}; };
  std::vector<float> f = two_blocks(tint(red), tint(blue), {0.95f, 0.95f, 0.95f});
  const std::vector<float> before = f;
  const ColourCorrection cc = correct_colours(f.data(), kW, kH, {red, blue});
  REQUIRE(cc.applied);
  // (8, 20): the red block's first column, beside the paper: not flat. The map alone would
  // take it to red (a different change per channel); it gets the luma of that change.
  const float* p = px(before, 8, 20);
  float mapped[3], l = 0;
  for (int j = 0; j < 3; ++j) {
    const float v = cc.map[4 * j] * p[0] + cc.map[4 * j + 1] * p[1] + cc.map[4 * j + 2] * p[2] + cc.map[4 * j + 3];
    mapped[j] = std::clamp(v, 0.f, 1.f);
  }
  l = 0.299f * (mapped[0] - p[0]) + 0.587f * (mapped[1] - p[1]) + 0.114f * (mapped[2] - p[2]);
  CHECK(std::fabs(mapped[0] - p[0] - (mapped[2] - p[2])) > 0.05);  // the map's own change is not grey
  // Then the shading step divides the pixel by the part's smoothed gain, one number for all
  // three channels (here about 1.01: the tint's 1.08 and 0.92 against red's own hue).
  const float g = (p[0] + l) / px(f, 8, 20)[0];
  CHECK(g == doctest::Approx(1.0).epsilon(0.05));
  for (int j = 1; j < 3; ++j) CHECK(px(f, 8, 20)[j] * g == doctest::Approx(p[j] + l).epsilon(1e-5));
  // Flat interiors are still the drawing's colours exactly.
  for (int j = 0; j < 3; ++j) CHECK(px(f, 15, 20)[j] == red[static_cast<size_t>(j)]);
}

TEST_CASE("colour correction: a 15% shading ramp inside a part is snapped flat") {
  const Colour red{0.8f, 0.1f, 0.1f}, blue{0.1f, 0.2f, 0.9f};
  std::vector<float> f = two_blocks(red, blue, {1, 1, 1});
  for (int y = 10; y < 38; ++y)
    for (int x = 8; x < 28; ++x)
      for (int j = 0; j < 3; ++j) f[(static_cast<size_t>(y) * kW + x) * 4 + j] *= 0.85f + 0.15f * (x - 8) / 19.f;
  correct_colours(f.data(), kW, kH, {red, blue});
  for (int x = 9; x < 27; ++x) CHECK(px(f, x, 20)[0] == doctest::Approx(0.8f).epsilon(1e-6));
}

TEST_CASE("colour correction: a shaded part between two similar colours of the drawing is still its own") {
  // octopus.svg's body pink and its darker cheek pink; the frame shows only the body, darkened
  // to 0.8..0.9 by a ramp, on 0.95 paper. Every body pixel is then nearer the cheek colour than
  // the ratio test allows (0.09 against 0.12 at 0.9), so without matching by hue only the paper
  // was matched and the frame was left as it was.
  const Colour body{1.f, 0.47f, 0.53f}, cheek{0.98f, 0.38f, 0.49f};
  std::vector<float> f = two_blocks(body, {0.95f, 0.95f, 0.95f}, {0.95f, 0.95f, 0.95f});
  for (int y = 10; y < 38; ++y)
    for (int x = 8; x < 28; ++x)
      for (int j = 0; j < 3; ++j) f[(static_cast<size_t>(y) * kW + x) * 4 + j] *= 0.8f + 0.1f * (x - 8) / 19.f;
  const ColourCorrection cc = correct_colours(f.data(), kW, kH, {body, cheek});
  CHECK(cc.applied);
  CHECK(cc.colours_matched == 2);  // body and white
  CHECK(cc.pixels_shaded > 0);
  for (int x = 10; x < 26; ++x)
    for (int j = 0; j < 3; ++j) CHECK(px(f, x, 20)[j] == doctest::Approx(body[static_cast<size_t>(j)]).epsilon(1e-6));
  CHECK(px(f, 45, 20)[0] == 1.f);  // the paper is white
}

TEST_CASE("colour correction: a clean frame is unchanged, and unknown colours are not invented") {
  const Colour red{0.8f, 0.1f, 0.1f}, blue{0.1f, 0.2f, 0.9f};
  std::vector<float> f = two_blocks(red, blue, {1, 1, 1});
  const std::vector<float> before = f;
  const ColourCorrection cc = correct_colours(f.data(), kW, kH, {red, blue});
  CHECK(cc.applied);
  CHECK(max_change(f, before) < 1e-6);
  // A green block the drawing does not have stays green (no palette colour is near it).
  std::vector<float> g = two_blocks(red, {0.1f, 0.9f, 0.1f}, {1, 1, 1});
  correct_colours(g.data(), kW, kH, {red, blue});
  CHECK(px(g, 45, 20)[1] > 0.85f);
  CHECK(px(g, 45, 20)[2] < 0.15f);
}

TEST_CASE("colour correction: the paper is not a shaded light grey") {
  // A light grey part on white paper: white is a grey at gain 1.18, so if the paper counted as
  // shading evidence the grey part would be divided by a false gain (the bench's man_fencing
  // was rejected so). A clean frame of such a drawing must come back unchanged.
  const Colour grey{0.85f, 0.85f, 0.85f}, blue{0.1f, 0.2f, 0.9f};
  std::vector<float> f = two_blocks(grey, blue, {1, 1, 1});
  const std::vector<float> before = f;
  const ColourCorrection cc = correct_colours(f.data(), kW, kH, {grey, blue});
  CHECK(cc.applied);
  CHECK(max_change(f, before) < 1e-6);
}

TEST_CASE("colour correction: a frame with too little evidence is left alone") {
  std::vector<float> f(static_cast<size_t>(kW) * kH * 4, 0.5f);  // all grey, no drawing colour
  const std::vector<float> before = f;
  const ColourCorrection cc = correct_colours(f.data(), kW, kH, {{0.8f, 0.1f, 0.1f}});
  CHECK_FALSE(cc.applied);
  CHECK(f == before);
}

TEST_CASE("held frames: keyframes of an 8 fps clip in a 24 fps container are timed at each pose's first frame") {
  test::TempDir dir("svgm_held_test");
  // 25 frames; a block moves one step every third frame (frames 3q, 3q+1, 3q+2 are the same).
  std::vector<RgbaImage> frames;
  for (int i = 0; i < 25; ++i) {
    RgbaImage img;
    img.width = kW;
    img.height = kH;
    img.rgba.assign(static_cast<size_t>(kW) * kH * 4, 255);
    const int x0 = 4 + 6 * (i / 3);
    for (int y = 16; y < 32; ++y)
      for (int x = x0; x < x0 + 8 && x < kW; ++x)
        for (int j = 0; j < 3; ++j) img.rgba[(static_cast<size_t>(y) * kW + x) * 4 + static_cast<size_t>(j)] = 0;
    frames.push_back(img);
  }
  const auto file = dir.path / "held.mp4";
  write_preview_video(file, 25, 1, [&](int k, int) { return frames[static_cast<size_t>(k)]; }, 24);
  TargetOptions o;
  o.keyframes = 5;  // uniform: frames 0, 6, 12, 18, 24 (each the first of its run) ...
  TargetFrames t = load_target(file, kW, kH, o);
  CHECK(t.held_frames == 16);
  CHECK(t.source_index == std::vector<int>{0, 6, 12, 18, 24});
  o.keyframes = 4;  // ... and 0, 8, 16, 24: frames 8 and 16 repeat 6 and 15
  t = load_target(file, kW, kH, o);
  CHECK(t.source_index == std::vector<int>{0, 6, 15, 24});
  o.retime_held_frames = false;
  t = load_target(file, kW, kH, o);
  CHECK(t.source_index == std::vector<int>{0, 8, 16, 24});
}

}  // TEST_SUITE
