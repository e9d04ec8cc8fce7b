// Petals a prompt names ("the petals open", "the daisy's petals spread"): the part of a flower
// arranged round a centre. A drawing gives them in one of two ways:
//  - a rosette: one closed outline whose distance from its middle rises and falls at least
//    kRosetteLobes times round it, each dip at least kRosetteDip of the farthest reach in (a
//    daisy's head drawn as one scalloped path, its outline stroke drawn over it);
//  - a ring of repeated elements (repeated_elements.h): at least three similar shapes whose
//    middles lie round a common centre, at like distances and on every side of it.
// The petals become one lobe (outline_lobes.h) centred on the flower's middle that holds the
// rosette or the ring and what is drawn inside it (the flower's heart); only those paths move,
// so the stem and the leaves hold. A grow ("open", "bloom", "unfold") scales the lobe's points
// about the centre, the petals spreading outward; other verbs turn it about the centre.
#pragma once

#include "procedural/part_locator.h"

namespace svgm {

// The petals of the rig's figure; lobes empty when there is neither a rosette nor a ring.
LocatedPart find_petals(const Rig& rig);

}  // namespace svgm
