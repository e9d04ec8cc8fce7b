// The part a clause of the prompt aims at (motion_plan.cpp's plan_from_prompt): a known part
// noun ("its wings"), a word naming a part of the document ("the mane"), a part the locator finds
// by its kind ("the ears"), or the whole figure when the clause's subject is a part the drawing
// is made of ("the face yawns" on a face). Words that name nothing drawn are collected for the
// report, apart from the figure's own noun and the ground's.
#pragma once

#include <string>
#include <vector>

#include "procedural/part_locator.h"
#include "procedural/prompt_parse.h"
#include "procedural/part_rig.h"

namespace svgm {

struct ClauseTarget {
  Target target = Target::Whole;
  std::vector<int> named;  // the rig's parts the word names (Named), else empty
  std::string word;
  bool plural = false, have = false;
  LocatedPart located;  // a part the rig has none for, found on the figure (lobes empty: none)
};

// `figure`: the plan's figure class; `ground`: the plan's ground words ("" for none);
// `unknown_words`, when given, gets the clause's nouns that name nothing drawn.
ClauseTarget clause_target(const Clause& c, const ParsedPrompt& prompt, const Rig& rig, FigureClass figure, const std::string& ground,
                           std::vector<std::string>* unknown_words);

// Whether the noun names a part the locator finds on the figure (part_locator.h), unless the
// document names a part so.
bool locatable_noun(const PromptNoun& n, const Rig& rig, FigureClass figure);

// A noun naming a kind of figure ("the grasshopper": an insect) was understood: it chose the
// figure's class, though no part is named so.
bool names_figure_kind(const PromptNoun& n);

}  // namespace svgm
