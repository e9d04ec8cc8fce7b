// OpenCL devices as the user sees them: `svgmotion devices` and the --device option.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace svgm {

struct DeviceInfo {
  std::string platform;   // e.g. "Portable Computing Language"
  std::string name;       // e.g. "pthread-skylake-avx512-AMD EPYC 7B13"
  std::string type;       // "cpu", "gpu", "accelerator" or "other"
  std::string version;    // device OpenCL version string
  std::string driver;     // driver version
  unsigned compute_units = 0;
  uint64_t global_mem_bytes = 0;
  uint64_t local_mem_bytes = 0;   // per work-group
};

// Every device of every platform, in platform order. Throws svgm::Error when no OpenCL platform
// is installed, naming the package that provides the CPU one.
std::vector<DeviceInfo> list_devices();

// The index into list_devices() that `spec` selects: "auto" (first GPU, else first CPU, else
// first device), "cpu", "gpu", or a case-insensitive substring of the device or platform name.
// Throws svgm::Error listing the devices when nothing matches.
size_t select_device(const std::vector<DeviceInfo>& devices, const std::string& spec);

}  // namespace svgm
