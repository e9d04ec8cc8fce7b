// A noun's sense chosen by the prompt's other nouns (see sense_context.h).
#include "motion/sense_context.h"

#include <algorithm>
#include <limits>
#include <unordered_map>

namespace svgm {

namespace {

using wordnet::Pos;

// The senses of a context noun that count: a word's rare senses are other meanings.
constexpr size_t kContextSenses = 3;

// A synset and its hypernyms up to `depth` steps, each with its fewest steps.
std::unordered_map<uint32_t, int> up_to(const wordnet::Database& db, uint32_t synset, int depth) {
  std::unordered_map<uint32_t, int> out = {{synset, 0}};
  for (const wordnet::Ancestor& a : db.hypernyms(Pos::Noun, synset, depth))
    if (!out.count(a.offset)) out[a.offset] = a.depth;
  return out;
}

// The context's synsets: the first senses of each word that is a noun, and the wholes each is a
// part of, with the word that led there.
struct ContextSynset {
  uint32_t offset;
  std::string word;
};

std::vector<ContextSynset> context_synsets(const wordnet::Database& db, const std::string& lemma, const std::vector<std::string>& context) {
  std::vector<ContextSynset> out;
  for (const std::string& w : context) {
    const std::vector<std::string> lemmas = db.base_forms(w, Pos::Noun);
    if (lemmas.empty() || lemmas.front() == lemma) continue;
    const std::vector<uint32_t> senses = db.senses(lemmas.front(), Pos::Noun);
    for (size_t r = 0; r < std::min(senses.size(), kContextSenses); ++r) {
      out.push_back({senses[r], w});
      if (const auto s = db.synset(Pos::Noun, senses[r]))
        for (const wordnet::Pointer& p : s->pointers)
          if (p.pos == Pos::Noun && p.symbol == "#p") out.push_back({p.offset, w});
    }
  }
  return out;
}

}  // namespace

std::vector<uint32_t> senses_by_context(const wordnet::Database& db, const std::string& lemma, const std::vector<uint32_t>& senses,
                                        const std::vector<std::string>& context, std::string* why) {
  if (senses.size() < 2 || context.empty()) return senses;
  const std::vector<ContextSynset> cues = context_synsets(db, lemma, context);
  if (cues.empty()) return senses;
  std::vector<std::unordered_map<uint32_t, int>> cue_up;
  for (const ContextSynset& c : cues) cue_up.push_back(up_to(db, c.offset, kMaxSensePath));
  constexpr int kFar = std::numeric_limits<int>::max();
  // Each sense's shortest path to a cue through a common hypernym, and the cue and the meeting point.
  struct Near {
    int path = kFar;
    size_t cue = 0;
    uint32_t meet = 0;
  };
  std::vector<Near> near(senses.size());
  for (size_t i = 0; i < senses.size(); ++i)
    for (const auto& [offset, d] : up_to(db, senses[i], kMaxSensePath))
      for (size_t c = 0; c < cues.size(); ++c)
        if (const auto it = cue_up[c].find(offset); it != cue_up[c].end() && d + it->second < near[i].path)
          near[i] = {d + it->second, c, offset};
  size_t best = 0;
  for (size_t i = 1; i < senses.size(); ++i)
    if (near[i].path < near[best].path) best = i;
  if (best == 0 || near[best].path > kMaxSensePath) return senses;
  std::vector<uint32_t> out = senses;
  std::rotate(out.begin(), out.begin() + static_cast<long>(best), out.begin() + static_cast<long>(best) + 1);
  if (why) {
    const auto meet = db.synset(Pos::Noun, near[best].meet);
    *why = lemma + ": sense " + std::to_string(best + 1) + " (" + (meet && !meet->words.empty() ? meet->words.front() : "?") + ", " +
           std::to_string(near[best].path) + " steps from '" + cues[near[best].cue].word + "')";
  }
  return out;
}

}  // namespace svgm
