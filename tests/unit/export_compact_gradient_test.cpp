// The compact animation.svg colours a moving part as the full export does: a user-space
// gradient is not carried by the wrapper group's affine map (which a part that stretches turns
// into a colour shift along its ramp) but placed where the full export places it.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "export/smil_writer.h"
#include "raster/raster_plan.h"
#include "svgmotion/svg_reader.h"

using namespace svgm;

TEST_SUITE("export") {

TEST_CASE("compact svg: a stretching part's user-space radial gradient is placed as in the full export") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("svgm_compact_grad_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path in = dir / "in.svg", full = dir / "full.svg", compact = dir / "compact.svg";
  // A ray from (20, 45) to (60, 55) under a radial ramp centred far to its left.
  std::ofstream(in) << R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
  <defs>
    <radialGradient id="glow" gradientUnits="userSpaceOnUse" cx="0" cy="50" r="70">
      <stop offset="0" stop-color="#ff0"/><stop offset="1" stop-color="#f00"/>
    </radialGradient>
  </defs>
  <rect id="ray" x="20" y="45" width="40" height="10" fill="url(#glow)"/>
</svg>)svg";
  const Scene scene = read_svg_file(in);
  const RasterPlan plan = plan_raster(scene, Affine{}, 100, 100);
  // Keyframe k of 5: the ray 1 + k/4 times as thick and moved by (1.5 k, -k) (affine maps, no
  // similarities).
  constexpr int K = 5;
  auto move = [](int k) {
    return Affine::translate(1.5 * k, -k) * Affine::translate(40, 50) * Affine::scale(1, 1 + k / 4.0) *
           Affine::translate(-40, -50);
  };
  std::vector<double> pts;
  for (int k = 0; k < K; ++k)
    for (int i = 0; i < plan.n_cp; ++i) {
      const Vec2 q = move(k).apply({plan.rest_cp[2 * i], plan.rest_cp[2 * i + 1]});
      pts.insert(pts.end(), {q.x, q.y});
    }
  AnimationTiming timing;
  timing.keyframes = K;
  timing.duration_s = 2;
  timing.loop = LoopMode::Once;
  write_animation_svg(in, scene, plan, pts, timing, full);
  write_compact_animation_svg(in, scene, plan, pts, timing, compact, nullptr, CompactExport{});
  const std::string text = [&] {
    std::ifstream f(compact);
    return std::string(std::istreambuf_iterator<char>(f), {});
  }();
  CHECK(text.find("<g><rect id=\"ray\"") != std::string::npos);  // the part is wrapped
  CHECK(text.find("attributeName=\"gradientTransform\"") != std::string::npos);
  for (int k = 1; k < K; ++k) {
    SvgReadLimits at;
    at.animation_time = 2.0 * k / (K - 1);
    const Scene a = read_svg_file(full, at), b = read_svg_file(compact, at);
    REQUIRE(a.gradients.size() == 1);
    REQUIRE(b.gradients.size() == 1);
    // Where each draws the ramp's centre and the ends of its radii: within twice the compact
    // export's tolerance (a quarter pixel at 1024 px: 0.024 px here) at each keyframe's time.
    const Affine &ga = a.gradients[0].to_canvas, &gb = b.gradients[0].to_canvas;
    double worst = 0;
    for (const Vec2 p : {Vec2{0, 50}, Vec2{70, 50}, Vec2{0, 120}, Vec2{0, -20}}) {
      const Vec2 d = ga.apply(p) - gb.apply(p);
      worst = std::max(worst, std::hypot(d.x, d.y));
    }
    CHECK(worst <= 0.05);
  }
  fs::remove_all(dir);
}

}  // TEST_SUITE
