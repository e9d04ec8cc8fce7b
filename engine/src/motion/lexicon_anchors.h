// The motion lexicon's hand anchors (lexicon.h): the few places where WordNet's graph does not
// lead from a word to a motion, and the noun synsets that name a figure class or a motion of
// their own. Data only; each row says why it is needed.
#pragma once

#include <vector>

#include "motion/lexicon.h"

namespace svgm {

// A verb lemma WordNet does not connect to any motion verb, and the vocabulary word it means.
struct VerbAnchor {
  const char* lemma;
  const char* motion;  // a word the vocabulary's stems match
};
const std::vector<VerbAnchor>& verb_anchors();

// A noun synset (lemma and WordNet 3.0 sense number, 1-based): the class of every noun under it,
// and the motion such a thing makes by itself (null: none). The nearest anchor up a noun's
// hypernym chain gives its class; the nearest with a motion, its motion.
struct NounAnchor {
  const char* lemma;
  int sense;
  FigureClass figure;  // None: only a motion
  const char* motion;
};
const std::vector<NounAnchor>& noun_anchors();

// A verb synset (lemma and WordNet 3.0 sense number, 1-based) that every way of making a noise
// is a kind of: "chug", "rumble", "drone" (sound, go: "make a certain noise"), "crow" (utter,
// emit). Lexicon::is_sound_verb reads a verb under one as a sound.
struct VerbSense {
  const char* lemma;
  int sense;
};
const std::vector<VerbSense>& sound_anchors();

// A verb synset that every verb beneath it draws as one vocabulary motion. Where a whole family
// of verbs has no motion above it in WordNet (the body's doings: laughing, breathing, weeping
// are filed under verb.body and rise to "express emotion" or to nothing), claiming the family's
// root places every kind of it: "giggles", "chuckles" and "guffaws" under laugh, "yawns",
// "sighs" and "snores" under breathe. A word's own claims nearer to it still win (lexicon.cpp).
struct VerbSenseAnchor {
  const char* lemma;
  int sense;
  const char* motion;  // a word the vocabulary's stems match
};
const std::vector<VerbSenseAnchor>& verb_sense_anchors();

// The motion word of each class (default_verb).
const char* class_motion(FigureClass c);

}  // namespace svgm
