// The compact animation.svg's part motion (smil_compact_writer.cpp): a part swinging about a
// joint away from its centre turns about that joint, so its translate stays still (no
// translate animation at all); a part whose shape jitters beyond its affine motion keeps a `d`
// animation at the transform's tolerance and none once the residual's own tolerance
// (CompactExport::residual_scale) covers the jitter.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include <unistd.h>

#include "export/smil_writer.h"
#include "raster/raster_plan.h"
#include "svgmotion/svg_reader.h"

using namespace svgm;
namespace fs = std::filesystem;

namespace {

constexpr int kKeys = 13;

// Writes the compact export of an 8 x 40 arm (hanging from (50, 20)) moved per keyframe k by
// `move(k)` plus `jitter(k)` on its first control point; returns the file's text.
std::string compact_of(const std::function<Affine(int)>& move, double jitter, const CompactExport& options,
                       CompactStats* stats) {
  const fs::path dir = fs::temp_directory_path() / ("svgm_compact_residual_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path in = dir / "in.svg", out = dir / "compact.svg";
  std::ofstream(in) << R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
  <rect id="arm" x="46" y="20" width="8" height="40" fill="#333"/>
</svg>)svg";
  const Scene scene = read_svg_file(in);
  const RasterPlan plan = plan_raster(scene, Affine{}, 100, 100);
  std::vector<double> pts;
  for (int k = 0; k < kKeys; ++k)
    for (int i = 0; i < plan.n_cp; ++i) {
      Vec2 q = move(k).apply({plan.rest_cp[2 * i], plan.rest_cp[2 * i + 1]});
      if (i == 0) q.x += (k % 2 ? jitter : -jitter) * (k > 0 && k + 1 < kKeys);
      pts.insert(pts.end(), {q.x, q.y});
    }
  AnimationTiming timing;
  timing.keyframes = kKeys;
  timing.duration_s = 2;
  timing.loop = LoopMode::Once;
  write_compact_animation_svg(in, scene, plan, pts, timing, out, nullptr, options, stats);
  std::ifstream f(out);
  std::string text(std::istreambuf_iterator<char>(f), {});
  fs::remove_all(dir);
  return text;
}

}  // namespace

TEST_SUITE("export") {

TEST_CASE("compact svg: an arm swinging about its joint turns about it with no translate animation") {
  // Up to 35 degrees about (50, 20), the arm's top: about its centre (50, 40) the position
  // would sweep an arc of 12 px.
  auto swing = [](int k) {
    return Affine::translate(50, 20) * Affine::rotate_deg(35 * std::sin(M_PI * k / (kKeys - 1))) *
           Affine::translate(-50, -20);
  };
  CompactStats st;
  const std::string text = compact_of(swing, 0, CompactExport{}, &st);
  CHECK(st.transformed == 1);
  CHECK(st.pivoted == 1);
  CHECK(text.find("type=\"rotate\"") != std::string::npos);
  CHECK(text.find("type=\"translate\"") == std::string::npos);
  // Every rotate key ("angle cx cy") about the joint (the least-squares fixed point, pulled a
  // hair towards the centre).
  const size_t at = text.find("values=\"", text.find("type=\"rotate\""));
  REQUIRE(at != std::string::npos);
  std::istringstream values(text.substr(at + 8, text.find('"', at + 8) - at - 8));
  int keys = 0;
  for (std::string key; std::getline(values, key, ';'); ++keys) {
    double angle = 0, cx = 0, cy = 0;
    std::istringstream(key) >> angle >> cx >> cy;
    CHECK(std::fabs(cx - 50) < 0.01);
    CHECK(std::fabs(cy - 20) < 0.01);
  }
  CHECK(keys >= 2);
  CHECK(text.find("attributeName=\"d\"") == std::string::npos);
}

TEST_CASE("compact svg: a shape jitter above the tolerance is a d animation, none within the residual's") {
  auto drift = [](int k) { return Affine::translate(2.0 * k, 0); };
  CompactExport tight;
  tight.tolerance_px = 0.1;
  CompactStats st;
  const std::string jittering = compact_of(drift, 0.3, tight, &st);
  CHECK(st.residual == 1);
  CHECK(jittering.find("attributeName=\"d\"") != std::string::npos);
  CompactExport loose = tight;
  loose.residual_scale = 6;  // 0.6 px: the jitter's miss of the affine maps is within it
  const std::string smooth = compact_of(drift, 0.3, loose, &st);
  CHECK(st.residual == 0);
  CHECK(st.transformed == 1);
  CHECK(smooth.find("attributeName=\"d\"") == std::string::npos);
  CHECK(smooth.find("type=\"translate\"") != std::string::npos);  // the drift is still drawn
}

}  // TEST_SUITE
