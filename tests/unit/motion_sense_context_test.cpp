// A noun's sense by the prompt's other nouns (motion/sense_context.h): a sense nearer a context
// noun (or the whole it is a part of) through a common hypernym than the frequent sense comes
// first; a verb, a word modifying the noun and the noun of a phrase of place are no evidence.
// Skipped without WordNet.
#include <doctest/doctest.h>

#include "motion/lexicon.h"
#include "motion/sense_context.h"
#include "procedural/prompt_parse.h"
#include "wordnet_or_skip.h"

using namespace svgm;

namespace {

FigureClass first_class(const char* prompt) {
  const ParsedPrompt p = parse_prompt(prompt);
  return p.clauses.empty() ? FigureClass::None : p.clauses[0].figure;
}

}  // namespace

TEST_SUITE("motion") {

TEST_CASE("sense by context: a drone with rotors is an aircraft, a drone alone the male bee") {
  if (!wordnet_or_skip()) return;
  const Lexicon& lex = Lexicon::shared();
  // WordNet's first sense: the male bee.
  CHECK(lex.noun("drone").figure == FigureClass::Insect);
  // A rotor is a part of a helicopter, a heavier-than-air craft, as the pilotless aircraft is.
  const NounReading r = lex.noun("drone", {"the", "hovers", "its", "rotors", "whirring"});
  CHECK(r.figure == FigureClass::Object);
  CHECK(r.sense_why == "drone: sense 4 (heavier-than-air_craft, 2 steps from 'rotors')");
  // Words that name nothing near any other sense change nothing.
  CHECK(lex.noun("drone", {"the", "hovers", "gently"}).figure == FigureClass::Insect);
  CHECK(first_class("the drone hovers, its rotors whirring") == FigureClass::Object);
  CHECK(first_class("the drone hovers") == FigureClass::Insect);
}

TEST_CASE("sense by context: a scooter with wheels is a wheeled vehicle, not the sea duck") {
  if (!wordnet_or_skip()) return;
  // No sense of "scooter" is ranked; the kick scooter is the one it names first, the scoter (a
  // duck) only another name of (motion_lexicon_test: a vehicle goes before a rare animal).
  CHECK(first_class("the scooter glides") == FigureClass::Wheeled);
  CHECK(first_class("the kick scooter's wheels spin") == FigureClass::Wheeled);
}

TEST_CASE("sense by context: a word right before the noun modifies it, a place's noun names another thing") {
  if (!wordnet_or_skip()) return;
  const wordnet::Database& db = *wordnet::Database::shared();
  const std::vector<uint32_t> smoke = db.senses("smoke", wordnet::Pos::Noun);
  REQUIRE(smoke.size() >= 5);
  // Given as context, a cigarette (a roll of tobacco) pulls smoke's fifth sense (the roll of
  // tobacco WordNet also calls smoke) to the front...
  CHECK(senses_by_context(db, "smoke", smoke, {"cigarette"}).front() == smoke[4]);
  CHECK(senses_by_context(db, "smoke", smoke, {}) == smoke);
  // ...but in a prompt it is where the smoke comes from: smoke keeps its first sense, which rises.
  const ParsedPrompt p = parse_prompt("smoke rises from the cigarette");
  bool rises = false;
  for (const auto& c : p.clauses)
    for (const auto& n : c.nouns) rises = rises || (n.word == "smoke" && n.motion && n.motion->name == "rise");
  CHECK(rises);
  // A verb is no evidence: "bobs" is also a haircut, which would make the waves hairdos.
  const ParsedPrompt boat = parse_prompt("the sailboat bobs on the waves");
  for (const auto& r : boat.readings) CHECK(r.find("by its context") == std::string::npos);
}

}  // TEST_SUITE
