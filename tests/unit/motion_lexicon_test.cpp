// The motion lexicon and its place in the prompt parse: new verbs read as the nearest
// vocabulary verb (shuffle -> walk), nouns as figure classes (hummingbird -> bird) and parts
// (talon -> claw), noun-driven motion (a flame flickers), "waves" after a verb or a preposition
// as a noun, and the travel direction of the whole figure ("to the right") apart from the
// figure's own side ("his right arm"). Tests that need WordNet are skipped without it.
#include <doctest/doctest.h>

#include <algorithm>

#include "motion/lexicon.h"
#include "svgmotion/svg_reader.h"
#include "procedural/motion_plan.h"
#include "procedural/prompt_parse.h"
#include "wordnet_or_skip.h"

using namespace svgm;

namespace {

std::string verb_of(const char* word) {
  const VerbReading r = Lexicon::shared().verb(word);
  return r.verb ? r.verb->name : "-";
}

std::vector<std::string> verb_names(const Clause& c) {
  std::vector<std::string> out;
  for (const Verb* v : c.verbs) out.push_back(v->name);
  return out;
}

}  // namespace

TEST_SUITE("motion") {

TEST_CASE("lexicon: new verbs read as the nearest vocabulary verb up WordNet's hypernyms") {
  if (!wordnet_or_skip()) return;
  CHECK(verb_of("shuffle") == "walk");
  CHECK(verb_of("shuffles") == "walk");
  CHECK(verb_of("plodding") == "walk");
  CHECK(verb_of("scurry") == "run");
  CHECK(verb_of("scampered") == "run");
  CHECK(verb_of("swivel") == "spin");
  CHECK(verb_of("applaud") == "clap");
  CHECK(verb_of("hoist") == "lift");
  CHECK(verb_of("drizzle") == "fall");
  // A synonym is nearer than any hypernym: "bound" is in jump's own synset.
  const VerbReading bound = Lexicon::shared().verb("bounds");
  REQUIRE(bound.verb);
  CHECK(bound.verb->name == "jump");
  CHECK(bound.depth == 0);
  // No motion above it, and none on the anchors: not placed.
  CHECK(verb_of("xyzzy") == "-");
  CHECK(verb_of("ponders") == "-");
  // A verb made from a noun that moves by itself moves as it does (burn: fire flickers).
  CHECK(verb_of("burns") == "twinkle");
  // The anchor table, where WordNet's graph reaches no motion.
  CHECK(verb_of("erupts") == "rise");
  // The body's doings, placed by the family's root (verb_sense_anchors): every kind of laugh
  // shakes, every kind of breath or weeping pulses, a shrug lifts the arms, melting slumps.
  CHECK(verb_of("giggles") == "shake");
  CHECK(verb_of("chuckling") == "shake");
  CHECK(verb_of("guffaws") == "shake");
  CHECK(verb_of("yawns") == "pulse");
  CHECK(verb_of("sighs") == "pulse");
  CHECK(verb_of("snores") == "pulse");
  CHECK(verb_of("sobs") == "pulse");
  CHECK(verb_of("shrugs") == "lift");
  CHECK(verb_of("melts") == "sit");
  CHECK(verb_of("thaws") == "sit");
}

TEST_CASE("lexicon: nouns get a figure class through their hypernyms") {
  if (!wordnet_or_skip()) return;
  const Lexicon& lx = Lexicon::shared();
  CHECK(lx.noun("hummingbird").figure == FigureClass::Bird);
  CHECK(lx.noun("gazelle").figure == FigureClass::Quadruped);
  CHECK(lx.noun("tractor").figure == FigureClass::Wheeled);
  CHECK(lx.noun("tulips").figure == FigureClass::Plant);
  CHECK(lx.noun("geese").figure == FigureClass::Bird);
  CHECK(lx.noun("salmon").figure == FigureClass::FishOrSnake);
  // A bus and a train are wheeled (anchors: WordNet files them under public transport); a
  // sailboat is a vessel that rocks; the space shuttle, public transport too, is not wheeled.
  CHECK(lx.noun("bus").figure == FigureClass::Wheeled);
  CHECK(lx.noun("train").figure == FigureClass::Wheeled);
  CHECK(lx.noun("car").figure == FigureClass::Wheeled);
  CHECK(lx.noun("sailboat").figure == FigureClass::Object);
  CHECK(lx.noun("shuttle").figure != FigureClass::Wheeled);
  CHECK(parse_prompt("the space shuttle blasts off").clauses.at(0).figure != FigureClass::Wheeled);
  CHECK(lx.noun("surfer").figure == FigureClass::Biped);
  CHECK(lx.noun("man").figure == FigureClass::Biped);        // not Homo the primate
  CHECK(lx.noun("whale").figure == FigureClass::FishOrSnake);  // not "a large person"
  CHECK(lx.noun("turtle").figure == FigureClass::Quadruped);   // not the turtleneck sweater
  CHECK(lx.noun("herb").figure == FigureClass::Plant);         // "herbaceous plant" is no clipping
  CHECK(lx.noun("peacock").figure == FigureClass::Bird);       // peacock_butterfly is one
  CHECK(lx.noun("happiness").figure == FigureClass::None);
  CHECK(std::string(figure_class_name(FigureClass::FishOrSnake)) == "fish_or_snake");
}

TEST_CASE("lexicon: noun-driven motion: flames flicker, rain falls, smoke rises, the sea's waves roll") {
  if (!wordnet_or_skip()) return;
  const Lexicon& lx = Lexicon::shared();
  const Verb* flicker = find_verb_by_word("flicker");
  REQUIRE(flicker);
  CHECK(flicker->name == "twinkle");  // its own stem, not wag's "flick" with the agent ending
  CHECK(lx.noun("flame").figure == FigureClass::Flame);
  CHECK(lx.noun("flame").motion == flicker);
  CHECK(lx.noun("candle").motion == flicker);
  CHECK(lx.noun("rain").motion == find_verb_by_name("fall"));
  CHECK(lx.noun("smoke").motion == find_verb_by_name("rise"));
  CHECK(lx.noun("waves").motion == find_verb_by_name("ripple"));
  CHECK(lx.noun("waves").figure == FigureClass::Liquid);
  CHECK(default_verb(FigureClass::Bird) == find_verb_by_name("flap"));
  CHECK(default_verb(FigureClass::Flame) == flicker);
  CHECK(default_verb(FigureClass::Scene) == nullptr);
}

TEST_CASE("lexicon: nouns reach the part nouns they are kinds or parts of") {
  if (!wordnet_or_skip()) return;
  const Lexicon& lx = Lexicon::shared();
  REQUIRE(lx.noun("talons").part);
  CHECK(lx.noun("talons").part->stem == "claw");
  REQUIRE(lx.noun("fingers").part);
  CHECK(lx.noun("fingers").part->target == Target::Arms);
  REQUIRE(lx.noun("toes").part);
  CHECK(lx.noun("toes").part->target == Target::Legs);
}

TEST_CASE("parse: a word the vocabulary lacks is read by the lexicon, and the reading recorded") {
  if (!wordnet_or_skip()) return;
  const ParsedPrompt p = parse_prompt("the old man shuffles slowly");
  REQUIRE(p.clauses.size() == 1);
  CHECK(verb_names(p.clauses[0]) == std::vector<std::string>{"walk"});
  CHECK(p.clauses[0].verb_words == std::vector<std::string>{"shuffles->walk"});
  CHECK(p.clauses[0].mods.speed == 0.5);
  CHECK(p.clauses[0].figure == FigureClass::Biped);
  CHECK(std::count(p.readings.begin(), p.readings.end(), "'shuffles' read as walk (WordNet: walk)") == 1);
  // The subject before a verb is a noun ("the candle flame flickers": not "to flame"), with its class.
  const ParsedPrompt f = parse_prompt("the candle flame flickers");
  REQUIRE(f.clauses.size() == 1);
  CHECK(verb_names(f.clauses[0]) == std::vector<std::string>{"twinkle"});
  CHECK(f.clauses[0].figure == FigureClass::Flame);
  // A hummingbird hovers: the class is recorded, the verb is the vocabulary's.
  const ParsedPrompt h = parse_prompt("a hummingbird hovers");
  CHECK(h.clauses[0].figure == FigureClass::Bird);
  CHECK(verb_names(h.clauses[0]) == std::vector<std::string>{"hover"});
  // A verb WordNet knows but the lexicon cannot place is listed, and kept as a noun as before.
  const ParsedPrompt y = parse_prompt("the cat ponders");
  CHECK(y.clauses[0].verbs.empty());
  CHECK(y.unplaced == std::vector<std::string>{"ponders"});
}

TEST_CASE("parse: 'waves' after a verb, an article or a preposition is the sea's, not a hand wave") {
  for (const char* prompt : {"a surfer riding waves", "the surfer rides the waves", "a boat bobs on waves"}) {
    CAPTURE(prompt);
    const ParsedPrompt p = parse_prompt(prompt);
    for (const Clause& c : p.clauses) CHECK(std::find(c.verbs.begin(), c.verbs.end(), find_verb_by_name("wave")) == c.verbs.end());
  }
  CHECK(verb_names(parse_prompt("she waves her hand").clauses[0]) == std::vector<std::string>{"wave"});
  // On a drawing: a surfer on a wave backdrop glides as a whole; no arm waves.
  const Scene s = read_svg_string(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">
           <g id="wave"><rect x="0" y="100" width="200" height="100" fill="#04c"/></g>
           <g id="surfer"><rect x="80" y="40" width="40" height="100" fill="#c33"/></g>
           <g id="board"><rect x="50" y="140" width="100" height="10" fill="#ee0"/></g></svg>)", "surfer.svg");
  const Rig rig = build_rig(s, {{s.paths[0].id, {{"/svg/g[1]", "wave"}}}});
  const MotionPlan plan = plan_from_prompt(parse_prompt("A surfer riding waves"), rig, 1);
  REQUIRE(!plan.actions.empty());
  for (const auto& a : plan.actions) CHECK(a.verb != "wave");
  CHECK(plan.actions[0].verb == "glide");
}

TEST_CASE("modifiers: the whole figure's travel is read apart from the figure's own side") {
  const Modifiers gallop = parse_prompt("a horse gallops to the right").clauses.at(0).mods;
  CHECK(gallop.travel == 1);
  CHECK(gallop.side == 0);
  const Modifiers walk = parse_prompt("the snail walks to the left").clauses.at(0).mods;
  CHECK(walk.travel == -1);
  CHECK(walk.side == 0);
  const Modifiers drift = parse_prompt("the balloon floats right").clauses.at(0).mods;
  CHECK(drift.travel == 1);
  const Modifiers arm = parse_prompt("the man waves his right arm").clauses.at(0).mods;
  CHECK(arm.side == 1);
  CHECK(arm.travel == 0);
  CHECK(parse_prompt("kicks with the left leg").clauses.at(0).mods.side == -1);
  CHECK(parse_prompt("kicks with the left leg").clauses.at(0).mods.travel == 0);
  CHECK(parse_prompt("it sways left and right").clauses.at(0).mods.travel == 0);
  CHECK(parse_prompt("the car drives towards the viewer").clauses.at(0).mods.depth == 1);
  CHECK(parse_prompt("the ship sails away").clauses.at(0).mods.depth == -1);
  CHECK(parse_prompt("it drifts leftwards").clauses.at(0).mods.travel == -1);
  const Modifiers up = parse_prompt("the rocket rises up slowly, once").clauses.at(0).mods;
  CHECK(up.vertical == 1);
  CHECK(up.speed == 0.5);
  CHECK(up.once == 1);
  CHECK(parse_prompt("flaps wildly").clauses.at(0).mods.size == doctest::Approx(1.6));
}

TEST_CASE("lexicon: without WordNet nothing is placed") {
  const Lexicon none(nullptr);
  CHECK_FALSE(none.has_wordnet());
  CHECK(none.verb("shuffle").verb == nullptr);
  CHECK(none.noun("hummingbird").figure == FigureClass::None);
}

TEST_CASE("lexicon: a word right before a part noun modifies it and is no part of its own") {
  if (!wordnet_or_skip()) return;
  // WordNet's noun "upper" is part of a shoe (a boot, so the legs): in "his upper body" it says
  // which body, and the body is what sways.
  const ParsedPrompt p = parse_prompt("his upper body sways subtly");
  REQUIRE(p.clauses.size() == 1);
  for (const auto& n : p.clauses[0].nouns) CHECK(n.target != Target::Legs);
  bool body = false;
  for (const auto& n : p.clauses[0].nouns) body = body || (n.word == "body" && n.target == Target::Root);
  CHECK(body);
}

// The subject, the verb, the direction and what the verb acts on, in prompts whose words the
// planner misread (issue 35's suite: tw_storm, tw_climber, tw_dribble, om_fencer_thrust).
namespace {
const PromptNoun* noun_named(const Clause& c, const std::string& word) {
  for (const auto& n : c.nouns)
    if (n.word == word) return &n;
  return nullptr;
}
}  // namespace

TEST_CASE("parse: a vocabulary verb's word before a verb WordNet uses as one is the subject ('rain lashes down')") {
  if (!wordnet_or_skip()) return;
  const ParsedPrompt p = parse_prompt("lightning strikes and rain lashes down");
  REQUIRE(p.clauses.size() == 2);
  // "rain" is who lashes, not the verb fall; "lashes" is how the rain moves, not eyelashes (a face).
  const Clause& rain = p.clauses[1];
  CHECK(verb_names(rain) == std::vector<std::string>{"fall"});
  CHECK(rain.verb_words == std::vector<std::string>{"lashes->fall"});
  CHECK(rain.figure == FigureClass::Liquid);
  REQUIRE(noun_named(rain, "rain"));
  CHECK_FALSE(noun_named(rain, "lashes"));
  CHECK(rain.mods.vertical == -1);
  // Lightning is a flash: it strikes as it moves by itself, not as "move" (WordNet's strike).
  CHECK(verb_names(p.clauses[0]) == std::vector<std::string>{"twinkle"});
  CHECK(p.clauses[0].figure == FigureClass::Flame);
  CHECK(std::count(p.readings.begin(), p.readings.end(), "'lashes' read as fall (what rain does)") == 1);
  // Two words of one verb still say it once; a creature's verb stays its own ("the sloth hangs").
  CHECK(verb_names(parse_prompt("rain falls").clauses.at(0)) == std::vector<std::string>{"fall"});
  CHECK(verb_names(parse_prompt("the old man shuffles").clauses.at(0)) == std::vector<std::string>{"walk"});
}

TEST_CASE("parse: 'up the rock face' is the way up a thing, not the figure's face") {
  if (!wordnet_or_skip()) return;
  const ParsedPrompt p = parse_prompt("she climbs up the rock face");
  REQUIRE(p.clauses.size() == 1);
  const Clause& c = p.clauses[0];
  CHECK(verb_names(c) == std::vector<std::string>{"climb"});
  CHECK(c.mods.vertical == 1);
  for (const auto& n : c.nouns) {
    CHECK(n.target != Target::Head);
    CHECK(n.object_of_preposition);
    CHECK(n.preposition == "up");
  }
  REQUIRE(noun_named(c, "rock"));
  // Without "up": the compound is still the rock, the verb's object, not a part of the figure.
  const ParsedPrompt pd = parse_prompt("she climbs the rock face");
  const Clause& d = pd.clauses.at(0);
  REQUIRE(noun_named(d, "face"));
  CHECK(noun_named(d, "face")->target == Target::Named);
  // A possessive makes it the figure's own: "his robot arm" is an arm.
  const ParsedPrompt pr = parse_prompt("he waves his robot arm");
  const Clause& r = pr.clauses.at(0);
  REQUIRE(noun_named(r, "arm"));
  CHECK(noun_named(r, "arm")->target == Target::Arms);
}

TEST_CASE("parse: a pronoun after a verb is the last object ('dribbles the ball, bouncing it')") {
  if (!wordnet_or_skip()) return;
  const ParsedPrompt p = parse_prompt("he dribbles the ball, bouncing it off the floor");
  REQUIRE(p.clauses.size() == 2);
  const Clause& c = p.clauses[1];
  CHECK(verb_names(c) == std::vector<std::string>{"bounce"});
  const PromptNoun* ball = noun_named(c, "ball");
  REQUIRE(ball);
  CHECK(ball->after_verb);
  CHECK_FALSE(ball->object_of_preposition);
  // A ball is no arm: WordNet's {weapon, arm} is not the limb (a musket ball is a weapon).
  CHECK(noun_named(p.clauses[0], "ball")->target == Target::Wheels);
  REQUIRE(noun_named(c, "floor"));
  CHECK(noun_named(c, "floor")->object_of_preposition);
  CHECK(std::count(p.readings.begin(), p.readings.end(), "'it' read as the ball") == 1);
  CHECK(Lexicon::shared().noun("arms").part->target == Target::Arms);
  CHECK(Lexicon::shared().noun("sword").part == nullptr);
  CHECK(Lexicon::shared().noun("bullet").part == nullptr);
  // A ball is a round thing of the figure, as a wheel is; and what a dribbled ball does is bounce.
  CHECK(ball->target == Target::Wheels);
  CHECK(verb_names(p.clauses[0]) == std::vector<std::string>{"bounce"});
}

TEST_CASE("parse: 'forward' is a direction, not a noun (a basketball forward is a person)") {
  if (!wordnet_or_skip()) return;
  const ParsedPrompt p = parse_prompt("the fencer thrusts his foil forward");
  const Clause& c = p.clauses.at(0);
  CHECK(verb_names(c) == std::vector<std::string>{"punch"});
  CHECK(c.figure == FigureClass::Biped);
  CHECK_FALSE(noun_named(c, "forward"));
  CHECK(std::count(c.mods.words.begin(), c.mods.words.end(), "forward") == 1);
  REQUIRE(noun_named(c, "foil"));
  CHECK(noun_named(c, "foil")->after_verb);
}

TEST_CASE("parse: what hangs from something sways under it ('the sloth hangs from the branch'), it does not sink") {
  if (!wordnet_or_skip()) return;
  const ParsedPrompt p = parse_prompt("the sloth hangs from the branch and sways slowly");
  REQUIRE(p.clauses.size() == 2);
  const Clause& c = p.clauses[0];
  CHECK(verb_names(c) == std::vector<std::string>{"sway"});
  CHECK(c.figure == FigureClass::Quadruped);
  const PromptNoun* branch = noun_named(c, "branch");
  REQUIRE(branch);
  CHECK(branch->object_of_preposition);
  CHECK(branch->preposition == "from");
  CHECK(verb_names(p.clauses[1]) == std::vector<std::string>{"sway"});
  CHECK(p.clauses[1].mods.speed == 0.5);
}

TEST_CASE("lexicon: a whole-figure motion claims no sense that only moves something else") {
  if (!wordnet_or_skip()) return;
  // WordNet's sentence frames: "travel, go, move" is said of its subject alone; "move, displace"
  // (cause to move) only with an object.
  const wordnet::Database* db = wordnet::Database::shared();
  const auto travel = db->synset(wordnet::Pos::Verb, 1835514), displace = db->synset(wordnet::Pos::Verb, 1850333);
  REQUIRE(travel);
  REQUIRE(displace);
  CHECK(travel->frames == std::vector<int>{1, 2, 4, 22});
  CHECK(displace->frames == std::vector<int>{8, 10, 11});
  // Kinds of "move, displace" (grabbing, combining, meeting someone) no longer slide the whole
  // figure; kinds of travelling still do.
  CHECK(verb_of("grab") == "-");
  CHECK(verb_of("combine") == "-");
  CHECK(verb_of("encounter") == "-");
  CHECK(verb_of("approach") == "move");
  // A limb's verb keeps its objects: throwing moves the arm.
  CHECK(verb_of("toss") == "throw");
  // Senses passed over so do not count among a verb's first: "exercise" claims its fourth, to
  // work out (a root of verb.body its own name names first).
  CHECK(verb_names(parse_prompt("the man works out").clauses.at(0)) == std::vector<std::string>{"exercise"});
}

TEST_CASE("lexicon: kinds of rubbing read as rub; a verb WordNet joins to the next word with no motion is not that verb") {
  if (!wordnet_or_skip()) return;
  // A stem that is a verb with and without an "e" stands for the one used more: twinkle's "shin"
  // is shine, and to clamber (a kind of shinning up) is to climb, not to twinkle.
  CHECK(verb_of("clamber") == "climb");
  CHECK(verb_of("wipe") == "rub");
  CHECK(verb_of("massages") == "rub");
  CHECK(verb_of("scour") == "rub");
  const ParsedPrompt asleep = parse_prompt("the man falls asleep");
  REQUIRE(asleep.clauses.size() == 1);
  CHECK(asleep.clauses[0].verbs.empty());
  CHECK(asleep.unplaced == std::vector<std::string>{"falls asleep"});
  // A direction or a preposition after the verb is where it goes, not one verb with it.
  CHECK(verb_names(parse_prompt("the boat bobs up and down").clauses.at(0)) == std::vector<std::string>{"bob"});
  CHECK(verb_names(parse_prompt("the man leans against the wall").clauses.at(0)) == std::vector<std::string>{"lean"});
  CHECK(verb_names(parse_prompt("the man sits down").clauses.at(0)) == std::vector<std::string>{"sit"});
}

TEST_CASE("parse: a verb said of fire next to it is fire's flicker; a participle before another noun stays its verb") {
  if (!wordnet_or_skip()) return;
  // "flames leaping around it": what the flames do, and fire does one thing (not the verb leap,
  // which moved the whole heart up and down).
  const ParsedPrompt heart = parse_prompt("the heart burns, flames leaping around it");
  const Clause& flames = heart.clauses.back();
  CHECK(verb_names(flames) == std::vector<std::string>{"twinkle"});
  CHECK(flames.verb_words == std::vector<std::string>{"leaping->twinkle"});
  CHECK(noun_named(flames, "flames"));
  CHECK(std::count(heart.readings.begin(), heart.readings.end(), "'leaping' said of flames read as twinkle (what flames does)") == 1);
  // Before the noun (its adjective) and as the subject's verb, the same.
  CHECK(verb_names(parse_prompt("leaping flames").clauses.at(0)) == std::vector<std::string>{"twinkle"});
  CHECK(verb_names(parse_prompt("the dancing flames").clauses.at(0)) == std::vector<std::string>{"twinkle"});
  CHECK(verb_names(parse_prompt("the fire dances").clauses.at(0)) == std::vector<std::string>{"twinkle"});
  CHECK(verb_names(parse_prompt("a flickering candle").clauses.at(0)) == std::vector<std::string>{"twinkle"});
  // Not fire: the participle is the noun's verb ("spinning wheels" spin; water does many things).
  const Clause wheels = parse_prompt("spinning wheels").clauses.at(0);
  CHECK(verb_names(wheels) == std::vector<std::string>{"spin"});
  CHECK(noun_named(wheels, "wheels"));
  const Clause leaves = parse_prompt("falling leaves").clauses.at(0);
  CHECK(verb_names(leaves) == std::vector<std::string>{"fall"});
  CHECK(noun_named(leaves, "leaves"));
  CHECK(verb_names(parse_prompt("rolling waves").clauses.at(0)) == verb_names(parse_prompt("the waves roll").clauses.at(0)));
  CHECK(verb_names(parse_prompt("rolling waves").clauses.at(0)) != std::vector<std::string>{"twinkle"});
  CHECK(verb_names(parse_prompt("the water falls").clauses.at(0)) == std::vector<std::string>{"fall"});
  // Fire after a preposition is where, not who: "the man leaps over the fire" leaps.
  CHECK(verb_names(parse_prompt("the man leaps over the fire").clauses.at(0)) == std::vector<std::string>{"leap"});
}

TEST_CASE("parse: a verb of making a noise moves who makes it: a vehicle's drive, an insect's wings, a thing's shake, a voice") {
  if (!wordnet_or_skip()) return;
  const Lexicon& lex = Lexicon::shared();
  CHECK(lex.is_sound_verb("chugs"));
  CHECK(lex.is_sound_verb("drones"));
  CHECK(lex.is_sound_verb("hums"));  // its first sense is to sing, its second a low sound
  CHECK_FALSE(lex.is_sound_verb("zooms"));  // moves along quickly (or with a hum): a motion
  CHECK_FALSE(lex.is_sound_verb("walks"));
  // The locomotive drives as it chugs, to the right; nothing is left not understood ("along" is
  // no noun).
  const ParsedPrompt loco = parse_prompt("the locomotive chugs along to the right");
  REQUIRE(loco.clauses.size() == 1);
  CHECK(verb_names(loco.clauses[0]) == std::vector<std::string>{"drive"});
  CHECK(loco.clauses[0].mods.travel == 1);
  CHECK(loco.unplaced.empty());
  CHECK(noun_named(loco.clauses[0], "along") == nullptr);
  CHECK(verb_names(parse_prompt("the train rumbles across the screen").clauses.at(0)) == std::vector<std::string>{"drive"});
  // An insect's noise is its wings (WordNet reads "drone" and "hum" as speaking).
  CHECK(verb_names(parse_prompt("the beetle drones").clauses.at(0)) == std::vector<std::string>{"buzz"});
  CHECK(verb_names(parse_prompt("the bee hums").clauses.at(0)) == std::vector<std::string>{"buzz"});
  // A thing that does not move by itself shakes; a creature's noise is its voice, a person's too.
  CHECK(verb_names(parse_prompt("the alarm clock rings").clauses.at(0)) == std::vector<std::string>{"tremble"});
  CHECK(verb_names(parse_prompt("the rooster crows").clauses.at(0)) == std::vector<std::string>{"eat"});
  CHECK(verb_names(parse_prompt("she hums a tune").clauses.at(0)) == std::vector<std::string>{"eat"});
}

TEST_CASE("parse: the head of a compound before a verb WordNet uses as one is who does it ('the steam train puffs')") {
  if (!wordnet_or_skip()) return;
  const Clause c = parse_prompt("the steam train puffs off to the left").clauses.at(0);
  const std::vector<std::string> verbs = verb_names(c);
  CHECK(std::find(verbs.begin(), verbs.end(), "exercise") == verbs.end());  // "train" is no training
  REQUIRE(noun_named(c, "train"));
  CHECK(c.figure == FigureClass::Wheeled);
  CHECK(c.mods.travel == -1);
  // Sent somewhere by a verb that takes it nowhere (a puff, read as a blow: sway), a vehicle
  // goes by its own drive; a creature's verb stays what it says ("the dog looks to the left").
  CHECK(std::find(verbs.begin(), verbs.end(), "drive") != verbs.end());
  CHECK(verb_names(parse_prompt("the dog looks to the left").clauses.at(0)) == std::vector<std::string>{"look"});
  CHECK(verb_names(parse_prompt("the car shakes").clauses.at(0)) == std::vector<std::string>{"shake"});
}

TEST_CASE("parse: 'across', 'from the left', 'along' and 'round and round' say where it goes, not who or what") {
  if (!wordnet_or_skip()) return;
  const Modifiers across = parse_prompt("the cloud floats across the screen slowly").clauses.at(0).mods;
  CHECK(across.across);
  CHECK(across.travel == 0);  // which way: the plan's (travel_across)
  CHECK(across.speed == 0.5);
  CHECK_FALSE(parse_prompt("a scarf across his shoulders flutters").clauses.at(0).mods.across);  // before any verb
  // Where it sets out from: it goes the other way (read as two ways, "from left to right" went none).
  CHECK(parse_prompt("the snake slithers from left to right").clauses.at(0).mods.travel == 1);
  CHECK(parse_prompt("the crab scuttles from the right").clauses.at(0).mods.travel == -1);
  // "round and round" says the spin again: no second clause, no "move" read from "round".
  const ParsedPrompt spin = parse_prompt("the wheel spins round and round");
  REQUIRE(spin.clauses.size() == 1);
  CHECK(verb_names(spin.clauses[0]) == std::vector<std::string>{"spin"});
  const Clause hop = parse_prompt("the chick hops along").clauses.at(0);
  CHECK(verb_names(hop) == std::vector<std::string>{"hop"});
  CHECK(noun_named(hop, "along") == nullptr);
}

TEST_CASE("lexicon: an animal sense the anchors class as no creature does not go before the person ('baby')") {
  if (!wordnet_or_skip()) return;
  CHECK(Lexicon::shared().noun("baby").figure == FigureClass::Biped);  // "baby" 6, a young mammal, is no mammal in WordNet
  // An animal sense that is a creature still goes before its figures of speech.
  CHECK(Lexicon::shared().noun("snake").figure == FigureClass::FishOrSnake);
  CHECK(Lexicon::shared().noun("whale").figure == FigureClass::FishOrSnake);
}

TEST_CASE("lexicon: a vehicle of the same word goes before a rare animal when no sense is ranked ('scooter', not the scoter)") {
  if (!wordnet_or_skip()) return;
  // No sense of "scooter" is tagged; its fifth is the scoter, a duck named "scoter" first.
  CHECK(Lexicon::shared().noun("scooter").figure == FigureClass::Wheeled);
  // Other unranked senses still give way to the animal ("donkey": the party's symbol first).
  CHECK(Lexicon::shared().noun("donkey").figure == FigureClass::Quadruped);
  CHECK(Lexicon::shared().noun("hippo").figure == FigureClass::Quadruped);
}

TEST_CASE("lexicon: a manner word the modifiers do not list is no object of the verb ('he bows politely' bows)") {
  if (!wordnet_or_skip()) return;
  // WordNet knows "politely" and "cheerfully" as adverbs and not as nouns: kept as nouns after
  // the verb they were its objects, things held (held_things.h), and the bow swung an arm.
  for (const char* prompt : {"he bows politely", "she waves cheerfully"}) {
    CAPTURE(prompt);
    const ParsedPrompt p = parse_prompt(prompt);
    REQUIRE(p.clauses.size() == 1);
    CHECK(p.clauses[0].nouns.empty());
    REQUIRE(p.clauses[0].verbs.size() == 1);
  }
  CHECK(parse_prompt("he bows politely").clauses[0].verbs[0]->name == "bow");
  // A word WordNet knows as a noun stays one ("the judge swings his gavel": the gavel is held).
  const ParsedPrompt g = parse_prompt("the judge swings his gavel");
  REQUIRE(g.clauses.size() == 1);
  bool gavel = false;
  for (const auto& n : g.clauses[0].nouns) gavel = gavel || n.word == "gavel";
  CHECK(gavel);
}

}  // TEST_SUITE
