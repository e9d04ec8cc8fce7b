// Prompt clauses and explicit plans: verbs with their inflections, part nouns (plural or not,
// after a preposition or not), modifiers, clause splitting and joining, exact errors for bad
// explicit plans.
#include <doctest/doctest.h>

#include <set>

#include "svgmotion/error.h"
#include "procedural/prompt_parse.h"

using namespace svgm;

TEST_SUITE("motion") {

TEST_CASE("stems match English inflections and nothing inside other words") {
  CHECK(word_matches("flapping", "flap"));
  CHECK(word_matches("flaps", "flap"));
  CHECK(word_matches("running", "run"));
  CHECK(word_matches("waving", "wav"));
  CHECK(word_matches("pedalling", "pedal"));
  CHECK(word_matches("pedaling", "pedal"));
  CHECK_FALSE(word_matches("show", "ho"));
  CHECK_FALSE(word_matches("runway", "run"));
  CHECK_FALSE(word_matches("sits", "sitting"));
}

TEST_CASE("the vocabulary has at least 40 verbs, no stem meaning two verbs") {
  CHECK(motion_verbs().size() >= 40);
  std::set<std::string> names;
  for (const auto& v : motion_verbs()) {
    CHECK(names.insert(v.name).second);
    CHECK(!v.actions.empty());
  }
}

TEST_CASE("one clause: verb, plural part noun, up and down cancel") {
  const ParsedPrompt p = parse_prompt("A bat is flapping its wings up and down.");
  REQUIRE(p.clauses.size() == 1);
  const Clause& c = p.clauses[0];
  REQUIRE(c.verbs.size() == 1);
  CHECK(c.verbs[0]->name == "flap");
  REQUIRE(c.nouns.size() == 2);
  CHECK(c.nouns[0].word == "bat");
  CHECK(c.nouns[0].target == Target::Named);
  CHECK(c.nouns[1].word == "wings");
  CHECK(c.nouns[1].target == Target::Arms);
  CHECK(c.nouns[1].plural);
  CHECK(c.mods.vertical == 0);
  CHECK(c.mods.words == std::vector<std::string>{"up", "down"});
}

TEST_CASE("clauses split at conjunctions; a noun after a preposition is not a target") {
  const ParsedPrompt p = parse_prompt("Rain falls on the umbrella and it sways gently");
  REQUIRE(p.clauses.size() == 2);
  REQUIRE(p.clauses[0].verbs.size() == 1);
  CHECK(p.clauses[0].verbs[0]->name == "fall");  // "rain" and "falls": one verb, once
  REQUIRE(p.clauses[0].nouns.size() == 1);
  CHECK(p.clauses[0].nouns[0].word == "umbrella");
  CHECK(p.clauses[0].nouns[0].object_of_preposition);
  REQUIRE(p.clauses[1].verbs.size() == 1);
  CHECK(p.clauses[1].verbs[0]->name == "sway");
  CHECK(p.clauses[1].mods.size == 0.5);
}

TEST_CASE("a noun of a prepositional phrase split by 'and' stays its object; a verb's word after 'the' is a noun") {
  const ParsedPrompt p = parse_prompt("A woman in a green dress with black dots and black boots is dancing joyfully.");
  REQUIRE(p.clauses.size() == 1);
  bool boots = false;
  for (const auto& n : p.clauses[0].nouns)
    if (n.word == "boots") {
      boots = true;
      CHECK(n.target == Target::Legs);
      CHECK(n.object_of_preposition);
    }
  CHECK(boots);
  // "and" after a verb starts a clause of its own: "his legs" there is a target.
  const ParsedPrompt q = parse_prompt("He sits on a chair and kicks his legs");
  REQUIRE(q.clauses.size() == 2);
  REQUIRE(q.clauses[1].nouns.size() == 1);
  CHECK_FALSE(q.clauses[1].nouns[0].object_of_preposition);
  // "rides the waves": one verb (glide); "waves" is a noun here.
  const ParsedPrompt s = parse_prompt("A surfer rides the waves.");
  REQUIRE(s.clauses.size() == 1);
  REQUIRE(s.clauses[0].verbs.size() == 1);
  CHECK(s.clauses[0].verbs[0]->name == "glide");
  // ... but a participle after an article is still the verb.
  const ParsedPrompt h = parse_prompt("A galloping horse.");
  REQUIRE(h.clauses[0].verbs.size() == 1);
  CHECK(h.clauses[0].verbs[0]->name == "gallop");
}

TEST_CASE("the one who moves ('a surfer', 'the riders') is the whole figure, not a part noun") {
  // "surfer": glide's stem "surf" with the agent ending; "rider": the verb's word "ride" + "r".
  for (const char* prompt : {"A surfer rides the waves.", "the riders are riding", "Runner runs fast", "the biker is pedalling"}) {
    const ParsedPrompt p = parse_prompt(prompt);
    REQUIRE(p.clauses.size() == 1);
    CHECK(p.clauses[0].verbs.size() == 1);
    for (const auto& n : p.clauses[0].nouns) CHECK(n.word == "waves");  // the only noun left
  }
  // Not an agent noun: "flower" is, harmlessly (the whole figure); "tower", "corner" are not.
  const ParsedPrompt q = parse_prompt("the tower in the corner sways");
  REQUIRE(q.clauses[0].nouns.size() == 2);
  CHECK(q.clauses[0].nouns[0].word == "tower");
}

TEST_CASE("riding and the rider: whole words, not the stem 'rid' inside other words") {
  const ParsedPrompt p = parse_prompt("The rider is riding");
  REQUIRE(p.clauses.size() == 1);
  REQUIRE(p.clauses[0].verbs.size() == 1);
  CHECK(p.clauses[0].verb_words == std::vector<std::string>{"riding"});
  CHECK(parse_prompt("the rider smiles").clauses[0].verbs.empty());
  CHECK(parse_prompt("she rode off").clauses[0].verbs.size() == 1);
}

TEST_CASE("'the cobra snake sways': the word before a verb is who does it; 'its hood flared' is not what sways") {
  const ParsedPrompt p = parse_prompt("The hypnotized cobra snake sways gently, its hood slightly flared.");
  REQUIRE(p.clauses.size() == 1);  // the verbless clause joins the one before it
  REQUIRE(p.clauses[0].verbs.size() == 1);
  CHECK(p.clauses[0].verbs[0]->name == "sway");  // "snake" (slither's stem "snak") is the subject
  bool hood = false;
  for (const auto& n : p.clauses[0].nouns)
    if (n.word == "hood") {
      hood = true;
      CHECK(n.target == Target::Head);
      CHECK(n.own_predicate);  // the hood flares
    }
  CHECK(hood);
  // Without a participle of its own the joined noun is the verb's target, as before.
  const ParsedPrompt q = parse_prompt("The snake sways, its hood up and down.");
  REQUIRE(q.clauses.size() == 1);
  for (const auto& n : q.clauses[0].nouns) CHECK_FALSE(n.own_predicate);
  // A verb's word not followed by another verb is still the verb, inflected or not.
  for (const char* prompt : {"the snake snakes along", "snake along the branch", "it is snaking"}) {
    const ParsedPrompt r = parse_prompt(prompt);
    REQUIRE(r.clauses.size() == 1);
    REQUIRE(r.clauses[0].verbs.size() == 1);
    CHECK(r.clauses[0].verbs[0]->name == "slither");
  }
  // ... and a verb in the third person followed by another is both ("flies flapping").
  const ParsedPrompt f = parse_prompt("the bird flies flapping its wings");
  CHECK(f.clauses[0].verbs.size() == 2);
}

TEST_CASE("modifiers: speed, size, once, the figure's side, both") {
  const ParsedPrompt p = parse_prompt("the man slowly waves his right arm once, then kicks wildly with both legs");
  REQUIRE(p.clauses.size() == 2);
  CHECK(p.clauses[0].mods.speed == 0.5);
  CHECK(p.clauses[0].mods.side == 1);
  CHECK(p.clauses[0].mods.once == 1);
  CHECK(p.clauses[1].verbs[0]->name == "kick");
  CHECK(p.clauses[1].mods.size == 1.6);
  CHECK(p.clauses[1].mods.both);
  CHECK(p.clauses[1].mods.side == 0);
  CHECK(parse_prompt("left and right").clauses[0].mods.side == 0);
}

TEST_CASE("a prompt with no verb keeps its words as nouns, for the report") {
  const ParsedPrompt p = parse_prompt("A snail.");
  REQUIRE(p.clauses.size() == 1);
  CHECK(p.clauses[0].verbs.empty());
  REQUIRE(p.clauses[0].nouns.size() == 1);
  CHECK(p.clauses[0].nouns[0].word == "snail");
}

TEST_CASE("explicit plans: verbs, patterns, modifiers; exact errors") {
  const auto steps = parse_explicit_plan("flap:wing*, bob:body+head slow");
  REQUIRE(steps.size() == 2);
  CHECK(steps[0].verb == "flap");
  CHECK(steps[0].patterns == std::vector<std::string>{"wing*"});
  CHECK(steps[1].verb == "bob");
  CHECK(steps[1].patterns == std::vector<std::string>{"body", "head"});
  CHECK(steps[1].mods.speed == 0.5);
  CHECK(parse_explicit_plan("spin").at(0).patterns.empty());
  try {
    parse_explicit_plan("flap:wing, zoom:head");
    FAIL("no error");
  } catch (const Error& e) {
    CHECK(std::string(e.what()).rfind("motion plan 'zoom:head': unknown verb 'zoom' (verbs: flap, fly,", 0) == 0);
  }
  CHECK_THROWS_WITH_AS(parse_explicit_plan("flap:wing quickly-ish"),
                       "motion plan 'flap:wing quickly-ish': unknown modifier 'quickly-ish' (modifiers: slow, fast, "
                       "gently, wildly, once, repeatedly, left, right, up, down, both, together)",
                       Error);
  CHECK_THROWS_WITH_AS(parse_explicit_plan("flap, ,bob"), "motion plan 'flap, ,bob': an empty item", Error);
  CHECK_THROWS_WITH_AS(parse_explicit_plan("flap:"), "motion plan 'flap:': an empty part pattern", Error);
}

TEST_CASE("glob patterns") {
  CHECK(glob_match("wing*", "wing_left"));
  CHECK(glob_match("*LEFT", "wing_left"));
  CHECK(glob_match("w*g*t", "wing_left"));
  CHECK_FALSE(glob_match("wing", "wing_left"));
  CHECK_FALSE(glob_match("arm*", "wing_left"));
}

}  // TEST_SUITE
