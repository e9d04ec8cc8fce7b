// Small wheels found from geometry: a car's, a tram's or a cart's wheels are round paths too
// small for the rig's rule for a wheel among other paths (part_rig_units.cpp: at least 2 % of
// the canvas, a bicycle's wheels), drawn in one group with the body (or, as openmoji draws,
// the tyre's fill in one group and its outline in another).
//
// What makes them wheels is the set: round paths (a near-square box that the outline fills as
// a circle does, part_rig_internal.h's round_path) in the lower third of a drawing wider than
// tall, at least two wheel positions of about the same size side by side at about the same
// height, far apart across the drawing. The round paths about one position's centre (a tyre,
// its rim, its hub) all belong to it. Eyes are up in the figure, a person's shoes stand in a
// drawing taller than wide, buttons or spots are in a column or of unlike sizes.
#pragma once

#include <set>

#include "svgmotion/scene.h"

namespace svgm {

// The paths of the wheels of `scene` found this way (empty when there is no such set).
std::set<int> wheel_set_paths(const Scene& scene);

// A round path of at least this share of the canvas may be a wheel of a set (the rig calls a part
// of this size round: part_rig_assemble.cpp's find_wheels).
constexpr double kSetWheelArea = 0.005;
// Its middle is below this share of the drawing's height from its top.
constexpr double kSetWheelLow = 2.0 / 3.0;
// Two positions are one wheel's when their middles are within this share of the larger's width
// (concentric rings); wheels of a set agree in width within kSetWheelSimilar, their middles'
// heights within kSetWheelLevel of the larger's height, and the outermost two lie at least
// kSetWheelSpread of the drawing's width apart.
constexpr double kSetWheelConcentric = 0.2;
constexpr double kSetWheelSimilar = 1.3;
constexpr double kSetWheelLevel = 0.5;
constexpr double kSetWheelSpread = 0.4;

}  // namespace svgm
