// The target at a glance (fit/target/frame_scan.h): a clip at a lower frame rate (each pose
// held for three frames) is found to have a cadence of 3 and is fitted at its poses, each at
// the frame it was first shown, with the frames between them the spline's (before, the
// keyframe choice made every repeat a keyframe and the fit copied the holds); a clip whose
// figure only stops now and then has no cadence; a clip whose whole frame jitters is found to
// shake and is stabilised by default, while the same motion without the jitter is not.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <unistd.h>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "fit/fit_job.h"
#include "fit/target/frame_scan.h"
#include "svgmotion/error.h"
#include "svgmotion/target_video.h"
#include "small_fit.h"

using namespace svgm;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("svgm_scan_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// A red square (as the SVG below draws it at rest) moved by (dx, dy) px, soft-edged so sub-pixel
// moves show: 64 x 64, 8-bit BGR on white.
cv::Mat square(double dx, double dy) {
  cv::Mat f(64, 64, CV_8UC3);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      auto cover = [](double lo, double hi, double c) { return std::clamp(std::min(c + 0.5 - lo, hi - (c - 0.5)), 0.0, 1.0); };
      const double ink = cover(18 + dx, 34 + dx, x + 0.5) * cover(22 + dy, 38 + dy, y + 0.5);
      f.at<cv::Vec3b>(y, x) = {static_cast<uint8_t>(std::lround(255 - ink * (255 - 0x20))),
                               static_cast<uint8_t>(std::lround(255 - ink * (255 - 0x30))),
                               static_cast<uint8_t>(std::lround(255 - ink * (255 - 0xc0)))};
    }
  return f;
}

const char* kSquareSvg =
    "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"64\" height=\"64\" viewBox=\"0 0 64 64\">"
    "<g id=\"part\"><path id=\"sq\" d=\"M18 22 H34 V38 H18 Z\" fill=\"#c03020\"/></g></svg>";

// Frames dir/frames/000.png.. of the square at offsets `at(i)`.
fs::path write_clip(const fs::path& dir, int frames, const std::function<std::array<double, 2>(int)>& at) {
  fs::create_directories(dir / "frames");
  for (int i = 0; i < frames; ++i) {
    char name[16];
    std::snprintf(name, sizeof name, "%03d.png", i);
    const auto d = at(i);
    cv::imwrite((dir / "frames" / name).string(), square(d[0], d[1]));
  }
  const fs::path svg = dir / "square.svg";
  std::ofstream(svg) << kSquareSvg;
  return svg;
}

// A white jitter of up to `a` px per axis (the shader hash: successive values uncorrelated).
std::array<double, 2> shake(int i, double a) {
  auto hash = [](double x) { const double v = std::sin(x) * 43758.5453; return v - std::floor(v); };
  return {a * (2 * hash(12.9898 * i + 0.5) - 1), a * (2 * hash(78.233 * i + 0.25) - 1)};
}

nlohmann::json fit_clip(const fs::path& dir, const fs::path& svg, int keyframes, int iterations) {
  return svgm::test::fit_frames(dir, svg, keyframes, iterations);
}

}  // namespace

