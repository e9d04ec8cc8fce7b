// The user's own document as the fit's output (svg/document_order.h, smil_writer.h timing) and
// the result gate (fit/output/result_gate.h): paths matched by id, paint orders applied by moving the
// fewest elements and only within their parents, keyTimes and loop modes, and the gate's
// verdict on a good fit, a fit that leaves the canvas and a fit that does not cover the figure.
#include <doctest/doctest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "svg/document_order.h"
#include "fit/optimise/inbetween.h"
#include "fit/output/result_gate.h"
#include "raster/raster_ref.h"
#include "export/smil_writer.h"
#include "raster/raster_plan.h"
#include "svgmotion/error.h"
#include "svgmotion/svg_reader.h"

using namespace svgm;

namespace {

// The reference rasteriser's render of `cp` (premultiplied RGBA) and the same over white (what
// a target frame shows), as the gate's float images.
std::vector<float> render_f(const RasterPlan& plan, const std::vector<double>& cp) {
  const std::vector<double> img = ref::render(plan, cp);
  return std::vector<float>(img.begin(), img.end());
}
std::vector<float> over_white(const std::vector<float>& premultiplied) {
  std::vector<float> o(premultiplied.size());
  for (size_t i = 0; i + 3 < o.size(); i += 4) {
    for (int c = 0; c < 3; ++c) o[i + c] = premultiplied[i + c] + (1 - premultiplied[i + 3]);
    o[i + 3] = 1;
  }
  return o;
}

// `cp` with path `path`'s points scaled along x about x = cx by f (the result-gate cases stretch
// or squash one part of a still body).
std::vector<double> scale_path_x(const RasterPlan& plan, std::vector<double> cp, int path, double cx, double f) {
  for (int i = 0; i < plan.path_cp_count[path]; ++i) {
    double& x = cp[2 * static_cast<size_t>(plan.path_cp_first[path] + i)];
    x = cx + f * (x - cx);
  }
  return cp;
}

std::vector<std::string> ids_in_order(const std::string& text) {
  std::vector<std::string> ids;
  for (const Path& p : read_svg_string(text, "t").paths) ids.push_back(p.id);
  return ids;
}

constexpr const char* kSiblings = R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="40" height="40">
  <rect id="a" x="1" y="1" width="10" height="10"/>
  <rect id="b" x="2" y="2" width="10" height="10"/>
  <rect id="c" x="3" y="3" width="10" height="10"/>
  <rect id="d" x="4" y="4" width="10" height="10"/>
</svg>)svg";

}  // namespace

TEST_SUITE("fit") {

TEST_CASE("reorder: the fewest elements move, and the document reads back in the new order") {
  const Scene s = read_svg_string(kSiblings, "t");
  std::string out;
  // a b c d -> b c d a: one move (a to the top), three stay.
  ReorderResult r = reorder_document_text(kSiblings, "t", s, {1, 2, 3, 0}, &out);
  REQUIRE_FALSE(r.refused);
  CHECK(r.moved == 1);
  CHECK(ids_in_order(out) == std::vector<std::string>{"b", "c", "d", "a"});
  // d c b a: three moves (the longest increasing run has length 1).
  r = reorder_document_text(kSiblings, "t", s, {3, 2, 1, 0}, &out);
  REQUIRE_FALSE(r.refused);
  CHECK(r.moved == 3);
  CHECK(ids_in_order(out) == std::vector<std::string>{"d", "c", "b", "a"});
  // The identity moves nothing and keeps the bytes inside the root.
  r = reorder_document_text(kSiblings, "t", s, {0, 1, 2, 3}, &out);
  CHECK(r.moved == 0);
  CHECK(out.find("<rect id=\"a\" x=\"1\"") != std::string::npos);
}

TEST_CASE("reorder: paths without ids (their generated ids follow position) are checked by geometry") {
  const char* doc = R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="40" height="40"><path d="M0 0 L9 0 L9 9 Z"/><path d="M1 1 L5 1 L5 5 Z"/></svg>)svg";
  const Scene s = read_svg_string(doc, "t");
  std::string out;
  const ReorderResult r = reorder_document_text(doc, "t", s, {1, 0}, &out);
  REQUIRE_FALSE(r.refused);
  CHECK(r.moved == 1);
  CHECK(out.find("<path d=\"M1 1 L5 1 L5 5 Z\"/><path d=\"M0 0") != std::string::npos);
}

