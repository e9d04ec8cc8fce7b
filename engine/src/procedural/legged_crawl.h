// A crawl on legs is a walk (issue 35): "the lobster crawls along", "the spider creeps", "the
// beetle moves to the left". The vocabulary's crawl (motion_verbs.cpp's "move": a slide of the
// whole figure and a stretch, gait_travel.h's crawl_in_steps) is a legless body's creep, a
// caterpillar's or a snail's: said of a figure with legs drawn, its legs stood still while the
// whole drawing slid and stretched like rubber, and the crawl read as a figure pushed along. A
// creature's crawl on legs it has (two or more rig parts of the legs' role, or with none, two or
// more legs of its silhouette's skeleton, skeleton_lobes.h) is the walk's: legs in turn, the body going steadily
// the way it goes (motion_plan.cpp's travel_where_told). A legless figure, a fish or a snake
// (its crawl is a slither's creep), a figure whose only "legs" are stand-ins (parts_for's
// fallback: a body bent at its lower part), and a crawler the lexicon files as no creature (a
// caterpillar, an object: its prolegs are no legs to stride on) crawl as before.
#pragma once

#include <string>

#include "motion/motion_verbs.h"
#include "procedural/part_rig.h"
#include "procedural/prompt_parse.h"

namespace svgm {

// The legs a crawl of `rig` can walk on, counted: its parts of the legs' role (the side limbs of
// a figure wider than tall seen from above: plan_targets.cpp) when parts_for needs no stand-in,
// else (no part of the role) its silhouette's leg limbs; 0 when fewer than two: the walk moves
// the parts when there are any (Builder::add), so one part is no gait. `why` gets "6 legs drawn
// as parts".
int walkable_legs(const Rig& rig, std::string* why);

// The verb `v` of clause `c` becomes: the walk when it is the generic move (a crawl, a creep,
// a move) said of a creature that is not a fish or a snake, drawn with legs to walk on, and the
// clause names no part of it to move ("lowers its neck"); else `v`.
const Verb* legged_crawl(const Verb* v, const Clause& c, const Rig& rig);

}  // namespace svgm
