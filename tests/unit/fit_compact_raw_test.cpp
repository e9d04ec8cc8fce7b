// compact_raw (fit/target/compact_raw.h): a fit's frames before cleanup kept as 8-bit RGB and
// the gate's figure. The preview's bytes and the result gate's verdict must be the same from
// the compact form as from the float frames, on frames that are not 8-bit values (resized and
// colour-corrected frames are not) and with figure pixels on both sides of the gate's contrast.
#include <doctest/doctest.h>

#include <cmath>

#include "fit/output/result_gate.h"
#include "fit/target/compact_raw.h"
#include "fit/target/white_runs.h"
#include "media/preview_video.h"
#include "raster/raster_plan.h"
#include "svgmotion/error.h"
#include "svgmotion/svg_reader.h"

using namespace svgm;

namespace {

constexpr int kW = 16, kH = 16, kK = 2;

// An off-white background that wavers below an 8-bit level, a dark 8 x 8 square (columns
// 4 + shift .. 11 + shift, rows 4 .. 11), and two single pixels at (1, 14) and (14, 1): 0.11 and
// 0.09 darker than the background, one each side of the gate's 0.1.
TargetFrames frames() {
  TargetFrames t;
  t.width = kW, t.height = kH, t.keyframes = kK;
  const size_t px = static_cast<size_t>(kW) * kH;
  t.raw.assign(kK * px * 4, 1.f);
  for (int k = 0; k < kK; ++k)
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        float* p = &t.raw[(k * px + static_cast<size_t>(y) * kW + x) * 4];
        const float bg[3] = {0.95f + 0.0013f * (x % 3), 0.94f, 0.96f - 0.0007f * (y % 2)};
        const bool square = x >= 4 + 2 * k && x < 12 + 2 * k && y >= 4 && y < 12;
        for (int c = 0; c < 3; ++c) p[c] = square ? 0.2f + 0.1f * c + 0.0031f * x : bg[c];
        if (x == 1 && y == 14) p[0] -= 0.11f;
        if (x == 14 && y == 1) p[1] -= 0.09f;
      }
  t.rgba = t.raw;
  return t;
}

}  // namespace

