// write_file_atomic and output_target: what an output path may be. A regular or absent file is
// replaced through a temporary; a device, FIFO or folder is refused with one line and left as
// it was; a symbolic link is written through to the file it names and stays a link.
//
// Only files made in a temporary folder are used: a broken writer must not be able to replace
// a real device while the test runs.
#include <doctest/doctest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "svgmotion/atomic_file.h"
#include "svgmotion/error.h"
#include "svgmotion/png_io.h"

#include "temp_dir.h"

using namespace svgm;
namespace fs = std::filesystem;

namespace {

struct TempDir : test::TempDir {
  TempDir() : test::TempDir("svgm_atomic_test") {}
};

std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

std::string error_of(const fs::path& file, std::string_view bytes) {
  try {
    write_file_atomic(file, bytes);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// Nothing but the named entries is left in the folder (no temporary).
size_t entries(const fs::path& dir) {
  size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

}  // namespace

TEST_SUITE("image") {

TEST_CASE("write_file_atomic replaces a regular file and creates an absent one") {
  TempDir t;
  const fs::path f = t.path / "out.txt";
  write_file_atomic(f, "first");
  CHECK(slurp(f) == "first");
  write_file_atomic(f, "second, longer");
  CHECK(slurp(f) == "second, longer");
  CHECK(entries(t.path) == 1);
}

TEST_CASE("a FIFO, a folder or a device at the output path is refused and left alone") {
  TempDir t;
  const fs::path fifo = t.path / "pipe";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  CHECK(error_of(fifo, "x") == fifo.string() + ": not a regular file");
  CHECK(fs::is_fifo(fifo));
  const fs::path dir = t.path / "folder";
  fs::create_directory(dir);
  CHECK(error_of(dir, "x") == dir.string() + ": not a regular file");
  CHECK(fs::is_directory(dir));
  CHECK(entries(t.path) == 2);
  // A device is only looked at, never written: output_target throws before any write.
  CHECK_THROWS_WITH_AS(output_target("/dev/null"), "/dev/null: not a regular file", Error);
  // The PNG writer goes through the same path.
  RgbaImage img{1, 1, {0, 0, 0, 255}};
  CHECK_THROWS_WITH_AS(write_png(fifo, img), (fifo.string() + ": not a regular file").c_str(), Error);
}

TEST_CASE("a symbolic link is written through to its target and stays a link") {
  TempDir t;
  fs::create_directory(t.path / "real");
  const fs::path target = t.path / "real" / "data.txt";
  write_file_atomic(target, "old");
  // A relative link, resolved against the link's own folder, through a second link.
  const fs::path link1 = t.path / "link1", link2 = t.path / "link2";
  fs::create_symlink("real/data.txt", link1);
  fs::create_symlink("link1", link2);
  write_file_atomic(link2, "new");
  CHECK(fs::is_symlink(link1));
  CHECK(fs::is_symlink(link2));
  CHECK(slurp(target) == "new");
  CHECK(entries(t.path / "real") == 1);

  // A dangling link makes its target.
  const fs::path dangling = t.path / "dangling";
  fs::create_symlink(t.path / "real" / "fresh.txt", dangling);
  write_file_atomic(dangling, "fresh");
  CHECK(fs::is_symlink(dangling));
  CHECK(slurp(t.path / "real" / "fresh.txt") == "fresh");
}

TEST_CASE("a link to a FIFO, and a loop of links, are refused") {
  TempDir t;
  const fs::path fifo = t.path / "pipe";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const fs::path link = t.path / "out.png";
  fs::create_symlink(fifo, link);
  CHECK(error_of(link, "x") == link.string() + ": not a regular file (it links to " + fifo.string() + ")");
  CHECK(fs::is_fifo(fifo));
  CHECK(fs::is_symlink(link));
  const fs::path a = t.path / "a", b = t.path / "b";
  fs::create_symlink("b", a);
  fs::create_symlink("a", b);
  CHECK(error_of(a, "x") == a.string() + ": too many levels of symbolic links");
  CHECK(entries(t.path) == 4);
}

}  // TEST_SUITE
