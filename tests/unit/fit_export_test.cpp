// The SMIL export round trip: keyframes written into the user's document come back, at each
// keyframe's time, as the same control points; basic shapes become paths with their ids.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>

#include <unistd.h>

#include "export/smil_writer.h"
#include "raster/gradient_paint.h"
#include "raster/raster_plan.h"
#include "svgmotion/svg_reader.h"

using namespace svgm;

namespace {

// Exports `in` with two keyframes, 2 s apart, played once: the rest pose and every rest point
// moved by `move` (canvas space, the plan at 100 x 100 px of a 100-unit canvas).
std::vector<std::string> export_moved(const std::filesystem::path& in, const Scene& scene, const RasterPlan& plan,
                                      const std::function<Vec2(Vec2)>& move, const std::filesystem::path& out) {
  std::vector<double> pts(plan.rest_cp.begin(), plan.rest_cp.end());
  for (int i = 0; i < plan.n_cp; ++i) {
    const Vec2 q = move({plan.rest_cp[2 * i], plan.rest_cp[2 * i + 1]});
    pts.push_back(q.x);
    pts.push_back(q.y);
  }
  AnimationTiming timing;
  timing.keyframes = 2;
  timing.duration_s = 2;
  timing.loop = LoopMode::Once;
  return write_animation_svg(in, scene, plan, pts, timing, out);
}

}  // namespace

TEST_SUITE("fit") {

TEST_CASE("animation.svg round trip: keyframes come back at their times, in the element's own coordinates") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("svgm_export_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path in = dir / "in.svg", out = dir / "animation.svg";
  std::ofstream(in) << R"svg(<?xml version="1.0"?>
<!-- kept -->
<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100" viewBox="0 0 200 200">
  <title>kept too</title>
  <g id="arm" transform="translate(10 20) rotate(30)">
    <rect id="box" x="10" y="10" width="40" height="20" fill="#c33"/>
    <path id="tip" d="M 60 10 C 70 0 80 0 90 10 Z" fill="blue" stroke="black"/>
  </g>
  <text>left alone</text>
</svg>)svg";
  const Scene scene = read_svg_file(in);
  REQUIRE(scene.paths.size() == 2);
  const RasterPlan plan = plan_raster(scene, Affine{}, 100, 100);
  const int K = 3;
  // Keyframe k moves every canvas point by (3k, -2k).
  std::vector<double> pts;
  for (int k = 0; k < K; ++k)
    for (int i = 0; i < plan.n_cp; ++i) {
      pts.push_back(plan.rest_cp[2 * i] + 3.0 * k);
      pts.push_back(plan.rest_cp[2 * i + 1] - 2.0 * k);
    }
  AnimationTiming timing;
  timing.keyframes = K;
  timing.duration_s = 2;
  CHECK(write_animation_svg(in, scene, plan, pts, timing, out).empty());

  std::ifstream f(out);
  const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  CHECK(text.find("<!-- kept -->") != std::string::npos);
  CHECK(text.find("<title>kept too</title>") != std::string::npos);
  CHECK(text.find("<text>left alone</text>") != std::string::npos);
  CHECK(text.find("<path id=\"box\"") != std::string::npos);  // the rect became a path
  CHECK(text.find("width=\"40\"") == std::string::npos);
  CHECK(text.find("keyTimes=\"0;0.5;1\"") != std::string::npos);

  for (int k = 0; k < K; ++k) {
    SvgReadLimits at;
    at.animation_time = k * 1.0 - (k == K - 1 ? 1e-9 : 0);  // the last keyframe just before the loop wraps
    const Scene back = read_svg_file(out, at);
    REQUIRE(back.paths.size() == 2);
    double worst = 0;
    for (size_t p = 0; p < 2; ++p) {
      int cp = plan.path_cp_first[p];
      for (const Subpath& sp : back.paths[p].subpaths)
        for (const Vec2& q : sp.points) {
          worst = std::max(worst, std::hypot(q.x - pts[(k * plan.n_cp + cp) * 2], q.y - pts[(k * plan.n_cp + cp) * 2 + 1]));
          ++cp;
        }
    }
    CAPTURE(k);
    CHECK(worst < 2e-3);  // coordinates are written to 1/1000 of a user unit
  }
  SvgReadLimits mid;
  mid.animation_time = 0.5;  // halfway between keyframes 0 and 1: moved by (1.5, -1)
  const Scene half = read_svg_file(out, mid);
  CHECK(half.paths[1].subpaths[0].points[0].x == doctest::Approx(plan.rest_cp[2 * plan.path_cp_first[1]] + 1.5).epsilon(1e-4));
  fs::remove_all(dir);
}

