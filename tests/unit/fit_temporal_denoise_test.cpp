// Temporal denoising of the sampled frames (fit/target/temporal_denoise.h), on an analytic figure (a
// disc with a one-pixel soft edge) moving a known sub-pixel distance per frame, with independent
// noise in every frame: the average of five aligned frames has about a fifth of one frame's noise
// variance, the disc stays where the keyframe shows it (no smear from the motion), a neighbour
// that shows something else is left out, the window hands back exactly the wanted frames once
// their neighbours are in, and load_target with `denoise_radius` gives keyframes closer to the
// clean clip than as decoded.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "fit/target/deflated_bytes.h"
#include "fit/target/temporal_denoise.h"
#include "svgmotion/target_video.h"

#include "temp_dir.h"

using namespace svgm;

namespace {

constexpr int kW = 128, kH = 96;

// Light grey RGB float frame with a dark blue-green disc of radius 20 centred at (cx, cy), its edge
// linear over one pixel, plus Gaussian noise of standard deviation `sigma` from `seed`.
cv::Mat disc(double cx, double cy, double sigma, int seed) {
  cv::Mat f(kH, kW, CV_32FC3);
  cv::RNG rng(static_cast<uint64_t>(seed) + 1);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const double ink = std::clamp(0.5 - (std::hypot(x + 0.5 - cx, y + 0.5 - cy) - 20), 0.0, 1.0);
      // A light grey paper (0.95, not 1): noise on white would be clipped to one side when
      // stored in 8 bits, a bias no average removes.
      cv::Vec3f v(static_cast<float>(0.95 - 0.85 * ink), static_cast<float>(0.95 - 0.4 * ink), static_cast<float>(0.95 - 0.7 * ink));
      for (int c = 0; c < 3; ++c) v[c] += static_cast<float>(rng.gaussian(sigma));
      f.at<cv::Vec3f>(y, x) = v;
    }
  return f;
}

double rms_diff(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat d;
  cv::absdiff(a, b, d);
  d = d.mul(d);
  const cv::Scalar s = cv::mean(d);
  return std::sqrt((s[0] + s[1] + s[2]) / 3);
}

// The ink's centroid (1 - red channel, the disc's strongest), for where the disc is. Ink below
// 0.1 does not count: the background's leftover noise (0.007 rms) would pull the centroid
// towards the frame's centre.
cv::Point2d centroid(const cv::Mat& f) {
  double sx = 0, sy = 0, s = 0;
  for (int y = 0; y < f.rows; ++y)
    for (int x = 0; x < f.cols; ++x) {
      const double ink = std::max(0.0, 0.85 - f.at<cv::Vec3f>(y, x)[0]);
      sx += ink * (x + 0.5), sy += ink * (y + 0.5), s += ink;
    }
  return {sx / s, sy / s};
}

}  // namespace