TEST_CASE("reorder: a move out of its parent group is refused and changes nothing") {
  const char* doc = R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="40" height="40">
  <g id="g1" transform="translate(5 0)"><rect id="a" width="10" height="10"/><rect id="b" width="5" height="5"/></g>
  <g id="g2"><rect id="c" width="10" height="10"/></g>
</svg>)svg";
  const Scene s = read_svg_string(doc, "t");
  std::string out = "untouched";
  // c below a: c would have to enter g1 (or a leave it).
  const ReorderResult r = reorder_document_text(doc, "t", s, {2, 0, 1}, &out);
  REQUIRE(r.refused);
  CHECK(r.refused->find("out of its parent") != std::string::npos);
  CHECK(out == "untouched");
  // Within g1 it works: b below a.
  const ReorderResult ok = reorder_document_text(doc, "t", s, {1, 0, 2}, &out);
  REQUIRE_FALSE(ok.refused);
  CHECK(ids_in_order(out) == std::vector<std::string>{"b", "a", "c"});
}

TEST_CASE("match_paths: a working copy maps onto the original by id, duplicates by rank") {
  const Scene orig = read_svg_string(R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="40" height="40">
    <path id="x" d="M0 0 L10 0 L10 10 Z"/><path id="y" d="M0 0 L5 0 L5 5 Z"/><path id="x" d="M1 1 L9 1 L9 9 Z"/>
  </svg>)svg", "o");
  const Scene copy = read_svg_string(R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="40" height="40">
    <g><path id="y" d="M0 0 C 1 0 4 0 5 0 C 5 1 5 4 5 5 C 4 4 1 1 0 0 Z"/></g>
    <g><path id="x" d="M0 0 L10 0 L10 10 Z"/><path id="x" d="M1 1 L9 1 L9 9 Z"/></g>
  </svg>)svg", "c");
  CHECK(match_paths(copy, orig, "c") == std::vector<int>{1, 0, 2});
  const Scene missing = read_svg_string(R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="40" height="40">
    <path id="z" d="M0 0 L10 0 L10 10 Z"/></svg>)svg", "m");
  CHECK_THROWS_WITH_AS(match_paths(missing, orig, "m"), "m: path 'z' is not in the original document", Error);
}

TEST_CASE("animation timing: keyTimes at the fitted frames, closed loops, once and mirror") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("svgm_timing_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path in = dir / "in.svg", out = dir / "a.svg";
  std::ofstream(in) << R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="40" height="40"><path id="p" d="M 0 0 L 10 0 L 10 10 Z"/></svg>)svg";
  const Scene scene = read_svg_file(in);
  const RasterPlan plan = plan_raster(scene, Affine{}, 40, 40);
  const int K = 4;
  std::vector<double> pts;
  for (int k = 0; k < K; ++k)
    for (int i = 0; i < plan.n_cp; ++i) pts.push_back(plan.rest_cp[2 * i] + k), pts.push_back(plan.rest_cp[2 * i + 1]);
  auto write = [&](AnimationTiming t) {
    write_animation_svg(in, scene, plan, pts, t, out);
    std::ifstream f(out);
    return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  };
  AnimationTiming t;
  t.keyframes = K;
  t.key_times = {0, 3.0 / 10, 7.0 / 10, 1};  // frames 0, 3, 7, 10 of 11
  t.duration_s = 10 / 24.0;
  std::string s = write(t);
  CHECK(s.find("keyTimes=\"0;0.3;0.7;1\"") != std::string::npos);
  CHECK(s.find("dur=\"0.4167s\"") != std::string::npos);
  CHECK(s.find("repeatCount=\"indefinite\"") != std::string::npos);
  // Keyframe k's shape is shifted by k: the last value is 3 to the right...
  CHECK(s.find(";M 3 0 C") != std::string::npos);
  // ...unless the loop is closed, when it is keyframe 0's shape again.
  t.close_loop = true;
  s = write(t);
  CHECK(s.find(";M 3 0 C") == std::string::npos);
  CHECK(s.find("values=\"M 0 0 C") != std::string::npos);
  const size_t last = s.rfind(";M ");
  CHECK(s.compare(last, 6, ";M 0 0") == 0);
  t.close_loop = false;
  t.loop = LoopMode::Once;
  s = write(t);
  CHECK(s.find("repeatCount=\"1\"") != std::string::npos);
  CHECK(s.find("fill=\"freeze\"") != std::string::npos);
  t.loop = LoopMode::Mirror;
  s = write(t);
  CHECK(s.find("keyTimes=\"0;0.15;0.35;0.5;0.65;0.85;1\"") != std::string::npos);
  CHECK(s.find("dur=\"0.8333s\"") != std::string::npos);
  CHECK_THROWS_WITH_AS(parse_loop_mode("sideways", "stages.fitter.loop"),
                       "stages.fitter.loop must be loop, once or mirror, not 'sideways'", Error);
  fs::remove_all(dir);
}

