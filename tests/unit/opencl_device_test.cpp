// Device discovery and selection, the on-disk program cache, and status code names.
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <sys/stat.h>
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

TEST_CASE("compiled programs are cached on disk, reused, and rebuilt when the cache is bad") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("svgm_cache_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  setenv("SVGMOTION_CACHE_DIR", dir.c_str(), 1);
  auto cache_files = [&] {
    std::vector<fs::path> files;
    for (const auto& e : fs::recursive_directory_iterator(dir))
      if (e.is_regular_file() && e.path().extension() == ".bin") files.push_back(e.path());
    return files;
  };
  auto stat_of = [](const fs::path& p) {
    struct stat st {};
    REQUIRE(::stat(p.c_str(), &st) == 0);
    return st;
  };
  const char* kOptions = "-DSVGM_CACHE_TEST=1";

  // 1. An empty cache: built from source, one binary written.
  {
    ClRuntime rt("auto");
    rt.program({"flatten.cl"}, kOptions);
    CHECK(rt.programs_built_from_source() == 1);
    CHECK(rt.programs_loaded_from_cache() == 0);
    rt.program({"flatten.cl"}, kOptions);  // the same runtime keeps it in memory
    CHECK(rt.programs_built_from_source() == 1);
    CHECK(rt.programs_loaded_from_cache() == 0);
  }
  auto files = cache_files();
  REQUIRE(files.size() == 1);
  const fs::path binary = files[0];
  const struct stat first = stat_of(binary);
  CHECK(first.st_size > 0);

  // 2. A new runtime (a second run of the CLI): loaded from the binary, nothing rebuilt, the
  //    file neither rewritten nor replaced (same inode, same modification time).
  {
    ClRuntime rt("auto");
    rt.program({"flatten.cl"}, kOptions);
    CHECK(rt.programs_loaded_from_cache() == 1);
    CHECK(rt.programs_built_from_source() == 0);
  }
  const struct stat second = stat_of(binary);
  CHECK(second.st_ino == first.st_ino);
  CHECK(second.st_mtim.tv_sec == first.st_mtim.tv_sec);
  CHECK(second.st_mtim.tv_nsec == first.st_mtim.tv_nsec);
  CHECK(cache_files().size() == 1);

  // 3. Other build options are another program: built, and cached beside the first.
  {
    ClRuntime rt("auto");
    rt.program({"flatten.cl"}, "-DSVGM_CACHE_TEST=2");
    CHECK(rt.programs_built_from_source() == 1);
    CHECK(rt.programs_loaded_from_cache() == 0);
  }
  CHECK(cache_files().size() == 2);

  // 4. A damaged binary (a foreign driver's, or a truncated write) is not an error: the program
  //    is built from source again and the cache entry replaced by a good binary.
  { std::ofstream(binary, std::ios::binary | std::ios::trunc) << "not a program binary"; }
  {
    ClRuntime rt("auto");
    rt.program({"flatten.cl"}, kOptions);
    CHECK(rt.programs_built_from_source() == 1);
    CHECK(rt.programs_loaded_from_cache() == 0);
  }
  CHECK(fs::file_size(binary) > std::string("not a program binary").size());
  {
    ClRuntime rt("auto");
    rt.program({"flatten.cl"}, kOptions);
    CHECK(rt.programs_loaded_from_cache() == 1);
  }
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

TEST_CASE("every OpenCL 1.2 status has its own name, checked against the header's numbers") {
  // The table is written in numbers; the header's macros are the independent check.
#define SVGM_STATUS(x) {x, #x}
  const std::pair<int, const char*> codes[] = {
      SVGM_STATUS(CL_SUCCESS), SVGM_STATUS(CL_DEVICE_NOT_FOUND), SVGM_STATUS(CL_DEVICE_NOT_AVAILABLE),
      SVGM_STATUS(CL_COMPILER_NOT_AVAILABLE), SVGM_STATUS(CL_MEM_OBJECT_ALLOCATION_FAILURE),
      SVGM_STATUS(CL_OUT_OF_RESOURCES), SVGM_STATUS(CL_OUT_OF_HOST_MEMORY),
      SVGM_STATUS(CL_PROFILING_INFO_NOT_AVAILABLE), SVGM_STATUS(CL_MEM_COPY_OVERLAP),
      SVGM_STATUS(CL_IMAGE_FORMAT_MISMATCH), SVGM_STATUS(CL_IMAGE_FORMAT_NOT_SUPPORTED),
      SVGM_STATUS(CL_BUILD_PROGRAM_FAILURE), SVGM_STATUS(CL_MAP_FAILURE),
      SVGM_STATUS(CL_MISALIGNED_SUB_BUFFER_OFFSET), SVGM_STATUS(CL_EXEC_STATUS_ERROR_FOR_EVENTS_IN_WAIT_LIST),
      SVGM_STATUS(CL_COMPILE_PROGRAM_FAILURE), SVGM_STATUS(CL_LINKER_NOT_AVAILABLE),
      SVGM_STATUS(CL_LINK_PROGRAM_FAILURE), SVGM_STATUS(CL_DEVICE_PARTITION_FAILED),
      SVGM_STATUS(CL_KERNEL_ARG_INFO_NOT_AVAILABLE), SVGM_STATUS(CL_INVALID_VALUE),
      SVGM_STATUS(CL_INVALID_DEVICE_TYPE), SVGM_STATUS(CL_INVALID_PLATFORM), SVGM_STATUS(CL_INVALID_DEVICE),
      SVGM_STATUS(CL_INVALID_CONTEXT), SVGM_STATUS(CL_INVALID_QUEUE_PROPERTIES),
      SVGM_STATUS(CL_INVALID_COMMAND_QUEUE), SVGM_STATUS(CL_INVALID_HOST_PTR), SVGM_STATUS(CL_INVALID_MEM_OBJECT),
      SVGM_STATUS(CL_INVALID_IMAGE_FORMAT_DESCRIPTOR), SVGM_STATUS(CL_INVALID_IMAGE_SIZE),
      SVGM_STATUS(CL_INVALID_SAMPLER), SVGM_STATUS(CL_INVALID_BINARY), SVGM_STATUS(CL_INVALID_BUILD_OPTIONS),
      SVGM_STATUS(CL_INVALID_PROGRAM), SVGM_STATUS(CL_INVALID_PROGRAM_EXECUTABLE),
      SVGM_STATUS(CL_INVALID_KERNEL_NAME), SVGM_STATUS(CL_INVALID_KERNEL_DEFINITION),
      SVGM_STATUS(CL_INVALID_KERNEL), SVGM_STATUS(CL_INVALID_ARG_INDEX), SVGM_STATUS(CL_INVALID_ARG_VALUE),
      SVGM_STATUS(CL_INVALID_ARG_SIZE), SVGM_STATUS(CL_INVALID_KERNEL_ARGS),
      SVGM_STATUS(CL_INVALID_WORK_DIMENSION), SVGM_STATUS(CL_INVALID_WORK_GROUP_SIZE),
      SVGM_STATUS(CL_INVALID_WORK_ITEM_SIZE), SVGM_STATUS(CL_INVALID_GLOBAL_OFFSET),
      SVGM_STATUS(CL_INVALID_EVENT_WAIT_LIST), SVGM_STATUS(CL_INVALID_EVENT), SVGM_STATUS(CL_INVALID_OPERATION),
      SVGM_STATUS(CL_INVALID_GL_OBJECT), SVGM_STATUS(CL_INVALID_BUFFER_SIZE), SVGM_STATUS(CL_INVALID_MIP_LEVEL),
      SVGM_STATUS(CL_INVALID_GLOBAL_WORK_SIZE), SVGM_STATUS(CL_INVALID_PROPERTY),
      SVGM_STATUS(CL_INVALID_IMAGE_DESCRIPTOR), SVGM_STATUS(CL_INVALID_COMPILER_OPTIONS),
      SVGM_STATUS(CL_INVALID_LINKER_OPTIONS), SVGM_STATUS(CL_INVALID_DEVICE_PARTITION_COUNT)};
#undef SVGM_STATUS
  for (const auto& [code, name] : codes)
    CHECK(cl_status_name(code) == std::string(name) + " (" + std::to_string(code) + ")");
  // The buffer creation failure that once read "unknown status (-37)".
  CHECK(cl_status_name(-37) == "CL_INVALID_HOST_PTR (-37)");
  CHECK(cl_status_name(-72) == "CL_MAX_SIZE_RESTRICTION_EXCEEDED (-72)");
  CHECK(cl_status_name(-25) == "unknown status (-25)");
  CHECK(cl_status_name(-73) == "unknown status (-73)");
  CHECK(cl_status_name(1) == "unknown status (1)");
}

}  // TEST_SUITE
