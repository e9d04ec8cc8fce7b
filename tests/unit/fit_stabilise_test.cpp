// Camera-shake removal (fit/target/stabilise.h): frames of an analytic figure (a disc and a bar with
// one-pixel soft edges, translated exactly by sub-pixel amounts) with a known jitter. The shake
// reported is the jitter minus its own low-pass, to a tenth of a pixel; a slow deliberate drift
// is kept; shifting by minus the shake brings a jittered frame back onto the clean one; and
// load_target with `stabilise` on gives keyframes much closer to the clean clip than without.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "fit/target/stabilise.h"
#include "fit/target/tile_steps.h"
#include "svgmotion/target_video.h"

#include "temp_dir.h"

using namespace svgm;

namespace {

constexpr int kW = 160, kH = 120;

// 1 inside, 0 outside, linear over the one pixel across the edge at signed distance 0.
double edge(double signed_distance) { return std::clamp(0.5 - signed_distance, 0.0, 1.0); }

// White frame (8-bit BGR) with a dark disc and a dark bar, everything moved by (dx, dy), the bar
// by (bx, by) more (a limb moving on a body that holds) and turned by `turn` radians about its
// centre, the disc's radius grown by `grow`.
cv::Mat figure(double dx, double dy, double bx = 0, double by = 0, double grow = 0, double turn = 0) {
  cv::Mat f(kH, kW, CV_8UC3);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const double px = x + 0.5 - dx, py = y + 0.5 - dy;
      const double disc = edge(std::hypot(px - 60, py - 55) - 22 - grow);
      const double ux = px - bx - 105, uy = py - by - 60;
      const double c = std::cos(turn), sn = std::sin(turn);
      const double bar = edge(std::max(std::fabs(c * ux + sn * uy) - 8, std::fabs(-sn * ux + c * uy) - 35));
      const double ink = std::max(disc, bar);
      const auto v = static_cast<uint8_t>(std::lround(255 * (1 - 0.8 * ink)));
      f.at<cv::Vec3b>(y, x) = {v, static_cast<uint8_t>(std::lround(255 * (1 - 0.5 * ink))), v};
    }
  return f;
}

// A fixed pseudo-random jitter in [-1.5, 1.5] px per frame and axis (no RNG state to vary).
std::array<double, 2> jitter(int i) {
  return {1.5 * std::sin(12.9898 * i + 1.0), 1.5 * std::sin(78.233 * i + 2.0)};
}

// A white jitter in [-1.5, 1.5] px: the classic shader hash (fract(sin(x) * 43758.5453)), whose
// successive values are uncorrelated. (jitter() above is two sinusoids sampled once a frame:
// shake as far as a low-pass of 3 frames is concerned, but not white.)
std::array<double, 2> white_jitter(int i) {
  auto hash = [](double x) { const double v = std::sin(x) * 43758.5453; return v - std::floor(v); };
  return {3 * hash(12.9898 * i + 0.5) - 1.5, 3 * hash(78.233 * i + 0.25) - 1.5};
}

// The low-pass the estimator applies: a Gaussian-weighted parabola fitted around each frame,
// taken at that frame (weighted least squares through the 3x3 normal equations, by Cramer's
// rule: an independent route to the estimator's).
std::vector<double> low_pass(const std::vector<double>& v, double sigma) {
  const int n = static_cast<int>(v.size()), r = static_cast<int>(std::ceil(3 * sigma));
  std::vector<double> out(v.size());
  auto det3 = [](const double m[3][3]) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  for (int i = 0; i < n; ++i) {
    double s[5] = {0, 0, 0, 0, 0}, sv[3] = {0, 0, 0};  // Σ w t^k, Σ w t^k v
    for (int j = std::max(0, i - r); j <= std::min(n - 1, i + r); ++j) {
      const double t = j - i, w = std::exp(-0.5 * t * t / (sigma * sigma));
      for (int k = 0; k < 5; ++k) s[k] += w * std::pow(t, k);
      for (int k = 0; k < 3; ++k) sv[k] += w * std::pow(t, k) * v[static_cast<size_t>(j)];
    }
    const double m[3][3] = {{s[0], s[1], s[2]}, {s[1], s[2], s[3]}, {s[2], s[3], s[4]}};
    const double m0[3][3] = {{sv[0], s[1], s[2]}, {sv[1], s[2], s[3]}, {sv[2], s[3], s[4]}};
    out[static_cast<size_t>(i)] = det3(m0) / det3(m);
  }
  return out;
}

