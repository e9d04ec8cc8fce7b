// A held thing moved by the arms (see held_things.h).
#include "procedural/held_things.h"

#include <cctype>
#include <string>

#include "procedural/motion_plan_internal.h"

namespace svgm {

namespace {

// The clause's object is a thing held: a noun after the verb, not after a preposition nor said
// to do something itself, naming no part of the drawing and no person or animal.
bool object_is_held_thing(const Clause& c, const Rig& rig) {
  for (const PromptNoun& n : c.nouns) {
    if (!n.after_verb || n.object_of_preposition || n.own_predicate || n.target != Target::Named) continue;
    if (n.figure != FigureClass::None && n.figure != FigureClass::Object) continue;
    std::string ignore;
    if (motion_plan_internal::parts_for(rig, Target::Named, n.word, &ignore).empty()) return true;
  }
  return false;
}

// Arms found on the figure: parts for them, arms drawn in an outline, or the silhouette's arm
// limbs. With none the arms' motion bends the sides of the whole figure (the rower's boat and
// sea with him), worse than the lexicon's whole-figure reading.
bool arms_found(const Rig& rig) {
  for (const RigPart& P : rig.parts)
    if (P.role == Role::UpperLimb || !P.arm_lobes.empty()) return true;
  for (const ArmLobe& l : rig.limbs)
    if (motion_plan_internal::lobe_serves(l.kind, Target::Arms)) return true;
  return false;
}

// Who does it is a person: the clause's figure is a person, or it names none and says "he" or
// "she" ("he swings his golf club": the pronouns are no nouns, and the clause had no class).
bool said_of_person(const Clause& c) {
  if (c.figure == FigureClass::Biped) return true;
  if (c.figure != FigureClass::None) return false;
  std::string word;
  for (size_t i = 0; i <= c.text.size(); ++i) {
    if (i < c.text.size() && c.text[i] != ' ') {
      word += static_cast<char>(std::tolower(static_cast<unsigned char>(c.text[i])));
      continue;
    }
    if (word == "he" || word == "she" || word == "his" || word == "her" || word == "him") return true;
    word.clear();
  }
  return false;
}

}  // namespace

const Verb* held_thing_reading(const Verb* v, const Clause& c, const Rig& rig) {
  if (!v || v->actions.empty() || !said_of_person(c)) return v;
  const Action& first = v->actions[0];
  if (first.target != Target::Whole) return v;
  const char* as = first.primitive == Primitive::Rock || first.primitive == Primitive::Sway ? "wield"
                   : v->name == "move" ? "haul" : nullptr;
  if (!as || !object_is_held_thing(c, rig) || !arms_found(rig)) return v;
  const Verb* held = find_verb_by_name(as);
  return held ? held : v;
}

}  // namespace svgm
