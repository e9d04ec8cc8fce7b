// The procedural video's motion vocabulary: the verbs a prompt may use (each with its
// synonyms), what each one moves (wings, arms, legs, head, tail, wheels, repeated elements such
// as drops, the whole figure) and how (a swing about a pivot, a spin about the part's own
// centre, a hop with squash and stretch, a wave along the body, a fall ...), plus the part
// nouns ("wings", "tentacles", "drops") and the modifiers (slow/fast, gently/wildly,
// once/repeatedly, left/right, up/down, both) that change a verb's target, speed and size.
//
// Words are matched as stems with English inflections (see word_matches): "flap" matches
// flap, flaps, flapped, flapping, flapper; "wav" matches wave, waves, waving. The table is data,
// so adding a verb is adding a row in motion_verbs.cpp.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace svgm {

// How a part moves over one loop (units of `amp` in brackets).
enum class Primitive {
  Swing,     // rotation about the part's attachment pivot, oscillating [degrees]
  Spin,      // whole turns about the part's own centre [turns per loop]
  Hop,       // up in an arc and back, squashed on landing and stretched in the air [figure heights]
  Bob,       // up and down [figure heights]
  Slide,     // side to side, along the figure's long axis [figure widths]
  Rock,      // rotation of the figure about its base [degrees]
  Undulate,  // a wave travelling along the long axis of the part (swimming) [figure lengths]
  Bend,      // the part curves about its middle, back and forth [degrees at the ends]
  Shake,     // small fast jitter [figure heights]
  Pulse,     // scale about the centre [fraction of the size]
  Squash,    // down and squashed, then back up (sitting, crouching) [figure heights]
  Stretch,   // longer along the part's long axis, then back [fraction of the length]
  Fall,      // each element falls and is replaced from above, its own phase [canvas heights]
  Sway,      // the figure's upper part leans side to side about a hinge at its middle, the
             // lower part planted (a glass on its foot, a tree on its roots) [degrees of lean]
  Turn,      // whole turns about the figure's vertical axis (a pirouette): its width scaled by
             // the turn's cosine about its middle, mirrored past a quarter turn [turns per loop]
  Toss,      // the small round things a figure holds up (balls) fly from hand to hand along
             // arcs, each in its own phase (a juggler's cascade: tossed_things.h) [share of the arc]
  Windmill,  // whole turns of a limb about its joint (a swimmer's over-arm stroke) [turns per loop]
};

// Which parts an action moves, by role in the rig (part_rig.h).
enum class Target { Whole, Root, Head, Arms, Legs, Limbs, Tail, Wheels, Repeated, Background, Named };

// How a pair of limbs moves together. OneSide: one limb (the side the prompt names, else the one
// the drawing shows reaching out); both mirrored when the prompt says both. OneAtATime: one limb
// the same way, both taking turns when the prompt says both (punches).
enum class Pairing { Same, Mirrored, Alternating, OneSide, OneAtATime };

struct Action {
  Primitive primitive;
  Target target;
  double amp;      // in the primitive's unit
  int cycles;      // whole cycles per loop (the loop stays seamless)
  Pairing pairing = Pairing::Mirrored;
};

struct Verb {
  std::string name;                // canonical ("flap")
  std::vector<std::string> stems;  // word stems that mean it
  std::vector<Action> actions;     // the first is the primary: a part noun retargets it
  Primitive on_part;               // the primary's primitive when a noun names the part
};

// Every verb (at least 40), in table order.
const std::vector<Verb>& motion_verbs();
const Verb* find_verb_by_name(std::string_view name);
// The verb whose stem `word` (lower case) inflects, the longest stem when several do.
const Verb* find_verb_by_word(std::string_view word);

struct PartNoun {
  std::string stem;
  Target target;
};
const std::vector<PartNoun>& part_nouns();

// The modifiers a clause may carry.
struct Modifiers {
  double speed = 1;  // cycles multiplier: slow 0.5, fast 2
  double size = 1;   // amplitude multiplier: gently 0.5, wildly 1.6
  int once = 0;      // +1 once, -1 repeatedly, 0 neither
  int side = 0;      // the figure's own side: +1 right, -1 left, 0 neither or both
  bool both = false;
  int vertical = 0;  // +1 up, -1 down, 0 neither or both
  // Where the whole figure travels, in the viewer's frame and apart from `side` (the figure's
  // own side: "his right arm"): "drifts right", "walks to the left" (prompt_parse reads which
  // a "left" or "right" is), "rightwards".
  int travel = 0;    // +1 to the viewer's right, -1 to the left, 0 neither or both
  // "across the screen", "swims across the pond": it goes across, the prompt says not which way
  // (motion_plan.cpp sends it the way it faces, else to the right).
  bool across = false;
  int depth = 0;     // +1 towards the viewer ("towards the camera"), -1 away ("into the distance")
  // Which of the named limbs, by where they are on the figure (prompt_parse reads these words
  // only right before a part noun: "its hind legs", "the front paws", "his lower arm"):
  int end = 0;       // +1 the front ones on the figure's facing axis ("front", "fore"), -1 the
                     // rear ones ("hind", "rear", "back"), 0 either
  int level = 0;     // +1 the upper ones, -1 the lower ones, 0 either
  bool together = false;  // a pair moves towards each other and back ("rubs its legs together")
  std::vector<std::string> words;  // the modifier words seen, for the report
};

// Applies `word` to `m` when it is a modifier; false otherwise.
bool apply_modifier(std::string_view word, Modifiers& m);

// True when `word` (lower case) is `stem` plus an English inflection: "", s, es, e, ed, d,
// ing, er, ers, y, ly, or a doubled last consonant before ing/ed/er ("flapping").
bool word_matches(std::string_view word, std::string_view stem);

// Small words that carry no motion (articles, pronouns, auxiliaries, prepositions).
bool is_filler_word(std::string_view word);

const char* primitive_name(Primitive p);
const char* target_name(Target t);

}  // namespace svgm
