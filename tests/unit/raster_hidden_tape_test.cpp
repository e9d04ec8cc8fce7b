// Tape entries of draws hidden at their pixel (kernels/raster_backward.cl, drop_hidden_entries):
// raster_taped keeps them out of the pool, since raster_backward gives them ∂L/∂a = 0 exactly.
// A circle wholly under an opaque square adds no entry to the pool, gets a zero gradient, and
// leaves the square's gradient bit for bit what it is without the circle; the pool's tapes
// (hidden entries dropped) and the backward's replay (every entry) give the same bits.
#include <doctest/doctest.h>

#include <cstring>

#include "raster_test_support.h"
#include "scene_builders.h"

using namespace svgm;
using namespace svgm::test;

namespace {

constexpr int kW = 40, kH = 32, kFrames = 2;

struct Pass {
  std::vector<float> grad;  // ∂L/∂(control points), every frame
  float loss = 0;
  int pool_entries = 0;
};

// The scene's loss pass with every frame a shift of (0.5 (k + 1), 0.25) px, against targets
// shifted by (1.25 (k + 1), 0.25); `pool` >= 0 sets the tape pool's capacity first (0: every
// band replays its tape in the backward pass).
Pass loss_pass(const Scene& scene, int pool = -1) {
  const RasterPlan plan = plan_raster(scene, Affine{}, kW, kH);
  const std::vector<float> targets = targets_on_white(plan, kFrames, 1.25f, 0.25f);
  ClRaster r(runtime(), plan, kFrames);
  r.set_control_points(shifted_cp(plan, kFrames, 0.5f, 0.25f));
  r.set_targets(targets);
  if (pool >= 0) r.set_tape_pool_capacity(pool);
  Pass p;
  p.loss = r.loss_and_gradient(1000.0f, {1, 1, 1, 1});
  p.grad = r.read_cp_gradient();
  p.pool_entries = r.tape_pool_entries();
  return p;
}

Path square() { return filled(polygon({{6, 3}, {34, 3}, {34, 29}, {6, 29}}), {0.1f, 0.3f, 0.8f, 1}); }

}  // namespace

TEST_SUITE("raster") {

TEST_CASE("a circle under an opaque square: no tape entry in the pool, a zero gradient, the square's bits unchanged") {
  // The circle (radius 6 about (20, 16)) lies 6 px and more inside the square at every shift:
  // every pixel its edges cross is covered by the square, coverage 1, alpha 1.
  const Scene hidden = scene_of(kW, kH, {filled(circle({20, 16}, 6), {0.9f, 0.2f, 0.1f, 1}), square()});
  const Scene alone = scene_of(kW, kH, {square()});
  const Pass h = loss_pass(hidden), a = loss_pass(alone);
  MESSAGE("pool entries: " << h.pool_entries << " with the hidden circle, " << a.pool_entries << " without");
  CHECK(a.pool_entries > 0);
  CHECK(h.pool_entries == a.pool_entries);
  CHECK(h.loss == a.loss);
  // Per frame: the circle's control points, then the square's, then 3 padding points.
  const size_t per_h = h.grad.size() / kFrames, per_a = a.grad.size() / kFrames;
  const size_t circle = per_h - per_a;
  REQUIRE(circle > 0);
  double square_norm = 0;
  for (int k = 0; k < kFrames; ++k) {
    const float* gh = h.grad.data() + k * per_h;
    const float* ga = a.grad.data() + k * per_a;
    for (size_t i = 0; i < circle; ++i) CHECK(gh[i] == 0.0f);
    CHECK(std::memcmp(gh + circle, ga, per_a * sizeof(float)) == 0);
    for (size_t i = 0; i < per_a; ++i) square_norm += double(ga[i]) * ga[i];
  }
  CHECK(square_norm > 0);
}

TEST_CASE("hidden entries dropped from the pool: the same bits as the backward pass's replay of every entry") {
  // Three layers: a triangle whose right part runs under an opaque circle, which runs under a
  // half-transparent band: some of the triangle's edge pixels are hidden, some seen.
  const Scene s = scene_of(kW, kH, {filled(polygon({{2, 4}, {30, 10}, {8, 28}}), {0.2f, 0.7f, 0.3f, 1}),
                                    filled(circle({24, 16}, 9), {0.9f, 0.2f, 0.1f, 1}),
                                    filled(polygon({{0, 12}, {40, 12}, {40, 19}, {0, 19}}), {0.1f, 0.1f, 0.1f, 0.5f})});
  const Pass pooled = loss_pass(s), replayed = loss_pass(s, 0);
  CHECK(pooled.loss == replayed.loss);
  CHECK(same_bits(pooled.grad, replayed.grad));
  double norm = 0;
  for (float v : pooled.grad) norm += double(v) * v;
  CHECK(norm > 0);
}

}  // TEST_SUITE
