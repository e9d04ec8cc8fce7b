// The loss's memory (ClRaster::set_targets, release_loss_buffers, set_loss_chunk_frames): the
// raster keeps no copy of the targets, frees its pixel-sized loss buffers on request and holds
// the residuals of a few frames at a time, and none of it changes a bit of the loss or the
// gradient; renders of a few frames (render_frames) hold only those frames, with their bits, and
// a caller drawing frame after frame (render_frames_into) reuses one image until release_image.
#include <doctest/doctest.h>

#include <cstring>
#include <string>

#include "raster_test_support.h"
#include "scene_builders.h"
#include "svgmotion/error.h"

using namespace svgm;
using namespace svgm::test;

namespace {

constexpr int kW = 40, kH = 32, kK = 3;
constexpr float kWeight = 1000.0f;  // the paper's image-loss weight
const std::array<float, 4> kWhite{1, 1, 1, 1};

Scene two_shapes() {
  return scene_of(kW, kH, {filled(circle({20, 16}, 9), {0.9f, 0.2f, 0.1f, 1}),
                           filled(polygon({{3, 4}, {30, 6}, {14, 28}}), {0.1f, 0.3f, 0.8f, 0.6f})});
}

// Every frame active, at the control points shifted by a growing amount per frame.
void pose_shifted(ClRaster& r, const RasterPlan& plan) {
  r.set_control_points(shifted_cp(plan, kK, 0.5f, 0.75f));
  r.set_active_frames(kK);
}

// The loss then the gradient, as one vector of bits to compare.
std::vector<float> pass(ClRaster& r) {
  const float loss = r.loss_and_gradient(kWeight, kWhite);
  std::vector<float> out = r.read_cp_gradient();
  out.push_back(loss);
  return out;
}

}  // namespace

