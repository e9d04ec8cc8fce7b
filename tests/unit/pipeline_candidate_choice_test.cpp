// stages.ranker.choose (pipeline/candidate_choice.h): the setting's form, and a run directory
// made by the test (candidates are .mp4 files, copied as bytes, so any bytes do) brought in
// line with a hand choice and back to the ranker's pick.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>

#include "error_of.h"
#include "pipeline/candidate_choice.h"
#include "temp_dir.h"

using namespace svgm;
namespace fs = std::filesystem;

namespace {

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

nlohmann::json ranking(const fs::path& run) { return nlohmann::json::parse(read(run / "ranking.json")); }

}  // namespace

TEST_SUITE("pipeline") {
  TEST_CASE("stages.ranker.choose is empty or a plain file name") {
    CHECK_NOTHROW(check_candidate_choice(""));
    CHECK_NOTHROW(check_candidate_choice(nullptr));
    CHECK_NOTHROW(check_candidate_choice("01.mp4"));
    CHECK(test::error_of([] { check_candidate_choice(1); }) ==
          "stages.ranker.choose: must name a file in the run's candidates/ folder (such as 01.mp4), not 1");
    CHECK(test::error_of([] { check_candidate_choice("a/01.mp4"); }) ==
          "stages.ranker.choose: must be a plain file name in the run's candidates/ folder (such as 01.mp4), not a/01.mp4");
    CHECK(test::error_of([] { check_candidate_choice(".."); }).find("not ..") != std::string::npos);
  }

  TEST_CASE("a hand choice replaces target.mp4 and is recorded; removing it brings the ranker's pick back") {
    test::TempDir dir("svgm_choice");
    const fs::path run = dir.path;
    fs::create_directories(run / "candidates");
    std::ofstream(run / "candidates" / "00.mp4") << "video zero";
    std::ofstream(run / "candidates" / "01.mp4") << "video one";
    std::ofstream(run / "candidates" / "notes.txt") << "a provider's side file, not a candidate";
    std::ofstream(run / "target.mp4") << "video one";
    std::ofstream(run / "ranking.json") << R"({"chosen": "01.mp4", "reason": "lowest score", "candidates": []})";

    CHECK_FALSE(apply_candidate_choice(run, ""));  // the ranker's pick is in place
    CHECK_FALSE(apply_candidate_choice(run, "01.mp4"));
    CHECK(apply_candidate_choice(run, "00.mp4"));
    CHECK(read(run / "target.mp4") == "video zero");
    nlohmann::json r = ranking(run);
    CHECK(r["chosen"] == "00.mp4");
    CHECK(r["ranker_chosen"] == "01.mp4");
    CHECK(r["chosen_by"] == "stages.ranker.choose");
    CHECK(r["reason"] == "lowest score");  // the ranker's record is kept
    CHECK_FALSE(apply_candidate_choice(run, "00.mp4"));  // a second run changes nothing

    CHECK(apply_candidate_choice(run, ""));
    CHECK(read(run / "target.mp4") == "video one");
    r = ranking(run);
    CHECK(r["chosen"] == "01.mp4");
    CHECK_FALSE(r.contains("ranker_chosen"));
    CHECK_FALSE(r.contains("chosen_by"));

    CHECK(test::error_of([&] { apply_candidate_choice(run, "02.mp4"); }) ==
          "stages.ranker.choose: no candidate '02.mp4' in " + (run / "candidates").string() +
              " (candidates: 00.mp4, 01.mp4)");
    CHECK(read(run / "target.mp4") == "video one");
  }
}
