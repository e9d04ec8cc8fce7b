// Group motion as animateTransform (export/group_transform.h): the decomposition of known affine
// maps into translate rotate skewX scale, the homography's affine part and its projective
// distance, and the export of a known motion whose written transforms are checked against
// hand-computed values and whose shapes read back (render --time) as the baked export's.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "fit/plan/fit_plan.h"
#include "export/group_transform.h"
#include "fit/optimise/motion_model.h"
#include "export/smil_writer.h"
#include "raster/raster_plan.h"
#include "svgmotion/svg_reader.h"

using namespace svgm;

namespace {

constexpr double kDeg = M_PI / 180;

std::string slurp(const std::filesystem::path& p) {
  std::ifstream f(p);
  return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

// The attribute `values` of the animateTransform of `type` inside the element with `id`, or "".
std::string transform_values(const std::string& text, const std::string& id, const std::string& type) {
  const size_t el = text.find("id=\"" + id + "\"");
  if (el == std::string::npos) return "";
  const size_t end = text.find("</path>", el);
  const size_t at = text.find("type=\"" + type + "\"", el);
  if (at == std::string::npos || at > end) return "";
  const size_t v = text.find("values=\"", at);
  return text.substr(v + 8, text.find('"', v + 8) - v - 8);
}

}  // namespace

TEST_SUITE("fit") {

TEST_CASE("decompose_affine: translate rotate skewX scale of known matrices, and back") {
  // rotate(90) scale(2 3): [0 -3; 2 0].
  TransformParts p = decompose_affine(Affine{0, 2, -3, 0, 5, 7});
  CHECK(p.tx == 5);
  CHECK(p.ty == 7);
  CHECK(p.rotate_deg == doctest::Approx(90));
  CHECK(p.sx == doctest::Approx(2));
  CHECK(p.sy == doctest::Approx(3));
  CHECK(p.skew_x_deg == doctest::Approx(0).epsilon(1e-12));
  // skewX(45): [1 1; 0 1].
  p = decompose_affine(Affine{1, 0, 1, 1, 0, 0});
  CHECK(p.rotate_deg == doctest::Approx(0));
  CHECK(p.skew_x_deg == doctest::Approx(45));
  CHECK(p.sx == doctest::Approx(1));
  CHECK(p.sy == doctest::Approx(1));
  // A mirror: scale(1 -1) rotated by 30 degrees keeps sx > 0 and shows as sy < 0.
  p = decompose_affine(Affine::rotate_deg(30) * Affine::scale(1, -1));
  CHECK(p.rotate_deg == doctest::Approx(30));
  CHECK(p.sy == doctest::Approx(-1));
  // Any product comes back.
  const Affine m = Affine::translate(3, -4) * Affine::rotate_deg(-120) * Affine::skew_x_deg(20) * Affine::scale(0.5, 1.5);
  const Affine back = compose_affine(decompose_affine(m));
  for (double d : {back.a - m.a, back.b - m.b, back.c - m.c, back.d - m.d, back.e - m.e, back.f - m.f})
    CHECK(std::fabs(d) < 1e-12);
  CHECK(unwrap_degrees(-170, 170) == doctest::Approx(190));
  CHECK(unwrap_degrees(350, 0) == doctest::Approx(-10));
  CHECK(unwrap_degrees(20, 10) == doctest::Approx(20));
}

TEST_CASE("group_affine: the homography's affine part in canvas space and its perspective in pixels") {
  // 100 x 100 pixels = canvas: origin (50, 50), scale 50. Rotate 30 degrees and scale by 2 about
  // the centre, then move by (0.2, -0.1) normalised = (10, -5) pixels:
  // x -> (60, 45) + 2 R(30) (x - (50, 50)).
  MotionParams th = identity_params();
  th[0] = 0.2, th[1] = -0.1, th[2] = 30 * kDeg, th[3] = th[4] = 2;
  const GroupAffine g = group_affine(th, {50, 50}, 50, Affine{}, 0, 0, 100, 100);
  const TransformParts p = decompose_affine(g.canvas);
  CHECK(p.rotate_deg == doctest::Approx(30));
  CHECK(p.sx == doctest::Approx(2));
  CHECK(p.sy == doctest::Approx(2));
  CHECK(p.tx == doctest::Approx(60 - 50 * (std::sqrt(3.0) - 1)));
  CHECK(p.ty == doctest::Approx(45 - 50 * (std::sqrt(3.0) + 1)));
  CHECK(g.projective_px == doctest::Approx(0).epsilon(1e-9));
  // Perspective px = 0.1 on the identity bends the whole canvas: with w = 1 + 0.1 n.x from 0.9 to
  // 1.1, no affine map comes within half a pixel (dropping the bottom row would be off by up to
  // 50 sqrt(2) / 9 = 7.9 px at the corners n = (-1, +-1); the best fit does better).
  MotionParams persp = identity_params();
  persp[7] = 0.1;
  const double bent = group_affine(persp, {50, 50}, 50, Affine{}, 0, 0, 100, 100).projective_px;
  CHECK(bent > kAffineTolerancePx);
  CHECK(bent < 50 * std::sqrt(2.0) / 9);
  // The same perspective over a 1-pixel box near the corner (centre n = (0.81, 0.81),
  // w = 1.081) is, to first order, the affine map of its Jacobian, which the fitted map
  // carries (dropping the bottom row would be 4 px off there): x' = n.x / w has the column
  // (1, -0.1 n.y) / w^2, so sx = sqrt(1 + 0.081^2) / 1.081^2 = 0.8586. The curvature left is
  // second order in the box size: 0.1 * (1/50)^2 * 50 = 0.002 px at most.
  const GroupAffine small = group_affine(persp, {50, 50}, 50, Affine{}, 90, 90, 91, 91);
  CHECK(small.projective_px < 2e-3);
  CHECK(decompose_affine(small.canvas).sx == doctest::Approx(std::sqrt(1 + 0.081 * 0.081) / (1.081 * 1.081)).epsilon(1e-3));
}

TEST_CASE("group transforms export: hand-computed transform values, shapes equal to the baked export at every keyframe") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("svgm_group_tf_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path in = dir / "in.svg", baked = dir / "baked.svg", moved = dir / "moved.svg";
  std::ofstream(in) << R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
  <g id="arm" transform="translate(10 20)">
    <path id="a" d="M 0 0 C 10 0 20 10 20 20 C 10 20 0 10 0 0 Z" fill="#c33"/>
    <rect id="b" x="25" y="0" width="10" height="8" fill="blue"/>
  </g>
  <path id="c" d="M 70 70 L 90 70 L 90 90 Z" fill="green"/>
</svg>)svg";
  const Scene scene = read_svg_file(in);
  REQUIRE(scene.paths.size() == 3);
  const RasterPlan plan = plan_raster(scene, Affine{}, 100, 100);
  const FitPlan fplan = plan_fit(scene, plan, FitPlanOptions{});
  REQUIRE(fplan.n_groups == 2);  // the <g> and the lone path
  const int K = 3, G = 2;
  const int arm = fplan.cp_group[static_cast<size_t>(plan.path_cp_first[0])];
  // The arm: identity; rotate 30 and scale 2 about the centre, moved (10, -5); rotate 190
  // (written as -170 by atan2: the export must unwrap it to 190, not spin back through 0).
  // The lone path: perspective 0.6 at keyframe 1 (over its 20-pixel box, far from affine), so
  // it stays baked.
  std::vector<MotionParams> th(K * G, identity_params());
  th[1 * G + arm][0] = 0.2, th[1 * G + arm][1] = -0.1, th[1 * G + arm][2] = 30 * kDeg;
  th[1 * G + arm][3] = th[1 * G + arm][4] = 2;
  th[2 * G + arm][2] = 190 * kDeg;
  th[1 * G + (1 - arm)][7] = 0.6;
  std::vector<float> params;
  for (const MotionParams& t : th) params.insert(params.end(), t.begin(), t.end());
  // Canvas points: each group's motion, and path a also moves by 1 pixel to the right within the
  // arm at keyframe 2 (a residual that must be animated in its d).
  std::vector<double> pts;
  for (int k = 0; k < K; ++k)
    for (int i = 0; i < plan.n_cp; ++i) {
      const int g = fplan.cp_group[static_cast<size_t>(i)];
      Vec2 r{plan.rest_cp[2 * i], plan.rest_cp[2 * i + 1]};
      if (k == 2 && i >= plan.path_cp_first[0] && i < plan.path_cp_first[0] + plan.path_cp_count[0]) r.x += 1;
      // The motion model's float parameters, as the fitter hands them over.
      MotionParams tf{};
      if (g >= 0)
        for (int j = 0; j < 12; ++j) tf[j] = static_cast<float>(th[k * G + g][j]);
      const Vec2 q = g >= 0 ? apply_motion(tf, r, {50, 50}, 50) : Vec2{};
      pts.push_back(q.x);
      pts.push_back(q.y);
    }
  const std::vector<double> key_times{0, 0.5, 1};
  const GroupMotionExport gm =
      group_motion_export(fplan, plan, params, K, Affine{}, 100, 100, key_times, key_times, 0, false, key_times);
  CHECK(gm.transform_groups == 1);
  REQUIRE(gm.baked.size() == 1);
  CHECK(gm.baked[0].rfind("c: not affine at keyframe 1", 0) == 0);

  AnimationTiming timing;
  timing.keyframes = K;
  timing.key_times = key_times;
  timing.duration_s = 2;
  CHECK(write_animation_svg(in, scene, plan, pts, timing, baked).empty());
  CHECK(write_animation_svg(in, scene, plan, pts, timing, moved, nullptr, kDefaultDecimals, &gm.paths).empty());
  const std::string text = slurp(moved);
  // Path a's own frame is the arm's translate(10 20): its local map is
  // T(-10,-20) A T(10,20), whose translation is A(10, 20) - (10, 20). At keyframe 1 that is
  // (60, 45) + 2 R(30) (-40, -30) - (10, 20) = (80 - 40 sqrt 3, -15 - 30 sqrt 3)
  // = (10.718, -66.962); at keyframe 2, (50, 50) + R(190) (-40, -30) - (10, 20) = (74.183, 66.49).
  CHECK(transform_values(text, "a", "rotate") == "0;30;190");
  CHECK(transform_values(text, "a", "scale") == "1 1;2 2;1 1");
  CHECK(transform_values(text, "a", "translate") == "0 0;10.718 -66.962;74.183 66.49");
  CHECK(transform_values(text, "a", "skewX").empty());  // the identity throughout: not written
  CHECK(transform_values(text, "b", "rotate") == "0;30;190");
  CHECK(transform_values(text, "c", "rotate").empty());  // baked
  CHECK(text.find("additive=\"sum\"") != std::string::npos);
  // a's residual moves (the extra pixel); b's does not, so b has no <animate> of d.
  const size_t b_at = text.find("id=\"b\""), b_end = text.find("</path>", b_at);
  CHECK(text.substr(b_at, b_end - b_at).find("attributeName=\"d\"") == std::string::npos);
  const size_t a_at = text.find("id=\"a\""), a_end = text.find("</path>", a_at);
  CHECK(text.substr(a_at, a_end - a_at).find("attributeName=\"d\"") != std::string::npos);

  // render --time: both exports read back as the same shapes at every keyframe (and as the
  // points given); between keyframes the transform export turns while the baked one moves
  // straight, so only the keyframes are compared.
  for (int k = 0; k < K; ++k) {
    SvgReadLimits at;
    at.animation_time = k * 1.0 - (k == K - 1 ? 1e-9 : 0);
    const Scene a = read_svg_file(baked, at), b = read_svg_file(moved, at);
    REQUIRE(a.paths.size() == 3);
    REQUIRE(b.paths.size() == 3);
    double worst_points = 0, worst_between = 0;
    for (size_t p = 0; p < 3; ++p) {
      int cp = plan.path_cp_first[p];
      REQUIRE(a.paths[p].subpaths.size() == b.paths[p].subpaths.size());
      for (size_t s = 0; s < a.paths[p].subpaths.size(); ++s)
        for (size_t j = 0; j < a.paths[p].subpaths[s].points.size(); ++j, ++cp) {
          const Vec2 qa = a.paths[p].subpaths[s].points[j], qb = b.paths[p].subpaths[s].points[j];
          worst_between = std::max(worst_between, std::hypot(qa.x - qb.x, qa.y - qb.y));
          worst_points = std::max(worst_points, std::hypot(qb.x - pts[(k * plan.n_cp + cp) * 2],
                                                           qb.y - pts[(k * plan.n_cp + cp) * 2 + 1]));
        }
    }
    CAPTURE(k);
    CHECK(worst_points < 3e-3);   // coordinates to 1/1000, angles to 1e-4 degrees
    CHECK(worst_between < 5e-3);
  }
  fs::remove_all(dir);
}

}  // TEST_SUITE
