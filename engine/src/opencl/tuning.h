// Per-device kernel tunables, passed to the OpenCL compiler as -D options.
//
// One kernel source serves PoCL and GPU drivers; what differs is chosen here from a small table
// keyed by device type, with a default row (the CLBlast habit). Today the tunable is the raster
// band height: rows per work-item, bounded by what fits the device's local memory.
#pragma once

#include <string>

#include "svgmotion/device.h"

namespace svgm {

struct RasterTuning {
  int band_height = 16;  // rows per raster work-group (BAND_H)
  int group_size = 1;    // work-items per raster work-group (they share clearing and output)
  size_t local_budget = 32768;  // bytes of local memory a raster work-group may use
  bool prefetch_rows = false;   // bands prefetch the rows they will read scattered (PREFETCH_ROWS)
};

// The tuning for rendering `width`-pixel rows on `device`.
RasterTuning raster_tuning(const DeviceInfo& device, int width);

// The OpenCL compiler options for the raster kernels with `t`.
std::string kernel_build_options(const RasterTuning& t);

}  // namespace svgm
