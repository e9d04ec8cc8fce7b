// A crawl on legs walks (see legged_crawl.h).
#include "procedural/legged_crawl.h"

#include <string>
#include <vector>

#include "motion/lexicon.h"
#include "procedural/motion_plan_internal.h"

namespace svgm {

int walkable_legs(const Rig& rig, std::string* why) {
  if (rig.root < 0) return 0;
  // Parts of the legs' role, with no stand-in (a note says parts_for fell back to other parts).
  std::string fallback;
  const std::vector<int> parts = motion_plan_internal::parts_for(rig, Target::Legs, "", &fallback);
  // They are what the walk moves (Builder::add): one (a cricket's hind leg taken for its side
  // limb) is no gait, whatever the silhouette shows.
  if (fallback.empty() && !parts.empty()) {
    if (parts.size() < 2) return 0;
    if (why) *why = std::to_string(parts.size()) + " legs drawn as parts";
    return static_cast<int>(parts.size());
  }
  // Else the silhouette's legs: what bend_region moves for the legs when no part is one.
  int legs = 0;
  for (const ArmLobe& l : rig.limbs) legs += l.kind == LobeKind::Leg;
  if (legs < 2) return 0;
  if (why) *why = std::to_string(legs) + " legs of the figure's silhouette skeleton";
  return legs;
}

const Verb* legged_crawl(const Verb* v, const Clause& c, const Rig& rig) {
  // Who crawls must be a creature the lexicon knows: a caterpillar (no class: an object) or a
  // box that "inches along" creeps by its steps whatever its drawing shows below it.
  if (!v || v->name != "move" || !is_creature(c.figure) || c.figure == FigureClass::FishOrSnake) return v;
  // A move of a part the clause names ("the giraffe lowers its long neck": WordNet's lower is a
  // move) moves that part; only the figure's own move is a crawl (the neck had walked).
  for (const PromptNoun& n : c.nouns)
    if (!n.object_of_preposition && motion_plan_internal::is_part_target(n.target)) return v;
  if (walkable_legs(rig, nullptr) == 0) return v;
  const Verb* walk = find_verb_by_name("walk");
  return walk ? walk : v;
}

}  // namespace svgm
