// The loss's constants Q and R (kernels/loss.cl) stored by tiles: most of a clipart frame is
// white paper far from any ink, where Q and R take one value (the blurred background less the
// blurred white target), and so do they inside a flat fill, far from its edges (the colour
// blurred less itself). A frame's Q and R (four halves a pixel each, as the device reads them)
// are cut into kLossTile x kLossTile tiles; a tile whose every pixel holds one value (Q's and
// R's halves alike) is held as that value, one pixel, the others are stored whole. The device
// reads a pixel through the frame's tile index (loss.cl's loss_tile_pixel): the same halves as
// the dense layout, so the same loss and gradient bits. At 512 px the bundled example's Q and R
// were 88 MB dense.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace svgm {

// The tile's side in pixels (loss.cl's LOSS_TILE; a power of two). Near the figure and the
// frame's border (zero padding) the values vary: smaller tiles store less around them, larger
// ones need a smaller index. 16: the index is 4 bytes per 256 pixels.
constexpr int kLossTile = 16;

// One frame's Q and R by tiles.
struct LossTiles {
  int tiles_x = 0, tiles_y = 0;
  // The values of the uniform tiles (not stored), each Q's four halves then R's; the commonest
  // first (the white paper's, on a clipart frame), then in the order first seen.
  std::vector<std::array<uint16_t, 8>> values;
  // Per tile, row-major: its number among the stored tiles, or -1 - j for values[j].
  std::vector<int> tile;
  // The stored tiles, kLossTile² pixels of four halves each, rows of the tile in order;
  // pixels outside the frame (a frame not a multiple of the tile) are zero.
  std::vector<uint16_t> q, r;
  int stored() const { return static_cast<int>(q.size() / (std::size_t{kLossTile} * kLossTile * 4)); }
};

// Tiles a frame's dense Q and R (W x H pixels of four halves, row-major). With `every_tile`
// every tile is stored (the dense layout by tiles: for tests comparing the two).
LossTiles tile_loss_frame(const uint16_t* q, const uint16_t* r, int W, int H, bool every_tile = false);

}  // namespace svgm
