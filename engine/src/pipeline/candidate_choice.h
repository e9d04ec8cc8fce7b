// A candidate video chosen by hand: `stages.ranker.choose: NAME` (a name in candidates/, such
// as 02.mp4) fits that candidate instead of the ranker's pick.
//
// The choice is the pipeline's, not the ranker plugin's, so it works with every ranker and does
// not ask the ranker again (an llm judge costs a request): the ranker's settings are hashed
// without `choose`, and after the ranker stage (run or up to date) the chosen candidate is
// written as target.mp4, which makes layers, tracker and fitter run again on it. ranking.json
// keeps every score and reason; "chosen" names the candidate target.mp4 holds, and while a hand
// choice overrides the ranker, "ranker_chosen" names the ranker's own pick and "chosen_by" is
// "stages.ranker.choose". Removing the setting brings the ranker's pick back the same way.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace svgm {

// The config key, for messages.
inline constexpr const char* kChooseKey = "stages.ranker.choose";

// Checks the setting's form before any stage runs: absent or "" (the ranker decides), else a
// plain file name (no folder, not "." or ".."). Throws svgm::Error naming the key.
void check_candidate_choice(const nlohmann::json& value);

// Makes target.mp4 and ranking.json in `run` agree with `choose` ("" = the ranker's pick).
// Returns true when target.mp4 was rewritten. Throws svgm::Error when `choose` names no
// candidate in run/candidates (the message lists the candidates there).
bool apply_candidate_choice(const std::filesystem::path& run, const std::string& choose);

}  // namespace svgm
