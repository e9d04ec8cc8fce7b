// Tiling of the loss's constants Q and R (see loss_tiles.h).
#include "raster/loss_tiles.h"

#include <algorithm>
#include <cstring>
#include <utility>

namespace svgm {

LossTiles tile_loss_frame(const uint16_t* q, const uint16_t* r, int W, int H, bool every_tile) {
  constexpr int T = kLossTile;
  LossTiles out;
  out.tiles_x = (W + T - 1) / T;
  out.tiles_y = (H + T - 1) / T;
  const int n = out.tiles_x * out.tiles_y;
  // A tile is uniform when each of its pixels has the halves of its first pixel, Q's and R's
  // (compared as bits: the device reads bits).
  using Value = std::array<uint16_t, 8>;
  auto value_at = [&](int x, int y) {
    Value v;
    const size_t at = (static_cast<size_t>(y) * W + x) * 4;
    std::copy_n(q + at, 4, v.begin());
    std::copy_n(r + at, 4, v.begin() + 4);
    return v;
  };
  std::vector<int> uniform(static_cast<size_t>(n), -1);  // index into `values`, or -1
  std::vector<std::pair<Value, int>> values;             // uniform values and their counts
  for (int ty = 0; ty < out.tiles_y && !every_tile; ++ty)
    for (int tx = 0; tx < out.tiles_x; ++tx) {
      const int x0 = tx * T, y0 = ty * T, x1 = std::min(x0 + T, W), y1 = std::min(y0 + T, H);
      const Value v = value_at(x0, y0);
      bool same = true;
      for (int y = y0; y < y1 && same; ++y)
        for (int x = x0; x < x1 && same; ++x) same = value_at(x, y) == v;
      if (!same) continue;
      auto it = std::find_if(values.begin(), values.end(), [&v](const auto& e) { return e.first == v; });
      if (it == values.end()) it = values.insert(values.end(), {v, 0});
      ++it->second;
      uniform[static_cast<size_t>(ty) * out.tiles_x + tx] = static_cast<int>(it - values.begin());
    }
  // The values held: the commonest first (the first seen among equals), then the others in
  // the order seen; every uniform tile is one of them (a flat fill's inside as well as the
  // paper: issue 38, the twemoji dog's 34 keyframes at 512 px).
  int best = -1;
  for (size_t i = 0; i < values.size(); ++i)
    if (best < 0 || values[i].second > values[static_cast<size_t>(best)].second) best = static_cast<int>(i);
  std::vector<int> slot(values.size(), -1);
  if (best >= 0) {
    slot[static_cast<size_t>(best)] = 0;
    out.values.push_back(values[static_cast<size_t>(best)].first);
    for (size_t i = 0; i < values.size(); ++i)
      if (static_cast<int>(i) != best) {
        slot[i] = static_cast<int>(out.values.size());
        out.values.push_back(values[i].first);
      }
  }
  out.tile.assign(static_cast<size_t>(n), -1);
  const size_t tile_halves = size_t{T} * T * 4;
  int stored = 0;
  for (int i = 0; i < n; ++i) {
    const int u = uniform[static_cast<size_t>(i)];
    out.tile[static_cast<size_t>(i)] = u < 0 ? stored++ : -1 - slot[static_cast<size_t>(u)];
  }
  out.q.assign(static_cast<size_t>(stored) * tile_halves, 0);
  out.r.assign(static_cast<size_t>(stored) * tile_halves, 0);
  for (int ty = 0; ty < out.tiles_y; ++ty)
    for (int tx = 0; tx < out.tiles_x; ++tx) {
      const int s = out.tile[static_cast<size_t>(ty) * out.tiles_x + tx];
      if (s < 0) continue;
      const int x0 = tx * T, y0 = ty * T, x1 = std::min(x0 + T, W), y1 = std::min(y0 + T, H);
      for (int y = y0; y < y1; ++y) {
        const size_t from = (static_cast<size_t>(y) * W + x0) * 4;
        const size_t to = static_cast<size_t>(s) * tile_halves + static_cast<size_t>(y - y0) * T * 4;
        std::memcpy(&out.q[to], q + from, static_cast<size_t>(x1 - x0) * 4 * sizeof(uint16_t));
        std::memcpy(&out.r[to], r + from, static_cast<size_t>(x1 - x0) * 4 * sizeof(uint16_t));
      }
    }
  return out;
}

}  // namespace svgm