TEST_CASE("result gate: passes a faithful fit, rejects points far off the canvas and a missed figure") {
  const Scene scene = read_svg_string(R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="32" height="32">
    <rect id="r" x="8" y="8" width="16" height="16" fill="#000"/></svg>)svg", "g");
  const RasterPlan plan = plan_raster(scene, Affine{}, 32, 32);
  const int K = 2, W = 32, H = 32;
  TargetFrames t;
  t.width = W, t.height = H, t.keyframes = K;
  t.rgba.assign(static_cast<size_t>(K) * W * H * 4, 1.f);
  t.mask.assign(static_cast<size_t>(K) * W * H, 0);
  std::vector<float> good(static_cast<size_t>(K) * W * H * 4, 0.f);  // premultiplied over nothing
  for (int k = 0; k < K; ++k)
    for (int y = 8; y < 24; ++y)
      for (int x = 8; x < 24; ++x) {
        const size_t i = (static_cast<size_t>(k) * W * H + static_cast<size_t>(y) * W + x);
        for (int c = 0; c < 3; ++c) t.rgba[4 * i + c] = 0;
        t.mask[i] = 1;
        good[4 * i + 3] = 1;  // black, opaque
      }
  t.raw = t.rgba;
  std::vector<double> pts;
  for (int k = 0; k < K; ++k)
    for (int i = 0; i < plan.n_cp; ++i) pts.push_back(plan.rest_cp[2 * i]), pts.push_back(plan.rest_cp[2 * i + 1]);
  GateVerdict v = judge_fit(t, good, pts, plan, scene, Affine{});
  CHECK(v.passed);
  CHECK(v.psnr_db[0] > 90);
  CHECK(v.iou[1] == doctest::Approx(1.0));
  // Keyframe 1's points thrown 100 canvases away.
  std::vector<double> far = pts;
  for (int i = 0; i < plan.n_cp; ++i) far[2 * (plan.n_cp + i)] += 3200;
  v = judge_fit(t, good, far, plan, scene, Affine{});
  CHECK_FALSE(v.passed);
  bool outside = false;
  for (const auto& r : v.reasons) outside = outside || r.find("keyframe 1: control points lie 99") == 0;
  CHECK(outside);
  // A fit that draws nothing where the figure is: PSNR and IoU both fail.
  std::vector<float> empty(good.size(), 0.f);
  v = judge_fit(t, empty, pts, plan, scene, Affine{});
  CHECK_FALSE(v.passed);
  CHECK(v.iou[0] == doctest::Approx(0.0));
}

