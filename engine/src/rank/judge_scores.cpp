// judge_scores.h: stage-1 answers of the two-stage judge and the finalists they select.
#include "rank/judge_scores.h"

#include <algorithm>
#include <cctype>

#include "svgmotion/error.h"
#include "svgmotion/utf8_text.h"

namespace svgm {

using json = nlohmann::json;

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Candidates ordered by points (most first), then by their place in `preference`.
std::vector<const JudgeScore*> by_points(const std::vector<JudgeScore>& scores,
                                         const std::vector<std::string>& preference) {
  auto place = [&](const std::string& c) {
    return std::find(preference.begin(), preference.end(), c) - preference.begin();
  };
  std::vector<const JudgeScore*> out;
  for (const auto& s : scores) out.push_back(&s);
  std::stable_sort(out.begin(), out.end(), [&](const JudgeScore* a, const JudgeScore* b) {
    return a->points != b->points ? a->points > b->points : place(a->candidate) < place(b->candidate);
  });
  return out;
}

}  // namespace

json JudgeScore::to_json() const {
  json j = {{"candidate", candidate}};
  for (int k = 0; k < 4; ++k) j[kJudgeConstraints[k]] = verdicts[k];
  j["viable"] = viable;
  j["points"] = points;
  j["reason"] = reason;
  j["answer"] = answer;
  return j;
}

JudgeScore read_judge_score(const std::string& candidate, const std::string& answer) {
  auto bad = [&](const std::string& what) -> Error {
    return Error("malformed answer for " + candidate + ": " + what);
  };
  const json a = json::parse(answer, nullptr, false);
  if (a.is_discarded() || !a.is_object()) throw bad("not a JSON object");
  JudgeScore s;
  s.candidate = candidate;
  s.answer = answer;
  for (int k = 0; k < 4; ++k) {
    const char* key = kJudgeConstraints[k];
    if (!a.contains(key) || !a[key].is_string()) throw bad(std::string("no \"") + key + "\" verdict");
    const std::string v = lower(a[key].get<std::string>());
    if (v == "yes") s.verdicts[k] = "Yes", s.points += 2;
    else if (v == "partial") s.verdicts[k] = "Partial", s.points += 1;
    else if (v == "no") s.verdicts[k] = "No";
    else throw bad(std::string("\"") + key + "\" is '" + a[key].get<std::string>() + "', not Yes, Partial or No");
  }
  if (!a.contains("viable")) throw bad("no \"viable\"");
  const json& v = a["viable"];
  if (v.is_boolean()) s.viable = v.get<bool>();
  else if (v.is_string() && (lower(v.get<std::string>()) == "yes" || lower(v.get<std::string>()) == "no"))
    s.viable = lower(v.get<std::string>()) == "yes";
  else throw bad("\"viable\" is " + json_text(v) + ", not true or false");
  if (a.contains("reason") && a["reason"].is_string()) s.reason = a["reason"].get<std::string>();
  return s;
}

std::vector<std::string> judge_finalists(const std::vector<JudgeScore>& scores,
                                         const std::vector<std::string>& preference, int top_k) {
  std::vector<std::string> out;
  for (const JudgeScore* s : by_points(scores, preference))
    if (s->viable && static_cast<int>(out.size()) < top_k) out.push_back(s->candidate);
  return out;
}

std::string judge_best_of_rest(const std::vector<JudgeScore>& scores, const std::vector<std::string>& preference) {
  const auto order = by_points(scores, preference);
  return order.empty() ? std::string() : order.front()->candidate;
}

}  // namespace svgm
