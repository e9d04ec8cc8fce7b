// Whether a prompt sends its figure across the canvas (see travel_words.h).
#include "procedural/travel_words.h"

#include "procedural/gait_travel.h"
#include "procedural/carried_flight.h"
#include "procedural/motion_plan_internal.h"
#include "procedural/self_movers.h"

#include <sstream>
#include <string>
#include <vector>

namespace svgm {

bool says_leaving(const Clause& c) {
  bool moves = false;
  // A launch's or a landing's "off" is its own ("takes off", "blasts off": flight_aim.h).
  for (const Verb* v : c.verbs) {
    if (v && (v->name == "takeoff" || v->name == "land")) return false;
    moves = moves || (v && (locomotes(*v) || v->name == "move"));
  }
  if (!moves) return false;
  std::vector<std::string> w;
  std::istringstream in(c.text);
  for (std::string x; in >> x;) w.push_back(x);
  for (size_t i = 0; i < w.size(); ++i) {
    const std::string next = i + 1 < w.size() ? w[i + 1] : std::string();
    const bool names_where = next == "the" || next == "a" || next == "an" || next == "its" || next == "his" || next == "her" || next == "their";
    if (w[i] == "away" || (w[i] == "off" && !names_where)) return true;
  }
  return false;
}

bool sends_figure_across(const ParsedPrompt& prompt) {
  bool stays = false, told = false, untold = false;
  for (const Clause& c : prompt.clauses) {
    stays = stays || stays_put(c.text);
    told = told || says_leaving(c);
    for (const PromptNoun& n : c.nouns) stays = stays || (!n.object_of_preposition && motion_plan_internal::is_limb_target(n.target));
    for (const Verb* v : c.verbs)
      if (gets_somewhere(*v) || v->name == "move") {
        told = told || c.mods.travel != 0 || c.mods.across;
        // Untold, only a gait goes (travel_where_told): a rider's pedalling is the vehicle's.
        untold = untold || (c.mods.travel == 0 && c.mods.vertical == 0 && c.mods.depth == 0 && is_gait(*v, c.figure));
      }
  }
  return told || (untold && !stays);
}

bool sends_figure_one_way(const ParsedPrompt& prompt) {
  bool told = false;
  for (const Clause& c : prompt.clauses) {
    if (stays_put(c.text)) return false;
    for (const Verb* v : c.verbs) told = told || (c.mods.travel != 0 && (locomotes(*v) || v->name == "move"));
  }
  return told;
}

bool carries_figure_about(const ParsedPrompt& prompt) {
  for (const Clause& c : prompt.clauses) {
    std::string part;
    for (const PromptNoun& n : c.nouns)
      if (part.empty() && !n.object_of_preposition && !n.own_predicate && n.target != Target::Named) part = n.word;
    for (size_t i = 0; i < c.verbs.size(); ++i) {
      const Verb* v = insect_flight(c.verbs[i], c, verb_word(c, i));
      if (v->name == "float" && part.empty()) return true;
      if (carries_figure(*v) && keeps_whole(*v, c, part)) return true;
    }
  }
  return false;
}

bool launches_figure(const ParsedPrompt& prompt) {
  for (const Clause& c : prompt.clauses)
    for (const Verb* v : c.verbs)
      if (v && (v->name == "takeoff" || v->name == "land")) return true;
  return false;
}

}  // namespace svgm
