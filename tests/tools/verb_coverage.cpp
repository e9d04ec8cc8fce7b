// Bench tool: how many common motion verbs the prompt parser understands (issue 35, "understand
// words broadly"). Reads rows "lemma <tab> lexicographer file" (tests/bench/verb_coverage.sh
// takes them from WordNet's tagged counts) and parses each verb in three template prompts, "the
// man VERBs", "the bird VERBs its wings", "the dog VERBs" (a phrasal lemma "take_off" as "takes
// off"). Prints one row per verb and template: the lemma, its file, the template, how the parse
// read it (vocabulary: a verb the table lists; lexicon: read through WordNet; none) and the
// motion, then a summary per template. Whether a reading is a plausible motion is judged by hand
// on a sample: the tool only counts.
#include <cstdio>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "procedural/prompt_parse.h"

namespace {

// The third person singular of a verb's first word: "wash" -> "washes", "fly" -> "flies".
std::string third_person(const std::string& lemma) {
  std::string w = lemma, rest;
  if (const size_t u = w.find('_'); u != std::string::npos) rest = w.substr(u), w = w.substr(0, u);
  for (char& c : rest)
    if (c == '_') c = ' ';
  static const std::map<std::string, std::string> irregular = {{"be", "is"}, {"have", "has"}, {"do", "does"}, {"go", "goes"}};
  if (const auto it = irregular.find(w); it != irregular.end()) return it->second + rest;
  auto ends = [&](const char* s) { const std::string e(s); return w.size() >= e.size() && w.compare(w.size() - e.size(), e.size(), e) == 0; };
  const bool vowel_before_y = w.size() > 1 && std::string("aeiou").find(w[w.size() - 2]) != std::string::npos;
  if (ends("y") && !vowel_before_y) return w.substr(0, w.size() - 1) + "ies" + rest;
  if (ends("s") || ends("x") || ends("z") || ends("ch") || ends("sh") || ends("o")) return w + "es" + rest;
  return w + "s" + rest;
}

}  // namespace

int main() {
  const std::vector<std::string> templates = {"the man %s", "the bird %s its wings", "the dog %s"};
  std::vector<std::map<std::string, int>> counts(templates.size());
  std::string line;
  int verbs = 0;
  while (std::getline(std::cin, line)) {
    if (line.empty() || line[0] == '#') continue;
    const size_t tab = line.find('\t');
    const std::string lemma = line.substr(0, tab), file = tab == std::string::npos ? "" : line.substr(tab + 1);
    ++verbs;
    for (size_t t = 0; t < templates.size(); ++t) {
      const std::string said = third_person(lemma);
      char prompt[256];
      std::snprintf(prompt, sizeof prompt, templates[t].c_str(), said.c_str());
      const svgm::ParsedPrompt p = svgm::parse_prompt(prompt);
      std::string how = "none", motion;
      for (const svgm::Clause& c : p.clauses)
        for (size_t i = 0; i < c.verbs.size(); ++i) {
          const bool lexicon = c.verb_words[i].find("->") != std::string::npos;
          if (how == "none" || (how == "lexicon" && !lexicon)) how = lexicon ? "lexicon" : "vocabulary";
          motion += (motion.empty() ? "" : "+") + c.verbs[i]->name;
        }
      ++counts[t][how];
      std::string readings;
      for (const std::string& r : p.readings) readings += (readings.empty() ? "" : "; ") + r;
      std::printf("%s\t%s\t%zu\t%s\t%s\t%s\t%s\n", lemma.c_str(), file.c_str(), t + 1, how.c_str(),
                  motion.empty() ? "-" : motion.c_str(), prompt, readings.c_str());
    }
  }
  for (size_t t = 0; t < templates.size(); ++t) {
    const int v = counts[t]["vocabulary"], l = counts[t]["lexicon"], n = counts[t]["none"];
    std::fprintf(stderr, "template %zu \"%s\": %d verbs: vocabulary %d, lexicon %d, understood %d (%.0f %%), not %d\n", t + 1,
                 templates[t].c_str(), verbs, v, l, v + l, verbs ? 100.0 * (v + l) / verbs : 0.0, n);
  }
  return 0;
}
