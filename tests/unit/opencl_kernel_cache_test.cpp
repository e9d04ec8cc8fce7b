// The compiled-program cache under concurrent writers (opencl/kernel_cache.h): a file read back
// is the payload written; truncated, corrupt or foreign files read as missing; writers racing on
// one entry never let a reader see anything but a whole entry or nothing; and a runtime handed
// a damaged cache file rebuilds the program and repairs the entry.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "opencl/kernel_cache.h"
#include "opencl/runtime.h"
#include "svgmotion/log.h"
#include "temp_dir.h"

using namespace svgm;
namespace fs = std::filesystem;

namespace {

std::string bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

TEST_SUITE("opencl") {
  TEST_CASE("a cache file reads back its payload; truncated, flipped or foreign files read as missing") {
    test::TempDir dir("svgm_kcache");
    const fs::path f = dir.path / "kernels" / "x.bin";
    std::string payload(5000, '\0');
    for (size_t i = 0; i < payload.size(); ++i) payload[i] = static_cast<char>(i * 7);
    write_cached_binary(f, payload);
    CHECK(read_cached_binary(f) == payload);
    const std::string whole = bytes_of(f);
    CHECK(whole.size() == payload.size() + 24);
    std::ofstream(f, std::ios::binary) << whole.substr(0, whole.size() - 1);  // truncated
    CHECK(!read_cached_binary(f));
    std::string flipped = whole;
    flipped[3000] ^= 1;
    std::ofstream(f, std::ios::binary) << flipped;
    CHECK(!read_cached_binary(f));
    std::ofstream(f, std::ios::binary) << payload;  // an old cache's bare binary
    CHECK(!read_cached_binary(f));
    CHECK(!read_cached_binary(dir.path / "none.bin"));
    size_t left = 0;
    for (const auto& e : fs::directory_iterator(dir.path / "kernels")) left += e.is_regular_file();
    CHECK(left == 1);  // no temporary files left behind
  }

  TEST_CASE("writers racing on one entry: a reader sees a whole entry or nothing") {
    test::TempDir dir("svgm_kcache");
    const fs::path f = dir.path / "race.bin";
    const std::string a(200000, 'a'), b(150000, 'b');
    std::vector<std::thread> writers;
    for (int w = 0; w < 4; ++w)
      writers.emplace_back([&, w] {
        for (int i = 0; i < 25; ++i) write_cached_binary(f, w % 2 ? a : b);
      });
    int seen = 0, bad = 0;
    for (int i = 0; i < 200; ++i)
      if (const auto got = read_cached_binary(f)) {
        ++seen;
        bad += *got != a && *got != b;
      }
    for (auto& t : writers) t.join();
    CHECK(bad == 0);
    const auto last = read_cached_binary(f);
    REQUIRE(last);
    CHECK((*last == a || *last == b));
    size_t files = 0;
    for (const auto& e : fs::directory_iterator(dir.path)) files += e.is_regular_file();
    CHECK(files == 1);
    MESSAGE("whole entries read while writers raced: " << seen);
  }

  TEST_CASE("a runtime given a damaged cache entry rebuilds the program and repairs the entry") {
    test::TempDir dir("svgm_kcache");
    setenv("SVGMOTION_CACHE_DIR", dir.path.c_str(), 1);
    {
      ClRuntime rt("auto");
      rt.program({"flatten.cl"}, "-DSVGM_CACHE_DAMAGE_TEST=1");
    }
    fs::path entry;
    for (const auto& e : fs::recursive_directory_iterator(dir.path))
      if (e.is_regular_file() && e.path().extension() == ".bin") entry = e.path();
    REQUIRE(!entry.empty());
    const std::string good = bytes_of(entry);
    std::ofstream(entry, std::ios::binary) << good.substr(0, good.size() / 2);  // a writer killed mid-file
    {
      ClRuntime rt("auto");
      CHECK_NOTHROW(rt.program({"flatten.cl"}, "-DSVGM_CACHE_DAMAGE_TEST=1"));
    }
    CHECK(read_cached_binary(entry).has_value());
    CHECK(bytes_of(entry).size() == good.size());
    unsetenv("SVGMOTION_CACHE_DIR");
  }

  TEST_CASE("a build from source says 'compiling the OpenCL kernels' once; a cached program says nothing") {
    test::TempDir dir("svgm_kcache");
    setenv("SVGMOTION_CACHE_DIR", dir.path.c_str(), 1);
    std::vector<std::string> said;
    log::set_forward([&](log::Level, const std::string& m) { said.push_back(m); });
    auto compiling = [&] {
      return std::count_if(said.begin(), said.end(), [](const std::string& m) {
        return m.find("compiling the OpenCL kernels (once, about ") != std::string::npos;
      });
    };
    {
      ClRuntime rt("auto");
      rt.program({"adam.cl"}, "-DSVGM_COMPILE_NOTICE_TEST=1");
      rt.program({"adam.cl"}, "-DSVGM_COMPILE_NOTICE_TEST=2");  // a second miss: no second line
      CHECK(rt.programs_built_from_source() == 2);
    }
    CHECK(compiling() == 1);
    // The measured time is kept for the next estimate.
    CHECK(bytes_of(dir.path / "kernels" / "compile_seconds.txt").rfind("adam.cl ", 0) == 0);
    said.clear();
    {
      ClRuntime rt("auto");
      rt.program({"adam.cl"}, "-DSVGM_COMPILE_NOTICE_TEST=1");
      CHECK(rt.programs_loaded_from_cache() == 1);
      CHECK(rt.programs_built_from_source() == 0);
    }
    CHECK(compiling() == 0);
    log::set_forward({});
    unsetenv("SVGMOTION_CACHE_DIR");
  }
}
