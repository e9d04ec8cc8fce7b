// The compact Lottie export (lottie_motion.h): a still path is static, a part turning about a
// joint is its group's eased transform about that joint with a static shape, and a part that
// also deforms keyframes its residual shape at fewer keys than values; what players draw at
// every written value is within the tolerance of the fitted points.
#include <doctest/doctest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "export/keyframe_reduce.h"
#include "export/lottie_writer.h"
#include "raster/raster_plan.h"
#include "svgmotion/svg_reader.h"

using namespace svgm;

namespace {

// A 100x100 canvas: a still disc, an arm hanging from a shoulder at (50, 20), and a flag.
constexpr const char* kDoc = R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
  <circle id="disc" cx="15" cy="80" r="8" fill="#c33"/>
  <rect id="arm" x="46" y="20" width="8" height="40" fill="#36c"/>
  <rect id="flag" x="70" y="10" width="20" height="12" fill="#3c6"/>
</svg>)svg";
constexpr int kValues = 49;  // 2 s at 24 fps
const Vec2 kShoulder{50, 20};

double angle_at(int k) { return 35.0 * std::sin(2 * M_PI * k / (kValues - 1)); }

// Value k: the disc still, the arm turned about the shoulder, the flag's far corner pulled out.
std::vector<double> fitted_points(const Scene& scene, const RasterPlan& plan) {
  std::vector<double> pts;
  for (int k = 0; k < kValues; ++k) {
    const Affine turn = Affine::translate(kShoulder.x, kShoulder.y) * Affine::rotate_deg(angle_at(k)) *
                        Affine::translate(-kShoulder.x, -kShoulder.y);
    std::vector<double> v(plan.rest_cp.begin(), plan.rest_cp.end());
    for (size_t p = 0; p < scene.paths.size(); ++p)
      for (int i = 0; i < plan.path_cp_count[p]; ++i) {
        double* q = &v[2 * (plan.path_cp_first[p] + static_cast<size_t>(i))];
        if (scene.paths[p].id == "arm") {
          const Vec2 t = turn.apply({q[0], q[1]});
          q[0] = t.x, q[1] = t.y;
        }
        if (scene.paths[p].id == "flag" && q[0] > 80) q[0] += 3 * std::sin(M_PI * k / (kValues - 1)) * (q[0] - 80) / 10;
      }
    pts.insert(pts.end(), v.begin(), v.end());
  }
  return pts;
}

nlohmann::json group_of(const nlohmann::json& lottie, const std::string& name) {
  for (const auto& l : lottie["layers"])
    if (l["nm"] == name) return l["shapes"][0]["it"];
  return nullptr;
}
nlohmann::json item(const nlohmann::json& items, const std::string& ty) {
  for (const auto& it : items)
    if (it["ty"] == ty) return it;
  return nullptr;
}

// A property's value at frame t as players interpolate it (bezier easing with handles at x 1/3
// and 2/3, as the writer writes them).
std::vector<double> value_at(const nlohmann::json& prop, double t) {
  if (prop["a"] == 0) return prop["k"].is_array() ? prop["k"].get<std::vector<double>>() : std::vector<double>{prop["k"].get<double>()};
  const auto& k = prop["k"];
  size_t s = 0;
  while (s + 2 < k.size() && k[s + 1]["t"].get<double>() <= t) ++s;
  const double t0 = k[s]["t"], t1 = k[s + 1]["t"];
  const std::vector<double> a = k[s]["s"], b = k[s + 1]["s"];
  Easing e;
  const double ox = k[s]["o"]["x"], oy = k[s]["o"]["y"], iy = k[s]["i"]["y"];
  if (ox != 0) e = Easing{oy, iy};
  const double u = ease(e, std::clamp((t - t0) / (t1 - t0), 0.0, 1.0));
  std::vector<double> out;
  for (size_t i = 0; i < a.size(); ++i) out.push_back(a[i] + u * (b[i] - a[i]));
  return out;
}

}  // namespace

