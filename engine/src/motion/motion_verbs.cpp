// The motion vocabulary (see motion_verbs.h). Amplitudes are for a "normal" clause; the
// modifiers scale them and the plan (motion_plan.h) scales them down further when a part would
// leave the canvas or move too far between keyframes for the fitter to follow.
#include "motion/motion_verbs.h"

#include <algorithm>
#include <array>

namespace svgm {

namespace {

using P = Primitive;
using T = Target;
using Pr = Pairing;

// clang-format off
const std::vector<Verb> kVerbs = {
  // Wings, arms.
  {"flap",    {"flap"},                         {{P::Swing, T::Arms, 30, 2, Pr::Mirrored}, {P::Bob, T::Whole, 0.03, 2}}, P::Swing},
  {"fly",     {"fly", "flie", "flew"},          {{P::Swing, T::Arms, 26, 2, Pr::Mirrored}, {P::Bob, T::Whole, 0.05, 1}}, P::Swing},
  {"flutter", {"flutter"},                      {{P::Swing, T::Arms, 16, 5, Pr::Mirrored}}, P::Swing},
  {"hover",   {"hover"},                        {{P::Swing, T::Arms, 18, 4, Pr::Mirrored}, {P::Bob, T::Whole, 0.04, 1}}, P::Swing},
  // The sound of wings or blades beating fast. Said of a flyer ("the bee buzzes about"), its wings
  // beat fast and its body darts about a small area: across once a loop and up and down twice, a
  // figure eight. Said of a part ("its rotor whirring"), that part moves (a rotor spins:
  // rotor_blades.h). Not "hum" nor "drone": a person hums a tune (WordNet: speak).
  {"buzz",    {"buzz", "whir", "whirr", "whiz", "whizz"}, {{P::Swing, T::Arms, 16, 6, Pr::Mirrored}, {P::Slide, T::Whole, 0.07, 1}, {P::Bob, T::Whole, 0.05, 2}}, P::Swing},
  {"soar",    {"soar", "glid"},                 {{P::Rock, T::Whole, 5, 1}, {P::Bob, T::Whole, 0.04, 1}, {P::Swing, T::Arms, 8, 1, Pr::Mirrored}}, P::Swing},
  {"wave",    {"wav", "greet", "goodby"},       {{P::Swing, T::Arms, 35, 2, Pr::OneSide}}, P::Swing},
  {"clap",    {"clap"},                         {{P::Swing, T::Arms, 22, 4, Pr::Mirrored}}, P::Swing},
  {"cheer",   {"cheer", "celebrat", "rejoic"},  {{P::Swing, T::Arms, 32, 3, Pr::Mirrored}, {P::Hop, T::Whole, 0.03, 3}}, P::Swing},
  {"punch",   {"punch", "box", "jab", "fight", "fenc", "thrust", "stab", "pok"}, {{P::Swing, T::Arms, 26, 3, Pr::OneAtATime}, {P::Swing, T::Root, 1.5, 3}}, P::Swing},  // the body turns into each punch about the hips, the legs planted (motion_plan.h), a little: at 4 degrees a boxer's body and head outweighed his fist; one fist, the other keeps guard
  // Juggling: the tossed things (balls held up by a figure, tossed_things.h) fly a cascade from
  // hand to hand, the arms pumping a little as they throw. "Tosses the balls" and "keeps the
  // balls in the air" read so too when the drawing holds such things (tossed_things.h); "toss"
  // alone stays the wind's (fronds toss).
  {"juggle",  {"juggl"},                        {{P::Toss, T::Whole, 1, 1}, {P::Swing, T::Arms, 8, 3, Pr::Alternating}}, P::Toss},
  {"throw",   {"throw", "threw", "hurl", "fling", "flung"}, {{P::Swing, T::Arms, 40, 1, Pr::OneSide}}, P::Swing},  // one arm swings over and back; not "toss" nor "pitch": fronds toss in the wind, boats pitch
  // A thing a person holds, moved by the arms (procedural/held_things.h reads "swings the club"
  // and "pulls the oars" so): a swing of it is one arm's big swing and back, as a throw's; a
  // pull or a push both arms' strokes. No stems: the prompt's own verb says which.
  {"wield",   {},                               {{P::Swing, T::Arms, 40, 1, Pr::OneSide}}, P::Swing},
  {"haul",    {},                               {{P::Swing, T::Arms, 24, 2, Pr::Mirrored}}, P::Swing},
  {"lift",    {"lift", "rais", "hold"},         {{P::Swing, T::Arms, 24, 2, Pr::Mirrored}}, P::Swing},
  {"reach",   {"reach", "spread"},              {{P::Swing, T::Arms, 20, 1, Pr::Mirrored}}, P::Swing},
  {"pump",    {"pump"},                         {{P::Swing, T::Arms, 20, 2, Pr::Alternating}}, P::Swing},
  // Rubbing is a part going back and forth against something (its pair, the body, a surface):
  // quick small swings of the part the prompt names, the hands when it names none. WordNet
  // places its kinds here (scour, massage, chafe, scratch).
  {"rub",     {"rub", "scrub"},                 {{P::Swing, T::Arms, 16, 4, Pr::Mirrored}}, P::Swing},
  // Legs and gaits.
  {"walk",    {"walk", "march", "stroll", "step", "strid"}, {{P::Swing, T::Legs, 18, 2, Pr::Alternating}, {P::Swing, T::Arms, 12, 2, Pr::Alternating}, {P::Bob, T::Whole, 0.015, 4}}, P::Swing},
  {"run",     {"run", "ran", "sprint", "jog", "rush", "dash"}, {{P::Swing, T::Legs, 28, 3, Pr::Alternating}, {P::Swing, T::Arms, 20, 3, Pr::Alternating}, {P::Bob, T::Whole, 0.025, 6}}, P::Swing},
  // A gallop's body rises at each stride as a runner's does. Rocked about its base as well, the
  // whole horse (a line drawing's head and mane are most of its strokes) moved as much as its
  // legs, which the turn limit cuts to half at three strides a loop (share on the legs 0.48).
  {"gallop",  {"gallop", "trot", "canter"},     {{P::Swing, T::Legs, 24, 3, Pr::Alternating}, {P::Bob, T::Whole, 0.025, 6}}, P::Swing},
  {"kick",    {"kick"},                         {{P::Swing, T::Legs, 30, 2, Pr::OneSide}}, P::Swing},
  {"pedal",   {"pedal", "cycl", "bik"},         {{P::Swing, T::Legs, 22, 2, Pr::Alternating}, {P::Spin, T::Wheels, 1, 1}}, P::Swing},
  {"climb",   {"climb", "scrambl"},             {{P::Swing, T::Arms, 20, 2, Pr::Alternating}, {P::Swing, T::Legs, 16, 2, Pr::Alternating}, {P::Bob, T::Whole, 0.02, 2}}, P::Swing},
  // The whole figure.
  {"jump",    {"jump", "skip", "spring"},       {{P::Hop, T::Whole, 0.14, 1}}, P::Hop},
  {"leap",    {"leap", "lept", "pounc"},        {{P::Hop, T::Whole, 0.16, 1}, {P::Rock, T::Whole, 8, 1}}, P::Hop},
  {"hop",     {"hop"},                          {{P::Hop, T::Whole, 0.07, 2}}, P::Hop},
  {"bounce",  {"bounc", "boing"},               {{P::Hop, T::Whole, 0.08, 2}}, P::Hop},
  {"bob",     {"bob"},                          {{P::Bob, T::Whole, 0.04, 2}}, P::Swing},  // a bobbing head nods on its neck: moved up and down whole it came off the neck, and a head drawn in the body's shape had no part to move
  {"float",   {"float", "drift", "levitat"},    {{P::Bob, T::Whole, 0.05, 1}, {P::Rock, T::Whole, 3, 1}}, P::Bob},
  // Leaving the ground (a plane taking off, a rocket lifting off: lexicon_anchors.cpp): the whole
  // figure climbs away and comes back, going forward as it climbs. Read as "move" (a slide of 4 %
  // and a stretch), the plane taking off crept along the runway; a bob of 12 % about where it
  // stood dipped as far below and read as a hover: it climbs only up (motion_plan.cpp), a
  // quarter of its height where the canvas has room (fit_plan scales it down where not). It also
  // shrinks toward its top, going away into the sky (a negative pulse, about its top: motion_plan.cpp),
  // and rumbles as it goes: a figure filling its canvas had no room to climb and did not move at
  // all. "Launches" is a launch (read as a drive, a rocket slid along the ground). A figure whose
  // nose is read (flight_axis.h: a rocket, a plane) goes along it instead, speeding up, without
  // the slide and the shrink (motion_plan.cpp): on a rocket on a slant they read as going away.
  {"takeoff", {"takeoff", "liftoff", "blastoff", "launch"}, {{P::Bob, T::Whole, 0.25, 1}, {P::Slide, T::Whole, 0.06, 1}, {P::Pulse, T::Whole, -0.3, 1}, {P::Shake, T::Whole, 0.012, 8}}, P::Bob},
  // Coming down to the ground (a plane landing: lexicon_anchors.cpp): the figure comes in along
  // its nose when it points down (flight_axis.h), else straight down, slowing to rest, and stays
  // (travel_profile.h's land_at). Read as a sink (a bob both ways and a rock), the arriving plane
  // rocked with its runway and bobbed about where it stood. Its stem is "touchdown" only: WordNet
  // reads "lands", "landed" as land (lexicon_anchors.cpp); a stem "land" would read "landscape".
  {"land",    {"touchdown"},                    {{P::Bob, T::Whole, 0.25, 1}}, P::Bob},
  {"rise",    {"ris", "rose", "ascend"},        {{P::Bob, T::Whole, 0.06, 1}}, P::Bob},
  {"sink",    {"sink", "sank", "div", "descend"}, {{P::Bob, T::Whole, 0.06, 1}, {P::Rock, T::Whole, 4, 1}}, P::Bob},
  {"sway",    {"sway", "blow", "breez"},        {{P::Sway, T::Whole, 8, 1}}, P::Swing},
  {"rock",    {"rock", "swing", "swung"},       {{P::Rock, T::Whole, 7, 1}}, P::Swing},
  {"lean",    {"lean", "tilt", "tip"},          {{P::Rock, T::Whole, 8, 1, Pr::OneSide}}, P::Swing},
  {"bow",     {"bow"},                          {{P::Rock, T::Whole, 10, 1, Pr::OneSide}}, P::Swing},
  {"dance",   {"danc", "groov", "boogi", "twerk"}, {{P::Swing, T::Arms, 28, 2, Pr::Alternating}, {P::Rock, T::Whole, 5, 2}, {P::Bob, T::Whole, 0.025, 4}}, P::Swing},
  {"play",    {"play", "frolic"},               {{P::Swing, T::Limbs, 14, 2, Pr::Alternating}, {P::Bob, T::Whole, 0.02, 2}}, P::Swing},
  {"exercise", {"exercis", "lung", "yoga", "workout", "train"}, {{P::Squash, T::Whole, 0.06, 1}, {P::Swing, T::Arms, 22, 1, Pr::Mirrored}}, P::Swing},
  {"sit",     {"sit", "sat", "crouch", "squat", "kneel", "duck"}, {{P::Squash, T::Whole, 0.1, 1}}, P::Swing},
  {"stretch", {"stretch", "extend", "elongat", "lengthen"}, {{P::Stretch, T::Whole, 0.08, 1}}, P::Swing},
  {"move",    {"mov", "go", "went", "advanc", "crawl", "creep", "inch", "proceed", "travel"}, {{P::Slide, T::Whole, 0.04, 1}, {P::Stretch, T::Whole, 0.04, 2}}, P::Swing},
  {"glide",   {"ski", "skat", "surf", "slid", "sled", "ride", "riding", "rode", "ridden", "maneuver", "manoeuvr", "sail", "row"}, {{P::Slide, T::Whole, 0.04, 1}, {P::Rock, T::Whole, 5, 1}}, P::Swing},
  // A vehicle drives: it travels (a slide, out and back within the canvas) with its engine's
  // tremor, its wheels rolling with it. With the shake and spin alone a car whose wheels are
  // plain discs did not move at all, and "drives off to the right" stood still.
  {"drive",   {"driv", "drove", "roll", "accelerat", "speed"}, {{P::Shake, T::Whole, 0.006, 6}, {P::Spin, T::Wheels, 1, 1}, {P::Slide, T::Whole, 0.1, 1}}, P::Spin},
  {"dodge",   {"dodg", "evad"},                 {{P::Swing, T::Root, 8, 2}}, P::Swing},  // a lean of the body about the hips, the legs planted
  // A swimmer's strokes: the arms turn over about the shoulders in whole turns, in turn (the
  // front crawl), backwards (backstroke) or together (butterfly: arm_strokes.h reads "crawl" and
  // "butterfly" so only of a swimmer).
  {"stroke",  {"freestyl"},                     {{P::Windmill, T::Arms, 1, 1, Pr::Alternating}}, P::Windmill},
  {"backstroke", {"backstrok"},                 {{P::Windmill, T::Arms, 1, 1, Pr::Alternating}}, P::Windmill},
  {"butterfly", {},                             {{P::Windmill, T::Arms, 1, 1, Pr::Mirrored}}, P::Windmill},
  // Bodies that bend.
  {"swim",    {"swim", "swam", "paddl"},        {{P::Undulate, T::Whole, 0.05, 1}, {P::Slide, T::Whole, 0.02, 1}}, P::Undulate},
  {"slither", {"slither", "undulat", "wriggl", "squirm", "sinuous", "snak", "weav"}, {{P::Undulate, T::Whole, 0.06, 1}}, P::Undulate},
  {"ripple",  {"rippl", "billow", "flow"},      {{P::Undulate, T::Whole, 0.04, 2}}, P::Undulate},
  {"bend",    {"bend", "bent", "arch", "curl", "flex", "curv", "contract", "droop", "wilt", "sag"}, {{P::Bend, T::Whole, 14, 1}}, P::Bend},
  {"twist",   {"twist", "wiggl"},               {{P::Swing, T::Root, 10, 2}}, P::Swing},
  {"wobble",  {"wobbl", "jiggl", "jell", "squish"}, {{P::Bend, T::Whole, 7, 3}}, P::Bend},
  // Heads and tails.
  {"nod",     {"nod", "agree", "yes"},          {{P::Swing, T::Head, 12, 2}}, P::Swing},
  {"look",    {"look", "glanc", "peek", "watch"}, {{P::Swing, T::Head, 10, 1}}, P::Swing},
  {"eat",     {"eat", "ate", "chew", "munch", "nibbl", "bite", "sing", "sang", "talk", "speak", "suck", "sip"}, {{P::Swing, T::Head, 6, 4}}, P::Swing},
  {"wag",     {"wag", "swish", "flick"},        {{P::Swing, T::Tail, 25, 4}}, P::Swing},
  {"shake",   {"shak", "shook", "jitter", "rattl"}, {{P::Shake, T::Whole, 0.012, 6}}, P::Swing},
  {"tremble", {"trembl", "shiver", "vibrat", "quiver", "shudder"}, {{P::Shake, T::Whole, 0.006, 12}}, P::Shake},
  // Turning about the part's own centre.
  {"spin",    {"spin", "spun", "turn", "rotat", "twirl", "whirl", "revolv", "pirouett"}, {{P::Spin, T::Root, 1, 1}}, P::Spin},
  // Size.
  {"pulse",   {"puls", "breath", "beat", "throb", "heav"}, {{P::Pulse, T::Whole, 0.05, 2}}, P::Pulse},
  {"grow",    {"grow", "grew", "inflat", "swell", "expand", "shrink", "shrank", "deflat", "open", "bloom", "unfold", "unfurl"}, {{P::Pulse, T::Whole, 0.1, 1}}, P::Pulse},
  // A flame flickers: its tip sways quickly and it stretches up from its base. No stem: the word
  // "flicker" is twinkle's (stars), and motion_plan.cpp reads it so when a fire or a light flickers.
  {"flicker", {},                               {{P::Bend, T::Whole, 12, 3}, {P::Stretch, T::Whole, 0.08, 2}}, P::Swing},
  {"twinkle", {"twinkl", "sparkl", "glow", "shin", "flicker", "blink", "glitter", "shimmer"}, {{P::Pulse, T::Repeated, 0.2, 2}}, P::Pulse},
  // A figure that falls itself (motion_plan.cpp: a fall with no repeated elements to move): down
  // and back, turning to and fro as a leaf does, drifting on the air. No stem: the words are
  // fall's. A figure in pieces (two leaves) tumbles each piece its own way (figure_pieces.h).
  {"tumble",  {},                               {{P::Bob, T::Whole, 0.12, 1}, {P::Rock, T::Whole, 12, 2}, {P::Slide, T::Whole, 0.05, 1}}, P::Bob},
  // Repeated elements.
  {"fall",    {"fall", "fell", "rain", "pour", "drip", "snow", "tumbl", "descend", "shower"}, {{P::Fall, T::Repeated, 0.12, 1}}, P::Fall},
};

const std::vector<PartNoun> kNouns = {
  {"wing", T::Arms}, {"arm", T::Arms}, {"hand", T::Arms}, {"fist", T::Arms}, {"paw", T::Arms},
  {"glove", T::Arms}, {"elbow", T::Arms}, {"dumbbell", T::Arms},
  {"leg", T::Legs}, {"foot", T::Legs}, {"feet", T::Legs}, {"knee", T::Legs}, {"boot", T::Legs},
  {"fin", T::Limbs}, {"flipper", T::Limbs}, {"tentacl", T::Limbs}, {"petal", T::Limbs}, {"leaf", T::Limbs},
  {"leav", T::Limbs}, {"frond", T::Limbs}, {"branch", T::Limbs}, {"limb", T::Limbs}, {"claw", T::Limbs},
  {"head", T::Head}, {"face", T::Head}, {"hood", T::Head}, {"neck", T::Head},
  {"tail", T::Tail},
  {"body", T::Root}, {"torso", T::Root}, {"trunk", T::Root}, {"hip", T::Root}, {"waist", T::Root},
  {"wheel", T::Wheels}, {"tire", T::Wheels}, {"tyre", T::Wheels},
  {"ball", T::Wheels},  // a round thing of the figure, as a wheel is: it bounces, rolls, spins
  {"drop", T::Repeated}, {"raindrop", T::Repeated}, {"droplet", T::Repeated}, {"star", T::Repeated},
  {"snowflak", T::Repeated}, {"flak", T::Repeated}, {"bubbl", T::Repeated}, {"confetti", T::Repeated},
  {"background", T::Background},
};
// clang-format on

bool in(std::string_view w, std::initializer_list<std::string_view> list) {
  return std::find(list.begin(), list.end(), w) != list.end();
}

}  // namespace

const std::vector<Verb>& motion_verbs() { return kVerbs; }

const Verb* find_verb_by_name(std::string_view name) {
  for (const auto& v : kVerbs)
    if (v.name == name) return &v;
  return nullptr;
}

const Verb* find_verb_by_word(std::string_view word) {
  // The longest stem wins: "flicker" is twinkle's stem, not wag's "flick" with the agent ending.
  const Verb* best = nullptr;
  size_t best_len = 0;
  for (const auto& v : kVerbs)
    for (const auto& s : v.stems)
      if (s.size() > best_len && word_matches(word, s)) best = &v, best_len = s.size();
  return best;
}

const std::vector<PartNoun>& part_nouns() { return kNouns; }

bool word_matches(std::string_view word, std::string_view stem) {
  if (word.size() < stem.size() || word.substr(0, stem.size()) != stem) return false;
  const std::string_view rest = word.substr(stem.size());
  if (in(rest, {"", "s", "es", "e", "ed", "d", "ing", "er", "ers", "y", "ly", "ion", "ions", "ies"})) return true;
  // A doubled last consonant: flap -> flapping, run -> running, pedal -> pedalling.
  return rest.size() >= 3 && rest[0] == stem.back() && in(rest.substr(1), {"ing", "ed", "er", "ers"});
}

bool apply_modifier(std::string_view w, Modifiers& m) {
  bool hit = true;
  if (in(w, {"slow", "slowly", "lazily", "leisurely", "calmly", "gradually"})) m.speed = 0.5;
  else if (in(w, {"fast", "quickly", "quick", "rapidly", "rapid", "swiftly", "briskly", "frantically"})) m.speed = 2;
  else if (in(w, {"gently", "gentle", "softly", "soft", "slightly", "slight", "subtly", "subtle", "little", "lightly", "mildly"})) m.size = 0.5;
  else if (in(w, {"wildly", "wild", "vigorously", "energetically", "powerfully", "powerful", "strongly", "violently", "hard", "big", "wide", "widely", "high", "madly"})) m.size = 1.6;
  else if (in(w, {"once", "single"})) m.once = 1;
  else if (in(w, {"repeatedly", "again", "continuously", "constantly", "rhythmically", "repeating"})) m.once = -1;
  else if (w == "right") m.side = m.side == -1 || m.both ? 0 : 1;
  else if (w == "left") m.side = m.side == 1 || m.both ? 0 : -1;
  else if (in(w, {"both", "two", "all"})) { m.both = true; m.side = 0; }
  // A pair that meets ("rubs its legs together", "claps its hands together") moves as mirror
  // images, towards each other and back, never in turns.
  else if (w == "together") { m.together = m.both = true; m.side = 0; }
  else if (in(w, {"up", "upward", "upwards"})) m.vertical = m.vertical == -1 ? 0 : (m.vertical == 2 ? 0 : 1);
  else if (in(w, {"down", "downward", "downwards"})) m.vertical = m.vertical == 1 ? 0 : -1;
  else if (in(w, {"rightward", "rightwards"})) m.travel = m.travel == -1 ? 0 : 1;
  else if (in(w, {"leftward", "leftwards"})) m.travel = m.travel == 1 ? 0 : -1;
  else if (in(w, {"away", "receding"})) m.depth = -1;
  // The way the figure faces: the limb a thrust or a punch moves is the one the drawing shows
  // reaching out (motion_plan.h), its forward side; the word says no more than that.
  else if (in(w, {"forward", "forwards", "ahead", "onward", "onwards"})) {}
  else if (in(w, {"approaching", "closer", "nearer"})) m.depth = 1;
  else hit = false;
  if (hit) m.words.emplace_back(w);
  return hit;
}

bool is_filler_word(std::string_view w) {
  return in(w, {"a", "an", "the", "is", "are", "was", "were", "be", "being", "been", "its", "it", "his", "her", "their",
                "them", "they", "he", "she", "him", "this", "that", "these", "those", "and", "or", "but", "with", "of",
                "in", "on", "onto", "into", "to", "at", "as", "by", "for", "from", "while", "then", "out", "over",
                "under", "through", "across", "around", "about", "its", "has", "have", "some", "very", "so", "too",
                "each", "other", "back", "forth", "side", "mid", "air", "s", "one", "own", "like", "making", "keeps",
                "keep", "starts", "start", "begins", "slowly", "along", "round"});
}

const char* primitive_name(Primitive p) {
  static constexpr std::array<const char*, 17> names = {"swing", "spin", "hop", "bob", "slide", "rock", "undulate", "bend", "shake",
                                                        "pulse", "squash", "stretch", "fall", "sway", "turn", "toss", "windmill"};
  return names[static_cast<size_t>(p)];
}

const char* target_name(Target t) {
  static constexpr std::array<const char*, 11> names = {"whole", "root", "head", "arms", "legs", "limbs",
                                                        "tail", "wheels", "repeated", "background", "named"};
  return names[static_cast<size_t>(t)];
}

}  // namespace svgm
