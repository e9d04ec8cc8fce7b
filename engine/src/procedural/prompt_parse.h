// Reading a prompt into clauses of motion: "a bat is flapping its wings up and down" becomes
// one clause {verbs: flap, nouns: wings (plural), modifiers: up, down}; "rain falls on the
// umbrella and it sways" becomes two clauses {fall} and {sway}. The motion vocabulary is in
// motion_verbs.h. Also reads an explicit plan ("flap:wing*, bob:body") that a user gives in
// stages.video.options.motion to say exactly what moves.
//
// Clauses split at punctuation and at conjunctions (and, while, then, as, but); a clause with no
// verb ("down" in "up and down", "his hands in the air") joins the clause before it, so its
// nouns and modifiers apply to that verb, unless it has a participle of its own that the
// vocabulary does not know ("sways gently, its hood slightly flared": the hood flares, it is not
// what sways). A noun right after a preposition ("falls on the
// umbrella", "the wheels of the bicycle") is where or whose, not what moves, and is kept apart.
//
// Words the vocabulary does not list are read by the motion lexicon (motion/lexicon.h) when
// WordNet is installed: in a verb's place, as the nearest vocabulary verb ("shuffles" read as
// walk); in a noun's place (after an article, a possessive or a preposition, or before a verb:
// "rides the waves", "the hummingbird hovers"), as a figure class and the motion such a thing
// makes by itself. "left" and "right" before a part ("his right arm") are the figure's own side;
// elsewhere ("drifts right", "walks to the left") where the whole figure travels; after "from"
// ("from left to right") where it sets out from. "across" after a verb says it goes across, not
// which way (Modifiers::across). A verb of making a noise ("the locomotive chugs", "the beetle
// drones") is read as the motion of who makes it: a vehicle's own, an insect's wings, a thing's
// shake, a creature's voice; a vehicle sent somewhere by a verb that takes it nowhere goes by its
// own motion too.
#pragma once

#include <string>
#include <vector>

#include "motion/lexicon.h"
#include "motion/motion_verbs.h"

namespace svgm {

struct PromptNoun {
  std::string word;      // as written ("wings")
  Target target;         // Named when it is not a known part noun (matched to part names later)
  bool plural = false;
  bool object_of_preposition = false;  // "on the umbrella": not a target
  bool after_verb = false;             // "rides the waves": the verb's object
  bool owned = false;                  // after a possessive ("its head", "his left arm")
  bool own_predicate = false;          // "its hood slightly flared": said to do something the
                                       // vocabulary does not know, so not another verb's target
  FigureClass figure = FigureClass::None;  // the lexicon's class of the thing it names
  const Verb* motion = nullptr;            // the motion such a thing makes by itself (lexicon)
  std::string preposition = {};            // the one its phrase opened with ("on" in "bobs on the
                                           // waves"); empty when not after one, or not known
};

struct Clause {
  std::string text;                 // the clause's words, space-separated
  std::vector<const Verb*> verbs;   // in order, no repeats
  std::vector<std::string> verb_words;  // as written; "shuffles->walk" when the lexicon read it
  std::vector<PromptNoun> nouns;    // known part nouns and every other content word, in order
  Modifiers mods;
  FigureClass figure = FigureClass::None;  // of who moves: its first noun with a class that is
                                           // not after a preposition ("a surfer" -> biped)
};

struct ParsedPrompt {
  std::vector<Clause> clauses;
  // Words in a verb's place that neither the vocabulary nor the lexicon could place ("yawns"
  // with no motion above it in WordNet); they are kept as nouns too, as before.
  std::vector<std::string> unplaced;
  // What the lexicon read, one line each for the report: "shuffles read as walk",
  // "hummingbird: a bird".
  std::vector<std::string> readings;
  // Every word of the prompt, lower case, in order: the context a noun's sense is chosen by.
  std::vector<std::string> words;
};

ParsedPrompt parse_prompt(const std::string& prompt);

// One step of an explicit plan: "flap:wing*" (verb, part name patterns joined by '+', '*'
// matching any run of characters), optionally followed by modifier words ("wave:arm* slow").
struct ExplicitStep {
  std::string verb;
  std::vector<std::string> patterns;  // empty: the verb's own targets
  Modifiers mods;
};

// Parses "verb[:pattern[+pattern...]] [modifier ...]" items separated by ',' or ';'. Throws
// svgm::Error ("motion plan 'xyz:wing': unknown verb 'xyz' ...") for an unknown verb or
// modifier, or an empty item.
std::vector<ExplicitStep> parse_explicit_plan(const std::string& text);

// '*' globbing, case-insensitive.
bool glob_match(const std::string& pattern, const std::string& text);

}  // namespace svgm
