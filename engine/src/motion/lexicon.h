// The motion lexicon: reads words the hand-written vocabulary (motion/motion_verbs.h) does not
// list, through WordNet (wordnet.h), as the nearest meaning the vocabulary has.
//
//  - A verb becomes the nearest vocabulary verb: its senses' hypernym chains (with verb groups and
//    entailments) are walked upwards until a synset holds a vocabulary verb ("shuffle" is a kind
//    of "walk"; "scurry" of "run"); a shorter path wins, then an earlier (more frequent) sense.
//  - A noun gets a figure class (hummingbird -> bird, gazelle -> quadruped, tractor -> wheeled),
//    the part noun it is a kind or a part of (talon -> claw, finger -> hand), and the motion the
//    thing itself makes when the prompt gives no verb for it (flame -> flicker, rain -> fall).
//
// Where WordNet's graph does not reach a motion, a small table of anchors (lexicon_anchors.h)
// does. Without the database, nothing is placed: the vocabulary alone is used.
#pragma once

#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "motion/wordnet.h"
#include "motion/motion_verbs.h"

namespace svgm {

// What kind of figure a noun names, for the motion it may make on its own.
enum class FigureClass { None, Biped, Quadruped, Bird, FishOrSnake, Insect, Plant, Wheeled, Flame, Liquid, Object, Scene };
const char* figure_class_name(FigureClass c);  // "biped", "fish_or_snake", ...; "none"
// A living thing that moves itself (biped, quadruped, bird, fish or snake, insect): what beats
// wings and walks; plants, flames, liquids, machines, objects and scenes do not.
bool is_creature(FigureClass c);

struct VerbReading {
  const Verb* verb = nullptr;  // null: not placed
  std::string via;             // how: "walk" (the WordNet word that holds it) or "anchor"
  int depth = 0;               // hypernym steps from the word's sense (0: a synonym)
};

struct NounReading {
  FigureClass figure = FigureClass::None;
  const PartNoun* part = nullptr;  // the vocabulary part noun it is a kind or part of
  const Verb* motion = nullptr;    // the motion the thing makes by itself (noun-driven)
  std::string motion_word;         // the word that motion was named by ("flicker" for twinkle)
  std::string via;                 // the WordNet word that gave the class ("bird", "ungulate" ...)
  std::string sense_why;           // when the context chose a sense other than the most frequent
                                   // (sense_context.h): "drone: sense 4 by 'aircraft', 'fly'"
};

class Lexicon {
 public:
  explicit Lexicon(const wordnet::Database* db);
  // Built once over wordnet::Database::shared().
  static const Lexicon& shared();

  bool has_wordnet() const { return db_ != nullptr; }
  // `word` as written ("shuffles", "scurrying"); read as a verb.
  VerbReading verb(std::string_view word) const;
  // A phrasal verb ("takes" "off", "fans" "out") when WordNet lists it; else not placed.
  VerbReading phrasal_verb(std::string_view word, std::string_view particle) const;
  // `context`: the prompt's other words, which may pick a less frequent sense (sense_context.h).
  NounReading noun(std::string_view word, const std::vector<std::string>& context = {}) const;
  // Whether WordNet files a sense of the noun `word` with the animals (noun.animal holds their
  // body parts: "foreleg", "forepaw", "forewing"; "forearm" and "forehead" are noun.body).
  bool noun_is_animal_word(std::string_view word) const;
  // Whether `word` as a verb mostly says a noise is made ("chugs", "rumbles", "drones", "hums",
  // "crows"): one of its first senses is a kind of making a noise (lexicon_anchors.h's
  // sound_anchors) and none of them a motion ("zooms", "whistles" past: moving with a noise).
  // What moves then is the one making it (prompt_parse.cpp: a machine's own motion, an
  // insect's wings, a creature's mouth).
  bool is_sound_verb(std::string_view word) const;
  bool knows_verb(std::string_view word) const;
  bool knows_noun(std::string_view word) const;
  // How many of the word's senses as `pos` are ranked by tagged frequency (its first base form):
  // how often it is used so, to tell "lands" the verb from "boots" the noun where the place in
  // the sentence does not.
  int tagged_senses(std::string_view word, wordnet::Pos pos) const;

 private:
  using Pos = wordnet::Pos;
  VerbReading verb_from_lemmas(const std::vector<std::string>& lemmas) const;
  std::vector<uint32_t> noun_senses(const std::string& lemma) const;
  FigureClass sense_class(uint32_t sense) const;  // the nearest class anchor up its hypernyms
  void claim_verbs();
  bool is_drawn_change(uint32_t offset) const;
  void claim_parts();
  void place_anchors();

  const wordnet::Database* db_;
  struct VerbClaim {
    const Verb* verb;
    std::string lemma;
  };
  std::unordered_map<uint32_t, std::vector<VerbClaim>> verb_claims_;  // verb synset -> vocabulary verbs
  std::unordered_map<uint32_t, const PartNoun*> part_claims_;         // noun synset -> part noun
  struct NounPlace {
    FigureClass figure;
    const char* motion;  // a word of the vocabulary, or null
  };
  std::unordered_map<uint32_t, NounPlace> noun_anchors_;  // noun synset -> class, motion
  std::vector<uint32_t> sound_roots_;                     // verb synsets of making a noise
};

// The motion a figure of this class makes when the prompt names none for it (a bird flaps, a
// flame flickers, a plant sways); null for objects and scenes.
const Verb* default_verb(FigureClass c);

// The vocabulary verb a word names by the table's stems (motion_verbs.h), or null.
const Verb* vocabulary_verb(std::string_view word);

}  // namespace svgm