TEST_CASE("a user-space gradient moves with its path's shape; a shared one stays") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("svgm_export_grad_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path in = dir / "in.svg", out = dir / "animation.svg";
  // "ramp" paints one square in its user space (with a transform of its own); "both" paints
  // two squares, so moving it for one would move it for the other.
  std::ofstream(in) << R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100" viewBox="0 0 100 100">
  <defs>
    <linearGradient id="ramp" gradientUnits="userSpaceOnUse" x1="0" y1="0" x2="20" y2="0" gradientTransform="translate(10 10)">
      <stop offset="0" stop-color="#f00"/><stop offset="1" stop-color="#00f"/>
    </linearGradient>
    <linearGradient id="both" gradientUnits="userSpaceOnUse" x1="60" y1="0" x2="80" y2="0">
      <stop offset="0" stop-color="#0f0"/><stop offset="1" stop-color="#000"/>
    </linearGradient>
  </defs>
  <rect id="a" x="10" y="10" width="20" height="20" fill="url(#ramp)"/>
  <rect id="b" x="60" y="10" width="20" height="20" fill="url(#both)"/>
  <rect id="c" x="60" y="60" width="20" height="20" fill="url(#both)"/>
</svg>)svg";
  const Scene scene = read_svg_file(in);
  REQUIRE(scene.paths.size() == 3);
  REQUIRE(scene.gradients.size() == 3);
  CHECK(scene.gradients[0].id == "ramp");
  CHECK(scene.gradients[0].user_space);
  const RasterPlan plan = plan_raster(scene, Affine{}, 100, 100);
  // Keyframe 1 turns every shape by 90 degrees about (50, 50) and moves it by (5, 0): the
  // same similarity must come back as the gradient's motion.
  const Affine move = Affine::translate(55, 50) * Affine{0, 1, -1, 0, 0, 0} * Affine::translate(-50, -50);
  const std::vector<std::string> warnings = export_moved(in, scene, plan, [&](Vec2 p) { return move.apply(p); }, out);
  REQUIRE(warnings.size() == 1);
  CHECK(warnings[0].find("1 gradients shared by several shapes stay where the document puts them") != std::string::npos);

  SvgReadLimits end;
  end.animation_time = 2;  // frozen on keyframe 1
  const Scene back = read_svg_file(out, end);
  REQUIRE(back.gradients.size() == 3);
  // ramp: the shape's motion after the gradient's own transform, to the written precision.
  const Affine want = move * Affine::translate(10, 10);
  const Affine& got = back.gradients[0].to_canvas;
  for (const auto& [g, w] : {std::pair{got.a, want.a}, {got.b, want.b}, {got.c, want.c}, {got.d, want.d}, {got.e, want.e}, {got.f, want.f}})
    CHECK(g == doctest::Approx(w).epsilon(1e-4));
  // Its stops therefore stay on the square: red where its left edge went, blue at its right.
  const Affine to_gradient = got.inverse();
  const auto left = gradient_color(back.gradients[0], to_gradient, move.apply({10, 20}));
  const auto right = gradient_color(back.gradients[0], to_gradient, move.apply({30, 20}));
  REQUIRE(left);
  REQUIRE(right);
  CHECK(left->r == doctest::Approx(1).epsilon(1e-3));
  CHECK(left->b == doctest::Approx(0).epsilon(1e-3));
  CHECK(right->b == doctest::Approx(1).epsilon(1e-3));
  CHECK(back.gradients[1].to_canvas.e == 0.0);  // both: untouched
  CHECK(back.gradients[2].to_canvas.e == 0.0);
  // At rest nothing has moved.
  SvgReadLimits start;
  start.animation_time = 0;
  const Scene rest = read_svg_file(out, start);
  CHECK(rest.gradients[0].to_canvas.e == doctest::Approx(10));
  CHECK(rest.gradients[0].to_canvas.a == doctest::Approx(1));
  fs::remove_all(dir);
}

