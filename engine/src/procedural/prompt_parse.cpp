// Prompt clauses and explicit plans (see prompt_parse.h).
#include "procedural/prompt_parse.h"

#include <algorithm>
#include <cctype>

#include "procedural/gait_travel.h"
#include "svgmotion/error.h"

namespace svgm {

namespace {

std::string lower(const std::string& s) {
  std::string r;
  for (char c : s) r += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return r;
}

bool is_conjunction(const std::string& w) {
  return w == "and" || w == "while" || w == "whilst" || w == "then" || w == "as" || w == "but" ||
         w == "before" || w == "after";
}

bool is_preposition(const std::string& w) {
  static const std::vector<std::string> p = {"on", "onto", "in", "into", "at", "over", "under", "from", "to",
                                             "through", "across", "against", "above", "below", "behind", "near",
                                             "of", "with", "by", "toward", "towards", "past", "beside", "off"};
  return std::find(p.begin(), p.end(), w) != p.end();
}

bool is_determiner(const std::string& w) {
  return w == "the" || w == "a" || w == "an" || w == "its" || w == "his" || w == "her" || w == "their" || w == "my" ||
         w == "your" || w == "our";
}

const Verb* verb_for_word(const std::string& w) { return find_verb_by_word(w); }

// "surfer", "runners", "biker", "rider": a verb with the agent ending ("er" after a stem, which
// word_matches reads as an inflection; "r" after a verb's word ending in "e").
bool is_agent_noun(const std::string& w) {
  const std::string one = w.size() > 1 && w.back() == 's' ? w.substr(0, w.size() - 1) : w;
  if (one.size() < 5 || one.compare(one.size() - 2, 2, "er") != 0) return false;
  return verb_for_word(one) || verb_for_word(one.substr(0, one.size() - 1));
}

const PartNoun* noun_for_word(const std::string& w) {
  for (const auto& n : part_nouns())
    if (word_matches(w, n.stem) || (n.stem == "leaf" && w == "leaves")) return &n;
  return nullptr;
}

bool is_possessive(const std::string& w) {
  return w == "his" || w == "her" || w == "its" || w == "their" || w == "my" || w == "your" || w == "our";
}

bool is_particle(const std::string& w) {
  return w == "off" || w == "out" || w == "up" || w == "down" || w == "away" || w == "over" || w == "around" || w == "along" ||
         w == "round" || w == "about";
}

// "left" or "right" where the whole figure goes ("drifts right", "walks to the left"), not the
// figure's own side ("his right arm", "the left wing", "to his left"): no possessive before it
// and no noun after it. A bare one ("leans left") keeps setting the side as it always has; "to
// the left" is only the travel. After "from" it is where the figure sets out from: it goes the
// other way ("from left to right": to the right; read as two ways, they cancelled to none).
bool read_travel(const std::string& w, const std::string& prev, const std::string& prev2, const std::string& next,
                 Modifiers& m) {
  if (w != "left" && w != "right") return false;
  Modifiers probe;
  const bool next_is_noun = !next.empty() && !is_filler_word(next) && !is_preposition(next) && !is_conjunction(next) &&
                            !apply_modifier(next, probe);
  if (is_possessive(prev) || next_is_noun) return false;
  if (prev == "from" || (prev == "the" && prev2 == "from")) {
    const int from = w == "right" ? -1 : 1;
    m.travel = m.travel == -from ? 0 : from;
    m.words.push_back("from the " + w);
    return true;
  }
  const int dir = w == "right" ? 1 : -1;
  m.travel = m.travel == -dir ? 0 : dir;
  const bool phrase = prev == "the" && (prev2 == "to" || prev2 == "toward" || prev2 == "towards");
  if (!phrase) apply_modifier(w, m);
  m.words.push_back(phrase ? "to the " + w : w + " (travel)");
  return true;
}

// A word right before a part noun that says WHICH of the figure's limbs of that kind move: by
// where they are along its facing ("its hind legs", "the front paws", "the back legs") or up
// and down ("his lower arm"). Not a noun of its own: WordNet's "hind" is a deer and a fish, its
// "back" the body's. "left" and "right" before a part are the figure's side (apply_modifier).
bool read_qualifier(const std::string& w, Modifiers& m) {
  int end = 0, level = 0;
  if (w == "front" || w == "fore" || w == "forward") end = 1;
  else if (w == "hind" || w == "rear" || w == "back" || w == "hinder") end = -1;
  else if (w == "upper" || w == "top") level = 1;
  else if (w == "lower" || w == "bottom") level = -1;
  else return false;
  if (end) m.end = m.end == -end ? 0 : end;
  if (level) m.level = m.level == -level ? 0 : level;
  m.words.push_back(w);
  return true;
}

// A part noun written with its qualifier as one word ("forelegs", "hindwings", "forepaws"):
// the part noun after "fore" or "hind" when WordNet does not know the word or files it with the
// animals, whose limbs come in front and hind pairs. A forearm (part of a person's arm) and a
// forehead are noun.body words: they stay words of their own.
const PartNoun* noun_for_word(const std::string& w);
bool split_qualified_part(const Lexicon& lexicon, const std::string& w, std::string& qualifier, std::string& part) {
  for (const char* q : {"fore", "hind"}) {
    const size_t n = std::char_traits<char>::length(q);
    if (w.size() <= n + 2 || w.compare(0, n, q) != 0) continue;
    const std::string rest = w.substr(n);
    const PartNoun* p = noun_for_word(rest);
    if (!p || (lexicon.knows_noun(w) && !lexicon.noun_is_animal_word(w))) continue;
    qualifier = q;
    part = rest;
    return true;
  }
  return false;
}

// The part noun of `w` when it is written with its qualifier ("forelegs": "legs", the qualifier
// read into `m`); else `w` itself.
std::string read_qualified_part(const Lexicon& lexicon, const std::string& w, Modifiers& m, ParsedPrompt& out) {
  std::string qualifier, part_word = w;
  if (lexicon.has_wordnet() && !noun_for_word(w) && split_qualified_part(lexicon, w, qualifier, part_word)) {
    read_qualifier(qualifier, m);
    out.readings.push_back("'" + w + "' read as " + qualifier + " " + part_word);
  }
  return part_word;
}

// A verb and the word after it that WordNet lists as one verb with no motion above it is not
// the verb's motion: "falls asleep" is no fall (the pair is named as not understood). Not before
// a direction ("bobs up and down") or a preposition ("leans against the wall"), which say where
// the verb's motion goes.
bool joined_without_motion(const Lexicon& lexicon, const std::string& w, const std::string& next, ParsedPrompt& out) {
  Modifiers direction;
  if (!lexicon.has_wordnet() || next.empty() || apply_modifier(next, direction) || is_filler_word(next) || is_preposition(next) ||
      !lexicon.knows_verb(w + "_" + next) || lexicon.phrasal_verb(w, next).verb)
    return false;
  out.readings.push_back("'" + w + " " + next + "' read as one verb, no motion");
  out.unplaced.push_back(w + " " + next);
  return true;
}

// "towards the viewer", "into the distance": the figure comes nearer or goes away.
int depth_of(const std::vector<std::string>& words, size_t at) {
  const std::string& w = words[at];
  if (w != "toward" && w != "towards" && w != "into") return 0;
  for (size_t k = at + 1; k < std::min(words.size(), at + 3); ++k) {
    const std::string& n = words[k];
    if (n == "viewer" || n == "camera" || n == "us" || n == "me" || n == "you" || n == "screen" || n == "foreground")
      return w == "into" ? 0 : 1;
    if (n == "distance" || n == "horizon" || n == "background") return -1;
  }
  return 0;
}

bool ends_with(const std::string& w, const char* suffix) {
  const size_t n = std::char_traits<char>::length(suffix);
  return w.size() > n && w.compare(w.size() - n, n, suffix) == 0;
}

// The words a noun's sense is chosen by (motion/sense_context.h): the prompt's other words, less
// the vocabulary's verbs that are no part nouns (a "bob" is also a haircut: "bobs on the waves"
// read the waves as hairdos) and the word right before each place the noun stands, which
// modifies it ("cigarette smoke" is smoke, not the roll of tobacco WordNet also calls smoke).
// Nor the noun of a prepositional phrase other than "of" ("rises from the cigarette", "bobs on
// the waves"): it names where or whence, another thing ("the wheels of the car" name its whole).
std::vector<std::string> sense_context(const std::vector<std::string>& words, const std::string& w) {
  std::vector<std::string> out;
  bool in_phrase = false;
  for (size_t i = 0; i < words.size(); ++i) {
    const std::string& x = words[i];
    if (is_preposition(x)) {
      in_phrase = x != "of";
      continue;
    }
    const bool before_it = i + 1 < words.size() && words[i + 1] == w;
    const bool verb = verb_for_word(x) && !noun_for_word(x);
    // (Nor a word of two letters or an auxiliary: "is" is also WordNet's noun Iceland.)
    const bool auxiliary = x.size() < 3 || x == "are" || x == "was" || x == "were" || x == "has" || x == "have" || x == "been" || x == "does";
    if (x != w && !before_it && !verb && !auxiliary && !in_phrase) out.push_back(x);
    // The phrase ends at its noun: the first word after it that is not an article or a possessive.
    if (in_phrase && !is_determiner(x) && !is_possessive(x)) in_phrase = false;
  }
  return out;
}

// A noun outside the vocabulary, as WordNet reads it: its figure class, the motion such a thing
// makes by itself, and the body part it is a kind or a part of.
void read_lexicon_noun(const Lexicon& lexicon, const std::string& w, const std::string& next, PromptNoun& n, ParsedPrompt& out) {
  const NounReading r = lexicon.noun(w, sense_context(out.words, w));
  if (!r.sense_why.empty()) out.readings.push_back("'" + w + "' by its context: " + r.sense_why);
  n.figure = r.figure;
  n.motion = r.motion;
  // A kind or a part of a body part the vocabulary knows ("talons": claws, "fingers": hands).
  // Not the body itself ("figure" is a synonym of body in WordNet, and a prompt's "figure"
  // is the whole), nor repeated elements or the background (a "sun" is not stars).
  // Nor a word right before a part noun the vocabulary knows: it is that noun's modifier
  // ("his upper body": WordNet's noun "upper" is part of a shoe, read as a boot, and the
  // saxophonist's legs swayed instead of his body).
  bool modifies_part = false;
  for (const PartNoun& pn : part_nouns()) modifies_part = modifies_part || word_matches(next, pn.stem);
  if (r.part && !modifies_part && r.part->target != Target::Root && r.part->target != Target::Repeated &&
      r.part->target != Target::Background) {
    n.target = r.part->target;
    out.readings.push_back("'" + w + "' read as " + r.part->stem);
  }
  if (r.figure != FigureClass::None)
    out.readings.push_back("'" + w + "': " + figure_class_name(r.figure) + (r.motion ? ", moves by itself as " + r.motion->name : ""));
}

// A pronoun after a verb is its object said again: "bouncing it" bounces the ball of
// "dribbles the ball" (the last object before it, in this clause or, `antecedent`, before).
bool read_pronoun(const std::string& w, const PromptNoun* antecedent, Clause& c, std::vector<bool>& modifier_noun,
                  ParsedPrompt& out) {
  if (w != "it" && w != "them") return false;
  const PromptNoun* said = antecedent;
  for (const PromptNoun& n : c.nouns)
    if (n.after_verb && !n.object_of_preposition && !n.own_predicate) said = &n;
  if (!said) return false;
  PromptNoun n = *said;
  n.after_verb = true;
  c.nouns.push_back(n);
  modifier_noun.push_back(false);
  out.readings.push_back("'" + w + "' read as the " + n.word);
  return true;
}

// After a noun naming a thing, not a creature, that the verb acts on ("climbs the rock face",
// "reads the clock face"), a part noun ends a compound naming that thing: it is not the figure's
// part. The caller checks that no possessive comes before ("his robot arm": the figure's own).
bool read_thing_compound(const std::string& w, bool plural, Clause& c, std::vector<bool>& modifier_noun, ParsedPrompt& out) {
  const PromptNoun* thing = c.nouns.empty() ? nullptr : &c.nouns.back();
  if (!thing || thing->target != Target::Named || !thing->after_verb ||
      (thing->figure != FigureClass::Object && thing->figure != FigureClass::Scene))
    return false;
  PromptNoun head = *thing;
  head.word = w;
  head.plural = plural;
  out.readings.push_back("'" + thing->word + " " + w + "' read as a " + thing->word + ", not the figure's " + w);
  c.nouns.push_back(head);
  modifier_noun.back() = true;
  modifier_noun.push_back(false);
  return true;
}

// A part noun the vocabulary knows, `w` as written: a noun of the clause, or the head of a
// compound naming a thing the verb acts on ("the rock face"; not after a possessive: "his robot
// arm"). Closes a prepositional phrase it ends. `after_possessive`: two words back ("his robot
// arm", "its left wing"); `owned`: one ("its head").
void read_part_noun(const std::string& w, const PartNoun& n, bool after_noun_word, bool owned, bool after_possessive, bool& after_prep,
                    const std::string& preposition, Clause& c, std::vector<bool>& modifier_noun, ParsedPrompt& out) {
  const bool plural = (w.size() > n.stem.size() && w.back() == 's') || w == "feet" || w == "leaves";
  if (after_noun_word && !after_possessive && read_thing_compound(w, plural, c, modifier_noun, out)) return;
  c.nouns.push_back({w, n.target, plural, after_prep, !c.verbs.empty(), owned || after_possessive});
  if (after_prep) c.nouns.back().preposition = preposition;
  if (after_noun_word && !modifier_noun.empty()) modifier_noun.back() = true;
  modifier_noun.push_back(false);
  after_prep = false;
}

// A verb said of fire right next to it ("flames leaping around it", "the leaping flames", "the
// fire dances") is how fire moves: fire does one thing, and the verbs said of it (leap, dance,
// lick, climb) are figures of speech for its flicker. A participle before a noun is that noun's
// adjective ("leaping flames"); after one, what it does ("flames leaping"). The heart on fire's
// flames read as leaping moved the whole heart up and down (share 0.32). Water does many things
// (falls, flows, ripples): its verbs stay. `subject`: the noun right before, or null.
const Verb* fire_motion(const Lexicon& lexicon, const std::string& w, const Verb* v, bool participle, const PromptNoun* subject,
                        const std::string& next, ParsedPrompt& out) {
  if (!lexicon.has_wordnet()) return v;
  const Verb* own = nullptr;
  std::string fire;
  if (subject && !subject->object_of_preposition && subject->figure == FigureClass::Flame && subject->motion)
    own = subject->motion, fire = subject->word;
  else if (participle && !next.empty()) {
    const NounReading r = lexicon.noun(next);
    if (r.figure == FigureClass::Flame && r.motion) own = r.motion, fire = next;
  }
  if (!own || own == v) return v;
  out.readings.push_back("'" + w + "' said of " + fire + " read as " + own->name + " (what " + fire + " does)");
  return own;
}

// A verb of making a noise (Lexicon::is_sound_verb: "chugs", "rumbles", "drones", "crows") says
// what moves by who makes it, the clause's first noun of a class that is not in a phrase: a
// thing that moves by itself makes its noise moving so (a train chugs as it drives, a boat as it
// rocks); an insect with its wings (its buzz); a thing that does not move by itself shakes
// with it (an alarm clock rings, as a cartoon draws it); a creature, or no one named, with its
// mouth (WordNet's reading where it has one, "hums": sings, speaks; else speak, a stem of eat).
// Read through WordNet alone, "the locomotive chugs" was not understood and "the beetle drones"
// moved its head.
// Who does what the clause says: its last noun of a class before its verb, not in a phrase (the
// head of a compound: the train of "the steam train", the clock of "the alarm clock").
const PromptNoun* clause_subject(const Clause& c) {
  const PromptNoun* who = nullptr;
  for (const PromptNoun& n : c.nouns)
    if (!n.object_of_preposition && !n.after_verb && n.figure != FigureClass::None) who = &n;
  return who;
}

VerbReading sound_motion(const Lexicon& lexicon, const std::string& w, const Clause& c) {
  const PromptNoun* who = clause_subject(c);
  if (who && who->figure == FigureClass::Insect) return {find_verb_by_name("buzz"), "an insect's noise: its wings", 0};
  if (who && who->motion && !is_creature(who->figure)) return {who->motion, "what " + who->word + " does", 0};
  if (who && who->figure == FigureClass::Object) return {find_verb_by_name("tremble"), "a thing making a noise shakes", 0};
  VerbReading r = lexicon.verb(w);
  if (!r.verb) r = {vocabulary_verb("speak"), "a voice: speak", 0};
  return r;
}

// A thing that goes by itself (a vehicle's drive, an aircraft's flight: not a creature, whose
// verbs say more) sent somewhere ("the steam train puffs off to the left": its smoke, read as a
// blow) goes by its own motion when no verb of the clause takes it anywhere: the train swayed
// where it stood. A clause with no verb moves by the noun's motion anyway (motion_plan.cpp); one
// that names a part moves that part ("the car's wheels spin to the right": they roll it along).
void own_motion_sent(Clause& c, ParsedPrompt& out) {
  const PromptNoun* who = clause_subject(c);
  if ((c.mods.travel == 0 && !c.mods.across) || c.verbs.empty() || !who || !who->motion || is_creature(who->figure) || !locomotes(*who->motion) ||
      std::any_of(c.verbs.begin(), c.verbs.end(), [](const Verb* v) { return locomotes(*v); }) ||
      std::any_of(c.nouns.begin(), c.nouns.end(), [](const PromptNoun& n) { return n.target != Target::Named && !n.object_of_preposition; }))
    return;
  out.readings.push_back("'" + who->word + "' sent somewhere goes by its own motion, " + who->motion->name);
  c.verbs.push_back(who->motion);
  c.verb_words.push_back(who->word + "->" + who->motion->name);
}

// A manner the modifiers do not list ("bows politely", "waves cheerfully"): WordNet knows the
// word as an adverb and not as a noun; said in the readings. Kept as a noun after the verb it
// was the verb's object, a thing held: "he bows politely" swung his arm (held_things.h).
bool read_manner(const Lexicon& lexicon, const std::string& w, ParsedPrompt& out) {
  if (!lexicon.has_wordnet() || lexicon.knows_noun(w) || lexicon.tagged_senses(w, wordnet::Pos::Adv) <= 0) return false;
  out.readings.push_back("'" + w + "': a manner, no motion");
  return true;
}

// Words of one clause (lower case, letters only). `after_prep` says the clause continues a
// prepositional phrase ("with black dots and black boots": "and" split it, and "boots" is
// still what she is dressed with); on return, whether the clause ends inside one. Words the
// lexicon could not place and what it read go to `out`. `antecedent`: the last verb's object of
// the clauses before, for a pronoun ("dribbles the ball, bouncing it"); null when none.
Clause read_clause(const std::vector<std::string>& words, bool& after_prep, ParsedPrompt& out,
                   const PromptNoun* antecedent) {
  const Lexicon& lexicon = Lexicon::shared();
  Clause c;
  FigureClass agent_figure = FigureClass::None;
  std::string prev, prev2;
  bool prev_was_verb = false, prev_was_noun = false;
  std::vector<bool> modifier_noun;  // per noun: followed by another noun ("candle" in "candle flame")
  std::string preposition;          // the last preposition of the clause
  for (size_t wi = 0; wi < words.size(); ++wi) {
    const std::string& w = words[wi];
    const bool prev_was_start = c.text.empty();
    c.text += (c.text.empty() ? "" : " ") + w;
    const bool after_determiner = is_determiner(prev);
    // "to" before a verb is the infinitive's ("starts to wave"), not a place.
    const bool after_preposition = is_preposition(prev) && prev != "to";
    const std::string before = prev, before2 = prev2;
    const bool after_verb = prev_was_verb, after_noun_word = prev_was_noun;
    prev2 = prev;
    prev = w;
    prev_was_verb = prev_was_noun = false;
    const std::string next = wi + 1 < words.size() ? words[wi + 1] : std::string();
    if (read_travel(w, before, before2, next, c.mods)) continue;
    // "walks across the road": it goes across (which way: gait_travel.h), after a verb only.
    if (w == "across" && !c.verbs.empty() && !c.mods.across) c.mods.across = true, c.mods.words.push_back("across");
    if (const int d = depth_of(words, wi)) {
      c.mods.depth = d;
      c.mods.words.push_back(d > 0 ? "towards the viewer" : "away");
    }
    if (Modifiers probe = c.mods; apply_modifier(w, probe)) {
      c.mods = probe;
      // "climbs up the rock face", "runs down the hill": the direction, and a phrase naming
      // where the figure moves along (not what moves).
      if ((w == "up" || w == "down") && is_determiner(next)) after_prep = true, preposition = w;
      continue;
    }
    if (after_verb && read_pronoun(w, antecedent, c, modifier_noun, out)) continue;
    if (noun_for_word(next) && read_qualifier(w, c.mods)) continue;
    const std::string part_word = read_qualified_part(lexicon, w, c.mods, out);
    // A known part noun is a noun even where its word could be a verb ("drops", "hands").
    if (const PartNoun* n = noun_for_word(part_word)) {
      read_part_noun(part_word, *n, after_noun_word, is_possessive(before), is_possessive(before2), after_prep, preposition, c, modifier_noun, out);
      prev_was_noun = true;
      continue;
    }
    // A verb's agent noun opening the clause or after an article ("a surfer rides", "the
    // biker is pedalling") is the one who moves: the whole figure, not a part named like it (a
    // surfer's shadow drawn as "shadow_surfer" swung while the surfer stood still).
    if ((prev_was_start || after_determiner) && is_agent_noun(w)) {
      if (agent_figure == FigureClass::None) agent_figure = lexicon.noun(w, sense_context(out.words, w)).figure;
      continue;
    }
    // A verb's word right after an article, a possessive or a preposition is a noun ("rides the
    // waves", "in the breeze", "on waves"), unless it is a participle ("a galloping horse", "a
    // waving flag"); so is a plural right after a verb, its object ("riding waves").
    const bool participle = w.size() > 4 && w.compare(w.size() - 3, 3, "ing") == 0;
    const bool object = after_verb && w.size() > 3 && w.back() == 's' && !ends_with(w, "ss") && verb_for_word(w) != verb_for_word(before);
    // ... and so is one right before a verb that says what it does ("the cobra snake sways": the
    // snake is who sways, it does not slither): a bare word followed by another verb's word
    // in the third person ("sways", not "swaying"). Two words of one verb say it once ("rain
    // falls").
    const bool bare = w.back() != 's' && !participle && !(w.size() > 3 && w.compare(w.size() - 2, 2, "ed") == 0);
    const bool next_third = next.size() > 3 && next.back() == 's' && next[next.size() - 2] != 's';
    const Verb* next_verb = next_third ? verb_for_word(next) : nullptr;
    // So is a vocabulary verb's word opening the clause or after an article when the next word
    // is a verb the vocabulary does not list but WordNet uses mostly as one ("rain lashes down":
    // the rain, lashing; not "rain" falling on eyelashes).
    const bool next_verb_only = next_third && !next_verb && lexicon.has_wordnet() && lexicon.knows_verb(next) &&
                                lexicon.tagged_senses(next, wordnet::Pos::Verb) > lexicon.tagged_senses(next, wordnet::Pos::Noun);
    // After a noun too, a compound's head ("the steam train puffs": no training, no exercise).
    const bool subject = bare && ((next_verb && next_verb != verb_for_word(w)) ||
                                  ((prev_was_start || after_determiner || after_noun_word) && next_verb_only));
    const bool noun_place = ((after_determiner || after_preposition) && !participle) || object;
    const Verb* v = noun_place || subject ? nullptr : verb_for_word(w);
    if (v && joined_without_motion(lexicon, w, next, out)) continue;
    if (v) v = fire_motion(lexicon, w, v, participle, after_noun_word && !c.nouns.empty() ? &c.nouns.back() : nullptr, next, out);
    if (v) {
      if (std::find(c.verbs.begin(), c.verbs.end(), v) == c.verbs.end()) {
        c.verbs.push_back(v);
        c.verb_words.push_back(v == verb_for_word(w) ? w : w + "->" + v->name);
      }
      after_prep = false;
      prev_was_verb = true;
      continue;
    }
    if (is_preposition(w)) { after_prep = true, preposition = w; continue; }
    if (is_filler_word(w) || read_manner(lexicon, w, out)) continue;
    // Not in the vocabulary: the lexicon, as a verb in a verb's place. Not in a noun's: inside
    // a prepositional phrase ("with black dots"), or as the subject of a verb after it ("horses
    // gallop", "the candle flame flickers"). A past participle says a state ("its hood
    // flared", "a hypnotized cobra"), not a motion. An "-s" word is a verb after a noun ("the
    // plane lands"; not after an adjective: "black boots") or when WordNet sees it used as a
    // verb at least as often as a noun; a bare word when it opens the clause (an imperative),
    // follows "to" or can only be a verb.
    const bool before_verb = !next.empty() && (verb_for_word(next) || (next_third && lexicon.verb(next).verb));
    const bool s_form = w.size() > 3 && w.back() == 's' && !ends_with(w, "ss");
    const bool past = ends_with(w, "ed");
    using wordnet::Pos;
    const bool after_noun = after_noun_word && lexicon.tagged_senses(before, Pos::Noun) >= lexicon.tagged_senses(before, Pos::Adj);
    const bool used_as_verb = lexicon.tagged_senses(w, Pos::Verb) >= lexicon.tagged_senses(w, Pos::Noun);
    const bool verb_form = participle || (s_form && (after_noun || used_as_verb)) ||
                           (!s_form && !past && (prev_was_start || before == "to" || !lexicon.knows_noun(w)));
    if (lexicon.has_wordnet() && verb_form && !noun_place && !after_prep && !before_verb) {
      VerbReading r = is_particle(next) ? lexicon.phrasal_verb(w, next) : VerbReading{};
      const std::string said = r.verb ? w + " " + next : w;
      // Said of fire or water, which move by themselves (rain, flames, lightning; not a creature
      // or a vessel, which do many things), a verb the vocabulary does not list is how that
      // thing moves: "rain lashes down" falls, "lightning strikes" flickers.
      const PromptNoun* subj = after_noun_word && !c.nouns.empty() ? &c.nouns.back() : nullptr;
      if (!r.verb && subj && subj->motion && !subj->object_of_preposition &&
          (subj->figure == FigureClass::Flame || subj->figure == FigureClass::Liquid))
        r = {subj->motion, "what " + subj->word + " does", 0};
      if (!r.verb && lexicon.is_sound_verb(w)) r = sound_motion(lexicon, w, c);
      if (!r.verb) r = lexicon.verb(w);
      if (r.verb) {
        if (std::find(c.verbs.begin(), c.verbs.end(), r.verb) == c.verbs.end()) {
          c.verbs.push_back(r.verb);
          c.verb_words.push_back(said + "->" + r.verb->name);
        }
        out.readings.push_back("'" + said + "' read as " + r.verb->name + (r.via == "anchor" ? "" : r.via.find(' ') != std::string::npos ? " (" + r.via + ")" : " (WordNet: " + r.via + ")"));
        after_prep = false;
        prev_was_verb = true;
        continue;
      }
    }
    PromptNoun n{w, Target::Named, w.size() > 3 && w.back() == 's', after_prep, !c.verbs.empty()};
    if (after_prep) n.preposition = preposition;
    // In a verb's place, a verb WordNet knows and the lexicon could not place ("the cat
    // yawns"): kept as a noun as before (a part may be named so), but it names no figure.
    if (lexicon.has_wordnet() && verb_form && !noun_place && !after_prep && !before_verb && lexicon.knows_verb(w)) {
      out.unplaced.push_back(w);
      c.nouns.push_back(n);
      modifier_noun.push_back(false);
      continue;
    }
    if (lexicon.has_wordnet()) read_lexicon_noun(lexicon, w, next, n, out);
    if (after_noun_word && !modifier_noun.empty()) modifier_noun.back() = true;
    c.nouns.push_back(n);
    modifier_noun.push_back(false);
    prev_was_noun = true;
  }
  // Who moves: an agent noun, else the first noun with a class that is not in a prepositional
  // phrase nor the modifier of a compound (the flame of "the candle flame").
  c.figure = agent_figure;
  for (size_t i = 0; i < c.nouns.size() && c.figure == FigureClass::None; ++i) {
    const PromptNoun& n = c.nouns[i];
    if (!n.object_of_preposition && !n.own_predicate && !(i < modifier_noun.size() && modifier_noun[i])) c.figure = n.figure;
  }
  return c;
}

// A verbless clause saying something of its nouns with a past participle the vocabulary does
// not know ("its hood slightly flared", "her eyes closed"): the unknown words are kept as
// nouns by read_clause, a participle among them ends in "ed".
bool has_unknown_participle(const Clause& c) {
  if (!c.verbs.empty()) return false;
  for (const auto& n : c.nouns)
    if (n.target == Target::Named && n.word.size() > 4 && n.word.compare(n.word.size() - 2, 2, "ed") == 0) return true;
  return false;
}

void merge_into(Clause& into, Clause from) {
  // Its nouns are described by the participle: not the targets of the verb it joins.
  if (has_unknown_participle(from))
    for (auto& n : from.nouns) n.own_predicate = true;
  into.text += " " + from.text;
  for (size_t i = 0; i < from.verbs.size(); ++i)
    if (std::find(into.verbs.begin(), into.verbs.end(), from.verbs[i]) == into.verbs.end()) {
      into.verbs.push_back(from.verbs[i]);
      into.verb_words.push_back(from.verb_words[i]);
    }
  into.nouns.insert(into.nouns.end(), from.nouns.begin(), from.nouns.end());
  if (into.figure == FigureClass::None) into.figure = from.figure;
  // Travel words are read in context (read_travel), not by apply_modifier: carried over as read.
  for (const auto& w : from.mods.words)
    if (!apply_modifier(w, into.mods)) into.mods.words.push_back(w);
  if (from.mods.travel) into.mods.travel = into.mods.travel == -from.mods.travel ? 0 : from.mods.travel;
  if (from.mods.depth) into.mods.depth = from.mods.depth;
  into.mods.across = into.mods.across || from.mods.across;
  if (from.mods.end) into.mods.end = from.mods.end;
  if (from.mods.level) into.mods.level = from.mods.level;
}

}  // namespace

ParsedPrompt parse_prompt(const std::string& prompt) {
  // Split into raw clauses of words.
  std::vector<std::vector<std::string>> raw(1);
  std::vector<char> after_and(1, 0);  // per raw clause: split from the one before by "and"
  std::string word;
  auto flush = [&] {
    if (word.empty()) return;
    if (is_conjunction(word)) {
      if (!raw.back().empty()) {
        raw.emplace_back();
        after_and.push_back(word == "and");
      }
    } else {
      raw.back().push_back(word);
    }
    word.clear();
  };
  for (char ch : lower(prompt)) {
    if (std::isalpha(static_cast<unsigned char>(ch))) {
      word += ch;
      continue;
    }
    flush();
    if (ch == ',' || ch == '.' || ch == ';' || ch == ':' || ch == '!' || ch == '?')
      if (!raw.back().empty()) {
        raw.emplace_back();
        after_and.push_back(0);
      }
  }
  flush();
  ParsedPrompt out;
  for (const auto& clause : raw) out.words.insert(out.words.end(), clause.begin(), clause.end());
  std::vector<Clause> clauses;
  bool prep_open = false;  // the clause before ended inside a prepositional phrase, with no verb
  for (size_t i = 0; i < raw.size(); ++i) {
    if (raw[i].empty()) continue;
    bool after_prep = prep_open && after_and[i];
    const PromptNoun* antecedent = nullptr;
    for (const Clause& c : clauses)
      for (const PromptNoun& n : c.nouns)
        if (n.after_verb && !n.object_of_preposition && !n.own_predicate) antecedent = &n;
    clauses.push_back(read_clause(raw[i], after_prep, out, antecedent));
    own_motion_sent(clauses.back(), out);
    prep_open = after_prep && clauses.back().verbs.empty();
  }
  // A clause without a verb joins the one before it (or, first in the prompt, the one after).
  for (const Clause& c : clauses) {
    if (!out.clauses.empty() && (c.verbs.empty() || out.clauses.back().verbs.empty()))
      merge_into(out.clauses.back(), c);
    else
      out.clauses.push_back(c);
  }
  return out;
}

bool glob_match(const std::string& pattern, const std::string& text) {
  const std::string p = lower(pattern), t = lower(text);
  // Iterative '*' matching with backtracking to the last star.
  size_t pi = 0, ti = 0, star = std::string::npos, mark = 0;
  while (ti < t.size()) {
    if (pi < p.size() && p[pi] == t[ti]) { ++pi; ++ti; }
    else if (pi < p.size() && p[pi] == '*') { star = pi++; mark = ti; }
    else if (star != std::string::npos) { pi = star + 1; ti = ++mark; }
    else return false;
  }
  while (pi < p.size() && p[pi] == '*') ++pi;
  return pi == p.size();
}

std::vector<ExplicitStep> parse_explicit_plan(const std::string& text) {
  std::vector<ExplicitStep> steps;
  std::string item;
  auto finish = [&] {
    std::string s = item;
    item.clear();
    // Trim.
    const size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
    if (a == std::string::npos) throw Error("motion plan '" + text + "': an empty item");
    s = s.substr(a, b - a + 1);
    ExplicitStep step;
    std::vector<std::string> tokens;
    for (size_t at = 0; at < s.size();) {
      const size_t sp = s.find_first_of(" \t", at);
      const std::string tok = s.substr(at, sp == std::string::npos ? std::string::npos : sp - at);
      if (!tok.empty()) tokens.push_back(tok);
      if (sp == std::string::npos) break;
      at = sp + 1;
    }
    const std::string head = tokens.front();
    const size_t colon = head.find(':');
    step.verb = lower(head.substr(0, colon));
    if (!find_verb_by_name(step.verb)) {
      std::string names;
      for (const auto& v : motion_verbs()) names += (names.empty() ? "" : ", ") + v.name;
      throw Error("motion plan '" + s + "': unknown verb '" + step.verb + "' (verbs: " + names + ")");
    }
    if (colon != std::string::npos) {
      const std::string pats = head.substr(colon + 1);
      size_t at = 0;
      while (at <= pats.size()) {
        const size_t plus = pats.find('+', at);
        const std::string p = pats.substr(at, plus == std::string::npos ? std::string::npos : plus - at);
        if (p.empty()) throw Error("motion plan '" + s + "': an empty part pattern");
        step.patterns.push_back(p);
        if (plus == std::string::npos) break;
        at = plus + 1;
      }
    }
    for (size_t i = 1; i < tokens.size(); ++i)
      if (!apply_modifier(lower(tokens[i]), step.mods))
        throw Error("motion plan '" + s + "': unknown modifier '" + tokens[i] +
                    "' (modifiers: slow, fast, gently, wildly, once, repeatedly, left, right, up, down, both, together)");
    steps.push_back(std::move(step));
  };
  for (char ch : text) {
    if (ch == ',' || ch == ';') finish();
    else item += ch;
  }
  finish();
  return steps;
}

}  // namespace svgm
