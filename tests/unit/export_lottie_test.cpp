// The Lottie writer: layers in paint order, keyframes at the SVG's times holding the fitted
// control points, paint (colour, opacity, fill rule, stroke) as the scene has it, mirror timing,
// precision, and the gradient warning.
#include <doctest/doctest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "export/lottie_writer.h"
#include "raster/raster_plan.h"
#include "svgmotion/svg_reader.h"

using namespace svgm;

namespace {

// A 100x50 canvas drawn from a 200x100 viewBox (every coordinate halves): a red rect at the
// bottom, then a group (half opaque) with an even-odd ring stroked in blue.
constexpr const char* kDoc = R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="50" viewBox="0 0 200 100">
  <rect id="back" x="20" y="20" width="40" height="20" fill="#ff0000"/>
  <g id="part" opacity="0.5">
    <path id="ring" d="M100 10 L180 10 L180 90 L100 90 Z M120 30 L160 30 L160 70 L120 70 Z" fill-rule="evenodd"
          fill="#00ff00" fill-opacity="0.25" stroke="#0000ff" stroke-width="4" stroke-linecap="round" stroke-linejoin="bevel"/>
  </g>
</svg>)svg";

struct Fixture {
  Scene scene = read_svg_string(kDoc, "doc.svg");
  RasterPlan plan = plan_raster(scene, Affine{}, 100, 50);
  // Keyframe k moves every canvas point by (2k, -k).
  std::vector<double> points(int K) const {
    std::vector<double> pts;
    for (int k = 0; k < K; ++k)
      for (int i = 0; i < plan.n_cp; ++i) {
        pts.push_back(plan.rest_cp[2 * i] + 2.0 * k);
        pts.push_back(plan.rest_cp[2 * i + 1] - 1.0 * k);
      }
    return pts;
  }
};

nlohmann::json layer_named(const nlohmann::json& lottie, const std::string& name) {
  for (const auto& l : lottie["layers"])
    if (l["nm"] == name) return l;
  return nullptr;
}

}  // namespace

