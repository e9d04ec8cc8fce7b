// The two-stage judge's stage-1 answers (rank/judge_scores.h): verdicts and points read by
// hand-computable rules, malformed answers named, and the finalists chosen by points with the
// pixel ranking breaking ties.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "rank/judge_scores.h"

#include "error_of.h"

using namespace svgm;
using test::error_of;

namespace {

std::string answer(const char* rot, const char* added, const char* flat, const char* cont, const char* viable) {
  return std::string("{\"no_3d_rotation\": \"") + rot + "\", \"no_new_elements\": \"" + added +
         "\", \"flat_colours\": \"" + flat + "\", \"continuity\": \"" + cont + "\", \"viable\": " + viable +
         ", \"reason\": \"r\"}";
}

}  // namespace

TEST_SUITE("fit") {

TEST_CASE("judge: a stage-1 answer gives verdicts, viability and points (Yes 2, Partial 1, No 0)") {
  const JudgeScore s = read_judge_score("03.mp4", answer("Yes", "partial", "NO", "Yes", "true"));
  CHECK(s.candidate == "03.mp4");
  CHECK(s.verdicts[0] == "Yes");
  CHECK(s.verdicts[1] == "Partial");
  CHECK(s.verdicts[2] == "No");
  CHECK(s.verdicts[3] == "Yes");
  CHECK(s.viable);
  CHECK(s.points == 2 + 1 + 0 + 2);
  CHECK(s.reason == "r");
  CHECK(s.answer == answer("Yes", "partial", "NO", "Yes", "true"));
  CHECK(s.to_json()["flat_colours"] == "No");
  CHECK(s.to_json()["points"] == 5);
  CHECK_FALSE(read_judge_score("x", answer("Yes", "Yes", "Yes", "Yes", "\"No\"")).viable);
  CHECK(read_judge_score("x", answer("Yes", "Yes", "Yes", "Yes", "\"yes\"")).viable);
}

TEST_CASE("judge: malformed stage-1 answers are named") {
  CHECK(error_of([] { read_judge_score("01.mp4", "{\"no_3d"); }) == "malformed answer for 01.mp4: not a JSON object");
  CHECK(error_of([] { read_judge_score("01.mp4", "[1]"); }) == "malformed answer for 01.mp4: not a JSON object");
  CHECK(error_of([] { read_judge_score("01.mp4", "{\"no_3d_rotation\": \"Yes\"}"); }) ==
        "malformed answer for 01.mp4: no \"no_new_elements\" verdict");
  CHECK(error_of([] { read_judge_score("01.mp4", answer("Yes", "Maybe", "Yes", "Yes", "true")); }) ==
        "malformed answer for 01.mp4: \"no_new_elements\" is 'Maybe', not Yes, Partial or No");
  CHECK(error_of([] { read_judge_score("01.mp4", answer("Yes", "Yes", "Yes", "Yes", "1")); }) ==
        "malformed answer for 01.mp4: \"viable\" is 1, not true or false");
}

TEST_CASE("judge: finalists are the viable ones by points, ties in the pixel ranking's order, at most top_k") {
  std::vector<JudgeScore> s = {
      read_judge_score("00.mp4", answer("Yes", "Yes", "Partial", "Yes", "true")),  // 7
      read_judge_score("01.mp4", answer("Yes", "Yes", "Yes", "Yes", "false")),     // 8, not viable
      read_judge_score("02.mp4", answer("Yes", "Yes", "Yes", "Partial", "true")),  // 7
      read_judge_score("03.mp4", answer("Yes", "Yes", "Yes", "Yes", "true")),      // 8
      read_judge_score("04.mp4", answer("No", "No", "Yes", "Yes", "true")),        // 4
  };
  const std::vector<std::string> pixel = {"02.mp4", "04.mp4", "00.mp4", "01.mp4", "03.mp4"};
  CHECK(judge_finalists(s, pixel, 3) == std::vector<std::string>{"03.mp4", "02.mp4", "00.mp4"});
  CHECK(judge_finalists(s, pixel, 10) == std::vector<std::string>{"03.mp4", "02.mp4", "00.mp4", "04.mp4"});
  for (auto& x : s) x.viable = false;
  CHECK(judge_finalists(s, pixel, 3).empty());
  CHECK(judge_best_of_rest(s, pixel) == "01.mp4");  // 8 points, before 03 in the pixel order
}

}  // TEST_SUITE