TEST_CASE("result gate: a path grown beyond the figure passes where the target shows it, not elsewhere") {
  // A 4 x 4 red square (an eye) on a black 48 x 48 body. In keyframe 1 the eye is stretched
  // to 24 x 4 (its box diagonal 4.3x the rest's; the figure's box keeps its size).
  const Scene scene = read_svg_string(R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="64" height="64">
    <rect id="body" x="8" y="8" width="48" height="48" fill="#000"/>
    <rect id="eye" x="28" y="28" width="4" height="4" fill="#f00"/></svg>)svg", "g");
  const RasterPlan plan = plan_raster(scene, Affine{}, 64, 64);
  const int W = 64, H = 64, K = 2;
  const size_t px = static_cast<size_t>(W) * H, n = static_cast<size_t>(plan.n_cp);
  const std::vector<double> rest(plan.rest_cp.begin(), plan.rest_cp.begin() + 2 * n);
  const std::vector<double> stretched = scale_path_x(plan, rest, 1, 30, 6);  // the eye, about its centre
  auto frames = [&](const std::vector<float>& a, const std::vector<float>& b) {
    std::vector<float> f(a);
    f.insert(f.end(), b.begin(), b.end());
    return f;
  };
  const std::vector<float> r0 = render_f(plan, rest), r1 = render_f(plan, stretched);
  std::vector<double> pts(rest);
  pts.insert(pts.end(), stretched.begin(), stretched.end());
  const std::vector<float> renders = frames(r0, r1);
  TargetFrames t;
  t.width = W, t.height = H, t.keyframes = K;
  t.mask.assign(static_cast<size_t>(K) * px, 1);

  // The target stretches the eye too: the growth is what it shows, and the fit passes.
  t.rgba = frames(over_white(r0), over_white(r1));
  t.raw = t.rgba;
  GateVerdict v = judge_fit(t, renders, pts, plan, scene, Affine{});
  CHECK(v.passed);
  REQUIRE(v.waived.size() == 1);
  CHECK(v.waived[0].find("keyframe 1: path 'eye' grew 4.3x") == 0);
  CHECK(v.waived[0].find("(1.00 of its pixels agree)") != std::string::npos);

  // The target keeps the eye small: 4 of its 24 columns show red where the target does.
  t.rgba = frames(over_white(r0), over_white(r0));
  t.raw = t.rgba;
  v = judge_fit(t, renders, pts, plan, scene, Affine{});
  CHECK_FALSE(v.passed);
  REQUIRE(v.reasons.size() == 1);
  CHECK(v.reasons[0] == "keyframe 1: path 'eye' grew 4.3x (the target's figure 1.00x), and only 0.17 of it shows "
                        "what the target shows");
  CHECK(v.waived.empty());
}

TEST_CASE("result gate: a path folded flat is passed with a warning naming it and its keyframes") {
  // An 8 x 8 red square (a hand) on a black 48 x 48 body, three keyframes. Keyframes 1 and 2
  // squash the hand about x = 30 to a factor f of its width: f = 0.02 encloses 2% of its area,
  // its box diagonal still 8.0 against 11.3 at rest (0.71x, not a collapse by size).
  const Scene scene = read_svg_string(R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="64" height="64">
    <rect id="body" x="8" y="8" width="48" height="48" fill="#000"/>
    <rect id="hand" x="26" y="26" width="8" height="8" fill="#f00"/></svg>)svg", "g");
  const RasterPlan plan = plan_raster(scene, Affine{}, 64, 64);
  const int W = 64, H = 64, K = 3;
  const size_t px = static_cast<size_t>(W) * H, n = static_cast<size_t>(plan.n_cp);
  const std::vector<double> rest(plan.rest_cp.begin(), plan.rest_cp.begin() + 2 * n);
  TargetFrames t;
  t.width = W, t.height = H, t.keyframes = K;
  t.mask.assign(static_cast<size_t>(K) * px, 1);
  for (int k = 0; k < K; ++k) {  // the target keeps the hand whole
    const std::vector<float> f = over_white(render_f(plan, rest));
    t.rgba.insert(t.rgba.end(), f.begin(), f.end());
  }
  t.raw = t.rgba;
  auto judge = [&](double f, double about = 30) {
    std::vector<double> pts = rest;
    std::vector<float> renders;
    for (int k = 0; k < K; ++k) {
      const std::vector<double> cp = k == 0 ? rest : scale_path_x(plan, rest, 1, about, f);
      if (k > 0) pts.insert(pts.end(), cp.begin(), cp.end());
      const std::vector<float> img = render_f(plan, cp);
      renders.insert(renders.end(), img.begin(), img.end());
    }
    return judge_fit(t, renders, pts, plan, scene, Affine{});
  };
  const GateVerdict folded = judge(0.02);
  CHECK(folded.passed);  // a fit a user may keep, but should look at
  REQUIRE(folded.warnings.size() == 1);
  CHECK(folded.warnings[0] == "path 'hand' folds flat at keyframes 1-2: its enclosed area falls to 2.0% of the first "
                              "keyframe's while the target's figure keeps its size");
  // Half as wide is a deformation, not a fold; the body never changes: no warning.
  CHECK(judge(0.5).warnings.empty());
  CHECK(judge(1.0).warnings.empty());
  // Squashed about x = 66, past the canvas's right edge (its middle at x = 65.3), it is leaving
  // the frame, where nothing shows it: no warning. About x = 62 (its middle at 61.4, 2.6 px in
  // from the edge, over 1% of the canvas) it is still on the canvas and warned of.
  CHECK(judge(0.02, 66).warnings.empty());
  CHECK(judge(0.02, 62).warnings.size() == 1);
}

