// Flames around what burns (issue 35): a heart on fire drawn as one blaze with the heart over its
// lower half (openmoji 2764-FE0F-200D-1F525). Nothing is drawn above the blaze's top, so the
// locator's tips of flame (part_locator.cpp) find none, and the whole figure flickered, the heart
// with it (share 0.22). What burns is drawn over the blaze, low in it and across most of its
// width down to its bottom, with a blunt top (a heart's two lobes, a log's or a bowl's rim); a flame drawn inside a
// flame (twemoji's fire 1f525: its yellow core) has a pointed top and is no such thing. The
// flames are then the blaze's stretch above the burning thing's top, flickering about the middle
// of that top; the thing and its details hold.
#pragma once

#include "procedural/part_locator.h"

namespace svgm {

// The flames over element `body` (the figure's largest box) around a thing drawn over it (see
// above): one lobe over the points above its top of every element reaching above it but those
// inside its box. Lobes empty when no element is such a thing.
LocatedPart flames_over_core(const Rig& rig, int body);

// Whether element `e`'s top is blunt: its points in its top `top` of its height spread over at
// least kBluntSpread of its width (a flame's tip is one point).
inline constexpr double kBluntTop = 0.15;
bool blunt_top(const RigElement& e, double top = kBluntTop);

inline constexpr double kCoreBelow = 0.25;   // its top below this share of the blaze's height
inline constexpr double kCoreBottom = 0.1;   // its bottom within this share of the blaze's height of the blaze's bottom
inline constexpr double kCoreSpan = 0.8;     // across at least this share of the blaze's width
inline constexpr double kCoreGrow = 0.05;    // its details' boxes within its box grown by this share of its diagonal
inline constexpr double kBluntSpread = 0.5;
inline constexpr double kTipTop = 0.05;      // a blaze's top this share of its height is one tip

}  // namespace svgm
