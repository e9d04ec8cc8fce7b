// The OpenCL C sources embedded into the binary at build time (cmake/EmbedKernels.cmake).
#pragma once

#include <string_view>
#include <vector>

namespace svgm {

struct KernelSource {
  const char* name;  // file name under kernels/, e.g. "raster.cl"
  const char* text;
};

const std::vector<KernelSource>& embedded_kernels();
// configs/*.yaml, the same way (default.yaml is the config schema).
const std::vector<KernelSource>& embedded_configs();

// The text of one embedded file; throws svgm::Error if there is none of that name.
std::string_view kernel_source(std::string_view name);

}  // namespace svgm
