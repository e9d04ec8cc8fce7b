// The tunables table (engine/src/opencl/tuning.cpp): which devices get the raster kernels'
// row prefetches, and that the choice reaches the kernels' build options.
#include <doctest/doctest.h>

#include <string>

#include "opencl/tuning.h"
#include "svgmotion/device.h"

using namespace svgm;

namespace {

DeviceInfo device(const std::string& type) {
  DeviceInfo d;
  d.type = type;
  d.local_mem_bytes = 4 << 20;  // PoCL's CPU device reports megabytes
  return d;
}

bool has(const std::string& options, const std::string& what) {
  return options.find(what) != std::string::npos;
}

}  // namespace

TEST_CASE("tuning: CPU devices prefetch the rows the raster bands read scattered; GPUs do not" *
          doctest::test_suite("opencl")) {
  const RasterTuning cpu = raster_tuning(device("cpu"), 256);
  CHECK(cpu.prefetch_rows);
  CHECK(has(kernel_build_options(cpu), " -DPREFETCH_ROWS"));
  CHECK(cpu.group_size == 1);

  const RasterTuning gpu = raster_tuning(device("gpu"), 256);
  CHECK_FALSE(gpu.prefetch_rows);
  CHECK_FALSE(has(kernel_build_options(gpu), "PREFETCH"));
  CHECK(gpu.group_size == 64);
  // The rest of the options is the same row for both.
  CHECK(has(kernel_build_options(gpu), "-DBAND_H=" + std::to_string(gpu.band_height)));
}