// Eight discs (radius 7) round the frame's middle, each swinging 6 px to and fro along its own
// direction with its own phase at loop angle `a` (parts of a figure moving every which way),
// everything moved by `shift`.
cv::Mat swarm(double a, const std::array<double, 2>& shift) {
  cv::Mat f(kH, kW, CV_8UC3);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      double ink = 0;
      for (int k = 0; k < 8; ++k) {
        const double at = 2 * M_PI * k / 8, dir = 2.4 * k, swing = 6 * std::sin(a + 1.7 * k);
        const double cx = 80 + 38 * std::cos(at) + swing * std::cos(dir), cy = 60 + 30 * std::sin(at) + swing * std::sin(dir);
        ink = std::max(ink, edge(std::hypot(x + 0.5 - shift[0] - cx, y + 0.5 - shift[1] - cy) - 7));
      }
      const auto v = static_cast<uint8_t>(std::lround(255 * (1 - 0.8 * ink)));
      f.at<cv::Vec3b>(y, x) = {v, v, v};
    }
  return f;
}

double mean_abs_diff(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat d;
  cv::absdiff(a, b, d);
  return cv::mean(d)[0];
}

}  // namespace

TEST_SUITE("fit") {

TEST_CASE("stabilise: the shake of a jittered clip is its jitter minus the jitter's low-pass") {
  constexpr int N = 36;
  constexpr double sigma = 3;
  ShakeEstimator est(kW);
  std::vector<double> jx, jy;
  for (int i = 0; i < N; ++i) {
    // A slow deliberate drift of 0.25 px per frame to the right and a fall accelerating
    // downwards (a hop's second half) are motion, not shake.
    const auto j = jitter(i);
    jx.push_back(j[0]), jy.push_back(j[1]);
    est.add(figure(0.25 * i + j[0], 0.008 * i * i + j[1]));
  }
  const ShakeEstimate estimate = est.estimate(sigma);
  const auto& shake = estimate.shake;
  REQUIRE(shake.size() == N);
  CHECK_FALSE(estimate.loop);  // it drifts and falls: its last frame is not its first
  MESSAGE("model " << estimate.model << ", still share " << estimate.still_share << ", residual " << estimate.still_residual_px
                   << " px, low-pass ratio " << estimate.path_lowpass_ratio);
  const std::vector<double> lx = low_pass(jx, sigma), ly = low_pass(jy, sigma);
  double worst = 0, raw = 0;
  for (int i = 0; i < N; ++i) {
    // The estimator sees the drift and the fall too; its low-pass of a parabola is the
    // parabola, ends included.
    worst = std::max({worst, std::fabs(shake[static_cast<size_t>(i)][0] - (jx[static_cast<size_t>(i)] - lx[static_cast<size_t>(i)])),
                      std::fabs(shake[static_cast<size_t>(i)][1] - (jy[static_cast<size_t>(i)] - ly[static_cast<size_t>(i)]))});
    raw = std::max({raw, std::fabs(jx[static_cast<size_t>(i)]), std::fabs(jy[static_cast<size_t>(i)])});
  }
  MESSAGE("largest error of the shake estimate " << worst << " px (jitter up to " << raw << " px)");
  CHECK(raw > 1.0);
  CHECK(worst < 0.05);
}

TEST_CASE("stabilise: on a loop the low-pass runs round it and the last frame lands on the first") {
  // The whole figure circles once over the clip and the last frame is the first again, each
  // shaken by a white jitter: once rigidly (the registered figure is its own still part, model
  // still_smooth) and once with the bar swinging and the disc breathing (nothing holds still,
  // model smooth). At the clip's ends a low-pass leans on one side, so a straight clip's
  // estimate leaves up to a pixel of the shake there: the loop's seam would jump. Round the
  // loop, the last frame's shake is the first's plus the camera's move between them, measured
  // directly.
  constexpr int P = 36, N = P + 1;
  constexpr double kPi = 3.14159265358979323846;
  for (const bool deforms : {false, true}) {
    CAPTURE(deforms);
    ShakeEstimator est(kW);
    std::vector<cv::Mat> frames;
    std::vector<std::array<double, 2>> jit;
    for (int i = 0; i < N; ++i) {
      const double a = 2 * kPi * (i % P) / P, d = deforms ? 1.0 : 0.0;
      jit.push_back(white_jitter(i + 7));
      frames.push_back(figure(5 * std::sin(a) + jit.back()[0], 3 * (1 - std::cos(a)) + jit.back()[1],
                              d * 4 * std::sin(a), d * 2 * std::sin(2 * a), d * 2 * (1 - std::cos(a)), d * 0.2 * std::sin(a)));
      est.add(frames.back());
    }
    const ShakeEstimate e = est.estimate(3);
    REQUIRE(e.shake.size() == N);
    CHECK(e.loop);
    CHECK(e.model == (deforms ? "smooth" : "still_smooth"));
    for (int a = 0; a < 2; ++a) {
      const double truth = jit[N - 1][a] - jit[0][a];
      MESSAGE("axis " << a << ": camera's move first to last " << truth << " px, estimated " << e.shake[N - 1][a] - e.shake[0][a]);
      CHECK(std::fabs(truth) > 0.2);
      CHECK(std::fabs(e.shake[N - 1][a] - e.shake[0][a] - truth) < 0.05);
    }
    // The stabilised clip closes: its last frame is its first.
    const double seam = mean_abs_diff(remove_shake(frames[N - 1], e.shake[N - 1]), remove_shake(frames[0], e.shake[0]));
    const double step = mean_abs_diff(remove_shake(frames[1], e.shake[1]), remove_shake(frames[0], e.shake[0]));
    MESSAGE("stabilised seam " << seam << " against one step of the motion " << step << " (8-bit levels)");
    CHECK(seam < 0.1 * step);
  }
}

TEST_CASE("stabilise: on a loop the summed path is closed on the camera's own first-to-last move") {
  // A camera path round a loop (a circle, the figure's common motion, plus a white jitter),
  // measured as a sum of frame-to-frame steps that each err by the same small bias: a figure
  // that deforms pulls every registration a little the same way. Summed over 36 steps the bias
  // leaves the path's end 36 biases from where the last frame registers onto the first (the
  // closure), and read as periodic the path would jump by that much at the seam. Closed, it is
  // the true path exactly: a constant bias per step is a ramp, and the ramp is what is spread.
  constexpr int P = 36, N = P + 1;
  constexpr double kPi = 3.14159265358979323846;
  const std::array<double, 2> bias{0.07, -0.05};
  std::vector<std::array<double, 2>> truth, summed;
  for (int i = 0; i < N; ++i) {
    const double a = 2 * kPi * (i % P) / P;
    const auto j = white_jitter(i + 3);
    truth.push_back({5 * std::sin(a) + j[0], 3 * (1 - std::cos(a)) + j[1]});
    summed.push_back(i == 0 ? truth[0]
                            : std::array<double, 2>{summed.back()[0] + truth[i][0] - truth[i - 1][0] + bias[0],
                                                    summed.back()[1] + truth[i][1] - truth[i - 1][1] + bias[1]});
  }
  const std::array<double, 2> closure{truth[N - 1][0] - truth[0][0], truth[N - 1][1] - truth[0][1]};
  CHECK(std::fabs(summed[N - 1][0] - summed[0][0] - closure[0] - P * bias[0]) < 1e-12);
  const auto closed = close_loop(summed, closure);
  REQUIRE(closed.size() == N);
  double worst = 0;
  for (int i = 0; i < N; ++i)
    for (int a = 0; a < 2; ++a) worst = std::max(worst, std::fabs(closed[i][a] - truth[i][a]));
  CHECK(worst < 1e-12);
  CHECK(std::fabs(closed[N - 1][0] - closed[0][0] - closure[0]) < 1e-12);
  CHECK(std::fabs(closed[N - 1][1] - closed[0][1] - closure[1]) < 1e-12);
  // Fewer than two frames: nothing to spread.
  CHECK(close_loop({{1.0, 2.0}}, {5.0, 5.0}) == std::vector<std::array<double, 2>>{{1.0, 2.0}});
}

TEST_CASE("stabilise: when nothing holds, the figure's motion enters the camera path smoothly") {
  // The swarm's discs swing every which way round a loop (nothing holds still), every frame
  // shaken by a white jitter and coded as JPEG. The path's part above the low-pass's band is
  // the jitter's there plus whatever the step measurements add, and the steps blended from
  // tiles with fixed weights add next to nothing. (A whole-frame registration also passes on
  // this clip, 0.022 px; its step-to-step wobble shows on the non-rigid bench clips under
  // H.264, tests/bench/fit_nonrigid.sh -d jitter, which no synthetic clip here reproduced.)
  constexpr int P = 36, N = P + 1;
  constexpr double kPi = 3.14159265358979323846;
  ShakeEstimator est(kW);
  std::vector<std::array<double, 2>> jit;
  for (int i = 0; i < N; ++i) {
    const double a = 2 * kPi * (i % P) / P;
    jit.push_back(white_jitter(i + 11));
    std::vector<uint8_t> jpeg;  // a codec's noise, as a video model's clip has
    REQUIRE(cv::imencode(".jpg", swarm(a, jit.back()), jpeg, {cv::IMWRITE_JPEG_QUALITY, 40}));
    est.add(cv::imdecode(jpeg, cv::IMREAD_COLOR));
  }
  const ShakeEstimate e = est.estimate(3);
  REQUIRE(e.shake.size() == N);
  CHECK(e.model == "smooth");
  // Harmonics 6..18 of the loop (the band a 3-frame low-pass leaves nearly whole): the
  // estimate's there against the jitter's.
  auto high_band = [&](auto value) {
    std::vector<std::array<double, 2>> out(P, {0, 0});
    for (int k = 6; k <= P / 2; ++k)
      for (int a = 0; a < 2; ++a) {
        double c = 0, s = 0;
        for (int i = 0; i < P; ++i) c += value(i, a) * std::cos(2 * kPi * k * i / P), s += value(i, a) * std::sin(2 * kPi * k * i / P);
        const double scale = (k == P / 2 ? 1.0 : 2.0) / P;
        for (int i = 0; i < P; ++i) out[i][a] += scale * (c * std::cos(2 * kPi * k * i / P) + s * std::sin(2 * kPi * k * i / P));
      }
    return out;
  };
  const auto got = high_band([&](int i, int a) { return e.shake[i][a]; });
  const auto want = high_band([&](int i, int a) { return jit[i][a]; });
  double err = 0, size = 0;
  for (int i = 0; i < P; ++i)
    for (int a = 0; a < 2; ++a) err += (got[i][a] - want[i][a]) * (got[i][a] - want[i][a]) / P, size += want[i][a] * want[i][a] / P;
  MESSAGE("above the band: jitter " << std::sqrt(size) << " px rms, estimate off by " << std::sqrt(err));
  CHECK(std::sqrt(size) > 0.5);
  CHECK(std::sqrt(err) < 0.05);
}

TEST_CASE("stabilise: tile steps recover a translated clip's steps from rough starts") {
  // The swarm held in one pose and shaken: every tile moves by the camera's step, so the
  // blend is that step, whatever the start (here 0.4 px off each way) and the tiles' weights.
  constexpr int N = 8;
  std::vector<cv::Mat> inks;
  std::vector<std::array<double, 2>> jit;
  for (int i = 0; i < N; ++i) {
    jit.push_back(white_jitter(i + 5));
    cv::Mat grey, ink;
    cv::cvtColor(swarm(0.7, jit.back()), grey, cv::COLOR_BGR2GRAY);
    grey.convertTo(ink, CV_32F, -1.0 / 255, 1.0);
    cv::GaussianBlur(ink, ink, cv::Size(), 1.0, 1.0, cv::BORDER_REPLICATE);
    inks.push_back(ink);
  }
  std::vector<std::optional<std::array<double, 2>>> starts;
  for (int i = 0; i + 1 < N; ++i) starts.push_back(std::array<double, 2>{jit[i + 1][0] - jit[i][0] + 0.4, jit[i + 1][1] - jit[i][1] - 0.4});
  starts[3] = std::nullopt;  // a step that did not register stays no motion
  TileStepBlend blend(inks[0].size());
  for (int i = 0; i + 1 < N; ++i) blend.add(inks[i], inks[i + 1], starts[i]);
  const auto steps = blend.steps();
  REQUIRE(steps);
  REQUIRE(steps->size() == N - 1);
  double worst = 0;
  for (int i = 0; i + 1 < N; ++i)
    for (int a = 0; a < 2; ++a)
      if (i == 3) CHECK((*steps)[3][a] == 0);
      else worst = std::max(worst, std::fabs((*steps)[i][a] - (jit[i + 1][a] - jit[i][a])));
  MESSAGE("largest step error " << worst << " px");
  CHECK(worst < 0.05);  // cubic resampling of one-pixel edges in 20-px tiles: a few hundredths
  // A blank clip has no texture to blend: nothing, and the caller keeps the whole-frame steps.
  const cv::Mat blank = cv::Mat::zeros(kH, kW, CV_32F);
  TileStepBlend plain(blank.size());
  for (int i = 0; i < 2; ++i) plain.add(blank, blank, std::array<double, 2>{0, 0});
  CHECK_FALSE(plain.steps());
}

TEST_CASE("stabilise: on a body that holds while a limb moves, the shake is the whole jitter") {
  // The disc holds; the bar swings 6 px to and fro and bobs (its own smooth motion); the camera
  // jitters. The still disc shows the jitter itself, about its mean (the first frame is shaken
  // too), not only what a low-pass leaves of it.
  constexpr int N = 36;
  ShakeEstimator est(kW);
  std::vector<std::array<double, 2>> j;
  std::array<double, 2> mean{0, 0};
  for (int i = 0; i < N; ++i) {
    j.push_back(white_jitter(i));
    mean[0] += j.back()[0] / N, mean[1] += j.back()[1] / N;
    const double phase = 2 * M_PI * i / (N - 1);
    est.add(figure(j.back()[0], j.back()[1], 6 * std::sin(phase), 3 * (1 - std::cos(phase))));
  }
  const ShakeEstimate e = est.estimate(3);
  MESSAGE("model " << e.model << ", still share " << e.still_share << ", residual " << e.still_residual_px << " px, low-pass ratio "
                   << e.path_lowpass_ratio);
  CHECK(e.model == "still");
  double worst = 0;
  for (int i = 0; i < N; ++i)
    for (int a = 0; a < 2; ++a)
      worst = std::max(worst, std::fabs(e.shake[static_cast<size_t>(i)][static_cast<size_t>(a)] - (j[static_cast<size_t>(i)][static_cast<size_t>(a)] - mean[static_cast<size_t>(a)])));
  MESSAGE("largest error of the shake estimate " << worst << " px");
  CHECK(worst < 0.05);

  // A disc that breathes (its radius grows 3 px and back) and a bar that turns 14 degrees to and
  // fro: nothing holds (nor moves by a translation alone), and the shake falls back to the
  // high-pass of the frame-to-frame path.
  ShakeEstimator moving(kW);
  for (int i = 0; i < N; ++i) {
    const double phase = 2 * M_PI * i / (N - 1);
    moving.add(figure(j[static_cast<size_t>(i)][0], j[static_cast<size_t>(i)][1], 0, 0, 3 * (1 - std::cos(phase)),
                      0.25 * std::sin(phase)));
  }
  const ShakeEstimate m = moving.estimate(3);
  MESSAGE("moving: model " << m.model << ", still share " << m.still_share << ", residual " << m.still_residual_px << " px");
  CHECK(m.model == "smooth");
}

TEST_CASE("stabilise: a still clip has no shake, and removing a known shake restores the frame") {
  ShakeEstimator est(kW);
  for (int i = 0; i < 10; ++i) est.add(figure(0, 0));
  for (const auto& s : est.shake(3)) CHECK(std::hypot(s[0], s[1]) < 1e-6);
  const cv::Mat clean = figure(0, 0), moved = figure(1.25, -0.75);
  const cv::Mat back = remove_shake(moved, {1.25, -0.75});
  const cv::Mat wrong = remove_shake(moved, {-1.25, 0.75});
  MESSAGE("mean |difference| after removal " << mean_abs_diff(back, clean) << ", before " << mean_abs_diff(moved, clean));
  CHECK(mean_abs_diff(back, clean) < 0.25 * mean_abs_diff(moved, clean));
  CHECK(mean_abs_diff(wrong, clean) > mean_abs_diff(moved, clean));
}

TEST_CASE("stabilise: load_target's keyframes of a shaking clip come back close to the clean clip") {
  test::TempDir dir("svgm_stabilise_test");
  // Two seconds at 24 fps (the low-pass's window, 0.2 s either way, needs frames on both sides).
  constexpr int N = 49, K = 7;
  for (int i = 0; i < N; ++i) {
    const auto j = jitter(i);
    char name[32];
    std::snprintf(name, sizeof name, "%03d.png", i);
    REQUIRE(cv::imwrite((dir.path / name).string(), figure(0.2 * i + j[0], j[1])));
  }
  TargetOptions opt;
  opt.keyframes = K;
  const TargetFrames plain = load_target(dir.path, kW, kH, opt);
  opt.stabilise = true;
  const TargetFrames steady = load_target(dir.path, kW, kH, opt);
  CHECK(plain.max_shake_px == 0);
  CHECK(steady.max_shake_px > 0.5);
  // Distance of each keyframe (raw, before cleanup) to the clean clip's frame at its time.
  const size_t px = static_cast<size_t>(kW) * kH;
  double err_plain = 0, err_steady = 0;
  for (int k = 1; k + 1 < K; ++k) {  // inner keyframes: the low-pass is two-sided there
    const int i = steady.source_index[static_cast<size_t>(k)];
    cv::Mat clean;
    figure(0.2 * i, 0).convertTo(clean, CV_32FC3, 1.0 / 255);
    auto dist = [&](const TargetFrames& t) {
      double s = 0;
      for (size_t p = 0; p < px; ++p) {
        const cv::Vec3f c = clean.at<cv::Vec3f>(static_cast<int>(p / kW), static_cast<int>(p % kW));
        // raw is RGB, the frame BGR
        for (int ch = 0; ch < 3; ++ch) s += std::fabs(t.raw[(k * px + p) * 4 + ch] - c[2 - ch]);
      }
      return s / (3.0 * px);
    };
    err_plain += dist(plain), err_steady += dist(steady);
  }
  MESSAGE("mean |keyframe - clean|: " << err_plain << " as decoded, " << err_steady << " stabilised");
  CHECK(err_steady < 0.5 * err_plain);

  // A second load (the refinement's) reuses the first load's camera path: the same shake for
  // every frame and the same keyframes, without measuring again.
  REQUIRE(steady.frame_shake.size() == N);
  opt.shake_from = &steady;
  const TargetFrames again = load_target(dir.path, kW, kH, opt);
  CHECK(again.frame_shake == steady.frame_shake);
  CHECK(again.shake_model == steady.shake_model);
  CHECK(again.raw == steady.raw);
}

}  // TEST_SUITE