TEST_SUITE("fit") {

TEST_CASE("compact_raw: the preview's bytes and the gate's figure as from the float frames, in a quarter of the memory") {
  TargetFrames t = frames();
  const TargetFrames before = t;
  const CompactRaw c = compact_raw(t);
  CHECK(t.raw.empty());
  const size_t px = static_cast<size_t>(kW) * kH;
  CHECK(c.keyframes() == static_cast<size_t>(kK));
  CHECK(c.pixels == px);
  for (int k = 0; k < kK; ++k) CHECK(compact_frame(c, k).size() == px * 4);
  CHECK(c.border.size() == static_cast<size_t>(kK));
  for (int k = 0; k < kK; ++k) {
    const RgbaImage a = rgba8_image(&before.raw[k * px * 4], kW, kH), b = raw_image(t, &c, k);
    CHECK(b.width == kW);
    CHECK(b.height == kH);
    CHECK(a.rgba == b.rgba);
    const RawFigure fa = raw_figure(before, nullptr, k), fb = raw_figure(t, &c, k);
    CHECK(fa.background == fb.background);
    CHECK(fa.figure == fb.figure);
    // The square and the pixel 0.11 off the background; not the one 0.09 off.
    size_t n = 0;
    for (uint8_t f : fb.figure) n += f;
    CHECK(n == 65);
    CHECK(fb.figure[14 * kW + 1] == 1);
    CHECK(fb.figure[1 * kW + 14] == 0);
  }
  // Again: nothing left to compact.
  CHECK(compact_raw(t).frames.empty());
}

TEST_CASE("compact_raw: the result gate's verdict is the same bits from the compact form") {
  const Scene scene = read_svg_string(R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="16" height="16">
    <rect id="r" x="4" y="4" width="8" height="8" fill="#000"/></svg>)svg", "g");
  const RasterPlan plan = plan_raster(scene, Affine{}, kW, kH);
  const size_t px = static_cast<size_t>(kW) * kH;
  // The fit draws the square black where keyframe 0 has it, in both keyframes.
  std::vector<float> renders(kK * px * 4, 0.f);
  for (int k = 0; k < kK; ++k)
    for (int y = 4; y < 12; ++y)
      for (int x = 4; x < 12; ++x) renders[(k * px + static_cast<size_t>(y) * kW + x) * 4 + 3] = 1;
  std::vector<double> pts;
  for (int k = 0; k < kK; ++k)
    for (int i = 0; i < plan.n_cp; ++i) pts.push_back(plan.rest_cp[2 * i]), pts.push_back(plan.rest_cp[2 * i + 1]);
  TargetFrames t = frames();
  const GateVerdict a = judge_fit(t, renders, pts, plan, scene, Affine{});
  const CompactRaw c = compact_raw(t);
  const size_t frame = px * 4;
  const GateVerdict b = judge_fit(t, &c, [&](int k) {
    return std::vector<float>(renders.begin() + static_cast<std::ptrdiff_t>(k * frame),
                              renders.begin() + static_cast<std::ptrdiff_t>((k + 1) * frame));
  }, pts, plan, scene, Affine{});
  CHECK(a.psnr_db == b.psnr_db);
  CHECK(a.iou == b.iou);
  CHECK(a.reasons == b.reasons);
  CHECK(a.passed == b.passed);
  // The cleaned frames read a keyframe at a time from their packed runs (the finer target's, kept
  // packed after the refinement), the target's rgba gone: the same verdict, to the bit.
  TargetFrames packed_target = t;
  WhiteRuns runs = pack_white_runs(packed_target.rgba);
  REQUIRE(packed_target.rgba.empty());
  int reads = 0;
  const GateVerdict p = judge_fit(packed_target, &c, [&](int k) {
    return std::vector<float>(renders.begin() + static_cast<std::ptrdiff_t>(k * frame),
                              renders.begin() + static_cast<std::ptrdiff_t>((k + 1) * frame));
  }, pts, plan, scene, Affine{}, {}, [&](int k, float* out) {
    ++reads;
    unpack_white_runs_range(runs, static_cast<size_t>(k) * px, px, out);
  });
  CHECK(reads == kK);
  CHECK(p.psnr_db == a.psnr_db);
  CHECK(p.iou == a.iou);
  CHECK(p.reasons == a.reasons);
  CHECK(p.passed == a.passed);
  // Keyframe 0: the 64 drawn pixels are the square, the figure is it and one pixel more;
  // keyframe 1's square is 2 columns on: 48 in common of 80 + 1.
  CHECK(b.iou[0] == doctest::Approx(64.0 / 65));
  CHECK(b.iou[1] == doctest::Approx(48.0 / 81));
}

TEST_CASE("compact_raw: a drawing's frames are held deflated, a small share of their 4 bytes a pixel") {
  // 64 x 64 white paper with a flat 16 x 16 square: 16 kB of bytes a keyframe before deflating.
  constexpr int W = 64;
  const size_t px = static_cast<size_t>(W) * W;
  std::vector<float> raw(px * 4, 1.f);
  for (int y = 20; y < 36; ++y)
    for (int x = 10; x < 26; ++x)
      for (int ch = 0; ch < 3; ++ch) raw[(static_cast<size_t>(y) * W + x) * 4 + ch] = 0.25f * (ch + 1);
  CompactRaw c;
  compact_raw_frame(c, raw.data(), W, W);
  compact_raw_frame(c, raw.data(), W, W);
  REQUIRE(c.keyframes() == 2);
  CHECK(c.bytes() < 2 * px * 4 / 20);
  // Inflated: the 8-bit colours and the figure, exactly.
  const std::vector<uint8_t> f = compact_frame(c, 1);
  REQUIRE(f.size() == px * 4);
  CHECK(f[3 * (20 * W + 10)] == 64);       // 0.25 -> 63.75, rounded
  CHECK(f[3 * (20 * W + 10) + 2] == 191);  // 0.75 -> 191.25
  CHECK(f[3 * px + 20 * W + 10] == 1);
  CHECK(f[3 * px + 0] == 0);
  CHECK(f[0] == 255);
  CHECK_THROWS_AS(compact_frame(c, 2), std::out_of_range);
}

TEST_CASE("compact_raw: a target without frames before cleanup is an internal error, not a read past the end") {
  TargetFrames t;
  t.width = kW, t.height = kH, t.keyframes = 1;
  CHECK_THROWS_WITH_AS(raw_image(t, nullptr, 0), "internal: the target holds no frames before cleanup", Error);
  const CompactRaw none;
  CHECK_THROWS_WITH_AS(raw_figure(t, &none, 0), "internal: the target holds no frames before cleanup", Error);
}

}  // TEST_SUITE