TEST_SUITE("raster") {

TEST_CASE("released loss buffers: device bytes fall by their size, and the next pass makes them again with identical bits") {
  const RasterPlan plan = plan_raster(two_shapes(), Affine{}, kW, kH);
  const std::vector<float> targets = targets_on_white(plan, kK, 2.5f, -1.25f);
  ClRaster r(runtime(), plan, kK);
  pose_shifted(r, plan);
  r.set_targets(targets);
  const std::vector<float> first = pass(r);
  const std::vector<float> losses = r.read_frame_losses();
  const size_t held = r.device_bytes();
  REQUIRE(r.holds_loss_buffers());

  r.release_loss_buffers();
  CHECK_FALSE(r.holds_loss_buffers());
  // Q and R are 8 bytes per pixel and frame each (four halves), the residual 16; the pool and
  // the partial gradients come on top.
  const size_t pixel_bytes = size_t{kK} * kW * kH * (8 + 8 + 16);
  CHECK(held - r.device_bytes() > pixel_bytes);
  // The last pass's losses are still readable (the report reads them after the release).
  CHECK(same_bits(r.read_frame_losses(), losses));
  r.release_loss_buffers();  // a second release is a no-op
  CHECK_FALSE(r.holds_loss_buffers());

  const std::vector<float> again = pass(r);
  CHECK(r.holds_loss_buffers());
  CHECK(r.device_bytes() == held);
  CHECK(same_bits(first, again));
  double norm = 0;
  for (size_t i = 0; i + 1 < first.size(); ++i) norm += first[i] * first[i];
  CHECK(norm > 0);
}

TEST_CASE("set_targets keeps no copy: the loss's constants are made from the caller's frames on the next pass") {
  const RasterPlan plan = plan_raster(two_shapes(), Affine{}, kW, kH);
  std::vector<float> targets = targets_on_white(plan, kK, 2.5f, -1.25f);
  const std::vector<float> other = targets_on_white(plan, kK, -3.0f, 2.0f);
  const std::vector<float> cp = shifted_cp(plan, kK, 0.5f, 0.75f);
  ClRaster r(runtime(), plan, kK);
  r.set_control_points(cp);
  r.set_active_frames(kK);
  r.set_targets(targets);
  const std::vector<float> before = pass(r);
  // The caller's frames change; the next pass after a release sees the new ones, exactly as a
  // raster given them from the start does.
  targets = other;
  r.release_loss_buffers();
  const std::vector<float> after = pass(r);
  ClRaster fresh(runtime(), plan, kK);
  fresh.set_control_points(cp);
  fresh.set_active_frames(kK);
  fresh.set_targets(other);
  CHECK(same_bits(after, pass(fresh)));
  CHECK_FALSE(same_bits(before, after));
  // Frames gone from under it: an internal error naming the cause, not a read past the end.
  targets.clear();
  r.release_loss_buffers();
  CHECK_THROWS_WITH_AS(r.loss_and_gradient(kWeight, kWhite),
                       "internal: the loss's targets are gone or resized (set_targets keeps no copy)", Error);
}

TEST_CASE("loss chunks: one, two or every frame at a time give the same bits, and X' and E' are held for a chunk only") {
  const RasterPlan plan = plan_raster(two_shapes(), Affine{}, kW, kH);
  const std::vector<float> targets = targets_on_white(plan, kK, 2.5f, -1.25f);
  const std::vector<float> cp = shifted_cp(plan, kK, 0.5f, 0.75f);
  // The plain loss, and the chroma-weighted one with a chroma blur of its own (the matched
  // build's YCbCr passes, raster/loss_blur.h, index X' and E' on their own lines).
  for (const auto& [chroma_sigma, chroma_weight] : {std::pair{0.0, 1.0}, std::pair{1.6, 0.25}}) {
    CAPTURE(chroma_weight);
    std::vector<float> bits[3], losses[3];
    size_t bytes[3] = {};
    for (int chunk = 1; chunk <= kK; ++chunk) {
      ClRaster r(runtime(), plan, kK, kLossSigma, chroma_sigma, chroma_weight);
      r.set_control_points(cp);
      r.set_active_frames(kK);
      r.set_targets(targets);
      r.set_loss_chunk_frames(chunk);
      CHECK(r.loss_chunk_frames() == chunk);
      bits[chunk - 1] = pass(r);
      losses[chunk - 1] = r.read_frame_losses();
      bytes[chunk - 1] = r.device_bytes();
      // Fewer active frames than a chunk holds (2 of them in chunks of 3, or a chunk of 2 then
      // one of 1 cut to 2): each frame's loss is the one it has among all three.
      r.set_active_frames(2);
      (void)r.loss_and_gradient(kWeight, kWhite);
      const std::vector<float> two = r.read_frame_losses();
      REQUIRE(two.size() == 2);
      CHECK(two[0] * 2 == doctest::Approx(losses[chunk - 1][0] * 3));
      CHECK(two[1] * 2 == doctest::Approx(losses[chunk - 1][1] * 3));
    }
    CHECK(same_bits(bits[0], bits[1]));
    CHECK(same_bits(bits[0], bits[2]));
    CHECK(same_bits(losses[0], losses[1]));
    CHECK(same_bits(losses[0], losses[2]));
    CHECK(losses[0][0] > 0);
    CHECK(losses[0][2] > losses[0][0]);  // the frames differ (the shift grows with the frame)
    // Each frame more in a chunk is one more frame of X' and E': 2 x 12 bytes per pixel
    // (packed RGB floats, kernels/loss.cl), and of the lines' partial gradients: 4 floats a
    // line a band (bands of 16 rows, raster_cl.h; gather_line_grads sums them chunk by chunk).
    const size_t bands = (kH + 15) / 16;
    const size_t frame = size_t{kW} * kH * 24 + size_t(plan.n_lines) * bands * 16;
    CHECK(bytes[1] - bytes[0] == frame);
    CHECK(bytes[2] - bytes[0] == 2 * frame);
  }
}

TEST_CASE("release_image: the Float renders' buffer goes once read, and the next render makes it again with the same bits") {
  const RasterPlan plan = plan_raster(two_shapes(), Affine{}, kW, kH);
  ClRaster r(runtime(), plan, kK);
  pose_shifted(r, plan);
  const size_t before = r.device_bytes();
  r.forward();
  const std::vector<float> first = r.read_image();
  CHECK(r.device_bytes() - before == size_t{kK} * kW * kH * 16);
  r.release_image();
  CHECK(r.device_bytes() == before);
  CHECK_THROWS_WITH_AS(r.read_image(), "internal: read_image before a Float forward pass", Error);
  r.release_image();  // a second release is a no-op
  r.forward();
  CHECK(same_bits(r.read_image(), first));
}

TEST_CASE("render_frames: a chunk of frames alone has the bits a Float forward of every frame gives them, and holds nothing after") {
  const RasterPlan plan = plan_raster(two_shapes(), Affine{}, kW, kH);
  ClRaster r(runtime(), plan, kK);
  pose_shifted(r, plan);
  r.forward();
  const std::vector<float> all = r.read_image();
  r.release_image();
  const size_t before = r.device_bytes();
  const size_t frame = size_t{kW} * kH * 4;
  for (int first = 0; first < kK; ++first)
    for (int count = 1; first + count <= kK; ++count) {
      CAPTURE(first);
      CAPTURE(count);
      const std::vector<float> part = r.render_frames(first, count, {0, 0, 0, 0});
      const std::vector<float> want(all.begin() + static_cast<std::ptrdiff_t>(first * frame),
                                    all.begin() + static_cast<std::ptrdiff_t>((first + count) * frame));
      CHECK(same_bits(part, want));
      CHECK(r.device_bytes() == before);  // its output is gone once read
    }
  // Frames are drawn whatever the active count (the fitter's final renders of any keyframe).
  r.set_active_frames(1);
  CHECK(same_bits(r.render_frames(2, 1, {0, 0, 0, 0}),
                  std::vector<float>(all.begin() + static_cast<std::ptrdiff_t>(2 * frame), all.end())));
  CHECK_THROWS_WITH_AS(r.render_frames(2, 2, {0, 0, 0, 0}), "internal: render_frames of frames 2..3 outside 0..2", Error);
  // And they differ from frame to frame (the test would pass on one frame drawn three times otherwise).
  CHECK_FALSE(same_bits(r.render_frames(0, 1, {0, 0, 0, 0}), r.render_frames(1, 1, {0, 0, 0, 0})));
}

TEST_CASE("render_frames_into: frame after frame through one kept image, the same bits, freed by release_image") {
  const RasterPlan plan = plan_raster(two_shapes(), Affine{}, kW, kH);
  ClRaster r(runtime(), plan, kK);
  pose_shifted(r, plan);
  const size_t before = r.device_bytes();
  const size_t frame_bytes = size_t{kW} * kH * 4 * sizeof(float);
  std::vector<float> out;
  for (int f = 0; f < kK; ++f) {
    CAPTURE(f);
    r.render_frames_into(f, 1, {1, 1, 1, 1}, out);
    CHECK(same_bits(out, r.render_frames(f, 1, {1, 1, 1, 1})));
    CHECK(r.device_bytes() == before + frame_bytes);  // one frame's image, kept
  }
  // Another count makes the image again at its size; the host vector is resized.
  r.render_frames_into(1, 2, {0, 0, 0, 0}, out);
  CHECK(out.size() == 2 * frame_bytes / sizeof(float));
  CHECK(same_bits(out, r.render_frames(1, 2, {0, 0, 0, 0})));
  CHECK(r.device_bytes() == before + 2 * frame_bytes);
  r.release_image();
  CHECK(r.device_bytes() == before);
  CHECK_THROWS_WITH_AS(r.render_frames_into(3, 1, {0, 0, 0, 0}, out), "internal: render_frames of frames 3..3 outside 0..2", Error);
}

TEST_CASE("loss chunks: a chunk of no frames is refused") {
  const RasterPlan plan = plan_raster(two_shapes(), Affine{}, kW, kH);
  ClRaster r(runtime(), plan, kK);
  CHECK_THROWS_WITH_AS(r.set_loss_chunk_frames(0), "internal: loss chunk of 0 frames", Error);
}

}  // TEST_SUITE
