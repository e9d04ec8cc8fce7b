// The loss's constants Q and R by tiles (raster/loss_tiles.h, kernels/loss.cl's
// loss_tile_pixel): which tiles a frame stores, where each pixel lands, and that the tiled
// layout gives the loss and the gradient bit for bit as the layout storing every tile does,
// while holding fewer tiles when the target is white far from its figure.
#include <doctest/doctest.h>

#include <cstring>

#include "raster/loss_tiles.h"
#include "raster_test_support.h"
#include "scene_builders.h"

using namespace svgm;
using namespace svgm::test;

namespace {

constexpr int T = kLossTile;

// W x H pixels of four halves, every one `v` (Q) and `v + 1` (R) in the three colours.
struct Frame {
  int W, H;
  std::vector<uint16_t> q, r;
  Frame(int w, int h, uint16_t v) : W(w), H(h), q(size_t(w) * h * 4, 0), r(q.size(), 0) {
    for (size_t p = 0; p < q.size(); p += 4)
      for (int c = 0; c < 3; ++c) set(p / 4 % w, p / 4 / w, v);
  }
  void set(size_t x, size_t y, uint16_t v) {
    for (int c = 0; c < 3; ++c) {
      q[(y * W + x) * 4 + c] = v;
      r[(y * W + x) * 4 + c] = static_cast<uint16_t>(v + 1);
    }
  }
};

// Frame pixel (x, y)'s Q halves as the device finds them (loss.cl's loss_tile_pixel, with each
// uniform tile's value as a pixel of its own).
std::array<uint16_t, 4> q_at(const LossTiles& t, int x, int y) {
  const int s = t.tile[static_cast<size_t>(y / T) * t.tiles_x + x / T];
  if (s < 0) {
    const auto& v = t.values[static_cast<size_t>(-1 - s)];
    return {v[0], v[1], v[2], v[3]};
  }
  std::array<uint16_t, 4> v;
  std::memcpy(v.data(), &t.q[(static_cast<size_t>(s) * T * T + (y % T) * T + x % T) * 4], sizeof v);
  return v;
}

constexpr int kW = 128, kH = 96, kK = 3;
const std::array<float, 4> kWhite{1, 1, 1, 1};

// A small figure in the middle of white paper, moved by (dx, dy) per frame.
Scene figure() {
  return scene_of(kW, kH, {filled(circle({64, 48}, 10), {0.9f, 0.2f, 0.1f, 1}),
                           filled(polygon({{56, 40}, {74, 44}, {62, 60}}), {0.1f, 0.3f, 0.8f, 0.6f})});
}

// One loss-and-gradient pass with the uniform tiles held as values (`every` false) or every tile
// stored: the gradient with the loss after it, the frame losses, the tiles stored, the device bytes.
struct TiledPass {
  std::vector<float> bits, losses;
  size_t stored = 0, bytes = 0;
};
TiledPass tiled_pass(const RasterPlan& plan, const std::vector<float>& targets, const std::vector<float>& cp, double chroma_sigma,
                     double chroma_weight, bool every) {
  ClRaster r(runtime(), plan, kK, kLossSigma, chroma_sigma, chroma_weight);
  r.set_every_loss_tile(every);
  r.set_control_points(cp);
  r.set_active_frames(kK);
  r.set_targets(targets);
  const float loss = r.loss_and_gradient(1000.0f, kWhite);
  TiledPass out{r.read_cp_gradient(), r.read_frame_losses(), r.loss_tiles_stored(), r.device_bytes()};
  out.bits.push_back(loss);
  return out;
}

}  // namespace

