// release_compiler_pages (opencl/compiler_pages.h): the OpenCL compiler's clean pages dropped
// from the resident set while the runtime goes on working. After the release no clean page of
// a compiler mapping it may drop is resident, and a render made afterwards (its programs
// already built, or built again from the cache) is the same bytes as before.
#include <doctest/doctest.h>

#include <cstdlib>
#include <fstream>
#include <string>

#include "opencl/compiler_pages.h"
#include "opencl/runtime.h"
#include "raster/render_image.h"
#include "svgmotion/svg_reader.h"

using namespace svgm;

namespace {

// kB resident in the compiler's mappings that are not writable and have no dirty page: what
// release_compiler_pages drops.
size_t droppable_kb() {
  std::ifstream smaps("/proc/self/smaps");
  size_t total = 0, rss = 0, dirty = 0;
  bool candidate = false;
  auto close = [&] {
    if (candidate && dirty == 0) total += rss;
  };
  for (std::string line; std::getline(smaps, line);) {
    const size_t dash = line.find('-'), space = line.find(' ');
    if (dash != std::string::npos && space != std::string::npos && dash < space && line.find(':') > space) {
      close();
      const size_t slash = line.rfind('/');
      const std::string name = slash == std::string::npos ? "" : line.substr(slash + 1);
      candidate = line[space + 2] != 'w' && (name.rfind("libLLVM", 0) == 0 || name.rfind("libclang-cpp", 0) == 0);
      rss = dirty = 0;
    } else if (line.rfind("Rss:", 0) == 0) {
      rss = std::strtoull(line.c_str() + 4, nullptr, 10);
    } else if (line.rfind("Private_Dirty:", 0) == 0) {
      dirty = std::strtoull(line.c_str() + 14, nullptr, 10);
    }
  }
  close();
  return total;
}

}  // namespace

TEST_SUITE("opencl") {
  TEST_CASE("the compiler's clean pages released: none left resident, and renders the same after") {
    const Scene scene = read_svg_string(
        "<svg xmlns='http://www.w3.org/2000/svg' viewBox='0 0 40 30'>"
        "<path d='M4 4 L30 6 L20 26 Z' fill='#c83020'/><circle cx='30' cy='20' r='6' fill='#2040c0'/></svg>",
        "test.svg");
    ClRuntime rt("auto");
    const RgbaImage before = render_image(rt, scene, 64, false);
    const size_t had = droppable_kb();
    const size_t dropped = release_compiler_pages();
    CHECK(dropped == had);  // every such page it found, and only those (none when PoCL has no LLVM)
    CHECK(droppable_kb() == 0);
    const RgbaImage after = render_image(rt, scene, 64, false);
    CHECK(after.width == before.width);
    CHECK(after.height == before.height);
    CHECK(after.rgba == before.rgba);
    ClRuntime again("auto");  // a new context: its programs come from the cache
    CHECK(render_image(again, scene, 64, false).rgba == before.rgba);
  }
}
