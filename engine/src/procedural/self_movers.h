// Things that move by themselves, as a prompt names them (issue 35): a fire's or a lamp's flames
// flicker, a plume of smoke or steam rises, a thing with nothing drawn apart to fall tumbles
// itself. What moves is the thing the noun names, found on the drawing, and how it moves is its
// own: a flame's tip sways fast from its base (not a pulse of repeated sparks), a plume swells up
// from where it leaves the body (not a swing on its base), a falling leaf goes down whole (not a
// fall of the drops it does not have). motion_plan.cpp asks these questions of each clause.
#pragma once

#include "motion/motion_verbs.h"
#include "procedural/legged_crawl.h"
#include "procedural/part_locator.h"
#include "procedural/prompt_parse.h"

#include <string>

namespace svgm {

// Whether the clause's twinkle ("flickers", "glows") is said of fire or of a light: who twinkles
// is a fire (the lexicon's flame class) or a thing whose own motion is a twinkle with no class
// (a source of light), or with `lights` any thing whose own motion is a twinkle (the lexicon
// files a candle as an object, as it does a star: asked only where flames are looked for).
bool twinkle_of_fire(const Clause& c, bool lights);

// The verb a clause's verb `v` becomes: a twinkle of fire or light is the flame's flicker when
// its flames are located (`located`) or the drawing has no repeated sparks to twinkle; any
// other verb is itself.
const Verb* flame_verb(const Verb* v, const Clause& c, const Rig& rig, const LocatedPart* located);

// The clause's verbs, each as flame_verb reads it, each of a figure on wheels as wheeled_travel
// does, each of an insect as insect_flight does, a crawl on legs as legged_crawl does, and a
// person's motion of a thing held as held_thing_reading does (held_things.h).
std::vector<const Verb*> clause_verbs(const Clause& c, const Rig& rig, const LocatedPart* located);

// An insect that goes about goes by flight (issue 35): a verb said of the whole insect (the
// clause's class is insect) that moves it about other than on its legs (a flight, a flutter, a
// soar, a glide, a generic move: WordNet reads "flits" as flutter, "zips" as move) is buzz's
// dart about a small area with its wings beating fast (motion_verbs.cpp). Read as they were, a
// mosquito that "flits around" and a butterfly that "flutters by" beat their wings in place, a
// fly that "zips around" slid with its wings still, and a beetle that "flies about, wings
// beating" (the wings named, the flight's bob left out as their accent) stayed where it was. A
// verb whose object is a part ("flutters its wings": a limb noun after the verb) moves that
// part; a crawl, a creep or an inch (move's words of legs on the ground) stays a crawl.
// `word`: the verb as written (Clause::verb_words).
const Verb* insect_flight(const Verb* v, const Clause& c, const std::string& word);

// The clause's verb `i` as written (Clause::verb_words), else its vocabulary name.
const std::string& verb_word(const Clause& c, size_t i);

// A figure on wheels (the clause's class is wheeled: a car, a tractor, a bus) gets somewhere by
// its wheels: a verb that carries a figure along by other means (a generic move, which WordNet
// reads "pulls away", "trundles", "chugs" as; a glide; a flight; a gait of legs in turn: "the
// racing car zooms off" read as a run and a soar) is its class's drive (wheels rolling as the
// body slides). Read as they were, the taxi slid and stretched with its wheels still, and the
// racing car bent its lower part for legs and bobbed as if in flight. Any other verb (a hop, a
// spin, a takeoff, a rock) is itself.
const Verb* wheeled_travel(const Verb* v, const Clause& c);

// The flames of a fire or a light that flickers with no part named ("the candles flicker"; in
// "the candle flames flicker" the flames read as a verb): the locator's flames, empty when the
// clause is not of fire or of a light or none are found (a star has nothing drawn above it).
LocatedPart flames_of_light(const Clause& c, const Rig& rig);

// Whether a verb of primitive `p` aimed at the located part makes a plume rise: a jet (smoke,
// steam, a spout) that bobs, swells, stretches or billows (swung, a billowing cloud of smoke
// rocked on the chimney it rises from).
bool plume_rises(const LocatedPart* located, Primitive p);

// How a located part that moves its own way moves, whatever verb is aimed at it: a plume that
// rises swells up from its base (plume_rises); a rotor's blades spin about their hub
// (rotor_blades.h: "the blades turn in the breeze" is no swing on a joint). Sets `primitive`
// and `amp`; returns why, empty when `located` is neither (nothing changed).
std::string own_motion(const Rig& rig, const LocatedPart* located, Primitive& primitive, double& amp);

// A rising plume's growth about its base (a fraction of its length): its top goes up
// kPlumeRise of the figure's height, the growth between kPlumeGrowMin and kPlumeGrowMax.
double plume_growth(const Rig& rig, const LocatedPart& plume);
inline constexpr double kPlumeRise = 0.12;     // issue 35's floor on a visible motion is 8 %
inline constexpr double kPlumeGrowMin = 0.25;  // a long plume still swells by a quarter
inline constexpr double kPlumeGrowMax = 0.6;   // a small one by at most this (it leaves the canvas)

// Whether the rig's repeated elements are the figure itself, one thing drawn in similar pieces
// (a snowflake's arms drawn as eight small strokes): together they span kOneThingSpan of the
// figure's box both across and down (openmoji's snowflake: its eight small strokes span all its
// width and 77 % of its height, the long arms reaching past them). Drops falling from a cloud
// span its width but not its height (the cloud above them: 32 % and 40 % in the suite's snow
// and rain). "The snowflake falls" then falls whole, turning as it goes
// (a tumble), not as eight strokes dropping apart from each other.
bool repeated_are_the_figure(const Rig& rig);
inline constexpr double kOneThingSpan = 0.7;

}  // namespace svgm