TEST_CASE("a gradient follows the part of its shape that shows; points under transparent paint do not count") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("svgm_export_fade_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path in = dir / "in.svg", out = dir / "animation.svg";
  // A ray from x = 10 to 90 whose paint fades out by x = 50 (a sun ray fading before its tip):
  // the fit never sees its right end, so its points there are free to wander.
  std::ofstream(in) << R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100" viewBox="0 0 100 100">
  <defs>
    <linearGradient id="fade" gradientUnits="userSpaceOnUse" x1="10" y1="0" x2="50" y2="0">
      <stop offset="0" stop-color="#f00"/><stop offset="0.5" stop-color="#f00"/>
      <stop offset="1" stop-color="#f00" stop-opacity="0"/>
    </linearGradient>
  </defs>
  <rect id="ray" x="10" y="45" width="80" height="10" fill="url(#fade)"/>
</svg>)svg";
  const Scene scene = read_svg_file(in);
  REQUIRE(scene.paths.size() == 1);
  const RasterPlan plan = plan_raster(scene, Affine{}, 100, 100);
  // Keyframe 1: the ray moves by (5, 0); the points under transparent paint (x >= 50) also
  // swing 15 px down. The shape's plain similarity fit would turn the gradient with them.
  int wandering = 0;
  for (int i = 0; i < plan.n_cp; ++i) wandering += plan.rest_cp[2 * i] >= 50;
  REQUIRE(wandering >= 2);
  REQUIRE(wandering < plan.n_cp - 2);
  CHECK(export_moved(in, scene, plan, [](Vec2 p) { return Vec2{p.x + 5, p.y + (p.x >= 50 ? 15 : 0)}; }, out).empty());
  SvgReadLimits end;
  end.animation_time = 2;
  const Scene back = read_svg_file(out, end);
  REQUIRE(back.gradients.size() == 1);
  const Affine& got = back.gradients[0].to_canvas;
  CHECK(got.a == doctest::Approx(1).epsilon(1e-4));
  CHECK(got.b == doctest::Approx(0).epsilon(1e-4));
  CHECK(got.c == doctest::Approx(0).epsilon(1e-4));
  CHECK(got.d == doctest::Approx(1).epsilon(1e-4));
  CHECK(got.e == doctest::Approx(5).epsilon(1e-3));
  CHECK(got.f == doctest::Approx(0).epsilon(1e-3));
  fs::remove_all(dir);
}

TEST_CASE("a gradient whose shape shows none of its motion along the ramp stays put") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("svgm_export_ray_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path in = dir / "in.svg", out = dir / "animation.svg";
  // Two thin wedges (rays from a sun at (10, 50)): "along" under a radial ramp centred on the
  // sun, fading out before the tip, so its outline runs along its ramp (n · m is sin 2.9° on
  // its sides, its tip transparent); "across" under a ramp across the wedge, which its long
  // sides show fully.
  std::ofstream(in) << R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100" viewBox="0 0 100 100">
  <defs>
    <radialGradient id="along" gradientUnits="userSpaceOnUse" cx="10" cy="50" r="60">
      <stop offset="0" stop-color="#fc0"/><stop offset="1" stop-color="#f80" stop-opacity="0"/>
    </radialGradient>
    <linearGradient id="across" gradientUnits="userSpaceOnUse" x1="0" y1="20" x2="0" y2="30">
      <stop offset="0" stop-color="#00f"/><stop offset="1" stop-color="#0ff"/>
    </linearGradient>
  </defs>
  <path id="a" d="M10 50 L90 46 L90 54 Z" fill="url(#along)"/>
  <path id="b" d="M10 25 L90 21 L90 29 Z" fill="url(#across)"/>
</svg>)svg";
  const Scene scene = read_svg_file(in);
  REQUIRE(scene.paths.size() == 2);
  const RasterPlan plan = plan_raster(scene, Affine{}, 100, 100);
  // Keyframe 1: both wedges turn by 6 degrees about the sun and move (2, 1).
  const double a = 6 * 3.14159265358979 / 180;
  const Affine move = Affine::translate(12, 51) * Affine{std::cos(a), std::sin(a), -std::sin(a), std::cos(a), 0, 0} *
                      Affine::translate(-10, -50);
  CHECK(export_moved(in, scene, plan, [&](Vec2 p) { return move.apply(p); }, out).empty());
  std::ifstream f(out);
  const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  const size_t along = text.find("<radialGradient"), across = text.find("<linearGradient");
  REQUIRE(along != std::string::npos);
  REQUIRE(across != std::string::npos);
  const std::string along_el = text.substr(along, text.find("</radialGradient>", along) - along);
  const std::string across_el = text.substr(across, text.find("</linearGradient>", across) - across);
  CHECK(along_el.find("gradientTransform") == std::string::npos);
  CHECK(across_el.find("attributeName=\"gradientTransform\"") != std::string::npos);
  fs::remove_all(dir);
}

}  // TEST_SUITE