TEST_SUITE("export") {

TEST_CASE("compact lottie: still paths static, a turning part keyed on its group about its joint, a deforming one's residual") {
  const Scene scene = read_svg_string(kDoc, "doc.svg");
  const RasterPlan plan = plan_raster(scene, Affine{}, 100, 100);
  REQUIRE(scene.paths.size() == 3);
  const std::vector<double> pts = fitted_points(scene, plan);
  AnimationTiming timing;
  timing.keyframes = kValues;
  timing.duration_s = 2;
  LottieOptions options;
  options.fps = 24;
  options.compact = true;
  options.decimals = -1;
  // One pixel at 1024 (a step of the measured ladder): the keys hold it between values too,
  // where the values blended trace the swing's sine in chords; a quarter pixel there (0.024 px
  // on this 100 px canvas) is below the chords' own gap from any smooth curve, and every value
  // is kept.
  const double tol = 1.0 * 100 / 1024;
  options.tolerance_px = tol;
  const auto j = nlohmann::json::parse(lottie_animation(scene, plan, pts, timing, options).json);
  const auto full = nlohmann::json::parse(lottie_animation(scene, plan, pts, timing, LottieOptions{}).json);
  CHECK(item(group_of(full, "disc"), "sh")["ks"]["a"] == 1);  // the full export keys every path

  const auto disc = group_of(j, "disc");
  CHECK(item(disc, "sh")["ks"]["a"] == 0);
  CHECK(item(disc, "tr") == nlohmann::json::parse(R"({"ty":"tr","o":{"a":0,"k":100}})"));  // identity: defaults

  // The arm: its shape static in a group of its own turning about the shoulder with fewer keys
  // than values; its fill after that group, in the layer's.
  const auto arm = group_of(j, "arm");
  CHECK(item(arm, "fl") != nullptr);
  CHECK(item(arm, "tr") == item(disc, "tr"));
  const auto moving = item(arm, "gr")["it"];
  CHECK(item(moving, "sh")["ks"]["a"] == 0);
  const auto tr = item(moving, "tr");
  REQUIRE(tr["r"]["a"] == 1);
  CHECK(tr["r"]["k"].size() < kValues / 2);
  CHECK(tr["p"]["a"] == 0);  // about the joint nothing but the angle moves
  CHECK(std::hypot(tr["a"]["k"][0].get<double>() - kShoulder.x, tr["a"]["k"][1].get<double>() - kShoulder.y) < 0.2);
  // What a player draws at each value's frame: the arm's rest corners within twice the
  // tolerance of the fitted ones.
  double worst = 0;
  for (int k = 0; k < kValues; ++k) {
    const double t = 48.0 * k / (kValues - 1);
    const std::vector<double> p = value_at(tr["p"], t), a = value_at(tr["a"], t), r = value_at(tr["r"], t);
    const std::vector<double> s = tr.contains("s") ? value_at(tr["s"], t) : std::vector<double>{100, 100};
    const Affine m = Affine::translate(p[0], p[1]) * Affine::rotate_deg(r[0]) * Affine::scale(s[0] / 100, s[1] / 100) *
                     Affine::translate(-a[0], -a[1]);
    const Affine turn = Affine::translate(kShoulder.x, kShoulder.y) * Affine::rotate_deg(angle_at(k)) *
                        Affine::translate(-kShoulder.x, -kShoulder.y);
    for (const Vec2 c : {Vec2{46, 20}, Vec2{54, 20}, Vec2{54, 60}, Vec2{46, 60}}) {
      const Vec2 d = m.apply(c) - turn.apply(c);
      worst = std::max(worst, std::hypot(d.x, d.y));
    }
  }
  CHECK(worst <= 2 * tol);

  // The flag deforms: its shape keyed, at fewer keys than values, with easing somewhere.
  const auto flag = item(item(group_of(j, "flag"), "gr")["it"], "sh")["ks"];
  REQUIRE(flag["a"] == 1);
  CHECK(flag["k"].size() >= 3);
  CHECK(flag["k"].size() < kValues);
  CHECK(j.dump().size() * 2 < full.dump().size());
}

}  // TEST_SUITE
