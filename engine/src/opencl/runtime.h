// The OpenCL runtime: one context, device and in-order queue, and the compiled programs.
//
// Programs are built from embedded kernel files (prelude.cl first) plus -D tunables, and cached
// on disk by (platform, device, driver, source hash, options): PoCL takes seconds to compile,
// and a second run of the CLI should not pay that again. The cache lives in
// $SVGMOTION_CACHE_DIR, else $XDG_CACHE_HOME/svgmotion, else ~/.cache/svgmotion; an unusable
// cache directory only costs compile time, never an error; concurrent writers and truncated
// files are safe (kernel_cache.h).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "opencl/cl.h"
#include "svgmotion/device.h"

namespace svgm {

// The fitter's program (field, motion, regularise, adam) uses none of the raster tunables: one
// build serves every size (with the raster's band height it was built again per width).
inline const char* const kFitterProgramOptions = "-cl-std=CL1.2";

class ClRuntime {
 public:
  // Selects a device by spec (see select_device) and creates the context and queue.
  // With `profiling`, the queue records kernel start/end times (bench --profile).
  explicit ClRuntime(const std::string& device_spec = "auto", bool profiling = false);
  bool profiling() const { return profiling_; }

  const DeviceInfo& info() const { return info_; }
  cl::Context& context() { return context_; }
  cl::CommandQueue& queue() { return queue_; }
  const cl::Device& device() const { return device_; }

  // The program made of prelude.cl + `files` built with `options` (cached in memory and on
  // disk). Throws svgm::Error with the build log on failure. The first build from source logs
  // "compiling the OpenCL kernels (once, about N s)" (N: the last such build measured here).
  // The raster program's options vary with the width's tuning and with whether its blur is the
  // paper's (raster/loss_blur.h: any other blur's taps are a kernel argument, not an option);
  // the fitter's program takes kFitterProgramOptions.
  // `child_spec`: how `svgmotion devices --warm-for` makes the same program and launches its
  // kernels; when given, the program is missing from the disk cache and compile_child_enabled(),
  // a child process compiles it (opencl/compile_child.h) and this one loads the cached binary.
  cl::Program& program(const std::vector<std::string>& files, const std::string& options,
                       const std::string& child_spec = "");

  // Seconds spent compiling or loading programs so far (benchmarks report time without it).
  double compile_seconds() const { return compile_seconds_; }

  // How the programs of this runtime were obtained: built from source (and written to the disk
  // cache when it is usable) or loaded from a cached binary. The cache's tests read these to
  // tell reuse from a silent rebuild.
  int programs_built_from_source() const { return built_from_source_; }
  int programs_loaded_from_cache() const { return loaded_from_cache_; }
  // Of those loaded from the cache, how many a child process compiled first.
  int programs_compiled_in_child() const { return compiled_in_child_; }

 private:
  DeviceInfo info_;
  cl::Device device_;
  cl::Context context_;
  cl::CommandQueue queue_;
  std::map<std::string, cl::Program> programs_;
  double compile_seconds_ = 0;
  std::string device_spec_;
  int built_from_source_ = 0, loaded_from_cache_ = 0, compiled_in_child_ = 0;
  bool said_compiling_ = false;  // "compiling the OpenCL kernels" was logged
  bool profiling_ = false;
};

}  // namespace svgm
