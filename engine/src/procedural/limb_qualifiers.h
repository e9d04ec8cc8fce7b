// Which of the figure's limbs a qualifier of the prompt picks (prompt_parse.h reads them right
// before a part noun): "its hind legs" are the legs at the end of the figure's facing axis away
// from its head, "the front paws" those at the head's end, "his upper arm" the higher of a pair.
// The facing comes from the figure, not from the words: a drawn eye (eye_cue.h), else the
// rig's head parts, else the silhouette skeleton's head limbs ahead of every leg (a head leads
// the legs; a lobe among them is a raised limb or a knee), else where the legs gather (legs hang under the front of a body,
// its chest or thorax: with no head to show which end leads, the end with fewer legs is the
// rear). A qualifier that picks nothing on the drawing is ignored, with a note saying so.
#pragma once

#include <string>
#include <vector>

#include "motion/lexicon.h"
#include "motion/motion_verbs.h"
#include "procedural/motion_plan.h"
#include "procedural/outline_lobes.h"
#include "procedural/part_rig.h"

namespace svgm {

// The viewer's side the figure faces: -1 left, +1 right, 0 unknown; `why` says how it was found.
// With the prompt's figure class `figure`: a vehicle (FigureClass::Wheeled) is read from its
// outline (shape_facing.h: its low front), else a rider's eye, and by nothing else.
int facing_side(const Rig& rig, FigureClass figure, std::string* why);
inline int facing_side(const Rig& rig, std::string* why) { return facing_side(rig, FigureClass::None, why); }

// The side (-1 left, +1 right, 0 none) a region bend of `target` on part `part` takes when the
// prompt names none: the side its limbs are on when they are found on one side only (a polo
// player's raised arm, the other under the water: the coin's other side bent the whole
// figure's sides), else for `one_sided` arm verbs (a throw, a wave, a swing of a thing held; not
// a punch's one arm then the other, nor one sent forward) the arm raised above its shoulder when
// the other is not (a throw's arm holding the ball up, not the one held out). Limbs: the part's
// arms drawn in its outline (for arms) and the silhouette's limbs that serve `target`.
int lone_or_raised_side(const Rig& rig, int part, Target target, bool one_sided);

// Keeps the parts (the rig's, by index) or the limbs of the silhouette that `mods.end` and
// `mods.level` pick; unchanged when neither is set or when none would be left. Returns a note for
// the plan's report ("hind: the rear limbs, the figure faces left (its head)"), empty when
// nothing was asked.
std::string keep_qualified(const Rig& rig, const Modifiers& mods, std::vector<int>& parts);
std::string keep_qualified(const Rig& rig, const Modifiers& mods, std::vector<ArmLobe>& limbs);

// Why the `i`th action of verb `v` (an arm or wing swing) is left out, empty when it is not: a
// gait's arm swing is a person's (on a four-legged animal, a bird or a fish it found no arms and
// bent the sides of the body: a running dog's head and tail swung as arms); a machine that flies
// (an object: a saucer, a balloon) beats no wings (its sides bent as wings, a hovering saucer
// narrowed as if it turned about its vertical axis). Only a creature beats wings or arms in
// flight: a figure of no creature's class (a machine, a plume, a plant) never does, and one the
// prompt names no class for only when the rig has arms or wings drawn apart (upper limbs: a
// "chopper" hovering had only its sides to bend). `figure`: the prompt's figure class;
// `clause_figure`: the clause's.
std::string arms_left_out(const Verb& v, size_t i, FigureClass figure, FigureClass clause_figure, const Rig& rig);

// Why a flight's wing beat `a` of verb `v` is left out, empty when it is not: it found no wings
// (no part apart, no lobe of the outline or the silhouette) and would bend the body's sides, which
// narrowed a hovering machine the prompt's noun called a creature ("blimp" is first a very fat
// person) as if it turned about its vertical axis, mirrored in some frames.
std::string wings_left_out(const Verb& v, const PlannedAction& a);

}  // namespace svgm
