// A luminance mask written as an alpha matte (export/lottie_luma_matte.h): each path white at
// alpha L a, gradient stops added where L a is quadratic, black paths over earlier content cut
// it (an inverted alpha matte), and grey over other content named as approximate.
#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <string>
#include <nlohmann/json.hpp>

#include "export/lottie_luma_matte.h"
#include "export/lottie_writer.h"
#include "raster/raster_plan.h"
#include "svgmotion/svg_reader.h"

using namespace svgm;

namespace {

double lum(const Rgba& c) { return 0.2125 * c.r + 0.7154 * c.g + 0.0721 * c.b; }

// The mask of the scene's only masked element, from a document whose <mask id="m"> holds `content`.
Scene masked(const std::string& content) {
  return read_svg_string(R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="40" height="40">
    <linearGradient id="g"><stop offset="0" stop-color="#f00" stop-opacity="0.25"/><stop offset="1" stop-color="#00f"/></linearGradient>
    <mask id="m" maskUnits="userSpaceOnUse" x="0" y="0" width="40" height="40">)svg" + content + R"svg(</mask>
    <rect width="40" height="40" fill="#0a0" mask="url(#m)"/></svg>)svg", "t.svg");
}

// Straight colour of stops at t, linearly interpolated (as the renders do).
Rgba at(const std::vector<GradientStop>& s, double t) {
  for (size_t i = 1; i < s.size(); ++i)
    if (t <= s[i].offset) {
      const float u = static_cast<float>((t - s[i - 1].offset) / (s[i].offset - s[i - 1].offset));
      const Rgba& a = s[i - 1].color;
      const Rgba& b = s[i].color;
      return {a.r + u * (b.r - a.r), a.g + u * (b.g - a.g), a.b + u * (b.b - a.b), a.a + u * (b.a - a.a)};
    }
  return s.back().color;
}

}  // namespace

TEST_SUITE("export") {

TEST_CASE("luma matte: flat paths become white at alpha L a; one path is exact") {
  const Scene s = masked(R"svg(<rect width="20" height="20" fill="#808080" fill-opacity="0.5"/>)svg");
  REQUIRE(s.masks.size() == 1);
  const lottie::AlphaMatteContent w = lottie::luminance_as_alpha(s.masks[0], s.gradients);
  REQUIRE(w.paths.size() == 1);
  CHECK(w.exact);
  CHECK_FALSE(w.cut[0]);
  const Rgba c = w.paths[0].fill;
  CHECK(c.r == 1);
  CHECK(c.g == 1);
  CHECK(c.b == 1);
  CHECK(c.a == doctest::Approx(0.5 * lum(s.masks[0].paths[0].fill)).epsilon(1e-6));
  CHECK(c.a == doctest::Approx(0.5 * 128.0 / 255).epsilon(1e-3));  // grey 128: L = 128/255
}

TEST_CASE("luma matte: a gradient's white stops follow L a within 1/512 between its stops") {
  const Scene s = masked(R"svg(<rect width="40" height="40" fill="url(#g)"/>)svg");
  REQUIRE(s.masks.size() == 1);
  const Path& src = s.masks[0].paths[0];
  REQUIRE(src.fill_gradient >= 0);
  const lottie::AlphaMatteContent w = lottie::luminance_as_alpha(s.masks[0], s.gradients);
  REQUIRE(w.paths[0].fill_gradient >= 0);
  const auto& in = s.gradients[static_cast<size_t>(src.fill_gradient)].stops;
  const auto& out = w.gradients[static_cast<size_t>(w.paths[0].fill_gradient)].stops;
  // Red at 0.25 to blue at 1: L a goes 0.053 -> 0.072 through a quadratic; |dL da| = 0.105.
  CHECK(out.size() > in.size());
  double worst = 0;
  for (int i = 0; i <= 1000; ++i) {
    const double t = i / 1000.0;
    const Rgba c = at(in, t), wc = at(out, t);
    CHECK(wc.r == 1);
    worst = std::max(worst, std::fabs(wc.a - lum(c) * c.a));
  }
  CHECK(worst <= 1.0 / 512 + 1e-6);
}

TEST_CASE("luma matte: black over white cuts it, white over black adds, grey over white is approximate") {
  const char* white_rect = R"svg(<rect width="40" height="40" fill="#fff"/>)svg";
  {
    const Scene s = masked(std::string(white_rect) + R"svg(<circle cx="20" cy="20" r="5" fill="#000"/>)svg");
    const lottie::AlphaMatteContent w = lottie::luminance_as_alpha(s.masks[0], s.gradients);
    CHECK(w.exact);
    CHECK(w.cut == std::vector<bool>{false, true});
    CHECK(w.paths[1].fill.a == 1);  // the cut's matte is the circle's own alpha
  }
  {
    const Scene s = masked(R"svg(<rect width="40" height="40" fill="#000"/><circle cx="20" cy="20" r="5" fill="#fff"/>)svg");
    const lottie::AlphaMatteContent w = lottie::luminance_as_alpha(s.masks[0], s.gradients);
    CHECK(w.exact);
    CHECK(w.cut == std::vector<bool>{false, false});
    CHECK(w.paths[0].fill.a == 0);
  }
  {
    const Scene s = masked(std::string(white_rect) + R"svg(<circle cx="20" cy="20" r="5" fill="#808080"/>)svg");
    CHECK_FALSE(lottie::luminance_as_alpha(s.masks[0], s.gradients).exact);
  }
  {  // black beside (not over) the white: nothing to cut
    const Scene s = masked(R"svg(<rect width="10" height="10" fill="#fff"/><rect x="20" y="20" width="10" height="10" fill="#000"/>)svg");
    const lottie::AlphaMatteContent w = lottie::luminance_as_alpha(s.masks[0], s.gradients);
    CHECK(w.exact);
    CHECK(w.cut == std::vector<bool>{false, false});
  }
}

TEST_CASE("luma matte: the Lottie writes a cut as an inverted alpha matte over the content below it") {
  const Scene scene = masked(R"svg(<rect width="40" height="40" fill="#fff"/><circle id="hole" cx="20" cy="20" r="5" fill="#000"/>)svg");
  const RasterPlan plan = plan_raster(scene, Affine{}, scene.width, scene.height);
  AnimationTiming timing;
  timing.keyframes = 1;
  const LottieDocument doc = lottie_animation(scene, plan, std::vector<double>(plan.rest_cp.begin(), plan.rest_cp.end()),
                                              timing, LottieOptions{});
  CHECK(doc.warnings.empty());
  const nlohmann::json j = nlohmann::json::parse(doc.json);
  std::map<std::string, nlohmann::json> assets;
  for (const auto& a : j["assets"]) assets[a["id"]] = a["layers"];
  REQUIRE(j["layers"].size() == 2);
  CHECK(j["layers"][0]["td"] == 1);
  CHECK(j["layers"][1]["tt"] == 1);
  CHECK(j.dump().find("\"tt\":3") == std::string::npos);  // no luma matte anywhere
  // The mask's content: [hole (td 1), "cut by hole" (tt 2) of [the white rect]].
  const nlohmann::json& content = assets.at(j["layers"][0]["refId"]);
  REQUIRE(content.size() == 2);
  CHECK(content[0]["nm"] == "content/hole");  // the mask content's path id
  CHECK(content[0]["td"] == 1);
  CHECK(content[1]["tt"] == 2);
  CHECK(content[1]["ind"].get<int>() == content[0]["ind"].get<int>() + 1);  // the matte is the layer right above
  CHECK(assets.at(content[1]["refId"]).size() == 1);
}

}  // TEST_SUITE
