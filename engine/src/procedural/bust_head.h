// The head of a figure drawn as a bust or as a head alone (issue 35): "she nods her head", "he
// shakes his head" on a portrait emoji (head and shoulders, or a face filling the canvas). The
// rig (part_rig.h) takes the largest central part for the body: on a bust that is the hair or
// the face, so it found no head (the nod bent the top of the hair and the face held still) or
// called the hair over a face the head (the hair turned on a still face). The head is read from
// the drawing's elements instead:
//  - a bust: the shoulders are the widest element standing on the figure's bottom, spanning most
//    of its width and lying wholly in its lower part; the head is what is drawn above them (each
//    element whose middle is above the shoulders' top), at least a good share of the figure's
//    height, turning whole about the middle of the shoulders' top (the neck);
//  - a head alone: no shoulders, no limbs in the rig, a compact figure: the whole figure is the
//    head, turning whole about the middle of its bottom (the chin on the neck below it).
// Never when the rig finds arms (a standing figure on a board or a band of ground has them); only
// said of a person or of no figure named (motion_plan.cpp): an owl is compact and limbless, a
// snake's coils lie wide on the bottom under its raised head, and neither is a portrait.
#pragma once

#include "procedural/part_locator.h"

namespace svgm {

// The head found so (one rigid lobe over its elements, its paths), or no lobes.
LocatedPart bust_head(const Rig& rig);

}  // namespace svgm
