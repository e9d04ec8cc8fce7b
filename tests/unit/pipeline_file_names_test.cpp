// File names are bytes: valid_utf8 (what messages, JSON and pages show), the plugin request's
// lossless round trip of names that are not UTF-8, our temporary names (which the clean-up of a
// killed run may remove, and no user's file may match), and run directories (a folder of the
// user's is refused, nothing in it deleted).
#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "run/run_directory.h"
#include "svgmotion/error.h"
#include "svgmotion/temporary_name.h"
#include "svgmotion/utf8_text.h"

#include "error_of.h"
#include "temp_dir.h"

using namespace svgm;
namespace fs = std::filesystem;

TEST_SUITE("pipeline") {

TEST_CASE("valid_utf8 keeps UTF-8 and replaces each stray byte by U+FFFD") {
  CHECK(shown_utf8("caf\xc3\xa9.svg") == "caf\xc3\xa9.svg");
  CHECK(shown_utf8("caf\xe9.svg") == "caf\xef\xbf\xbd.svg");  // Latin-1 e-acute
  CHECK(shown_utf8("\xc0\xaf") == "\xef\xbf\xbd\xef\xbf\xbd");  // an overlong "/"
  CHECK(shown_utf8("\xed\xa0\x80") == "\xef\xbf\xbd\xef\xbf\xbd\xef\xbf\xbd");  // a surrogate
  CHECK(shown_utf8("\xf0\x9f\x98\x80") == "\xf0\x9f\x98\x80");  // U+1F600
  CHECK(shown_utf8("ab\xe2\x82") == "ab\xef\xbf\xbd\xef\xbf\xbd");  // cut short
  CHECK(is_valid_utf8("plain"));
  CHECK_FALSE(is_valid_utf8("caf\xe9"));
  // nlohmann's own dump throws for these bytes; json_text never does.
  CHECK(json_text(nlohmann::json{{"svg", "caf\xe9.svg"}}) == "{\"svg\":\"caf\xef\xbf\xbd.svg\"}");
}

TEST_CASE("a plugin request carries names that are not UTF-8 there and back unchanged") {
  nlohmann::json req = {{"run_dir", "/tmp/out\xe9"}, {"prompt", "ok"},
                        {"stages", {{"video", {{"path", "v\xff.mp4"}}}, {"a/b~c", {"x\x80"}}}}};
  const nlohmann::json original = req;
  pack_raw_strings(req);
  CHECK(req["run_dir"] == "/tmp/out\xef\xbf\xbd");
  CHECK(req[kRawStringsKey].size() == 3);
  const std::string text = json_text(req);
  CHECK(is_valid_utf8(text));
  nlohmann::json back = nlohmann::json::parse(text);
  unpack_raw_strings(back);
  CHECK(back == original);
}

TEST_CASE("temporary names: ours are recognised with their pid, a user's file never") {
  const fs::path t = temporary_path("/run/preview.mp4", ".mp4");
  CHECK(t.parent_path() == "/run");
  CHECK(t.filename().string() == ".preview.mp4.svgm-tmp-" + std::to_string(::getpid()) + ".mp4");
  CHECK(temporary_name_pid(t.filename().string()) == ::getpid());
  CHECK(temporary_name_pid(".fit.json.svgm-tmp-123") == 123);
  CHECK(temporary_name_pid(".00.webm.svgm-tmp-7.webm") == 7);
  for (const char* user : {"thesis.part1.pdf", "fit.json.part999", ".preview.mp4.part12.mp4", "svgm-tmp-12",
                           ".svgm-tmp-12", ".x.svgm-tmp-", ".x.svgm-tmp-12a", "x.svgm-tmp-12"})
    CHECK_MESSAGE(temporary_name_pid(user) == -1, user);
}

TEST_CASE("claim_run_directory: empty or ours is taken, a folder of the user's is refused untouched") {
  test::TempDir tmp("svgm_run_dir_test");
  const fs::path fresh = tmp.path / "a" / "b";
  claim_run_directory(fresh, false, run_output_names());
  CHECK(fs::is_directory(fresh / ".svgmotion"));
  claim_run_directory(fresh, false, run_output_names());  // a run directory: taken again

  const fs::path mine = tmp.path / "mine";
  fs::create_directories(mine / "candidates");
  std::ofstream(mine / "thesis.part1.pdf") << "thesis";
  CHECK(test::error_of([&] { claim_run_directory(mine, false, run_output_names()); }) ==
        mine.string() + ": not a svgmotion run directory and not empty (2 entries); choose an empty folder or pass --force");
  CHECK(test::error_of([&] { claim_run_directory(mine, true, run_output_names()); }) ==
        (mine / "candidates").string() + ": not written by svgmotion, and a run would replace it; move it away or "
                                         "choose an empty folder");
  CHECK_FALSE(fs::exists(mine / ".svgmotion"));
  // fit -o writes no candidates/: forced, the folder is taken, its files left alone.
  claim_run_directory(mine, true, fit_output_names());
  CHECK(fs::is_directory(mine / ".svgmotion"));
  CHECK(fs::is_regular_file(mine / "thesis.part1.pdf"));

  std::ofstream(tmp.path / "file") << "x";
  CHECK(test::error_of([&] { claim_run_directory(tmp.path / "file", false, run_output_names()); }) ==
        (tmp.path / "file").string() + ": not a folder");
}

TEST_CASE("RunLock removes only our temporaries of ended processes") {
  test::TempDir tmp("svgm_run_lock_test");
  const fs::path run = tmp.path / "run";
  claim_run_directory(run, false, run_output_names());
  fs::create_directories(run / "candidates");
  // A pid that no process has: the largest the kernel hands out, plus one.
  long max_pid = 4194304;
  std::ifstream("/proc/sys/kernel/pid_max") >> max_pid;
  const std::string dead = std::to_string(max_pid + 1);
  for (const fs::path& f : {run / (".fit.json.svgm-tmp-" + dead), run / (".preview.mp4.svgm-tmp-" + dead + ".mp4"),
                            run / "candidates" / (".00.mp4.svgm-tmp-" + dead), run / "thesis.part1.pdf",
                            run / "candidates" / "take.part2.mp4",
                            run / (".report.html.svgm-tmp-" + std::to_string(::getppid()))})
    std::ofstream(f) << "x";
  {
    const RunLock lock(run, false, run_output_names());
    CHECK(test::error_of([&] { RunLock second(run, false, run_output_names()); }) ==
          run.string() + ": another svgmotion run is using this run directory (pid " + std::to_string(::getpid()) + ")");
  }
  CHECK_FALSE(fs::exists(run / (".fit.json.svgm-tmp-" + dead)));
  CHECK_FALSE(fs::exists(run / (".preview.mp4.svgm-tmp-" + dead + ".mp4")));
  CHECK_FALSE(fs::exists(run / "candidates" / (".00.mp4.svgm-tmp-" + dead)));
  CHECK(fs::exists(run / "thesis.part1.pdf"));
  CHECK(fs::exists(run / "candidates" / "take.part2.mp4"));
  CHECK(fs::exists(run / (".report.html.svgm-tmp-" + std::to_string(::getppid()))));  // its writer runs
}

}  // TEST_SUITE
