// Where a sway of the whole figure leans from, and the lean itself.
//
// A figure swaying in general (a wine glass, a saxophonist, a sloth on its branch) leans its top
// about its middle: below kSwayHinge of its height (motion_plan_internal.h) it holds. A plant
// grows from the ground or its pot: it sways about where it meets them, and bends more towards
// its tips. Leaning about the figure's middle, a seedling's stem stood stiff over its lower half
// while its top half swung about a point beside the stem (the box's middle), and a herb's stem
// was rigid where it rises from the ground. So a plant's sway, and its bend from its base, is
// rooted (plant_base), for a figure the prompt names a plant:
//  - at the mouth of what holds it (a pot, a vase, a mound of earth): the widest solid element
//    drawn at the figure's bottom (it spans at least kHolderWide of the figure's width, fills
//    at least kHolderSolid of its own box, stands at most kHolderTall of the figure's height,
//    has a flat top and stands under the figure's middle),
//    with the solid bands stacked on it (a pot's rim: as wide, at its top); its top's middle;
//  - else at the foot of its stem: the middle of the points drawn in the lowest kFootBand of
//    the figure.
// Above the root each point turns about it by the angle times its height above the root over
// the plant's height there (the tips turn by the whole angle): a point moves by about the square
// of its height, a cantilever's curve, smooth through the root line (no cut), and the pot and
// what is drawn below its mouth hold. A bend of a rooted plant (motion_frames.cpp's cantilever)
// measures its height from the root too.
#pragma once

#include <string>

#include "procedural/motion_plan.h"
#include "procedural/part_rig.h"

namespace svgm {

inline constexpr double kHolderWide = 0.3, kHolderSolid = 0.5, kHolderTall = 0.6, kFootBand = 0.05;

struct PlantBase {
  Vec2 root;         // where the plant is held: it sways about this point
  bool held = false; // a holder (pot, vase, earth) was found; false: the stem's foot
  std::string why;   // "held at its pot's mouth (y 30.1)", for motion.json
};

// Where the plant drawn by `rig` is held (see above).
PlantBase plant_base(const Rig& rig);

// Roots `a` at plant_base when it is a sway of a whole figure the prompt names a plant (`figure`),
// or its bend from its base (anchored at the bottom): PlannedAction::rooted and root. Returns
// where it is held, in words, or "" when `a` is left as it was.
std::string root_plant(PlannedAction& a, const Rig& rig, FigureClass figure);

// Point q of a figure with box `box` under the sway `a` at time t, with amplitude `amp` in
// degrees: rooted about a.root (PlannedAction::rooted), else leaning its top about its middle.
Vec2 sway_lean(const PlannedAction& a, double amp, double t, const RigBox& box, Vec2 q);

}  // namespace svgm
