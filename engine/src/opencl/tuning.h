// Per-device kernel tunables, passed to the OpenCL compiler as -D options.
//
// One kernel source serves PoCL and GPU drivers; what differs is chosen here from a small table
// keyed by device type, with a default row (the CLBlast habit). Today only the band height is
// tunable and every device uses 16, which matches kBandHeight in raster_plan.h.
#pragma once

#include <string>

#include "svgmotion/device.h"

namespace svgm {

std::string kernel_build_options(const DeviceInfo& device);

}  // namespace svgm
