// Kernels compiled in a child process (opencl/compile_child.h): a program missing from the cache
// is built by `svgmotion devices --warm-for`, and the process that asked only loads it; the
// child launches the kernels as the caller will, so the caller's launches compile nothing more
// in PoCL's own cache of work-group functions.
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "opencl/compile_child.h"
#include "opencl/runtime.h"
#include "raster/raster_cl.h"
#include "raster/raster_plan.h"
#include "scene/synthetic_scene.h"
#include "scoped_env.h"
#include "temp_dir.h"
#include "test_paths.h"

using namespace svgm;
namespace fs = std::filesystem;

namespace {

// PoCL's compiled work-group functions (DIR/<program>/<kernel>/<group size>/<kernel>.so); it
// also leaves a temporary file of its own there per process, not counted.
size_t work_group_functions(const fs::path& dir) {
  size_t n = 0;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator(); ++it)
    n += it->is_regular_file() && it->path().extension() == ".so";
  return n;
}

}  // namespace

TEST_SUITE("opencl") {
  TEST_CASE("a program missing from the cache is compiled by a child; this process loads it and builds none") {
    test::TempDir dir("svgm_child");
    // Given back at the end of the case, set or not: later tests share this process.
    test::ScopedEnv cache("SVGMOTION_CACHE_DIR", dir.path.string());
    test::ScopedEnv child(kCompileChildVar, svgm::test::cli_exe());
    {
      ClRuntime rt("auto");
      const Scene s = synthetic_blobs(2, 64);
      const RasterPlan plan = plan_raster(s, Affine{}, 64, 48);
      // The matched build (a fresh cache: no other test's program).
      ClRaster r(rt, plan, 2, 1.37, 0, 0.8125);
      CHECK(rt.programs_compiled_in_child() == 1);
      CHECK(rt.programs_loaded_from_cache() == 1);
      CHECK(rt.programs_built_from_source() == 0);
      size_t bins = 0;
      for (const auto& e : fs::directory_iterator(dir.path / "kernels")) bins += e.path().extension() == ".bin";
      CHECK(bins == 1);
    }
    // Without a usable child it compiles here, as before.
    child.set(std::string("/nonexistent/svgmotion"));
    {
      ClRuntime rt("auto");
      const Scene s = synthetic_blobs(2, 64);
      // The paper's blur: every matched blur shares the program the child built above
      // (raster/loss_blur.h).
      ClRaster r(rt, plan_raster(s, Affine{}, 64, 48), 2);
      CHECK(rt.programs_compiled_in_child() == 0);
      CHECK(rt.programs_built_from_source() == 1);
    }
  }

  TEST_CASE("after the child, a render of many strokes compiles nothing in PoCL's cache") {
    // Two processes with caches of their own (PoCL reads POCL_CACHE_DIR once, as it loads): the
    // child's command, then a render whose 16 strokes would have launched the stroke kernel in
    // groups of 16 (the largest dividing the count) where the child's one stroke took 8.
    test::TempDir dir("svgm_child_pocl");
    const fs::path svg = dir.path / "strokes.svg";
    {
      std::ofstream f(svg);
      f << "<svg xmlns='http://www.w3.org/2000/svg' viewBox='0 0 64 48' width='64' height='48'>";
      for (int i = 0; i < 16; ++i)
        f << "<path d='M" << 4 + 3 * i << " 6 C " << 10 + 3 * i << " 20 " << 2 + 3 * i << " 30 " << 5 + 3 * i
          << " 42' fill='none' stroke='#" << (i % 2 ? "c02020" : "2040a0") << "' stroke-width='1.5'/>";
      f << "</svg>";
    }
    const std::string env = "SVGMOTION_CACHE_DIR='" + (dir.path / "svgm").string() + "' POCL_CACHE_DIR='" +
                            (dir.path / "pocl").string() + "' ";
    const std::string exe = "'" + svgm::test::cli_exe() + "'";
    REQUIRE(std::system((env + exe + " devices --warm-for 'raster 64 48 1 1 1' >/dev/null 2>&1").c_str()) == 0);
    const size_t after_child = work_group_functions(dir.path / "pocl");
    CHECK(after_child > 0);
    REQUIRE(std::system((env + exe + " render '" + svg.string() + "' -o '" + (dir.path / "x.png").string() +
                         "' --size 64 >/dev/null 2>&1").c_str()) == 0);
    CHECK(fs::exists(dir.path / "x.png"));
    CHECK(work_group_functions(dir.path / "pocl") == after_child);
  }
}
