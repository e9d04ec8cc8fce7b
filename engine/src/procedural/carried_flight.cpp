// Flight that carries the whole figure (see carried_flight.h).
#include "procedural/carried_flight.h"

#include <algorithm>
#include <sstream>
#include <vector>

namespace svgm {

bool carries_figure(const Verb& v) { return v.name == "hover" || v.name == "buzz"; }

namespace {

// Where `word` first is in `words`; words.size() when it is not there.
size_t position(const std::vector<std::string>& words, const std::string& word) {
  return static_cast<size_t>(std::find(words.begin(), words.end(), word) - words.begin());
}

}  // namespace

bool keeps_whole(const Verb& v, const Clause& c, const std::string& part_word) {
  if (!carries_figure(v)) return false;
  // By the clause's words, not the noun's after_verb: a clause with no verb of its own joins the
  // one before it ("hovers, its wings a blur"), its nouns read before the verb was.
  std::vector<std::string> words;
  std::istringstream in(c.text);
  for (std::string w; in >> w;) words.push_back(w);
  size_t verb_at = words.size();
  for (size_t i = 0; i < c.verbs.size() && i < c.verb_words.size(); ++i)
    if (c.verbs[i] == &v) {
      // "whirring", "shuffles->walk", "takes off->takeoff": the first word as written.
      const std::string said = c.verb_words[i].substr(0, c.verb_words[i].find_first_of(" -"));
      verb_at = std::min(verb_at, position(words, said));
    }
  // Said of a part ("its rotors whirring": a possessive before the verb), found or not: the
  // figure does not dart about for it. Unfound, a drone's rotors whirring had it dart instead of
  // hovering.
  for (size_t i = 0; i < verb_at; ++i)
    if (words[i] == "its" || words[i] == "his" || words[i] == "her" || words[i] == "their") return false;
  return part_word.empty() || position(words, part_word) > verb_at;
}

bool carried_whole(const PlannedAction& a) {
  if (a.target != Target::Whole || !a.parts.empty() || a.primitive == Primitive::Spin || a.primitive == Primitive::Turn) return false;
  const Verb* v = find_verb_by_name(a.verb);
  return v && carries_figure(*v);
}

}  // namespace svgm