TEST_CASE("in-betweens: keyframes kept exactly, a smooth motion followed far closer than straight lines") {
  // One coordinate moving as sin(2 pi t), keyframes at 7 uneven times, in-betweens at 25 frames.
  const double pi = 3.14159265358979323846;
  const std::vector<double> kt = {0, 0.125, 0.25, 0.5, 0.625, 0.875, 1};
  std::vector<double> kp;
  for (double t : kt) kp.push_back(std::sin(2 * pi * t)), kp.push_back(7);  // (x, y) per key
  std::vector<double> frames;
  for (int i = 0; i < 25; ++i) frames.push_back(i / 24.0);
  const InBetween ib = in_between(kp, kt, 2, frames, 3, /*closed=*/true);
  REQUIRE(ib.points.size() == 2 * ib.times.size());
  CHECK(ib.times.size() > kt.size());
  double worst_spline = 0, worst_linear = 0;
  size_t key = 0;
  for (size_t j = 0; j < ib.times.size(); ++j) {
    const double t = ib.times[j];
    if (j > 0) CHECK(t > ib.times[j - 1]);
    CHECK(ib.points[2 * j + 1] == 7);  // a still coordinate stays exactly still
    if (key < kt.size() && t == kt[key]) {
      // The fitted keyframe itself; a closed loop ends on the first keyframe's shape.
      CHECK(ib.points[2 * j] == kp[2 * (key + 1 == kt.size() ? 0 : key)]);
      ++key;
      continue;
    }
    const size_t k = static_cast<size_t>(std::upper_bound(kt.begin(), kt.end(), t) - kt.begin()) - 1;
    const double f = (t - kt[k]) / (kt[k + 1] - kt[k]);
    const double linear = (1 - f) * kp[2 * k] + f * kp[2 * k + 2];
    worst_spline = std::max(worst_spline, std::fabs(ib.points[2 * j] - std::sin(2 * pi * t)));
    worst_linear = std::max(worst_linear, std::fabs(linear - std::sin(2 * pi * t)));
  }
  CHECK(key == kt.size());
  CHECK(worst_linear > 0.05);
  CHECK(worst_spline < 0.25 * worst_linear);
  // No frames between the keys: nothing added.
  CHECK(in_between(kp, kt, 2, {0, 1}, 3, true).times == kt);
}

TEST_CASE("in-betweens: a longer interval between retimed keyframes gets proportionally more") {
  // An 8 fps clip in a 24 fps container: keyframes at the first frame of each held run, one
  // interval twice as long as the others (frames 9 to 15). With 3 in-betweens per interval of
  // the mean length (24/7 frames), every frame of the clip is written, the long interval's 5
  // included; a fixed 3 per interval wrote only 3 of them, and the browser drew a straight
  // line over the other two.
  std::vector<double> frames;
  for (int i = 0; i < 25; ++i) frames.push_back(i / 24.0);
  std::vector<double> kt, kp;
  for (int f : {0, 3, 6, 9, 15, 18, 21, 24}) kt.push_back(f / 24.0), kp.push_back(f * f);
  const InBetween ib = in_between(kp, kt, 1, frames, 3, /*closed=*/false);
  CHECK(ib.times == frames);
  // Evenly spaced keyframes keep exactly 3 per interval (one frame of each 4 left out).
  std::vector<double> even_t, even_p;
  for (int f = 0; f <= 24; f += 4) even_t.push_back(f / 24.0), even_p.push_back(f);
  CHECK(in_between(even_p, even_t, 1, frames, 3, false).times.size() == 7 + 6 * 3);
}

}  // TEST_SUITE
