// The paper's two-stage judge (ranker `llm`) minus the model: reading a stage-1 answer (the four
// constraints a fittable video meets, each Yes / Partial / No, and whether the candidate is
// viable at all), its points, and which candidates go on to stage 2, where the model compares
// the best few side by side.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace svgm {

// The constraints, in the order of the answer's keys: no 3D rotation (motion in the picture
// plane), no new elements, constant flat colours, continuity (nothing appears, vanishes or
// jumps).
inline constexpr const char* kJudgeConstraints[4] = {"no_3d_rotation", "no_new_elements", "flat_colours",
                                                      "continuity"};

struct JudgeScore {
  std::string candidate;
  std::string verdicts[4];  // "Yes", "Partial" or "No", in kJudgeConstraints' order
  bool viable = false;
  std::string reason;
  int points = 0;      // Yes 2, Partial 1, No 0, summed: 0..8
  std::string answer;  // the model's text, as it came
  nlohmann::json to_json() const;
};

// Reads an answer (JSON, already without ``` fences):
//   {"no_3d_rotation": "Yes", "no_new_elements": "Partial", "flat_colours": "No",
//    "continuity": "Yes", "viable": true, "reason": "..."}
// Verdicts are matched without regard to case; "viable" may be true/false or "Yes"/"No".
// Throws svgm::Error "malformed answer for <candidate>: <what>".
JudgeScore read_judge_score(const std::string& candidate, const std::string& answer);

// The viable candidates, most points first (ties: the order of `preference`, the pixel
// ranking's), at most `top_k`.
std::vector<std::string> judge_finalists(const std::vector<JudgeScore>& scores,
                                         const std::vector<std::string>& preference, int top_k);

// When no candidate is viable: the one with the most points (ties as above).
std::string judge_best_of_rest(const std::vector<JudgeScore>& scores, const std::vector<std::string>& preference);

}  // namespace svgm
