// Keyframes from the target (fit/optimise/keyframe_choice.h) and a video that does not start at rest
// (fit/target/rest_start.h): the rule that adds keyframes, its budget, fit.json's reason, and a
// known motion whose clip starts mid-way, fitted with keyframe 0 free. Targets are drawn by the
// independent rasteriser of supersampled_fill.h (known_motion.h), on a 64-px canvas so each
// fit takes a second or two.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "fit/fit_job.h"
#include "small_fit.h"
#include "fit/optimise/fitter.h"
#include "fit/optimise/keyframe_choice.h"
#include "fit/target/rest_start.h"
#include "known_motion.h"
#include "raster/render_image.h"
#include "raster_test_support.h"
#include "svgmotion/svg_reader.h"
#include "svgmotion/target_video.h"

using namespace svgm;
using namespace svgm::test;
namespace fs = std::filesystem;

namespace {

// A square in a group on a 64 x 64 canvas.
const char* kSquareSvg =
    "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"64\" height=\"64\" viewBox=\"0 0 64 64\">"
    "<g id=\"part\"><path id=\"sq\" d=\"M18 22 H34 V38 H18 Z\" fill=\"#c03020\"/></g></svg>";

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("svgm_keys_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// The square moved right by dx(i) pixels in frame i, `frames` frames written to dir/frames;
// returns the SVG's path.
fs::path square_clip(const fs::path& dir, int frames, const std::function<double(int)>& dx) {
  const fs::path svg = dir / "square.svg";
  std::ofstream(svg) << kSquareSvg;
  const Scene s = read_svg_file(svg);
  write_known_motion(
      s, 64, frames,
      [&](int k, int) {
        MotionParams p = identity_params();
        p[0] = dx(k) / 32;  // normalised by half the width
        return p;
      },
      [](int, Vec2) { return Vec2{}; }, dir / "frames");
  return svg;
}

nlohmann::json fit_clip(const fs::path& dir, const fs::path& svg, int max_keyframes) {
  return svgm::test::fit_frames(dir, svg, 4, 200, max_keyframes);
}

}  // namespace

TEST_SUITE("fit") {

TEST_CASE("keyframe choice: a frame the spline misses is added, a predicted one is not") {
  const std::vector<int> keys{0, 4, 8};
  const std::vector<double> key_db{52, 50, 51};
  // Frame 2: the motion jumped there and back (28 dB); the others follow the spline closely.
  const std::vector<int> frames{1, 2, 3, 5, 6, 7};
  const KeyframeChoice c = choose_keyframes(keys, key_db, frames, {49, 28, 48.5, 49, 47, 48}, 20);
  CHECK(c.added == std::vector<int>{2});
  CHECK(c.frames == std::vector<int>{0, 2, 4, 8});
  CHECK(c.worst_frame == 2);
  CHECK(c.reason ==
        "keyframes 3 -> 4: frame 2 was not predicted by the spline through the keyframes (worst: frame 2, 28.0 dB)");
  // A smooth clip: every frame a little below its keyframes, none added, no reason.
  const KeyframeChoice smooth = choose_keyframes(keys, key_db, frames, {49, 48, 48.5, 49, 47, 48}, 20);
  CHECK(smooth.added.empty());
  CHECK(smooth.frames == keys);
  CHECK(smooth.reason.empty());
  // Well predicted in absolute terms (above good_db) is enough, however good the keyframes.
  CHECK(choose_keyframes(keys, {70, 70, 70}, frames, {47, 47, 47, 47, 47, 47}, 20).added.empty());
}

TEST_CASE("keyframe choice: the budget keeps the worst missed frames and says what it left") {
  const std::vector<int> keys{0, 4, 8};
  const std::vector<double> key_db{50, 50, 50};
  const std::vector<int> frames{2, 6};
  const KeyframeChoice c = choose_keyframes(keys, key_db, frames, {30, 25}, 4);
  CHECK(c.added == std::vector<int>{6});
  CHECK(c.missed == std::vector<int>{2, 6});
  CHECK(c.reason ==
        "keyframes 3 -> 4: frames 2, 6 were not predicted by the spline through the keyframes (worst: frame 6, 25.0 dB); "
        "1 left to the spline by the budget of 4 keyframes");
  CHECK(choose_keyframes(keys, key_db, frames, {30, 25}, 3).added.empty());
  // The automatic budget: every frame of a short clip, at most twice the keyframes asked for.
  CHECK(default_keyframe_budget(15, 24) == 24);
  CHECK(default_keyframe_budget(15, 200) == 30);
}

TEST_CASE("keyframes from the target: an abrupt jump between keyframes becomes a keyframe, fit.json says why") {
  const fs::path dir = scratch("abrupt");
  // 7 frames, keyframes at 0, 2, 4, 6; frame 3 jumps 12 px to the right and back.
  const fs::path svg = square_clip(dir, 7, [](int i) { return i == 3 ? 12.0 : 0.0; });
  const nlohmann::json fj = fit_clip(dir, svg, -1);
  const nlohmann::json& k = fj.at("keyframes_from_target");
  CHECK(fj.at("keyframes") == 5);
  CHECK(fj.at("keyframe_frames") == std::vector<int>{0, 2, 3, 4, 6});
  CHECK(k.at("added") == std::vector<int>{3});
  CHECK(k.at("reason").get<std::string>().rfind("keyframes 4 -> 5: frame 3 was not predicted by the spline", 0) == 0);
  // The new keyframe was fitted: as well as the others.
  const auto losses = fj.at("keyframe_image_loss").get<std::vector<double>>();
  CHECK(losses[2] < 4 * std::max({losses[0], losses[1], losses[3], losses[4], 1e-4}));
  CHECK(fj.at("start").at("pinned_to_rest") == true);  // the clip starts at rest

  // The same clip with no room above the keyframes asked for: nothing added.
  const nlohmann::json capped = fit_clip(dir, svg, 4);
  CHECK(capped.at("keyframes") == 4);
  CHECK(capped.at("keyframes_from_target").at("chosen") == 4);
  CHECK_FALSE(capped.at("keyframes_from_target").contains("added"));
  fs::remove_all(dir);
}

TEST_CASE("keyframes from the target: a smooth motion keeps its keyframes") {
  const fs::path dir = scratch("smooth");
  const fs::path svg = square_clip(dir, 7, [](int i) { return 2.0 * i; });  // steady drift
  const nlohmann::json fj = fit_clip(dir, svg, -1);
  CHECK(fj.at("keyframes") == 4);
  CHECK(fj.at("keyframes_from_target").at("added").empty());
  CHECK(fj.at("keyframes_from_target").at("reason").get<std::string>().rfind("keyframes 4 kept", 0) == 0);
  fs::remove_all(dir);
}

TEST_CASE("a clip that starts mid-motion: keyframe 0 is freed and its pose recovered") {
  const fs::path dir = scratch("midstart");
  // A steady 1.5 px per frame move caught from half-way: frame 0 is 9 px right of rest.
  const fs::path svg = square_clip(dir, 5, [](int i) { return 9.0 + 1.5 * i; });
  const Scene s = read_svg_file(svg);
  TargetOptions to;
  to.keyframes = 5;
  const TargetFrames target = load_target(dir / "frames", 64, 64, to);
  const RestStart start = judge_rest_start(render_image(runtime(), s, 64, false), target, to.white_threshold, to.dilate_px);
  CHECK_FALSE(start.at_rest);
  CHECK(start.iou < 0.6);
  FitOptions fo;
  fo.iterations = 300;
  fo.pin_rest_keyframe = start.at_rest;
  Fitter fitter(runtime(), s, target, fo);
  while (!fitter.done()) fitter.step();
  // Keyframe 0's corners 9 px right of rest, as the clip shows them.
  const auto pts = fitter.keyframe_points_canvas();
  const RasterPlan& plan = fitter.raster_plan();
  double worst = 0;
  for (int i = 0; i < plan.path_cp_count[0]; i += 3)
    worst = std::max(worst, std::hypot(pts[2 * i] - (plan.rest_cp[2 * i] + 9), pts[2 * i + 1] - plan.rest_cp[2 * i + 1]));
  MESSAGE("keyframe 0: corners within " << worst << " px of the truth");
  CHECK(worst < 0.5);

  // A clip that starts at rest keeps the pin.
  const fs::path rest_dir = scratch("reststart");
  square_clip(rest_dir, 3, [](int i) { return 1.5 * i; });
  to.keyframes = 3;
  const TargetFrames at_rest = load_target(rest_dir / "frames", 64, 64, to);
  const RestStart r = judge_rest_start(render_image(runtime(), s, 64, false), at_rest, to.white_threshold, to.dilate_px);
  CHECK(r.at_rest);
  CHECK(r.iou > 0.95);
  fs::remove_all(dir);
  fs::remove_all(rest_dir);
}

}  // TEST_SUITE
