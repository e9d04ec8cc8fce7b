// Qualifiers that pick WHICH limbs move ("its hind legs", "the front paws", "rubs them
// together"): how the prompt reads them (not nouns of their own: WordNet's "hind" is a deer and a
// fish) and which limbs of a figure they keep, by the figure's facing (limb_qualifiers.h).
#include <doctest/doctest.h>

#include "motion/lexicon.h"
#include "procedural/limb_qualifiers.h"
#include "procedural/prompt_parse.h"
#include "wordnet_or_skip.h"

using namespace svgm;

namespace {

ArmLobe limb(LobeKind kind, double px, double py, double tx, double ty) {
  ArmLobe l;
  l.kind = kind;
  l.pivot = {px, py};
  l.tip = {tx, ty};
  return l;
}

// A figure seen from the side, 8..61 wide: two legs under its left half, one under its right.
Rig side_view() {
  Rig rig;
  rig.figure.add(Vec2{8, 34});
  rig.figure.add(Vec2{61, 59});
  rig.limbs = {limb(LobeKind::Leg, 27, 52, 21, 59), limb(LobeKind::Leg, 32.5, 54.5, 34, 59), limb(LobeKind::Leg, 53, 53.5, 55, 59)};
  return rig;
}

bool has_noun(const Clause& c, const std::string& w) {
  for (const PromptNoun& n : c.nouns)
    if (n.word == w) return true;
  return false;
}

}  // namespace

TEST_SUITE("video") {

TEST_CASE("qualifiers before a part noun pick which limbs, and are no nouns") {
  const ParsedPrompt p = parse_prompt("the grasshopper rubs its hind legs together");
  REQUIRE(p.clauses.size() == 1);
  const Clause& c = p.clauses[0];
  REQUIRE(c.verbs.size() == 1);
  CHECK(c.verbs[0]->name == "rub");
  CHECK(c.mods.end == -1);
  CHECK(c.mods.together);
  CHECK(c.mods.both);
  CHECK_FALSE(has_noun(c, "hind"));
  REQUIRE(has_noun(c, "legs"));
  CHECK(c.nouns.back().target == Target::Legs);
  CHECK(parse_prompt("the dog lifts its front paw").clauses.at(0).mods.end == 1);
  CHECK(parse_prompt("the horse kicks its back legs").clauses.at(0).mods.end == -1);
  CHECK(parse_prompt("he raises his upper arm").clauses.at(0).mods.level == 1);
  // Not before a part noun: "back and forth", "in front of" qualify nothing.
  CHECK(parse_prompt("the dog wags its tail back and forth").clauses.at(0).mods.end == 0);
  CHECK(parse_prompt("the man walks in front of the house").clauses.at(0).mods.end == 0);
  // "together" pairs what it names; "rubs" with no part rubs the hands.
  const Clause hands = parse_prompt("the man rubs his hands together").clauses.at(0);
  CHECK(hands.mods.together);
  CHECK(hands.nouns.back().target == Target::Arms);
}

TEST_CASE("a qualifier written into the part noun: forelegs, hindwings; not forearm") {
  if (!wordnet_or_skip()) return;
  const Clause fore = parse_prompt("the horse paws with its forelegs").clauses.at(0);
  CHECK(fore.mods.end == 1);
  REQUIRE(has_noun(fore, "legs"));
  const Clause hind = parse_prompt("the beetle flaps its hindwings").clauses.at(0);
  CHECK(hind.mods.end == -1);
  CHECK(has_noun(hind, "wings"));
  // A forearm is a person's (noun.body), not a front arm; a forehead is no front head.
  CHECK(parse_prompt("he rubs his forearm").clauses.at(0).mods.end == 0);
  CHECK(parse_prompt("he rubs his forehead").clauses.at(0).mods.end == 0);
  // The grasshopper is an insect (WordNet's hypernyms), and who moves.
  CHECK(parse_prompt("the grasshopper rubs its hind legs together").clauses.at(0).figure == FigureClass::Insect);
}

TEST_CASE("facing: the head part, a head limb ahead of the legs, else where the legs gather") {
  Rig rig = side_view();
  std::string why;
  CHECK(facing_side(rig, &why) == -1);
  CHECK(why == "its legs gather at that end");
  // A lobe pointing up among the legs (a raised knee) shows no head.
  rig.limbs.push_back(limb(LobeKind::Head, 53, 41.6, 56.7, 34.3));
  CHECK(facing_side(rig, &why) == -1);
  // One based ahead of every leg does.
  rig.limbs.push_back(limb(LobeKind::Head, 58, 44, 60, 36));
  CHECK(facing_side(rig, &why) == 1);
  CHECK(why == "its head ahead of the legs");
  // A head part decides first.
  RigPart head;
  head.role = Role::Head;
  head.box.add(Vec2{8, 34});
  head.box.add(Vec2{14, 42});
  rig.parts.push_back(head);
  CHECK(facing_side(rig, &why) == -1);
  CHECK(why == "its head");
  // Two legs at each end and no head: not known.
  Rig even = side_view();
  even.limbs.push_back(limb(LobeKind::Leg, 50, 53, 50, 59));
  CHECK(facing_side(even, &why) == 0);
}

TEST_CASE("hind keeps the rear limbs, front the others; nothing kept leaves them all") {
  const Rig rig = side_view();
  Modifiers hind;
  hind.end = -1;
  std::vector<ArmLobe> limbs = rig.limbs;
  const std::string note = keep_qualified(rig, hind, limbs);
  REQUIRE(limbs.size() == 1);
  CHECK(limbs[0].pivot.x == 53);
  CHECK(note == "'rear': 1 of 3, the figure faces left (its legs gather at that end)");
  Modifiers front;
  front.end = 1;
  limbs = rig.limbs;
  keep_qualified(rig, front, limbs);
  CHECK(limbs.size() == 2);
  // No qualifier: all of them, and no note.
  limbs = rig.limbs;
  CHECK(keep_qualified(rig, Modifiers{}, limbs).empty());
  CHECK(limbs.size() == 3);
  // Facing unknown: all of them, and the note says why.
  Rig even = side_view();
  even.limbs.push_back(limb(LobeKind::Leg, 50, 53, 50, 59));
  limbs = even.limbs;
  CHECK(keep_qualified(even, hind, limbs) == "'rear': the figure's facing is not known; every one of them moves");
  CHECK(limbs.size() == 4);
}

}  // TEST_SUITE
