// The part a clause aims at (see clause_target.h).
#include "procedural/clause_target.h"

#include <string>
#include <vector>

#include "procedural/motion_plan_internal.h"

namespace svgm {

using namespace motion_plan_internal;

// Whether the noun names a part the locator finds on the figure (part_locator.h), unless the
// document names a part so.
bool locatable_noun(const PromptNoun& n, const Rig& rig, FigureClass figure) {
  const PartShape shape = part_shape_of(n.word, figure);
  std::string ignore;
  return shape != PartShape::None && rig.root >= 0 && parts_for(rig, Target::Named, n.word, &ignore).empty() &&
         !locate_part(rig, shape).lobes.empty();
}

bool names_figure_kind(const PromptNoun& n) { return n.figure != FigureClass::None && n.figure != FigureClass::Object && n.figure != FigureClass::Scene; }

ClauseTarget clause_target(const Clause& c, const ParsedPrompt& prompt, const Rig& rig, FigureClass figure, const std::string& ground,
                           std::vector<std::string>* unknown_words) {
  ClauseTarget ct;
  for (const auto& n : c.nouns) {
    std::vector<int> hits;
    // A part of a kind the locator knows, unless the document names a part so: found on the
    // figure by its kind's prior (part_locator.h).
    if (!ct.have && (!n.object_of_preposition || n.preposition == "of") && !n.own_predicate && locatable_noun(n, rig, figure)) {  // "a cloud of smoke"
      ct.have = true;
      ct.target = Target::Named;
      ct.word = n.word;
      ct.plural = n.plural;
      ct.located = locate_part(rig, part_shape_of(n.word, figure));
      continue;
    }
    if (n.target == Target::Named) {
      std::string ignore;
      hits = parts_for(rig, Target::Named, n.word, &ignore);
      if (hits.empty()) {
        // The ground's noun was understood: it is where the figure moves. So was the figure's
        // own noun, the subject naming a kind of figure ("the tiger": a quadruped): it names
        // who moves, not a part (the report listed "tiger" as not understood).
        // So was a thing's noun the lexicon gave a motion of its own ("the ship": a vessel, which
        // rocks; "the speedboat"): the suite listed every ship, ferry and speedboat as not understood.
        const bool kind = names_figure_kind(n) || (n.figure == FigureClass::Object && n.motion);
        const bool own_noun = kind && n.figure == c.figure && !n.after_verb && !n.object_of_preposition;
        if (unknown_words && !own_noun && ground.substr(ground.rfind(' ') + 1) != n.word) unknown_words->push_back(n.word);
        continue;
      }
      // The verb's object naming only the backdrop ("rides the waves") is where the figure
      // moves, not what moves: the backdrop moves when it is the subject ("the waves roll").
      bool backdrop = true;
      for (int h : hits) backdrop = backdrop && rig.parts[h].role == Role::Background;
      if (backdrop && n.after_verb) continue;
    }
    if (ct.have || n.object_of_preposition || n.own_predicate) continue;
    ct.have = true;
    // The prompt's first word of a part, said of itself ("the face yawns", "the head nods"),
    // with no such part in the drawing: the drawing is that part (a face emoji, a lone leaf),
    // and the whole figure moves. Not a part named after a verb ("raises its head"), nor one
    // owned ("its head slithers"), nor of something named before it ("the man's face": its
    // first noun is the man); not the drawing's repeated elements or backdrop.
    if (is_part_target(n.target) && &c == &prompt.clauses.front() && &n == &c.nouns.front() && !n.after_verb && !n.owned) {
      std::string none;
      if (parts_for(rig, n.target, n.word, &none).empty()) {
        ct.target = Target::Whole;
        ct.word = n.word;
        ct.plural = n.plural;
        continue;
      }
    }
    ct.target = n.target;
    ct.named = hits;
    ct.word = n.word;
    ct.plural = n.plural;
  }
  return ct;
}

}  // namespace svgm
