// Device discovery and selection, and the on-disk program cache.
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>

#include <unistd.h>

#include "opencl/runtime.h"
#include "svgmotion/device.h"
#include "svgmotion/error.h"

using namespace svgm;

TEST_SUITE("opencl") {

TEST_CASE("selection by auto, type and name substring") {
  std::vector<DeviceInfo> devs(3);
  devs[0].name = "pthread-skylake";
  devs[0].platform = "Portable Computing Language";
  devs[0].type = "cpu";
  devs[1].name = "GeForce RTX";
  devs[1].platform = "NVIDIA CUDA";
  devs[1].type = "gpu";
  devs[2].name = "Other accel";
  devs[2].platform = "X";
  devs[2].type = "accelerator";
  CHECK(select_device(devs, "auto") == 1);
  CHECK(select_device(devs, "cpu") == 0);
  CHECK(select_device(devs, "GPU") == 1);
  CHECK(select_device(devs, "rtx") == 1);
  CHECK(select_device(devs, "portable") == 0);
  CHECK(select_device({devs[0], devs[2]}, "auto") == 0);
  CHECK(select_device({devs[2]}, "auto") == 0);
  CHECK_THROWS_WITH_AS(select_device(devs, "tpu"),
                       "no OpenCL device matches --device tpu; available: pthread-skylake (cpu), "
                       "GeForce RTX (gpu), Other accel (accelerator)",
                       Error);
}

TEST_CASE("this machine offers at least one device and the runtime builds kernels") {
  const auto devs = list_devices();
  REQUIRE(!devs.empty());
  CHECK(devs[0].compute_units > 0);
  ClRuntime rt("auto");
  CHECK(!rt.info().name.empty());
}

TEST_CASE("compiled programs are cached on disk and reused") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("svgm_cache_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  setenv("SVGMOTION_CACHE_DIR", dir.c_str(), 1);
  {
    ClRuntime rt("auto");
    rt.program({"flatten.cl"}, "-DSVGM_CACHE_TEST=1");
  }
  size_t files = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir)) files += e.is_regular_file();
  CHECK(files == 1);
  {
    ClRuntime rt("auto");
    rt.program({"flatten.cl"}, "-DSVGM_CACHE_TEST=1");  // loads the binary
  }
  files = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir)) files += e.is_regular_file();
  CHECK(files == 1);
  unsetenv("SVGMOTION_CACHE_DIR");
  fs::remove_all(dir);
}

TEST_CASE("a kernel that does not compile reports the build log") {
  ClRuntime rt("auto");
  try {
    rt.program({"raster.cl"}, "-DBAND_H=undefined_symbol");
    FAIL("the build did not fail");
  } catch (const Error& e) {
    const std::string msg = e.what();
    CHECK(msg.find("OpenCL build of raster.cl failed on") == 0);
    CHECK(msg.find("undefined_symbol") != std::string::npos);  // the log is in the message
  }
}

}  // TEST_SUITE
