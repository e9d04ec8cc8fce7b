// A candidate video chosen by hand (see candidate_choice.h).
#include "pipeline/candidate_choice.h"

#include <fstream>

#include "svgmotion/atomic_file.h"
#include "svgmotion/error.h"
#include "generators/candidates.h"
#include "svgmotion/utf8_text.h"

namespace svgm {

namespace fs = std::filesystem;

void check_candidate_choice(const nlohmann::json& v) {
  if (v.is_null() || (v.is_string() && v.get<std::string>().empty())) return;
  const std::string shown = v.is_string() ? v.get<std::string>() : json_text(v);
  if (!v.is_string())
    throw Error(std::string(kChooseKey) + ": must name a file in the run's candidates/ folder (such as 01.mp4), not " + shown);
  const std::string s = v.get<std::string>();
  if (s == "." || s == ".." || s.find('/') != std::string::npos || s.find('\\') != std::string::npos)
    throw Error(std::string(kChooseKey) + ": must be a plain file name in the run's candidates/ folder (such as 01.mp4), not " + s);
}

bool apply_candidate_choice(const fs::path& run, const std::string& choose) {
  const fs::path ranking_file = run / "ranking.json", target = run / "target.mp4";
  std::ifstream in(ranking_file);
  nlohmann::json ranking = nlohmann::json::parse(in, nullptr, false);
  in.close();
  if (!ranking.is_object()) {
    // A third-party ranker may write no JSON object; a hand choice still needs a record of it.
    if (choose.empty()) return false;
    ranking = nlohmann::json::object();
  }
  const std::string chosen = ranking.value("chosen", std::string());
  const std::string ranker_pick = ranking.contains("ranker_chosen") && ranking["ranker_chosen"].is_string()
                                      ? ranking["ranker_chosen"].get<std::string>()
                                      : chosen;
  const std::string want = choose.empty() ? ranker_pick : choose;
  std::error_code ec;
  if (want.empty() || (want == chosen && fs::exists(target, ec))) return false;
  bool found = false;
  std::string names;
  for (const fs::path& c : list_candidates(run / "candidates")) {
    found = found || c.filename() == want;
    names += (names.empty() ? "" : ", ") + c.filename().string();
  }
  if (!found)
    throw Error(std::string(kChooseKey) + ": no candidate '" + want + "' in " + (run / "candidates").string() +
                " (candidates: " + (names.empty() ? "none" : names) + ")");
  // target.mp4 first: if the process dies in between, ranking.json still disagrees with the
  // choice and the next run writes the target again.
  write_target_video(run / "candidates" / want, target);
  ranking["chosen"] = want;
  if (want == ranker_pick) {
    ranking.erase("ranker_chosen");
    ranking.erase("chosen_by");
  } else {
    ranking["ranker_chosen"] = ranker_pick;
    ranking["chosen_by"] = kChooseKey;
  }
  write_file_atomic(ranking_file, json_text(ranking, 2) + "\n");
  return true;
}

}  // namespace svgm