TEST_SUITE("export") {

TEST_CASE("lottie: layers in paint order, keyframes at the SVG's times with the fitted points") {
  Fixture f;
  REQUIRE(f.scene.paths.size() == 2);
  AnimationTiming timing;
  timing.keyframes = 3;
  timing.key_times = {0, 0.25, 1};
  timing.duration_s = 2;
  LottieOptions options;
  options.fps = 24;
  options.name = "doc.svg";
  const LottieDocument doc = lottie_animation(f.scene, f.plan, f.points(3), timing, options);
  CHECK(doc.warnings.empty());
  const auto j = nlohmann::json::parse(doc.json);
  CHECK(j["w"] == 100);
  CHECK(j["h"] == 50);
  CHECK(j["fr"] == 24);
  CHECK(j["ip"] == 0);
  CHECK(j["op"] == 48);  // 2 s at 24 fps
  // Top layer first: the half-opaque group (drawn last) as one precomposition faded once,
  // then the rect. The ring and its group's null layer are inside the precomposition.
  REQUIRE(j["layers"].size() == 2);
  CHECK(j["layers"][0]["ty"] == 0);
  CHECK(j["layers"][0]["ks"]["o"]["k"] == 50);  // the group's opacity, once
  CHECK(j["layers"][1]["nm"] == "back");
  CHECK(!j["layers"][1].contains("parent"));
  CHECK(j["layers"][1]["ks"]["o"]["k"] == 100);
  REQUIRE(j["assets"].size() == 1);
  CHECK(j["assets"][0]["id"] == j["layers"][0]["refId"]);
  const auto& inner = j["assets"][0]["layers"];
  REQUIRE(inner.size() == 2);
  CHECK(inner[0]["nm"] == "ring");
  CHECK(inner[0]["ks"]["o"]["k"] == 100);  // not the group's opacity again
  CHECK(inner[1]["nm"] == "part");
  CHECK(inner[1]["ty"] == 3);
  CHECK(inner[0]["parent"] == inner[1]["ind"]);

  // The rect: one closed subpath of four corners (the closing line folded into the first).
  const auto back = layer_named(j, "back");
  const auto& items = back["shapes"][0]["it"];
  REQUIRE(items.size() == 3);  // sh, fl, tr
  CHECK(items[0]["ty"] == "sh");
  CHECK(items[1]["ty"] == "fl");
  CHECK(items[2]["ty"] == "tr");
  const auto& keys = items[0]["ks"]["k"];
  REQUIRE(keys.size() == 3);
  CHECK(keys[0]["t"] == 0);
  CHECK(keys[1]["t"] == 12);  // 0.25 of 48 frames
  CHECK(keys[2]["t"] == 48);
  const auto& shape1 = keys[1]["s"][0];
  CHECK(shape1["c"] == true);
  REQUIRE(shape1["v"].size() == 4);
  // Canvas space: the rect's corner (20, 20) in the viewBox is (10, 10); keyframe 1 adds (2, -1).
  CHECK(shape1["v"][0][0].get<double>() == doctest::Approx(12));
  CHECK(shape1["v"][0][1].get<double>() == doctest::Approx(9));
  CHECK(shape1["v"][2][0].get<double>() == doctest::Approx(32));  // (60, 40) -> (30, 20)
  CHECK(shape1["v"][2][1].get<double>() == doctest::Approx(19));
  for (size_t v = 0; v < 4; ++v) {  // straight edges: tangents along the edges, a third of them
    const double ox = shape1["o"][v][0].get<double>(), oy = shape1["o"][v][1].get<double>();
    CHECK(std::fabs(ox) + std::fabs(oy) > 3);
  }
  CHECK(items[1]["c"]["k"][0] == 1);
  CHECK(items[1]["c"]["k"][1] == 0);
  CHECK(items[1]["r"] == 1);
  // Linear easing between keyframes, none after the last.
  CHECK(keys[0]["o"]["x"] == 0);
  CHECK(keys[0]["i"]["x"] == 1);
  CHECK(!keys[2].contains("o"));

  // The ring: two subpaths, stroke listed before fill (drawn over it), even-odd.
  const auto ring = inner[0];
  const auto& it = ring["shapes"][0]["it"];
  REQUIRE(it.size() == 5);  // sh, sh, st, fl, tr
  CHECK(it[2]["ty"] == "st");
  CHECK(it[2]["w"]["k"] == 2);  // 4 user units at half scale
  CHECK(it[2]["lc"] == 2);      // round
  CHECK(it[2]["lj"] == 3);      // bevel
  CHECK(it[2]["c"]["k"][2] == 1);
  CHECK(it[3]["ty"] == "fl");
  CHECK(it[3]["r"] == 2);
  CHECK(it[3]["o"]["k"] == 25);
}

TEST_CASE("lottie: a mirror plays forwards then back over twice the time; one keyframe is static") {
  Fixture f;
  AnimationTiming timing;
  timing.keyframes = 3;
  timing.duration_s = 1;
  timing.loop = LoopMode::Mirror;
  LottieOptions options;
  options.fps = 10;
  const auto j = nlohmann::json::parse(lottie_animation(f.scene, f.plan, f.points(3), timing, options).json);
  CHECK(j["op"] == 20);
  const auto back = layer_named(j, "back");
  const auto& keys = back["shapes"][0]["it"][0]["ks"]["k"];
  REQUIRE(keys.size() == 5);
  const double want_t[] = {0, 5, 10, 15, 20};
  const double want_x[] = {10, 12, 14, 12, 10};  // keyframes 0 1 2 1 0
  for (size_t i = 0; i < 5; ++i) {
    CAPTURE(i);
    CHECK(keys[i]["t"].get<double>() == doctest::Approx(want_t[i]));
    CHECK(keys[i]["s"][0]["v"][0][0].get<double>() == doctest::Approx(want_x[i]));
  }

  timing.keyframes = 1;
  timing.loop = LoopMode::Loop;
  const auto one = nlohmann::json::parse(lottie_animation(f.scene, f.plan, f.points(1), timing, options).json);
  const auto ks = layer_named(one, "back")["shapes"][0]["it"][0]["ks"];
  CHECK(ks["a"] == 0);
  CHECK(ks["k"]["v"][0][0].get<double>() == doctest::Approx(10));
}

TEST_CASE("lottie and SMIL: coordinates carry the decimals asked for") {
  Fixture f;
  std::vector<double> pts = f.points(2);
  for (double& v : pts) v += 0.123456;
  AnimationTiming timing;
  timing.keyframes = 2;
  for (int decimals : {0, 1, 3}) {
    CAPTURE(decimals);
    LottieOptions options;
    options.decimals = decimals;
    const auto j = nlohmann::json::parse(lottie_animation(f.scene, f.plan, pts, timing, options).json);
    const double x = layer_named(j, "back")["shapes"][0]["it"][0]["ks"]["k"][1]["s"][0]["v"][0][0].get<double>();
    const double want = std::round((12.123456) * std::pow(10, decimals)) / std::pow(10, decimals);
    CHECK(x == doctest::Approx(want).epsilon(1e-12));
    // The SMIL writer's path data rounds the same way (in the element's units: twice the canvas').
    const std::string d = path_data(f.scene.paths[0], &pts[2 * f.plan.path_cp_first[0]],
                                    f.scene.paths[0].to_canvas.inverse(), decimals);
    const double local = std::round(2 * 10.123456 * std::pow(10, decimals)) / std::pow(10, decimals);
    std::string first = d.substr(2, d.find(' ', 2) - 2);
    CHECK(std::stod(first) == doctest::Approx(local).epsilon(1e-12));
    CHECK((decimals == 0 ? first.find('.') == std::string::npos : first.size() - first.find('.') - 1 <= static_cast<size_t>(decimals)));
  }
}

}  // TEST_SUITE
