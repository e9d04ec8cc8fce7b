// The tunables table (see tuning.h).
#include "opencl/tuning.h"

#include <algorithm>

namespace svgm {

RasterTuning raster_tuning(const DeviceInfo& device, int width) {
  RasterTuning t;
  // Default row: 16 rows per band (enough work per item to amortise the per-draw culling). A
  // band keeps, per row, (W + 2) floats of accumulation and W float4 colours in local memory,
  // and the backward pass four more words per pixel (transmittance, the two one-sided ∂L/∂a,
  // the replay's last tape entry) and a mark byte plus its tape. Halve the band until the rows
  // take at most half of 3/4 of the local memory, leaving the rest to the tape.
  const uint64_t per_row = static_cast<uint64_t>(width + 2) * 4 + static_cast<uint64_t>(width) * 33;
  const uint64_t budget = device.local_mem_bytes ? device.local_mem_bytes * 3 / 4 : 32768;
  while (t.band_height > 1 && per_row * t.band_height > budget / 2) t.band_height /= 2;
  t.local_budget = budget;
  // On PoCL a group of 1 is fastest (measured: 64 items per group cost 1.8x, from barrier
  // bookkeeping); GPUs need many items to hide memory latency.
  t.group_size = device.type == "gpu" ? 64 : 1;
  // A CPU core reaches the loss's rows at a band's edge pixels, scattered: a demand miss each
  // (two thirds of the gradient's ∂L/∂C time on a sushi scene). A paint image's row is a 4 kB
  // page of its own, where the hardware's streamer starts cold (half of the backward sweep's
  // time on a scene of gradients). Prefetched up front, the rows stream in (sushi:
  // raster_backward 15.0 -> 13.1 ms CPU per iteration). Likewise the loss's y-blur reads its
  // next row of X' and Q and writes E', the residual output writes X', and the backward reads
  // a painted draw's colour at each of its tape entries: as demand misses these were the
  // y-blur's stalls (sushi) and over half of raster_backward's own time (sunrise's gradients).
  // GPUs hide the latency.
  t.prefetch_rows = device.type != "gpu";
  return t;
}

std::string kernel_build_options(const RasterTuning& t) {
  // -cl-fast-relaxed-math is deliberately absent: coverage must be exact and deterministic.
  return "-cl-std=CL1.2 -DBAND_H=" + std::to_string(t.band_height) +
         (t.prefetch_rows ? " -DPREFETCH_ROWS" : "");
}

}  // namespace svgm
