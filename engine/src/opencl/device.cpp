// Discovery and selection of OpenCL devices.
#include "svgmotion/device.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <optional>

#include "opencl/cl.h"
#include "opencl/cpu_share.h"
#include "opencl/kernel_cache.h"
#include "svgmotion/error.h"

namespace svgm {

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::string type_name(cl_device_type t) {
  if (t & CL_DEVICE_TYPE_GPU) return "gpu";
  if (t & CL_DEVICE_TYPE_CPU) return "cpu";
  if (t & CL_DEVICE_TYPE_ACCELERATOR) return "accelerator";
  return "other";
}

constexpr const char* kNoPlatform =
    "no OpenCL platform found: install one (on Debian/Ubuntu: apt-get install pocl-opencl-icd "
    "for CPUs, or your GPU vendor's OpenCL driver)";

}  // namespace

std::vector<DeviceInfo> list_devices() {
  // PoCL's CPU device: pin its worker threads to cores when this process owns the machine.
  // Unpinned, a lone process ran either at full speed or at about half (measured 0.88 ms vs
  // 1.73 ms per batch, decided at start-up by where the scheduler put the workers); but jobs
  // sharing a machine would pin to the same cores, so they are not pinned (cpu_share.h). Read by
  // PoCL when the platform loads; a user's own setting wins.
  apply_cpu_share();
  // PoCL compiles each kernel again at its first launch (per work-group size) and keeps those
  // in a cache of its own: beside ours, one directory holds everything a first run compiles,
  // `devices --warm` fills both, and clearing ours clears both (a program found in our cache
  // with PoCL's entries gone would recompile silently). A user's own POCL_CACHE_DIR wins.
  if (const auto dir = kernel_cache_dir(); !dir.empty())
    setenv("POCL_CACHE_DIR", (dir / "pocl").c_str(), 0);
  std::vector<cl::Platform> platforms;
  try {
    cl::Platform::get(&platforms);
  } catch (const cl::Error&) {
    throw Error(kNoPlatform);
  }
  std::vector<DeviceInfo> out;
  for (const auto& p : platforms) {
    std::vector<cl::Device> devs;
    try {
      p.getDevices(CL_DEVICE_TYPE_ALL, &devs);
    } catch (const cl::Error&) {
      continue;  // a platform without devices is not an error while another one has some
    }
    for (const auto& d : devs) {
      DeviceInfo i;
      i.platform = p.getInfo<CL_PLATFORM_NAME>();
      i.name = d.getInfo<CL_DEVICE_NAME>();
      i.type = type_name(d.getInfo<CL_DEVICE_TYPE>());
      i.version = d.getInfo<CL_DEVICE_VERSION>();
      i.driver = d.getInfo<CL_DRIVER_VERSION>();
      i.compute_units = d.getInfo<CL_DEVICE_MAX_COMPUTE_UNITS>();
      i.global_mem_bytes = d.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>();
      i.local_mem_bytes = d.getInfo<CL_DEVICE_LOCAL_MEM_SIZE>();
      out.push_back(std::move(i));
    }
  }
  if (out.empty()) throw Error(kNoPlatform);
  return out;
}

size_t select_device(const std::vector<DeviceInfo>& devices, const std::string& spec) {
  const std::string s = lower(spec.empty() ? "auto" : spec);
  auto first_of = [&](const std::string& type) -> std::optional<size_t> {
    for (size_t i = 0; i < devices.size(); ++i)
      if (devices[i].type == type) return i;
    return std::nullopt;
  };
  std::optional<size_t> hit;
  if (s == "auto") {
    hit = first_of("gpu");
    if (!hit) hit = first_of("cpu");
    if (!hit && !devices.empty()) hit = 0;
  } else if (s == "cpu" || s == "gpu") {
    hit = first_of(s);
  } else {
    for (size_t i = 0; i < devices.size() && !hit; ++i)
      if (lower(devices[i].name).find(s) != std::string::npos ||
          lower(devices[i].platform).find(s) != std::string::npos)
        hit = i;
  }
  if (!hit) {
    std::string names;
    for (const auto& d : devices) names += (names.empty() ? "" : ", ") + d.name + " (" + d.type + ")";
    throw Error("no OpenCL device matches --device " + spec + "; available: " + names);
  }
  return *hit;
}

}  // namespace svgm