TEST_SUITE("raster") {

TEST_CASE("tile_loss_frame: uniform tiles are held as their values, the commonest first; each pixel reads its own halves") {
  // 40 x 20: tiles 3 x 2, the last column 8 pixels wide, the last row 4 high.
  Frame f(40, 20, 7);
  f.set(20, 3, 9);   // tile (1, 0) differs inside
  f.set(39, 19, 5);  // the corner tile (2, 1), partial, differs at its last pixel
  const LossTiles t = tile_loss_frame(f.q.data(), f.r.data(), f.W, f.H);
  CHECK(t.tiles_x == 3);
  CHECK(t.tiles_y == 2);
  CHECK(t.tile == std::vector<int>{-1, 0, -1, -1, -1, 1});
  CHECK(t.stored() == 2);
  CHECK(t.values == std::vector<std::array<uint16_t, 8>>{{7, 7, 7, 0, 8, 8, 8, 0}});
  for (int y = 0; y < f.H; ++y)
    for (int x = 0; x < f.W; ++x) {
      std::array<uint16_t, 4> want;
      std::memcpy(want.data(), &f.q[(static_cast<size_t>(y) * f.W + x) * 4], sizeof want);
      REQUIRE(q_at(t, x, y) == want);
    }
  // Pixels of a stored tile outside the frame are zero.
  CHECK(t.q[(size_t(1) * T * T + 4 * T + 0) * 4] == 0);  // tile (2, 1), row 4: below the frame
  CHECK(t.q[(size_t(1) * T * T + 0 * T + 8) * 4] == 0);  // tile (2, 1), column 8: right of it

  // A uniform tile of another value is held as that value too (a flat fill's inside), after
  // the commonest; every_tile stores all of them in order.
  Frame g(40, 20, 7);
  for (int y = 16; y < 20; ++y)
    for (int x = 0; x < 16; ++x) g.set(x, y, 3);  // tile (0, 1), all 3
  const LossTiles u = tile_loss_frame(g.q.data(), g.r.data(), g.W, g.H);
  CHECK(u.tile == std::vector<int>{-1, -1, -1, -2, -1, -1});
  CHECK(u.stored() == 0);
  CHECK(u.values == std::vector<std::array<uint16_t, 8>>{{7, 7, 7, 0, 8, 8, 8, 0}, {3, 3, 3, 0, 4, 4, 4, 0}});
  const LossTiles every = tile_loss_frame(g.q.data(), g.r.data(), g.W, g.H, true);
  CHECK(every.tile == std::vector<int>{0, 1, 2, 3, 4, 5});
  for (int y = 0; y < g.H; ++y)
    for (int x = 0; x < g.W; ++x) REQUIRE(q_at(every, x, y) == q_at(u, x, y));
}

TEST_CASE("tiled Q and R: the same loss, frame losses and gradient bits as every tile stored, from fewer tiles") {
  const RasterPlan plan = plan_raster(figure(), Affine{}, kW, kH);
  const std::vector<float> targets = targets_on_white(plan, kK, 2.5f, -1.25f);
  const std::vector<float> cp = shifted_cp(plan, kK, 0.5f, 0.75f);
  const size_t tiles = size_t{kK} * (kW / T) * (kH / T);
  // The plain loss, and the chroma-weighted one with a chroma blur of its own (R and Q then
  // go through the per-group blur and the metric).
  for (const auto& [chroma_sigma, chroma_weight] : {std::pair{0.0, 1.0}, std::pair{1.6, 0.25}}) {
    CAPTURE(chroma_weight);
    std::vector<float> bits[2], losses[2];
    size_t stored[2] = {}, bytes[2] = {};
    for (int every = 0; every < 2; ++every) {
      TiledPass t = tiled_pass(plan, targets, cp, chroma_sigma, chroma_weight, every == 1);
      bits[every] = std::move(t.bits), losses[every] = std::move(t.losses), stored[every] = t.stored, bytes[every] = t.bytes;
    }
    CHECK(same_bits(bits[0], bits[1]));
    CHECK(same_bits(losses[0], losses[1]));
    CHECK(losses[0][0] > 0);
    double norm = 0;
    for (size_t i = 0; i + 1 < bits[0].size(); ++i) norm += double(bits[0][i]) * bits[0][i];
    CHECK(norm > 0);
    CHECK(stored[1] == tiles);
    // The white paper's tiles inside the frame, away from its border and the figure, are not
    // stored: at most the border ring (24 of 48 tiles a frame) and the figure's 4 x 4.
    CHECK(stored[0] <= size_t{kK} * (24 + 16));
    CHECK(stored[0] >= size_t{kK} * 4);  // the figure's tiles at least
    // Q and R are T² pixels of 8 bytes a stored tile each, the uniform tiles' values a tile
    // more (fewer than T² values: a few per frame), none when every tile is stored.
    CHECK(bytes[1] - bytes[0] == (stored[1] - stored[0] - 1) * T * T * 16);
  }
}

TEST_CASE("tiled Q and R: a flat fill's inside is held as its value, with the same loss and gradient bits") {
  // 192 x 128 (12 x 8 tiles), an opaque rectangle over (32, 32)-(128, 96) on the pixel grid.
  // On white paper Q and R are 0 (the white target blurred less the white paper blurred), so
  // the commonest value is the paper's. The blurs (the target's σ 1, the render's σ 1 with a
  // chroma σ 1.6) reach under 16 px from the rectangle's edges: they touch its 8 x 6 tiles
  // (16 px around it), while the 4 x 2 tiles of (48, 48)-(112, 80) take the fill's one value.
  // Stored: the 40 others of the 8 x 6 (48 a frame while a value other than the commonest
  // made a tile stored).
  constexpr int W = 192, H = 128;
  const RasterPlan plan = plan_raster(
      scene_of(W, H, {filled(polygon({{32, 32}, {128, 32}, {128, 96}, {32, 96}}), {0.2f, 0.6f, 0.3f, 1})}), Affine{},
      W, H);
  const std::vector<float> targets = targets_on_white(plan, kK, 0, 0);
  const std::vector<float> cp = shifted_cp(plan, kK, 0.5f, 0.75f);
  const TiledPass held = tiled_pass(plan, targets, cp, 1.6, 0.25, false), every = tiled_pass(plan, targets, cp, 1.6, 0.25, true);
  CHECK(same_bits(held.bits, every.bits));
  CHECK(same_bits(held.losses, every.losses));
  CHECK(every.stored == size_t{kK} * (W / T) * (H / T));
  CHECK(held.stored == size_t{kK} * 40);
}

}  // TEST_SUITE