TEST_SUITE("fit") {

TEST_CASE("frame scan: runs of one length are a cadence, a figure that stops now and then is not") {
  FrameScan s;
  // 8 fps in 24: every pose three times; the last pose's run is the clip's end.
  std::vector<int> runs;
  for (int i = 0; i < 24; ++i) runs.push_back(i - i % 3);
  find_cadence(runs, s);
  CHECK(s.cadence == 3);
  CHECK(s.poses == std::vector<int>{0, 3, 6, 9, 12, 15, 18, 21, 23});
  // A pose held twice as long (the figure still for two poses) keeps both.
  runs = {0, 0, 0, 3, 3, 3, 3, 3, 3, 9, 9, 9, 12, 12, 12};
  find_cadence(runs, s);
  CHECK(s.cadence == 3);
  CHECK(s.poses == std::vector<int>{0, 3, 6, 9, 12, 14});
  // 3:2 pulldown (12 fps in 30: runs of 3 and 2, tied, the shorter the cadence): a run of 3 is
  // one pose, its third frame a repeat, not a pose shown late.
  runs = {0, 0, 0, 3, 3, 5, 5, 5, 8, 8, 10, 10};
  find_cadence(runs, s);
  CHECK(s.cadence == 2);
  CHECK(s.poses == std::vector<int>{0, 3, 5, 8, 10, 11});
  // A 24-fps clip whose figure stops twice: every frame is its own.
  runs = {0, 1, 2, 2, 2, 2, 6, 7, 8, 8, 8, 11, 12};
  find_cadence(runs, s);
  CHECK(s.cadence == 1);
  CHECK(s.poses.size() == 13);
  // A path that zigzags a pixel every step is shake when each step's shift explains the frame's
  // change, and a figure's own abrupt motion (6 poses played back and forth) when it does not.
  std::vector<std::array<double, 2>> zigzag;
  for (int i = 0; i < 12; ++i) zigzag.push_back({i % 2 ? 1.0 : -1.0, 0});
  FrameScan z;
  judge_shake(zigzag, std::vector<double>(11, 0.6), z);
  CHECK(z.shaking);
  judge_shake(zigzag, std::vector<double>(11, 1.0), z);
  CHECK_FALSE(z.shaking);
  CHECK(z.jitter_fit_px == doctest::Approx(2.0));
  // Spread over the poses: all of them when there are fewer than asked for.
  CHECK(spread_over_poses({0, 3, 6, 9, 12, 14}, 15) == std::vector<int>{0, 3, 6, 9, 12, 14});
  CHECK(spread_over_poses({0, 3, 6, 9, 12, 15, 18, 21, 24}, 5) == std::vector<int>{0, 6, 12, 18, 24});
}

TEST_CASE("frame scan: 8 poses each held 3 frames are fitted as 8 poses at their own frames, the frames between interpolated") {
  const fs::path dir = scratch("held");
  // The square steps 2 px right per pose: poses at frames 0, 3, ..., 21, each held 3 frames.
  const fs::path svg = write_clip(dir, 24, [](int i) { return std::array<double, 2>{2.0 * (i / 3), 0}; });
  const FrameScan scan = scan_frames(dir / "frames", 64);
  CHECK(scan.distinct == std::vector<int>{0, 3, 6, 9, 12, 15, 18, 21});
  CHECK(scan.cadence == 3);
  CHECK_FALSE(scan.shaking);
  const nlohmann::json fj = fit_clip(dir, svg, 15, 150);
  // Keyframes at the poses (and the clip's held end), none at a repeat: no staircase to copy.
  CHECK(fj.at("keyframe_frames") == std::vector<int>{0, 3, 6, 9, 12, 15, 18, 21, 23});
  CHECK(fj.at("target_frames").at("cadence") == 3);
  // The animation between two poses is the spline's: frame 4's in-between lies between the
  // square at frame 3 (2 px) and at frame 6 (4 px), not held at frame 3's.
  const std::vector<double> kt = fj.at("key_times").get<std::vector<double>>();
  CHECK(kt[2] == doctest::Approx(6.0 / 23));
  fs::remove_all(dir);
}

TEST_CASE("frame scan: a clip whose whole frame jitters is stabilised by default, the same motion without jitter is not") {
  const fs::path dir = scratch("shake"), calm = scratch("calm");
  // A slow sway (4 px over the clip) with and without a 1.5 px white jitter.
  auto sway = [](int i) { return std::array<double, 2>{4 * std::sin(i / 6.0), 0}; };
  const fs::path svg = write_clip(dir, 16, [&](int i) {
    const auto s = sway(i), j = shake(i, 1.5);
    return std::array<double, 2>{s[0] + j[0], s[1] + j[1]};
  });
  write_clip(calm, 16, sway);
  const FrameScan shaky = scan_frames(dir / "frames", 64), still = scan_frames(calm / "frames", 64);
  MESSAGE("jitter " << shaky.jitter_fit_px << " px (step " << shaky.step_fit_px << "), without " << still.jitter_fit_px
                    << " px (step " << still.step_fit_px << ")");
  CHECK(shaky.shaking);
  CHECK_FALSE(still.shaking);
  CHECK(shaky.cadence == 1);
  const nlohmann::json fj = fit_clip(dir, svg, 4, 20);
  CHECK(fj.at("target_frames").at("stabilise").at("on") == true);
  CHECK(fj.at("target_frames").at("stabilise").at("decided") == "target");
  CHECK(fj.at("target_frames").contains("shake_model"));
  const nlohmann::json fc = fit_clip(calm, calm / "square.svg", 4, 20);
  CHECK(fc.at("target_frames").at("stabilise").at("on") == false);
  fs::remove_all(dir);
  fs::remove_all(calm);
}

TEST_CASE("frame scan: every frame is visited once, in order, with the pixels load_target keeps for it") {
  const fs::path dir = scratch("visit");
  // 40 frames: more than one of the 32-frame batches the scan used to load, each from the start.
  write_clip(dir, 40, [](int i) { return std::array<double, 2>{0.5 * i, 0.25 * i}; });
  std::vector<int> seen;
  std::vector<std::vector<float>> pixels;
  for_each_target_frame(dir / "frames", 32, 32, [&](int i, const float* rgba) {
    seen.push_back(i);
    pixels.emplace_back(rgba, rgba + 32 * 32 * 4);
  });
  std::vector<int> all(40);
  for (int i = 0; i < 40; ++i) all[static_cast<size_t>(i)] = i;
  CHECK(seen == all);
  for (int i : {0, 17, 31, 32, 39}) {
    TargetOptions o;
    o.denoise_radius = 0;
    o.retime_held_frames = false;
    o.frames = {i};
    CHECK(load_target(dir / "frames", 32, 32, o).raw == pixels[static_cast<size_t>(i)]);
  }
  // A bad source is named as load_target names it.
  CHECK_THROWS_WITH_AS(for_each_target_frame(dir / "missing", 32, 32, [](int, const float*) {}),
                       doctest::Contains("missing"), svgm::Error);
}

}  // TEST_SUITE