TEST_SUITE("fit") {

TEST_CASE("temporal denoise: five aligned frames of a moving disc keep about a fifth of the noise variance") {
  constexpr double sigma = 0.02, step = 1.3;  // px per frame, along x and half as much along y
  std::vector<cv::Mat> frames;
  for (int i = 0; i < 5; ++i) frames.push_back(disc(50 + step * i, 45 + 0.5 * step * i, sigma, i));
  const cv::Mat clean = disc(50 + 2 * step, 45 + step, 0, 0);
  const std::vector<const cv::Mat*> near{&frames[0], &frames[1], &frames[3], &frames[4]};
  const cv::Mat avg = average_aligned(frames[2], near);
  const double before = rms_diff(frames[2], clean), after = rms_diff(avg, clean);
  MESSAGE("rms error against the clean frame: " << before << " decoded, " << after << " averaged");
  // Pure noise would fall to 1/sqrt(5) = 0.45 of itself; the flow's sub-pixel error at the
  // edge adds a little.
  CHECK(after < 0.55 * before);
  // The disc stays where the middle frame shows it: the neighbours were moved onto it, not
  // averaged where they were (that would drag the centroid by up to 2.6 px).
  const cv::Point2d c = centroid(avg), c0 = centroid(clean);
  MESSAGE("centroid " << c.x << ", " << c.y << " against " << c0.x << ", " << c0.y);
  CHECK(std::fabs(c.x - c0.x) < 0.05);
  CHECK(std::fabs(c.y - c0.y) < 0.05);
}

TEST_CASE("temporal denoise: a neighbour that shows something else is left out") {
  const cv::Mat centre = disc(60, 48, 0, 0);
  cv::Mat other = disc(60, 48, 0, 0);
  // A dark square the keyframe does not have (an occluder passing, a cut).
  other(cv::Rect(8, 8, 24, 24)).setTo(cv::Scalar(0.1, 0.1, 0.1));
  const cv::Mat avg = average_aligned(centre, {&other});
  cv::Mat a = avg(cv::Rect(12, 12, 16, 16)), c = centre(cv::Rect(12, 12, 16, 16));
  MESSAGE("rms difference inside the square: " << rms_diff(a, c));
  CHECK(rms_diff(a, c) < 0.01);  // a plain average would be 0.45 off there
  CHECK(rms_diff(avg, centre) < 0.01);
}

TEST_CASE("temporal denoise: the window hands back each wanted frame once its neighbours are in") {
  TemporalDenoiser d(2, {0, 5, 12});
  // Needed: 0..2, 3..7, 10..14; not 8, 9 (out of every wanted frame's reach).
  for (int i : {0, 1, 2, 3, 7, 10, 14}) CHECK(d.needs(i));
  for (int i : {8, 9, 15}) CHECK_FALSE(d.needs(i));
  std::vector<int> back, when;
  for (int i = 0; i < 16; ++i) {
    if (!d.needs(i)) continue;
    for (const auto& [index, frame] : d.push(i, disc(40 + i, 48, 0.01, i))) {
      back.push_back(index);
      when.push_back(i);
      CHECK(frame.size() == cv::Size(kW, kH));
    }
  }
  CHECK(back == std::vector<int>{0, 5, 12});
  CHECK(when == std::vector<int>{2, 7, 14});  // each as soon as its second later neighbour came
  CHECK(d.finish().empty());

  // A clip that ends before a wanted frame's later neighbours: finish hands it back.
  TemporalDenoiser e(2, {0, 3});
  CHECK(e.push(0, disc(40, 48, 0.01, 0)).empty());
  CHECK(e.push(1, disc(41, 48, 0.01, 1)).empty());
  CHECK(e.push(2, disc(42, 48, 0.01, 2)).size() == 1);
  CHECK(e.push(3, disc(43, 48, 0.01, 3)).empty());
  const auto rest = e.finish();
  REQUIRE(rest.size() == 1);
  CHECK(rest[0].first == 3);
}

TEST_CASE("temporal denoise: load_target's denoised keyframes are closer to the clean clip") {
  test::TempDir dir("svgm_denoise_test");
  constexpr int N = 25, K = 5;
  for (int i = 0; i < N; ++i) {
    cv::Mat f8;
    disc(30 + 1.3 * i, 48, 0.02, i).convertTo(f8, CV_8UC3, 255.0);
    char name[32];
    std::snprintf(name, sizeof name, "%03d.png", i);
    // disc() is RGB; imwrite takes BGR: swap so the file shows the same colours.
    cv::cvtColor(f8, f8, cv::COLOR_RGB2BGR);
    REQUIRE(cv::imwrite((dir.path / name).string(), f8));
  }
  TargetOptions opt;
  opt.keyframes = K;
  const TargetFrames plain = load_target(dir.path, kW, kH, opt);
  opt.denoise_radius = 2;
  const TargetFrames calm = load_target(dir.path, kW, kH, opt);
  CHECK(calm.source_index == plain.source_index);
  const size_t px = static_cast<size_t>(kW) * kH;
  for (int k = 0; k < K; ++k) {
    const int i = plain.source_index[static_cast<size_t>(k)];
    const cv::Mat clean = disc(30 + 1.3 * i, 48, 0, 0);
    auto err = [&](const TargetFrames& t) {
      double s = 0;
      for (size_t p = 0; p < px; ++p)
        for (int ch = 0; ch < 3; ++ch) {
          const double d = t.raw[(k * px + p) * 4 + ch] - clean.at<cv::Vec3f>(static_cast<int>(p / kW), static_cast<int>(p % kW))[ch];
          s += d * d;
        }
      return std::sqrt(s / (3.0 * px));
    };
    MESSAGE("keyframe " << k << " (frame " << i << "): rms " << err(plain) << " decoded, " << err(calm) << " denoised");
    // The end keyframes have two neighbours, not four.
    CHECK(err(calm) < (k == 0 || k == K - 1 ? 0.7 : 0.6) * err(plain));
  }
  // Same inputs, same bits.
  const TargetFrames again = load_target(dir.path, kW, kH, opt);
  CHECK(again.raw == calm.raw);

  // A load at half the width keeps its denoised keyframes (made at the frames' own size, which
  // is at most twice its width); a second load at full width reuses them and gives exactly what
  // decoding and aligning again gives.
  TargetOptions half = opt;
  half.keep_denoised = true;
  TargetFrames coarse = load_target(dir.path, kW / 2, kH / 2, half);
  CHECK(coarse.denoised_width == kW);
  REQUIRE(coarse.denoised.size() == static_cast<size_t>(K));
  // Held deflated by byte planes: each inflates to exactly a frame's floats, and is smaller.
  std::vector<float> inflated(px * 3);
  for (const std::vector<uint8_t>& d : coarse.denoised) {
    CHECK(d.size() < px * 3 * sizeof(float));
    CHECK_NOTHROW(inflate_floats(d, inflated.data(), px * 3));
    CHECK_THROWS(inflate_floats(d, inflated.data(), px * 3 - 1));
  }
  CHECK(coarse.denoised_frame == coarse.source_index);
  TargetOptions reuse = opt;
  reuse.denoised_from = &coarse;
  const TargetFrames fine = load_target(dir.path, kW, kH, reuse);
  CHECK(fine.raw == calm.raw);
  CHECK(fine.denoise_seconds == 0);  // nothing aligned a second time
  CHECK(coarse.denoised.empty());     // taken by the second load, each keyframe freed as stored
  CHECK(calm.denoise_seconds > 0);
}

}  // TEST_SUITE
