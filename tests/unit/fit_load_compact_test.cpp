// load_target_compact (fit/target/compact_raw.h): a target's frames before cleanup compacted
// keyframe by keyframe inside the load (TargetOptions::raw_sink), so the load never holds every
// keyframe's floats. It must give the same target as load_target followed by compact_raw: the
// cleaned frames, masks and distance fields bit for bit, the same compact frames, on a clip
// that exercises colour correction, stabilising and denoising, whose paths store keyframes at
// different moments of the load. The cleaned frames streamed out of the load
// (TargetOptions::rgba_sink) and packed as they come must be the same as the whole load's.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "fit/target/compact_raw.h"
#include "fit/target/distance_field.h"
#include "fit/target/white_runs.h"
#include "svgmotion/target_video.h"

#include "temp_dir.h"

using namespace svgm;

namespace {

constexpr int kW = 48, kH = 40, kFrames = 9;

// Frame i (8-bit BGR): an off-white background with a faint pattern, a red square moving one
// pixel right per frame, a blue bar holding still and a grey speck.
cv::Mat frame(int i) {
  cv::Mat f(kH, kW, CV_8UC3);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      cv::Vec3b v(static_cast<uint8_t>(246 + (x + y + i) % 3), 247, 245);
      if (x >= 8 + i && x < 20 + i && y >= 10 && y < 22) v = {40, 30, static_cast<uint8_t>(200 + (x % 2))};
      if (x >= 30 && x < 36 && y >= 6 && y < 34) v = {190, 60, 20};
      if (x == 4 && y == 35) v = {120, 120, 120};
      f.at<cv::Vec3b>(y, x) = v;
    }
  return f;
}

// Every keyframe of `c` inflated, one after the other (rgb8 then figure of each).
std::vector<uint8_t> inflated(const CompactRaw& c) {
  std::vector<uint8_t> out;
  for (size_t k = 0; k < c.keyframes(); ++k) {
    const std::vector<uint8_t> f = compact_frame(c, static_cast<int>(k));
    out.insert(out.end(), f.begin(), f.end());
  }
  return out;
}

bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

void check_same(const std::filesystem::path& dir, const TargetOptions& o, int w, int h) {
  TargetFrames whole = load_target(dir, w, h, o);
  REQUIRE_FALSE(whole.raw.empty());
  const CompactRaw expected = compact_raw(whole);
  CompactRaw got;
  const TargetFrames t = load_target_compact(dir, w, h, o, got);
  CHECK(t.raw.empty());
  CHECK(same_bits(t.rgba, whole.rgba));
  CHECK(same_bits(t.sdf, whole.sdf));
  CHECK(t.mask == whole.mask);
  CHECK(t.source_index == whole.source_index);
  CHECK(t.colour_corrected == whole.colour_corrected);
  CHECK(inflated(got) == inflated(expected));
  CHECK(got.border == expected.border);
  CHECK(inflated(got).size() == static_cast<size_t>(t.keyframes) * w * h * 4);
  // The cleaned frames handed over keyframe by keyframe (TargetOptions::rgba_sink) and packed as
  // they come are the whole load's, packed, bit for bit; the returned rgba is empty.
  TargetOptions streamed = o;
  WhiteRuns packed;
  int next = 0;
  streamed.rgba_sink = [&](int k, const float* rgba) {
    CHECK(k == next++);
    append_white_runs(packed, rgba, static_cast<size_t>(w) * h);
  };
  CompactRaw got2;
  const TargetFrames s = load_target_compact(dir, w, h, streamed, got2);
  CHECK(s.rgba.empty());
  CHECK(next == whole.keyframes);
  CHECK(same_bits(s.sdf, whole.sdf));
  CHECK(s.mask == whole.mask);
  CHECK(inflated(got2) == inflated(expected));
  std::vector<float> whole_rgba = whole.rgba;
  const WhiteRuns expected_runs = pack_white_runs(whole_rgba);
  CHECK(packed.pixels == expected_runs.pixels);
  CHECK(packed.runs == expected_runs.runs);
  CHECK(same_bits(packed.others, expected_runs.others));
  CHECK(same_bits(unpack_white_runs(packed), whole.rgba));
  // The distance field made again from the mask (distance_field.h) is the load's, bit for bit.
  TargetFrames remade = whole;
  std::vector<float>().swap(remade.sdf);
  fill_distance_fields(remade);
  CHECK(same_bits(remade.sdf, whole.sdf));
}

}  // namespace

TEST_SUITE("fit") {

TEST_CASE("load_target_compact: the same target and compact frames as load_target then compact_raw") {
  test::TempDir dir("svgm_load_compact_test");
  for (int i = 0; i < kFrames; ++i) {
    const std::string name = (i < 10 ? "00" : "0") + std::to_string(i) + ".png";
    REQUIRE(cv::imwrite((dir.path / name).string(), frame(i)));
  }
  TargetOptions o;
  o.keyframes = 4;
  SUBCASE("plain") { check_same(dir.path, o, 32, 27); }
  SUBCASE("colour-corrected to a palette") {
    o.palette = {{200 / 255.f, 30 / 255.f, 40 / 255.f}, {20 / 255.f, 60 / 255.f, 190 / 255.f}};
    check_same(dir.path, o, 32, 27);
  }
  SUBCASE("chosen frames, denoised and stabilised (every keyframe stored at the end)") {
    o.frames = {0, 3, 5, 8};
    o.denoise_radius = 1;
    o.stabilise = true;
    check_same(dir.path, o, 40, 33);
  }
  SUBCASE("denoised without stabilising, at the frames' own size") {
    o.denoise_radius = 1;
    check_same(dir.path, o, kW, kH);
  }
}

}  // TEST_SUITE
