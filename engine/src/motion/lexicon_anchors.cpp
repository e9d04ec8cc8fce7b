// The lexicon's anchors (see lexicon_anchors.h). Sense numbers are WordNet 3.0's, the only
// version Debian ships; an anchor whose sense is missing is skipped (lexicon.cpp).
#include "motion/lexicon_anchors.h"

namespace svgm {

namespace {

using F = FigureClass;

// clang-format off
const std::vector<VerbAnchor> kVerbAnchors = {
  // Every sense of "erupt" is a beginning, an increase, an appearance or catching fire; what a
  // drawing of an eruption shows is its plume going up.
  {"erupt", "rise"},
  // Taking off is leaving (a departure, "move") and landing arriving in WordNet; what a drawing
  // of either shows is the whole figure climbing away or coming down.
  {"take_off", "takeoff"},
  {"lift_off", "takeoff"},
  {"blast_off", "takeoff"},
  {"land", "touchdown"},
  // "explode" and "burst" are changes of integrity in WordNet (no motion above them); drawn,
  // a burst is a quick swelling.
  {"explode", "swell"},
  // "unfurl", "unfold": changes of shape; drawn, the thing lengthens.
  {"unfurl", "stretch"},
  {"unfold", "stretch"},
  // "dribble" is first a liquid's drip in WordNet (read as pour, a fall); dribbling a ball, its
  // third sense, is what a drawing of it shows: the ball bouncing.
  {"dribble", "bounce"},
  // "hang" is first to be suspended (a state), read up WordNet's graph as sink; what hangs from
  // something, drawn, swings to and fro under it ("the sloth hangs from the branch").
  {"hang", "sway"},
};

const std::vector<NounAnchor> kNounAnchors = {
  // Bodies, by how they move.
  {"person", 1, F::Biped, "wave"},
  {"mammal", 1, F::Quadruped, "walk"},
  // WordNet files Homo ("man" in one sense) under the primates: a person's body.
  {"hominid", 1, F::Biped, "wave"},
  {"reptile", 1, F::Quadruped, "walk"},
  {"amphibian", 3, F::Quadruped, "hop"},
  {"bird", 1, F::Bird, "flap"},
  // WordNet files bats under the placental mammals; their body is a pair of wings.
  {"chiropteran", 1, F::Bird, "flap"},
  {"fish", 1, F::FishOrSnake, "swim"},
  {"aquatic_mammal", 1, F::FishOrSnake, "swim"},  // whales, dolphins, seals: a swimmer's body
  {"cephalopod", 1, F::FishOrSnake, "swim"},      // octopus, squid
  {"snake", 1, F::FishOrSnake, "slither"},
  {"worm", 1, F::FishOrSnake, "slither"},
  {"arthropod", 1, F::Insect, "crawl"},
  {"insect", 1, F::Insect, "flutter"},
  {"plant", 2, F::Plant, "sway"},
  {"fungus", 1, F::Plant, "sway"},
  {"plant_part", 1, F::Plant, "sway"},
  // Vehicles: wheels turn; boats rock on the water; aircraft glide (a flap would move wings).
  {"wheeled_vehicle", 1, F::Wheeled, "drive"},
  // WordNet files a bus and a train as public transport (a conveyance), not as wheeled vehicles;
  // drawn, they run on wheels (the bus that "drives off" was an object whose wheels' turning
  // the lexicon did not know). Not public transport as a whole: a shuttle is one too, and
  // "the space shuttle" read so was wheeled.
  {"bus", 1, F::Wheeled, "drive"},
  {"train", 1, F::Wheeled, "drive"},
  {"vessel", 2, F::Object, "rock"},
  {"aircraft", 1, F::Object, "soar"},
  // Fire and light. "fire" 1 is the event of burning, 3 the flame itself.
  {"fire", 1, F::Flame, "flicker"},
  {"fire", 3, F::Flame, "flicker"},
  {"source_of_illumination", 1, F::None, "flicker"},  // candle, lamp, lantern, torch
  // WordNet's first lightning is the discharge (an electrical phenomenon), its second the flash;
  // drawn, a bolt that flashes as a flame flickers.
  {"lightning", 1, F::Flame, "flicker"},
  {"celestial_body", 1, F::Object, "twinkle"},        // sun, star, moon
  // Water and weather. A wave of the sea is a "movement" (an event) in WordNet.
  {"precipitation", 3, F::Liquid, "fall"},
  {"drop", 2, F::Liquid, "fall"},
  {"liquid", 1, F::Liquid, "flow"},
  {"liquid", 3, F::Liquid, "flow"},
  {"wave", 1, F::Liquid, "ripple"},
  {"body_of_water", 1, F::Scene, "ripple"},
  {"cloud", 1, F::None, "rise"},  // smoke, steam, dust: particles in the air go up
  {"cloud", 2, F::Object, "float"},
  {"steam", 1, F::None, "rise"},  // WordNet files steam as water (a liquid)
  {"plume", 1, F::None, "rise"},  // "a plume of smoke" is a shape (an abstraction) in WordNet
  // A volcano is a mountain (or a vent) in WordNet; its motion is its plume going up.
  {"volcano", 1, F::Scene, "rise"},
  {"volcano", 2, F::Scene, "rise"},
  {"flag", 1, F::Object, "ripple"},  // cloth on a pole: the wind runs along it
  // Still things: where the figure is, or a thing among others.
  {"geological_formation", 1, F::Scene, nullptr},
  {"location", 1, F::Scene, nullptr},
  {"structure", 1, F::Scene, nullptr},  // buildings, bridges
  {"physical_entity", 1, F::Object, nullptr},
};

// Making a noise: WordNet's "sound, go" (make a certain noise: chug, rumble, drone, hum 2, buzz),
// "noise, make noise, resound" (clang, clatter) and "utter, emit, let out" (crow, bark, roar).
const std::vector<VerbSense> kSoundAnchors = {{"sound", 2}, {"noise", 1}, {"utter", 2}};

// The body's doings, drawn as what a viewer sees the body do.
const std::vector<VerbSenseAnchor> kVerbSenseAnchors = {
  // Laughing shakes the body (giggle, chuckle, guffaw, snicker: all kinds of laugh 1).
  {"laugh", 1, "shake"},
  // Breathing swells and settles the chest (yawn, sigh, snore, inhale, exhale, wheeze).
  {"breathe", 1, "pulse"},
  // Weeping heaves it (sob, bawl, wail, whimper: kinds of cry 2, "cry, weep").
  {"cry", 2, "pulse"},
  // A shrug is WordNet's gesture; drawn, both arms lift from the shoulders and fall.
  {"shrug", 1, "lift"},
  // Melting is a change of state (no motion above it); drawn, the thing slumps down and spreads:
  // melt 2 "dissolve, thaw, unfreeze" and melt 3 "melt, run, melt down" (melt 1 is to fade).
  {"melt", 2, "sit"},
  {"melt", 3, "sit"},
};
// clang-format on

}  // namespace

const std::vector<VerbAnchor>& verb_anchors() { return kVerbAnchors; }
const std::vector<VerbSense>& sound_anchors() { return kSoundAnchors; }
const std::vector<VerbSenseAnchor>& verb_sense_anchors() { return kVerbSenseAnchors; }
const std::vector<NounAnchor>& noun_anchors() { return kNounAnchors; }

const char* class_motion(FigureClass c) {
  switch (c) {
    case F::Biped: return "wave";
    case F::Quadruped: return "walk";
    case F::Bird: return "flap";
    case F::FishOrSnake: return "swim";
    case F::Insect: return "flutter";
    case F::Plant: return "sway";
    case F::Wheeled: return "drive";
    case F::Flame: return "flicker";
    case F::Liquid: return "ripple";
    default: return nullptr;
  }
}

}  // namespace svgm
