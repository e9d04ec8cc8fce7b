// Which elements a plume is (issue 35): what is drawn above its source's top, less what stands
// under it. part_locator.cpp's jet turns them about their lowest middle.
//  - The source is the element of most drawn area (a thin curl of smoke can have the largest box:
//    twemoji's cigarette 1f6ac, whose curl spans more than the cigarette); with nothing above it,
//    the one of most drawn area in the figure's lower half (a plume rises from what is under it):
//    twemoji's factory (1f3ed) has its building read as the backdrop, and of what is left a puff
//    of smoke had the most area, with nothing above it.
//  - Everything drawn above the source's top (a spout's drops together), but what stands on it (a
//    factory's roof under its smoke: its bottom at the source's top) when anything else is.
//  - But the source's own top: what lies across it, reaching below its top and as wide as
//    kRimSpan of it (twemoji's coffee 2615: the cup's rim and the coffee in it rose with the
//    steam, share 0.55, under a saucer of most area). A plume is narrower than what it rises from,
//    or floats above it (a cigarette's curl, wider than the cigarette, starts above its end).
//  - A stack: a factory's chimney drawn as bands edge to edge, a puff of smoke sitting on its top
//    band. An element with another sitting on it edge to edge (the other's bottom at its top,
//    within kStackTouch of the figure's height, its middle over it) stays with the source: the
//    chimney's bands rose with the puffs (still ratio 0.56). What sits on top of a stack, with
//    nothing on it, leaves it. A spout's drops, a cigarette's curl and wisps of steam float apart
//    or overlap: no stack, no change.
#pragma once

#include <cstddef>
#include <vector>

#include "procedural/part_rig.h"

namespace svgm {

// The plume's elements (see above), sorted; `stacked`: how many were left as a stack. Empty when
// nothing is drawn above the source.
std::vector<int> plume_elements(const Rig& rig, size_t& stacked);

// The elements of `els` with another of `els` sitting on them edge to edge (see above), sorted.
std::vector<int> plume_stack(const Rig& rig, const std::vector<int>& els);

inline constexpr double kStackTouch = 0.01;  // bands drawn edge to edge touch exactly
inline constexpr double kRimSpan = 0.6;    // the source's own top: this share of its width at least
inline constexpr double kJetGap = 0.02;      // a plume floats this share of the figure's height above its source's top

}  // namespace svgm
