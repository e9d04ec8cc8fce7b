// A thing a person holds and moves with the hands (issue 35): "the golfer swings the club", "the
// batter swings the bat", "the rower pulls the oars". The lexicon reads such verbs as the whole
// figure's (swing: a rock of the whole figure; pull: WordNet's move, a slide), so the golfer
// rocked on his feet with the club still in his hands and the rower slid with his boat. When
// the verb's object is a thing the drawing has no part for (not the figure's own part, not a
// person) and who does it is a person, the arms move instead, and what the hand holds goes with
// them (skeleton_lobes.h: a piece drawn beside a hand is that limb's); "he" or "she" says a
// person too. A swing of a held thing is one arm's big swing, as a throw's (wield); a pull or a
// push of it is both arms' strokes (haul). motion_verbs.cpp has both verbs. Only when the rig finds arms: else their motion
// would bend the sides of the whole figure (a rower's boat and sea).
#pragma once

#include "motion/motion_verbs.h"
#include "procedural/part_rig.h"
#include "procedural/prompt_parse.h"

namespace svgm {

// The verb `v` becomes in clause `c` (wield or haul, see above), or `v` itself.
const Verb* held_thing_reading(const Verb* v, const Clause& c, const Rig& rig);

}  // namespace svgm
