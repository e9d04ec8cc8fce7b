// The tunables table (see tuning.h).
#include "opencl/tuning.h"

#include "raster/raster_plan.h"

namespace svgm {

std::string kernel_build_options(const DeviceInfo& /*device*/) {
  // -cl-fast-relaxed-math is deliberately absent: coverage must be exact and deterministic.
  std::string opts = "-cl-std=CL1.2 -DBAND_H=" + std::to_string(kBandHeight);
  return opts;
}

}  // namespace svgm
